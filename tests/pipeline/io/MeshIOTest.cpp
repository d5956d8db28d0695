#include "hs/io/MeshIO.h"
#include "IoTestMeshes.h"
#include "TestSupport.h"

#include <gtest/gtest.h>

#include <array>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <limits>
#include <thread>
#include <vector>

namespace hs::io {
namespace {

std::string fixture(const std::string& name) {
    return (test::testDataDir() / "io" / name).string();
}

TEST(MeshIO, ChoosesFormatByExtensionIgnoringCase) {
    EXPECT_EQ(*formatFromPath("a/b/mesh.OBJ"), MeshFormat::Obj);
    EXPECT_EQ(*formatFromPath("x.stl"), MeshFormat::Stl);
    EXPECT_EQ(*formatFromPath("x.Ply"), MeshFormat::Ply);
    EXPECT_EQ(*formatFromPath("x.off"), MeshFormat::Off);
    EXPECT_EQ(*formatFromPath("x.vtp"), MeshFormat::Vtp);
    EXPECT_EQ(*formatFromPath("x.vtu"), MeshFormat::Vtu);
    EXPECT_EQ(*formatFromPath("x.msh"), MeshFormat::GmshMsh);
    EXPECT_EQ(*formatFromPath("x.mesh"), MeshFormat::Medit);
    const auto unknown = formatFromPath("notes.txt");
    ASSERT_FALSE(unknown.ok());
    EXPECT_EQ(unknown.error().code, ErrorCode::InvalidInput);
    EXPECT_NE(unknown.error().detail.find(".obj"), std::string::npos);
    EXPECT_FALSE(formatFromPath("no-extension").ok());
}

TEST(MeshIO, NamesAndClassifiesEveryFormat) {
    EXPECT_EQ(formatName(MeshFormat::GmshMsh), "msh");
    EXPECT_EQ(formatName(MeshFormat::Medit), "mesh");
    EXPECT_EQ(supportedExtensions().size(), 8u);
    for (const auto& ext : supportedExtensions()) {
        const auto format = formatFromPath("x" + ext);
        ASSERT_TRUE(format.ok()) << ext;
        EXPECT_NE(isSurfaceFormat(*format), isTetFormat(*format)) << ext;
        EXPECT_EQ("." + formatName(*format), ext);
    }
}

TEST(MeshIO, ReadsGmshFixtureWithPhysicalTagsAsRegions) {
    const auto mesh = readTetMesh(fixture("two-regions.msh"));
    ASSERT_TRUE(mesh.ok()) << mesh.error().message();
    ASSERT_EQ(mesh->points.size(), 5u);
    EXPECT_EQ(mesh->points[4], Vec3(1, 1, 1));
    ASSERT_EQ(mesh->tets.size(), 2u);
    EXPECT_EQ(mesh->tets[0], (Tet{0, 1, 2, 3}));
    EXPECT_EQ(mesh->tets[1], (Tet{1, 2, 3, 4}));
    EXPECT_EQ(mesh->regions, (std::vector<std::int32_t>{5, 9}));
    EXPECT_EQ(invertedTetCount(*mesh), 0u);
}

TEST(MeshIO, ReadsMeditFixtureWithReferencesAsRegions) {
    const auto mesh = readTetMesh(fixture("two-regions.mesh"));
    ASSERT_TRUE(mesh.ok()) << mesh.error().message();
    EXPECT_EQ(mesh->points.size(), 5u);
    EXPECT_EQ(mesh->tets[1], (Tet{1, 2, 3, 4}));
    EXPECT_EQ(mesh->regions, (std::vector<std::int32_t>{5, 9}));
}

TEST(MeshIO, ReadsObjWithQuadsTextureIndicesAndRelativeIndices) {
    const auto mesh = readSurface(fixture("quad-cube.obj"));
    ASSERT_TRUE(mesh.ok()) << mesh.error().message();
    EXPECT_EQ(mesh->points.size(), 8u);
    EXPECT_EQ(mesh->triangles.size(), 12u);
    EXPECT_TRUE(analyzeTopology(*mesh).isWatertight());
    EXPECT_NEAR(enclosedVolume(*mesh), 1.0, 1e-12);
}

TEST(MeshIO, ReadsPlyIntPropertiesAsLabels) {
    const auto mesh = readSurface(fixture("labelled-tetrahedron.ply"));
    ASSERT_TRUE(mesh.ok()) << mesh.error().message();
    EXPECT_EQ(mesh->points.size(), 4u);
    EXPECT_TRUE(analyzeTopology(*mesh).isWatertight());
    ASSERT_EQ(mesh->faceLabels.count("patch"), 1u);
    EXPECT_EQ(mesh->faceLabels.at("patch"), (std::vector<std::int32_t>{7, 7, 8, 9}));
    EXPECT_TRUE(mesh->vertexLabels.empty()) << "uchar colours and float properties are not labels";
}

TEST(MeshIO, ReadsAsciiStlAndMergesCorners) {
    const auto mesh = readSurface(fixture("tetrahedron-ascii.stl"));
    ASSERT_TRUE(mesh.ok()) << mesh.error().message();
    EXPECT_EQ(mesh->points.size(), 4u);
    EXPECT_EQ(mesh->triangles.size(), 4u);
    EXPECT_TRUE(analyzeTopology(*mesh).isWatertight());
    EXPECT_NEAR(enclosedVolume(*mesh), 1.0 / 6.0, 1e-12);
}

TEST(MeshIO, SplitsPolygonsIntoFansAndRepeatsTheirLabels) {
    test::TempDir dir;
    const std::string path = dir.file("quad.ply");
    test::writeBytes(path, "ply\nformat ascii 1.0\nelement vertex 4\nproperty double x\nproperty double y\n"
                           "property double z\nelement face 1\nproperty list uchar int vertex_indices\n"
                           "property int region\nend_header\n0 0 0\n1 0 0\n1 1 0\n0 1 0\n4 0 1 2 3 42\n");
    const auto mesh = readSurface(path);
    ASSERT_TRUE(mesh.ok()) << mesh.error().message();
    EXPECT_EQ(mesh->triangles, (std::vector<Triangle>{{0, 1, 2}, {0, 2, 3}}));
    EXPECT_EQ(mesh->faceLabels.at("region"), (std::vector<std::int32_t>{42, 42}));
}

TEST(MeshIO, RefusesToWriteInvalidMeshesAndKeepsTheOldFile) {
    test::TempDir dir;
    for (const char* ext : {".obj", ".stl", ".ply", ".off", ".vtp", ".vtu"}) {
        const std::string path = dir.file(std::string("old") + ext);
        test::writeBytes(path, "previous content");
        SurfaceMesh bad = test::labelledOctahedron();
        bad.triangles[3][1] = 99;
        auto status = writeSurface(bad, path);
        ASSERT_FALSE(status.ok()) << ext;
        EXPECT_EQ(status.error().code, ErrorCode::InvalidInput);
        EXPECT_NE(status.error().detail.find(path), std::string::npos) << status.error().detail;
        bad = test::labelledOctahedron();
        bad.points[2].y = std::numeric_limits<double>::quiet_NaN();
        EXPECT_FALSE(writeSurface(bad, path).ok()) << ext;
        EXPECT_FALSE(writeSurface(SurfaceMesh{}, path).ok()) << ext;
        EXPECT_EQ(test::readBytes(path), "previous content") << ext;
    }
    for (const char* ext : {".vtu", ".msh", ".mesh"}) {
        const std::string path = dir.file(std::string("old-tets") + ext);
        test::writeBytes(path, "previous content");
        TetMesh bad = test::labelledCube();
        bad.tets[0][0] = -1;
        EXPECT_FALSE(writeTetMesh(bad, path).ok()) << ext;
        bad = test::labelledCube();
        bad.regions.pop_back();
        EXPECT_FALSE(writeTetMesh(bad, path).ok()) << ext;
        EXPECT_FALSE(writeTetMesh(TetMesh{}, path).ok()) << ext;
        EXPECT_EQ(test::readBytes(path), "previous content") << ext;
    }
}

TEST(MeshIO, RefusesLabelNamesThatFilesCannotStore) {
    test::TempDir dir;
    SurfaceMesh mesh = test::labelledOctahedron();
    mesh.faceLabels["two words"] = std::vector<std::int32_t>(mesh.triangles.size(), 1);
    EXPECT_FALSE(writeSurface(mesh, dir.file("m.vtp")).ok());
    TetMesh tets = test::labelledCube();
    tets.tetLabels["region"] = std::vector<std::int32_t>(tets.tets.size(), 1);
    EXPECT_FALSE(writeTetMesh(tets, dir.file("m.vtu")).ok());
}

TEST(MeshIO, RefusesToWriteAMeshKindTheFormatCannotHold) {
    test::TempDir dir;
    const auto toMsh = writeSurface(test::labelledOctahedron(), dir.file("s.msh"));
    ASSERT_FALSE(toMsh.ok());
    EXPECT_EQ(toMsh.error().code, ErrorCode::InvalidInput);
    EXPECT_FALSE(writeSurface(test::labelledOctahedron(), dir.file("s.mesh")).ok());
    EXPECT_FALSE(writeTetMesh(test::labelledCube(), dir.file("t.obj")).ok());
    EXPECT_FALSE(writeTetMesh(test::labelledCube(), dir.file("t.txt")).ok());
}

TEST(MeshIO, ReportsMissingOutputFolderAsNotFound) {
    test::TempDir dir;
    const auto status = writeSurface(test::labelledOctahedron(), dir.file("missing/folder/m.obj"));
    ASSERT_FALSE(status.ok());
    EXPECT_EQ(status.error().code, ErrorCode::NotFound);
}

TEST(MeshIO, RefusesSurfaceReadOfTetFormatAndTetReadOfSurfaceFormat) {
    const auto surface = readSurface(fixture("two-regions.msh"));
    ASSERT_FALSE(surface.ok());
    EXPECT_EQ(surface.error().code, ErrorCode::InvalidInput);
    EXPECT_FALSE(readTetMesh(fixture("quad-cube.obj")).ok());
}

TEST(MeshIO, ReadsMeshOfEitherKind) {
    const auto tets = readMesh(fixture("two-regions.mesh"));
    ASSERT_TRUE(tets.ok()) << tets.error().message();
    EXPECT_TRUE(std::holds_alternative<TetMesh>(*tets));
    const auto surface = readMesh(fixture("quad-cube.obj"));
    ASSERT_TRUE(surface.ok()) << surface.error().message();
    EXPECT_TRUE(std::holds_alternative<SurfaceMesh>(*surface));
}

} // namespace
} // namespace hs::io

namespace hs::io {
namespace {

TEST(MeshIO, KeepsVtkErrorsOfConcurrentReadsApart) {
    test::TempDir dir;
    const std::string valid = dir.file("valid.vtp");
    ASSERT_TRUE(writeSurface(test::labelledOctahedron(), valid).ok());
    const std::string bytes = test::readBytes(valid);
    constexpr int kThreads = 4;
    std::vector<std::string> paths;
    for (int t = 0; t < kThreads; ++t) {
        paths.push_back(dir.file("broken-" + std::to_string(t) + ".vtp"));
        // Cut inside the XML so VTK's parser reports an error.
        test::writeBytes(paths.back(), bytes.substr(0, 200 + 10 * static_cast<std::size_t>(t)));
    }
    std::vector<std::string> details(kThreads);
    std::vector<std::thread> threads;
    for (int t = 0; t < kThreads; ++t) {
        threads.emplace_back([&, t] {
            for (int round = 0; round < 20; ++round) {
                const auto good = readSurface(valid);
                const auto bad = readSurface(paths[static_cast<std::size_t>(t)]);
                if (!good.ok() || bad.ok()) {
                    details[static_cast<std::size_t>(t)] = "unexpected outcome";
                    return;
                }
                details[static_cast<std::size_t>(t)] = bad.error().detail;
            }
        });
    }
    for (auto& thread : threads)
        thread.join();
    for (int t = 0; t < kThreads; ++t) {
        const std::string& detail = details[static_cast<std::size_t>(t)];
        EXPECT_EQ(detail.find(paths[static_cast<std::size_t>(t)]), 0u) << detail;
        for (int other = 0; other < kThreads; ++other)
            if (other != t) {
                EXPECT_EQ(detail.find(paths[static_cast<std::size_t>(other)]), std::string::npos) << detail;
            }
    }
}

} // namespace
} // namespace hs::io

TEST(MeshIO, WritesTextureCoordinatesIntoVtpAndRefusesAWrongCount) {
    hs::SurfaceMesh m;
    m.points = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {0, 0, 1}};
    m.triangles = {{0, 2, 1}, {0, 1, 3}, {0, 3, 2}, {1, 2, 3}};
    hs::test::TempDir tmp;
    std::vector<std::array<float, 2>> uv{{0.f, 0.f}, {1.f, 0.f}, {0.f, 1.f}, {0.5f, 0.5f}};
    hs::io::WriteOptions options;
    options.textureCoordinates = &uv;
    ASSERT_TRUE(hs::io::writeSurface(m, tmp.file("uv.vtp"), options).ok());
    auto back = hs::io::readSurface(tmp.file("uv.vtp"));
    ASSERT_TRUE(back.ok()) << back.error().message();
    EXPECT_EQ(back->triangles, m.triangles);
    std::ifstream in(tmp.file("uv.vtp"));
    const std::string text((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
    EXPECT_NE(text.find("Name=\"uv\""), std::string::npos);
    uv.pop_back();
    EXPECT_FALSE(hs::io::writeSurface(m, tmp.file("bad.vtp"), options).ok());
    EXPECT_FALSE(std::filesystem::exists(tmp.file("bad.vtp")));
}
