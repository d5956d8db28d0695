#include "hs/core/TetMesh.h"

#include <algorithm>
#include <cmath>
#include <unordered_map>

namespace hs {
namespace {

struct FaceKey {
    std::array<std::int32_t, 3> sorted;
    bool operator==(const FaceKey& o) const { return sorted == o.sorted; }
};
struct FaceKeyHash {
    std::size_t operator()(const FaceKey& k) const {
        std::uint64_t h = 1469598103934665603ull;
        for (auto v : k.sorted) {
            h ^= static_cast<std::uint32_t>(v);
            h *= 1099511628211ull;
        }
        return static_cast<std::size_t>(h);
    }
};

// Faces of a positively oriented tet (p0, p1, p2, p3), each wound so that its normal points out of the tet.
constexpr const auto& kTetFaces = kTetFacePoints;

FaceKey faceKey(const Tet& tet, int face) {
    FaceKey key{{tet[static_cast<std::size_t>(kTetFaces[face][0])], tet[static_cast<std::size_t>(kTetFaces[face][1])],
                 tet[static_cast<std::size_t>(kTetFaces[face][2])]}};
    std::sort(key.sorted.begin(), key.sorted.end());
    return key;
}

} // namespace

std::vector<std::array<std::int32_t, 4>> tetNeighbours(const TetMesh& mesh) {
    std::vector<std::array<std::int32_t, 4>> out(mesh.tets.size(), {-1, -1, -1, -1});
    std::unordered_map<FaceKey, std::pair<std::int32_t, int>, FaceKeyHash> open; // face -> (tet, face index)
    open.reserve(mesh.tets.size() * 2);
    for (std::size_t t = 0; t < mesh.tets.size(); ++t)
        for (int f = 0; f < 4; ++f) {
            const auto [it, inserted] = open.try_emplace(faceKey(mesh.tets[t], f), static_cast<std::int32_t>(t), f);
            if (inserted)
                continue;
            const auto [other, otherFace] = it->second;
            if (other < 0)
                continue; // already paired: a third tet on the face is not linked
            out[t][static_cast<std::size_t>(f)] = other;
            out[static_cast<std::size_t>(other)][static_cast<std::size_t>(otherFace)] = static_cast<std::int32_t>(t);
            it->second.first = -1;
        }
    return out;
}

Status validate(const TetMesh& mesh) {
    HS_TRY(checkCoordinates(mesh.points, "point"));
    const auto n = static_cast<std::int64_t>(mesh.points.size());
    for (std::size_t t = 0; t < mesh.tets.size(); ++t) {
        for (auto v : mesh.tets[t]) {
            if (v < 0 || v >= n)
                return fail(ErrorCode::InvalidInput, "tetrahedron " + std::to_string(t) + " references point " +
                                                         std::to_string(v) + ", allowed 0.." + std::to_string(n - 1));
        }
    }
    if (!mesh.regions.empty() && mesh.regions.size() != mesh.tets.size())
        return fail(ErrorCode::InvalidInput, "region array has " + std::to_string(mesh.regions.size()) +
                                                 " values for " + std::to_string(mesh.tets.size()) + " tetrahedra");
    for (const auto& [name, values] : mesh.tetLabels)
        if (!values.empty() && values.size() != mesh.tets.size())
            return fail(ErrorCode::InvalidInput, "tetrahedron label '" + name + "' has " +
                                                     std::to_string(values.size()) + " values, expected " +
                                                     std::to_string(mesh.tets.size()));
    for (const auto& [name, values] : mesh.pointLabels)
        if (!values.empty() && values.size() != mesh.points.size())
            return fail(ErrorCode::InvalidInput, "point label '" + name + "' has " + std::to_string(values.size()) +
                                                     " values, expected " + std::to_string(mesh.points.size()));
    return {};
}

Bounds bounds(const TetMesh& mesh) {
    Bounds b;
    for (const auto& p : mesh.points)
        b.add(p);
    return b;
}

double signedVolume(const TetMesh& mesh, std::size_t t) {
    const auto& tet = mesh.tets[t];
    const Vec3& p0 = mesh.points[static_cast<std::size_t>(tet[0])];
    const Vec3 a = mesh.points[static_cast<std::size_t>(tet[1])] - p0;
    const Vec3 b = mesh.points[static_cast<std::size_t>(tet[2])] - p0;
    const Vec3 c = mesh.points[static_cast<std::size_t>(tet[3])] - p0;
    return dot(a, cross(b, c)) / 6.0;
}

double totalVolume(const TetMesh& mesh) {
    double v = 0.0;
    for (std::size_t t = 0; t < mesh.tets.size(); ++t)
        v += std::fabs(signedVolume(mesh, t));
    return v;
}

std::map<std::int32_t, double> regionVolumes(const TetMesh& mesh) {
    std::map<std::int32_t, double> volumes;
    for (std::size_t t = 0; t < mesh.tets.size(); ++t)
        volumes[mesh.regionOf(t)] += std::fabs(signedVolume(mesh, t));
    return volumes;
}

std::size_t invertedTetCount(const TetMesh& mesh, double minVolume) {
    std::size_t count = 0;
    for (std::size_t t = 0; t < mesh.tets.size(); ++t)
        if (signedVolume(mesh, t) <= minVolume)
            ++count;
    return count;
}

SurfaceMesh extractBoundary(const TetMesh& mesh, bool includeInterfaces) {
    struct FaceUse {
        std::size_t tet = 0;
        std::array<std::int32_t, 3> oriented{};
        int count = 0;
        std::size_t otherTet = 0;
    };
    std::unordered_map<FaceKey, FaceUse, FaceKeyHash> faces;
    faces.reserve(mesh.tets.size() * 2);
    std::vector<FaceKey> order; // first-seen order keeps the output deterministic
    order.reserve(mesh.tets.size() * 2);

    for (std::size_t t = 0; t < mesh.tets.size(); ++t) {
        const auto& tet = mesh.tets[t];
        const bool flipped = signedVolume(mesh, t) < 0.0;
        for (const auto& f : kTetFaces) {
            std::array<std::int32_t, 3> tri{tet[static_cast<std::size_t>(f[0])], tet[static_cast<std::size_t>(f[1])],
                                            tet[static_cast<std::size_t>(f[2])]};
            if (flipped)
                std::swap(tri[1], tri[2]);
            FaceKey key{tri};
            std::sort(key.sorted.begin(), key.sorted.end());
            auto [it, inserted] = faces.try_emplace(key);
            FaceUse& use = it->second;
            if (inserted) {
                use.tet = t;
                use.oriented = tri;
                order.push_back(key);
            } else {
                use.otherTet = t;
            }
            ++use.count;
        }
    }

    SurfaceMesh out;
    std::vector<std::int32_t> newIndex(mesh.points.size(), -1);
    std::vector<std::int32_t>& source = out.vertexLabels["sourcePoint"];
    std::vector<std::int32_t>& region = out.faceLabels["region"];
    std::vector<std::int32_t>& otherRegion = out.faceLabels["otherRegion"];
    auto mapPoint = [&](std::int32_t p) {
        auto& idx = newIndex[static_cast<std::size_t>(p)];
        if (idx < 0) {
            idx = static_cast<std::int32_t>(out.points.size());
            out.points.push_back(mesh.points[static_cast<std::size_t>(p)]);
            source.push_back(p);
        }
        return idx;
    };
    for (const auto& key : order) {
        const FaceUse& use = faces.at(key);
        std::array<std::int32_t, 3> tri = use.oriented;
        std::int32_t r = mesh.regionOf(use.tet);
        std::int32_t other = -1;
        if (use.count == 2) {
            if (!includeInterfaces)
                continue;
            other = mesh.regionOf(use.otherTet);
            if (other == r)
                continue;
            if (other < r) { // orient out of the lower region id
                std::swap(r, other);
                std::swap(tri[1], tri[2]);
            }
        } else if (use.count != 1) {
            continue; // a face of more than two tets: not a valid mesh; validate() callers see it elsewhere
        }
        out.triangles.push_back({mapPoint(tri[0]), mapPoint(tri[1]), mapPoint(tri[2])});
        region.push_back(r);
        otherRegion.push_back(other);
    }
    return out;
}

} // namespace hs
