// The textured surface (the UV-split mesh) and the bake's folder; hs::io writes the files.
#include "hs/texture/Bake.h"
#include "hs/texture/ImageFiles.h"

#include "hs/core/Subdivision.h"
#include "hs/io/AtomicFile.h"
#include "hs/io/MeshIO.h"
#include "hs/io/TexturedSurface.h"

#include <algorithm>
#include <array>
#include <filesystem>
#include <map>
#include <string>
#include <system_error>
#include <tuple>
#include <unordered_map>

namespace hs::texture {

namespace {

/// An output point: a point of the subdivided surface, its fan there and its chart.
using SplitKey = std::tuple<std::int32_t, std::uint8_t, std::int32_t>;

/// The fans of faces around each point: faces at a point that share an edge through it are in one fan. A point where
/// two sheets of the surface touch (a pinch of the tets' boundary where a pathology meets the wall) has two fans, and
/// one normal there cannot face out of both: each fan's corner gets its own output point and normal. fanOf[f][k] is
/// the fan of face f at its corner k (0 for a manifold point).
std::vector<std::array<std::uint8_t, 3>> fansAtCorners(const SurfaceMesh& mesh) {
    std::vector<std::vector<std::pair<std::int32_t, std::int32_t>>> incident(mesh.points.size()); // (face, corner)
    for (std::size_t f = 0; f < mesh.triangles.size(); ++f)
        for (std::int32_t k = 0; k < 3; ++k)
            incident[static_cast<std::size_t>(mesh.triangles[f][static_cast<std::size_t>(k)])].emplace_back(
                static_cast<std::int32_t>(f), k);
    std::vector<std::array<std::uint8_t, 3>> fanOf(mesh.triangles.size(), {0, 0, 0});
    std::vector<int> group;
    for (const auto& around : incident) {
        if (around.size() < 2)
            continue;
        // Union-find over the faces at this point, joined when they share the edge to one of its other corners.
        group.resize(around.size());
        for (std::size_t i = 0; i < around.size(); ++i)
            group[i] = static_cast<int>(i);
        const auto root = [&](int i) {
            while (group[static_cast<std::size_t>(i)] != i)
                i = group[static_cast<std::size_t>(i)] =
                    group[static_cast<std::size_t>(group[static_cast<std::size_t>(i)])];
            return i;
        };
        const auto others = [&](std::size_t i) {
            const auto& t = mesh.triangles[static_cast<std::size_t>(around[i].first)];
            const auto k = static_cast<std::size_t>(around[i].second);
            return std::array<std::int32_t, 2>{t[(k + 1) % 3], t[(k + 2) % 3]};
        };
        for (std::size_t i = 0; i < around.size(); ++i)
            for (std::size_t j = i + 1; j < around.size(); ++j) {
                const auto a = others(i), b = others(j);
                if (a[0] == b[0] || a[0] == b[1] || a[1] == b[0] || a[1] == b[1])
                    group[static_cast<std::size_t>(root(static_cast<int>(i)))] = root(static_cast<int>(j));
            }
        // Fans numbered in order of their first face, at most 255 (a point has a handful).
        std::vector<std::pair<int, std::uint8_t>> numbered;
        for (std::size_t i = 0; i < around.size(); ++i) {
            const int r = root(static_cast<int>(i));
            auto it = std::find_if(numbered.begin(), numbered.end(), [r](const auto& n) { return n.first == r; });
            if (it == numbered.end())
                it = numbered.insert(numbered.end(),
                                     {r, static_cast<std::uint8_t>(std::min<std::size_t>(numbered.size(), 255))});
            fanOf[static_cast<std::size_t>(around[i].first)][static_cast<std::size_t>(around[i].second)] = it->second;
        }
    }
    return fanOf;
}

} // namespace

TexturedSurface makeTexturedSurface(const SurfaceMesh& surface, const Atlas& atlas) {
    TexturedSurface out;
    out.mesh.points.reserve(atlas.uvVertices.size());
    out.uv.reserve(atlas.uvVertices.size());
    const std::vector<Vec3> normals = vertexNormals(surface);
    for (const UvVertex& q : atlas.uvVertices) {
        out.mesh.points.push_back(surface.points[static_cast<std::size_t>(q.vertex)]);
        out.uv.push_back({static_cast<float>(q.u), static_cast<float>(q.v)});
        out.normals.push_back(normals[static_cast<std::size_t>(q.vertex)]);
    }
    for (const auto& t : atlas.uvTriangles)
        out.mesh.triangles.push_back({t[0], t[1], t[2]});
    out.mesh.faceLabels = surface.faceLabels;
    out.mesh.faceLabels["chart"] = atlas.chartOfFace;
    for (const auto& [name, values] : surface.vertexLabels) {
        if (values.size() != surface.points.size())
            continue;
        auto& dst = out.mesh.vertexLabels[name];
        for (const UvVertex& q : atlas.uvVertices)
            dst.push_back(values[static_cast<std::size_t>(q.vertex)]);
    }
    return out;
}

TexturedSurface makeCloseUpSurface(const SurfaceMesh& surface, const Atlas& atlas, const CloseUpParams& params) {
    const int levels = params.levels;
    SurfaceMesh labelled =
        params.smoothing.iterations > 0 ? taubinSmooth(surface, params.seen, params.smoothing) : surface;
    labelled.vertexLabels.clear();
    labelled.faceLabels["chart"] = atlas.chartOfFace;
    std::vector<std::array<CornerUv, 3>> corners(surface.triangles.size());
    for (std::size_t f = 0; f < corners.size(); ++f)
        for (std::size_t k = 0; k < 3; ++k) {
            const UvVertex& q = atlas.uvVertices[static_cast<std::size_t>(atlas.uvTriangles[f][k])];
            corners[f][k] = {q.u, q.v};
        }
    SurfaceMesh smooth = loopSubdivide(labelled, levels);
    for (int i = 0; i < levels; ++i)
        corners = subdivideCorners(corners);
    if (!params.pits.empty()) {
        const std::vector<Vec3> before = vertexNormals(smooth);
        for (std::size_t v = 0; v < smooth.points.size(); ++v)
            for (const SurfacePit& pit : params.pits) {
                const double d = distance(smooth.points[v], pit.centreMm);
                const double len = norm(before[v]);
                if (d >= pit.radiusMm || len <= 0.0 || dot(before[v], pit.normal) < 0.5 * len)
                    continue;
                const double s = 1.0 - (d / pit.radiusMm) * (d / pit.radiusMm);
                smooth.points[v] -= pit.normal * (pit.depthMm * s * s);
            }
    }
    // A point where two sheets touch (several fans) is opened: each fan gets its own copy of the point, at the
    // centroid of its own ring, so the two no longer touch and each fan's faces turn one way (the fans there are
    // tenths of a millimetre across).
    const auto fanOf = fansAtCorners(smooth);
    std::vector<char> pinched(smooth.points.size(), 0);
    for (std::size_t f = 0; f < smooth.triangles.size(); ++f)
        for (std::size_t k = 0; k < 3; ++k)
            if (fanOf[f][k] > 0)
                pinched[static_cast<std::size_t>(smooth.triangles[f][k])] = 1;
    std::map<std::pair<std::int32_t, std::uint8_t>, std::pair<Vec3, double>> pinchRing; // (point, fan) -> ring sum
    for (std::size_t f = 0; f < smooth.triangles.size(); ++f)
        for (std::size_t k = 0; k < 3; ++k)
            if (pinched[static_cast<std::size_t>(smooth.triangles[f][k])]) {
                auto& ring = pinchRing[{smooth.triangles[f][k], fanOf[f][k]}];
                ring.first += smooth.points[static_cast<std::size_t>(smooth.triangles[f][(k + 1) % 3])] +
                              smooth.points[static_cast<std::size_t>(smooth.triangles[f][(k + 2) % 3])];
                ring.second += 2.0;
            }

    // One output point per (point, fan, chart), numbered in order of first use.
    const auto& chart = smooth.faceLabels.at("chart");
    std::map<SplitKey, std::int32_t> split;
    std::vector<std::pair<std::int32_t, std::uint8_t>> fanOfPoint; // per output point
    TexturedSurface out;
    out.mesh.triangles.resize(smooth.triangles.size());
    for (std::size_t f = 0; f < smooth.triangles.size(); ++f)
        for (std::size_t k = 0; k < 3; ++k) {
            const std::int32_t v = smooth.triangles[f][k];
            const SplitKey key{v, fanOf[f][k], chart[f]};
            const auto [it, inserted] = split.try_emplace(key, static_cast<std::int32_t>(out.mesh.points.size()));
            if (inserted) {
                Vec3 p = smooth.points[static_cast<std::size_t>(v)];
                if (const auto ring = pinchRing.find({v, fanOf[f][k]}); ring != pinchRing.end())
                    p = ring->second.first / ring->second.second;
                out.mesh.points.push_back(p);
                out.uv.push_back({static_cast<float>(corners[f][k][0]), static_cast<float>(corners[f][k][1])});
                fanOfPoint.emplace_back(v, fanOf[f][k]);
            }
            out.mesh.triangles[f][k] = it->second;
        }
    // Area-weighted normals of the unsplit surface (the split points of a seam share one), per point and fan.
    std::map<std::pair<std::int32_t, std::uint8_t>, Vec3> fanNormals;
    for (const auto& t : out.mesh.triangles) {
        const Vec3& a = out.mesh.points[static_cast<std::size_t>(t[0])];
        const Vec3 n = cross(out.mesh.points[static_cast<std::size_t>(t[1])] - a,
                             out.mesh.points[static_cast<std::size_t>(t[2])] - a); // length = 2 * area
        for (auto q : t)
            fanNormals[fanOfPoint[static_cast<std::size_t>(q)]] += n;
    }
    out.normals.reserve(out.mesh.points.size());
    for (const auto& key : fanOfPoint)
        out.normals.push_back(normalized(fanNormals.at(key)));
    out.mesh.faceLabels = std::move(smooth.faceLabels);
    return out;
}

Status writeBakeOutputs(const SurfaceMesh& surface, const BakeResult& result, const std::string& dir) {
    std::error_code ec;
    std::filesystem::create_directories(dir, ec);
    if (ec)
        return fail(ErrorCode::IoError, dir + ": cannot create the folder: " + ec.message());
    const auto file = [&dir](const char* name) { return (std::filesystem::path(dir) / name).string(); };
    HS_TRY(writeImage(result.albedo, file("albedo.png")));
    HS_TRY(writeImage(result.normal, file("normal.png")));
    HS_TRY(writeImage(result.roughness, file("roughness.png")));
    const TexturedSurface textured = makeTexturedSurface(surface, result.atlas);
    io::WriteOptions vtp;
    vtp.binary = false;
    vtp.textureCoordinates = &textured.uv;
    vtp.normals = &textured.normals;
    HS_TRY(io::writeSurface(textured.mesh, file("surface.vtp"), vtp));
    io::TexturedObjOptions obj;
    obj.materialLibrary = "surface.mtl";
    HS_TRY(io::writeTexturedObj(textured.mesh, textured.uv, file("surface.obj"), obj));
    return io::writeFileAtomically(file("surface.mtl"), "# hysteroscene material\nnewmtl organ\nKd 1 1 1\n"
                                                        "map_Kd albedo.png\nnorm normal.png\nmap_Pr roughness.png\n");
}

} // namespace hs::texture
