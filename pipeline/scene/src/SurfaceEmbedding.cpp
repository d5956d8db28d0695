#include "SurfaceEmbedding.h"

#include <string>

namespace hs::scene::detail {

void splitEmbedding(const std::vector<TetEmbedding>& embedding, SurfaceMesh& mesh, io::PointArrays& arrays,
                    const char* tetLabel, const char* weightsArray) {
    auto& tets = mesh.vertexLabels[tetLabel];
    tets.clear();
    io::PointArray weights;
    weights.components = 4;
    weights.values.reserve(embedding.size() * 4);
    for (const TetEmbedding& e : embedding) {
        tets.push_back(e.tet);
        weights.values.insert(weights.values.end(), e.weights.begin(), e.weights.end());
    }
    arrays[weightsArray] = std::move(weights);
}

Status joinEmbedding(SurfaceMesh& mesh, const io::PointArrays& arrays, std::vector<TetEmbedding>& embedding,
                     const char* tetLabel, const char* weightsArray) {
    embedding.clear();
    const auto label = mesh.vertexLabels.find(tetLabel);
    const auto weights = arrays.find(weightsArray);
    const bool hasLabel = label != mesh.vertexLabels.end(), hasWeights = weights != arrays.end();
    if (!hasLabel && !hasWeights)
        return {};
    if (hasLabel != hasWeights)
        return fail(ErrorCode::InvalidInput, std::string("surface.vtp: has '") + (hasLabel ? tetLabel : weightsArray) +
                                                 "' without '" + (hasLabel ? weightsArray : tetLabel) +
                                                 "': the embedding needs both");
    if (weights->second.components != 4)
        return fail(ErrorCode::InvalidInput, std::string("surface.vtp: '") + weightsArray + "' has " +
                                                 std::to_string(weights->second.components) +
                                                 " components, expected 4");
    const auto& tets = label->second;
    embedding.resize(tets.size());
    for (std::size_t i = 0; i < tets.size(); ++i) {
        embedding[i].tet = tets[i];
        for (std::size_t k = 0; k < 4; ++k)
            embedding[i].weights[k] = weights->second.values[4 * i + k];
    }
    mesh.vertexLabels.erase(label);
    return {};
}

} // namespace hs::scene::detail
