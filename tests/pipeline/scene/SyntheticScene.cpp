// A complete synthetic Scene for the package tests.

#include "SyntheticScene.h"

#include <array>
#include <cassert>

namespace hs::test {

namespace {

TetMesh blockMesh(int n, double size) {
    TetMesh mesh;
    const auto index = [n](int x, int y, int z) { return static_cast<std::int32_t>((z * (n + 1) + y) * (n + 1) + x); };
    for (int z = 0; z <= n; ++z)
        for (int y = 0; y <= n; ++y)
            for (int x = 0; x <= n; ++x)
                mesh.points.push_back(Vec3(x, y, z) * (size / n));
    // The six tets of a cube along the paths from corner 0 to corner 7 (Kuhn triangulation): conforming.
    static constexpr std::array<std::array<int, 3>, 6> kPaths{
        {{0, 1, 2}, {0, 2, 1}, {1, 0, 2}, {1, 2, 0}, {2, 0, 1}, {2, 1, 0}}};
    for (int z = 0; z < n; ++z)
        for (int y = 0; y < n; ++y)
            for (int x = 0; x < n; ++x) {
                const bool inner = x > 0 && y > 0 && z > 0 && x < n - 1 && y < n - 1 && z < n - 1;
                for (const auto& path : kPaths) {
                    std::array<int, 3> c{x, y, z};
                    Tet tet{};
                    tet[0] = index(c[0], c[1], c[2]);
                    for (int k = 0; k < 3; ++k) {
                        ++c[static_cast<std::size_t>(path[static_cast<std::size_t>(k)])];
                        tet[static_cast<std::size_t>(k) + 1] = index(c[0], c[1], c[2]);
                    }
                    mesh.tets.push_back(tet);
                    if (signedVolume(mesh, mesh.tets.size() - 1) < 0.0)
                        std::swap(mesh.tets.back()[2], mesh.tets.back()[3]);
                    mesh.regions.push_back(inner ? 1 : 0);
                }
            }
    return mesh;
}

ImageU8 pattern(int size, int channels, int salt) {
    ImageU8 image = ImageU8::create(size, size, channels).value();
    for (int y = 0; y < size; ++y)
        for (int x = 0; x < size; ++x)
            for (int c = 0; c < channels; ++c)
                image.at(x, y, c) = static_cast<std::uint8_t>((x * 37 + y * 11 + c * 71 + salt) % 256);
    return image;
}

} // namespace

scene::Scene syntheticScene(const SyntheticSceneOptions& options) {
    scene::Scene s;
    s.caseSpec = scene::defaultCase();
    s.caseSpec.seed = options.seed;
    s.tets = blockMesh(options.cells, options.sizeMm);
    s.regions = {{0, "myometrium", clinical::Tissue::Myometrium, ""},
                 {1, "myoma-1", clinical::Tissue::Myoma, "myoma-1"}};
    scene::MaterialOptions materialOptions;
    materialOptions.heterogeneity = options.heterogeneity;
    materialOptions.seed = options.seed;
    s.materials = scene::assignMaterials(s.tets, s.regions, s.caseSpec.scene, materialOptions).value();

    s.surface.mesh = extractBoundary(s.tets);
    for (const Vec3& p : s.surface.mesh.points)
        s.surface.uvs.push_back({static_cast<float>(p.x / options.sizeMm), static_cast<float>(p.y / options.sizeMm)});
    s.surface.albedo = pattern(options.mapSize, 3, 1);
    s.surface.normal = pattern(options.mapSize, 3, 2);
    s.surface.roughness = pattern(options.mapSize, 1, 3);

    scene::SceneLabel myoma{"tets:myoma-1", scene::LabelKind::Other, scene::LabelElement::Tet, "myoma-1", {}};
    for (std::size_t t = 0; t < s.tets.tetCount(); ++t)
        if (s.tets.regionOf(t) == 1)
            myoma.indices.push_back(static_cast<std::int32_t>(t));
    scene::SceneLabel canal{
        "cervical-canal", scene::LabelKind::CervicalCanal, scene::LabelElement::SurfaceFace, "", {}};
    for (std::size_t f = 0; f < s.surface.mesh.faceCount(); ++f) {
        const auto& tri = s.surface.mesh.triangles[f];
        if (s.surface.mesh.points[static_cast<std::size_t>(tri[0])].z == 0.0 &&
            s.surface.mesh.points[static_cast<std::size_t>(tri[1])].z == 0.0 &&
            s.surface.mesh.points[static_cast<std::size_t>(tri[2])].z == 0.0)
            canal.indices.push_back(static_cast<std::int32_t>(f));
    }
    s.labels = {canal, myoma};

    s.clinical.organ = {72.0, 45.0, 40.0, 35.0, 30.0, 72.0 * 45.0 * 40.0 * 0.523 / 1000.0};
    scene::PathologyDescriptor myomaDescriptor;
    myomaDescriptor.id = "myoma-1";
    myomaDescriptor.regionId = 1;
    myomaDescriptor.sizeMm = 20.0;
    myomaDescriptor.volumeMl = regionVolumes(s.tets)[1] / 1000.0;
    myomaDescriptor.figo = clinical::FigoType{2, -1};
    myomaDescriptor.lasmar = clinical::LasmarScore{1, 2, 1, 2, 0};
    myomaDescriptor.location = "posterior";
    s.clinical.pathologies = {myomaDescriptor};
    s.hydrometra = scene::computeHydrometra(s.clinical.organ.uterineVolumeMl, 8.0).value();
    s.hydrometra.modelCurve = {{2.5, 0.75}, {5.0, 1.625}, {10.0, 4.125}};
    s.quality.vertexCount = s.tets.vertexCount();
    s.quality.tetCount = s.tets.tetCount();
    s.quality.minDihedralDeg = 35.26;
    s.quality.radiusRatioHistogram.assign(10, 0);
    s.quality.minDihedralHistogram.assign(9, 0);
    s.toolVersions = scene::defaultToolVersions();
    s.warnings = {"synthetic scene for tests"};
    return s;
}

} // namespace hs::test
