#include "IoTestMeshes.h"
#include "TestSupport.h"
#include "hs/io/MeshIO.h"

#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>

namespace hs::io {
namespace {

struct SurfaceCase {
    const char* name;      ///< test name suffix
    const char* extension; ///< with dot
    bool binary;
    bool exactCoordinates; ///< false for STL (single precision)
    bool keepsLabels;
};

void PrintTo(const SurfaceCase& c, std::ostream* os) {
    *os << c.name;
}

class SurfaceRoundTrip : public ::testing::TestWithParam<SurfaceCase> {};

TEST_P(SurfaceRoundTrip, KeepsGeometryTopologyAndLabels) {
    const SurfaceCase& c = GetParam();
    test::TempDir dir;
    const std::string path = dir.file(std::string("octahedron") + c.extension);
    const SurfaceMesh original = test::labelledOctahedron();
    const Status written = writeSurface(original, path, WriteOptions{c.binary});
    ASSERT_TRUE(written.ok()) << written.error().message();

    const Result<SurfaceMesh> read = readSurface(path);
    ASSERT_TRUE(read.ok()) << read.error().message();
    ASSERT_EQ(read->points.size(), original.points.size());
    ASSERT_EQ(read->triangles.size(), original.triangles.size());
    for (std::size_t f = 0; f < original.triangles.size(); ++f) {
        for (std::size_t k = 0; k < 3; ++k) {
            const Vec3 expected = original.points[static_cast<std::size_t>(original.triangles[f][k])];
            const Vec3 actual = read->points[static_cast<std::size_t>(read->triangles[f][k])];
            if (c.exactCoordinates)
                EXPECT_EQ(actual, expected) << "face " << f << " corner " << k;
            else
                EXPECT_LT(distance(actual, expected), 1e-6) << "face " << f << " corner " << k;
        }
    }
    EXPECT_TRUE(analyzeTopology(*read).isWatertight());
    if (c.exactCoordinates) {
        EXPECT_EQ(read->points, original.points);
        EXPECT_EQ(read->triangles, original.triangles);
    }
    if (c.keepsLabels) {
        EXPECT_EQ(read->faceLabels, original.faceLabels);
        EXPECT_EQ(read->vertexLabels, original.vertexLabels);
    } else {
        EXPECT_TRUE(read->faceLabels.empty());
        EXPECT_TRUE(read->vertexLabels.empty());
    }
}

TEST_P(SurfaceRoundTrip, WritesByteIdenticalFilesForTheSameMesh) {
    const SurfaceCase& c = GetParam();
    test::TempDir dir;
    const std::string first = dir.file(std::string("a") + c.extension);
    const std::string second = dir.file(std::string("b") + c.extension);
    const SurfaceMesh mesh = test::labelledOctahedron();
    ASSERT_TRUE(writeSurface(mesh, first, WriteOptions{c.binary}).ok());
    ASSERT_TRUE(writeSurface(mesh, second, WriteOptions{c.binary}).ok());
    EXPECT_EQ(test::readBytes(first), test::readBytes(second));
}

TEST_P(SurfaceRoundTrip, LeavesNoTemporaryFileBehind) {
    const SurfaceCase& c = GetParam();
    test::TempDir dir;
    ASSERT_TRUE(
        writeSurface(test::labelledOctahedron(), dir.file(std::string("m") + c.extension), WriteOptions{c.binary})
            .ok());
    int files = 0;
    for ([[maybe_unused]] const auto& entry : std::filesystem::directory_iterator(dir.path()))
        ++files;
    EXPECT_EQ(files, 1);
}

INSTANTIATE_TEST_SUITE_P(Formats, SurfaceRoundTrip,
                         ::testing::Values(SurfaceCase{"obj", ".obj", true, true, false},
                                           SurfaceCase{"off", ".off", true, true, false},
                                           SurfaceCase{"plyBinary", ".ply", true, true, true},
                                           SurfaceCase{"plyAscii", ".ply", false, true, true},
                                           SurfaceCase{"stlBinary", ".stl", true, false, false},
                                           SurfaceCase{"stlAscii", ".stl", false, false, false},
                                           SurfaceCase{"vtpAppended", ".vtp", true, true, true},
                                           SurfaceCase{"vtpAscii", ".vtp", false, true, true},
                                           SurfaceCase{"vtuSurface", ".vtu", true, true, true}),
                         [](const auto& param) { return std::string(param.param.name); });

struct TetCase {
    const char* name;
    const char* extension;
    bool binary;
    bool keepsLabels; ///< tet and point labels (regions are kept by every format)
};

void PrintTo(const TetCase& c, std::ostream* os) {
    *os << c.name;
}

class TetRoundTrip : public ::testing::TestWithParam<TetCase> {};

TEST_P(TetRoundTrip, KeepsPointsTetsRegionsAndLabels) {
    const TetCase& c = GetParam();
    test::TempDir dir;
    const std::string path = dir.file(std::string("cube") + c.extension);
    const TetMesh original = test::labelledCube();
    const Status written = writeTetMesh(original, path, WriteOptions{c.binary});
    ASSERT_TRUE(written.ok()) << written.error().message();

    const Result<TetMesh> read = readTetMesh(path);
    ASSERT_TRUE(read.ok()) << read.error().message();
    EXPECT_EQ(read->points, original.points);
    EXPECT_EQ(read->tets, original.tets);
    EXPECT_EQ(read->regions, original.regions);
    if (c.keepsLabels) {
        EXPECT_EQ(read->tetLabels, original.tetLabels);
        EXPECT_EQ(read->pointLabels, original.pointLabels);
    }
    EXPECT_DOUBLE_EQ(totalVolume(*read), totalVolume(original));
}

TEST_P(TetRoundTrip, WritesByteIdenticalFilesForTheSameMesh) {
    const TetCase& c = GetParam();
    test::TempDir dir;
    const std::string first = dir.file(std::string("a") + c.extension);
    const std::string second = dir.file(std::string("b") + c.extension);
    ASSERT_TRUE(writeTetMesh(test::labelledCube(), first, WriteOptions{c.binary}).ok());
    ASSERT_TRUE(writeTetMesh(test::labelledCube(), second, WriteOptions{c.binary}).ok());
    EXPECT_EQ(test::readBytes(first), test::readBytes(second));
}

TEST_P(TetRoundTrip, WritesMeshWithoutRegionsAsRegionZero) {
    const TetCase& c = GetParam();
    test::TempDir dir;
    const std::string path = dir.file(std::string("plain") + c.extension);
    TetMesh mesh = test::labelledCube();
    mesh.regions.clear();
    ASSERT_TRUE(writeTetMesh(mesh, path, WriteOptions{c.binary}).ok());
    const Result<TetMesh> read = readTetMesh(path);
    ASSERT_TRUE(read.ok()) << read.error().message();
    for (std::size_t t = 0; t < read->tets.size(); ++t)
        EXPECT_EQ(read->regionOf(t), 0);
}

INSTANTIATE_TEST_SUITE_P(Formats, TetRoundTrip,
                         ::testing::Values(TetCase{"vtuAppended", ".vtu", true, true},
                                           TetCase{"vtuAscii", ".vtu", false, true},
                                           TetCase{"gmsh", ".msh", true, false},
                                           TetCase{"medit", ".mesh", true, false}),
                         [](const auto& param) { return std::string(param.param.name); });

TEST(MeshIO, ReadsTriangleOnlyVtuAsSurface) {
    test::TempDir dir;
    const std::string path = dir.file("surface.vtu");
    ASSERT_TRUE(writeSurface(test::labelledOctahedron(), path).ok());
    const Result<AnyMesh> read = readMesh(path);
    ASSERT_TRUE(read.ok()) << read.error().message();
    ASSERT_TRUE(std::holds_alternative<SurfaceMesh>(*read));
    EXPECT_EQ(std::get<SurfaceMesh>(*read).faceLabels, test::labelledOctahedron().faceLabels);
    EXPECT_FALSE(readTetMesh(path).ok());
}

TEST(MeshIO, ReadsTetVtuAsTetMesh) {
    test::TempDir dir;
    const std::string path = dir.file("cube.vtu");
    ASSERT_TRUE(writeTetMesh(test::labelledCube(), path).ok());
    const Result<AnyMesh> read = readMesh(path);
    ASSERT_TRUE(read.ok()) << read.error().message();
    EXPECT_TRUE(std::holds_alternative<TetMesh>(*read));
    const Result<SurfaceMesh> surface = readSurface(path);
    ASSERT_FALSE(surface.ok());
    EXPECT_NE(surface.error().detail.find("readTetMesh"), std::string::npos);
}

TEST(MeshIO, RoundTripsBoundaryOfTetMeshThroughVtp) {
    test::TempDir dir;
    const std::string path = dir.file("boundary.vtp");
    const SurfaceMesh boundary = extractBoundary(test::labelledCube(), true);
    ASSERT_TRUE(writeSurface(boundary, path).ok());
    const Result<SurfaceMesh> read = readSurface(path);
    ASSERT_TRUE(read.ok()) << read.error().message();
    EXPECT_EQ(read->points, boundary.points);
    EXPECT_EQ(read->triangles, boundary.triangles);
    EXPECT_EQ(read->faceLabels, boundary.faceLabels);
    EXPECT_EQ(read->vertexLabels, boundary.vertexLabels);
}

} // namespace
} // namespace hs::io
