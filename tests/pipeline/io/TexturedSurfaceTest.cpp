#include "hs/io/TexturedSurface.h"
#include "TestSupport.h"
#include "hs/io/MeshIO.h"

#include <gtest/gtest.h>

#include <array>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <limits>
#include <string>
#include <vector>

namespace hs::io {
namespace {

SurfaceMesh tetrahedron() {
    SurfaceMesh m;
    m.points = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {0, 0, 0.1}};
    m.triangles = {{0, 2, 1}, {0, 1, 3}, {0, 3, 2}, {1, 2, 3}};
    return m;
}

std::string fileText(const std::string& path) {
    std::ifstream in(path);
    return {std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
}

TEST(TexturedObj, WritesPointsUvsAndFacesWithTheMaterialWhenGiven) {
    const SurfaceMesh m = tetrahedron();
    const std::vector<std::array<float, 2>> uv{{0.f, 0.f}, {1.f, 0.f}, {0.f, 1.f}, {0.5f, 0.25f}};
    TexturedObjOptions options;
    options.comment = "test";
    EXPECT_EQ(texturedObjText(m, uv, options), "# test\n"
                                               "v 0 0 0\nv 1 0 0\nv 0 1 0\nv 0 0 0.10000000000000001\n"
                                               "vt 0 0\nvt 1 0\nvt 0 1\nvt 0.5 0.25\n"
                                               "f 1/1 3/3 2/2\nf 1/1 2/2 4/4\nf 1/1 4/4 3/3\nf 2/2 3/3 4/4\n");
    options.materialLibrary = "surface.mtl";
    const std::string text = texturedObjText(m, uv, options);
    EXPECT_EQ(text.rfind("# test\nmtllib surface.mtl\nv ", 0), 0u);
    EXPECT_NE(text.find("vt 0.5 0.25\nusemtl organ\nf 1/1 3/3 2/2\n"), std::string::npos);
}

TEST(TexturedObj, RefusesAUvCountOtherThanThePointCount) {
    test::TempDir tmp;
    const std::vector<std::array<float, 2>> uv{{0.f, 0.f}};
    EXPECT_EQ(writeTexturedObj(tetrahedron(), uv, tmp.file("bad.obj")).error().code, ErrorCode::InvalidInput);
    EXPECT_FALSE(std::filesystem::exists(tmp.file("bad.obj")));
}

TEST(TexturedVtp, WritesNormalsAsTheActiveNormalsAndRefusesLabelsNamedLikeThem) {
    SurfaceMesh m = tetrahedron();
    test::TempDir tmp;
    const std::vector<std::array<float, 2>> uv(4, {0.f, 0.f});
    const std::vector<Vec3> normals(4, Vec3{0, 0, 1});
    WriteOptions options;
    options.binary = false;
    options.textureCoordinates = &uv;
    options.normals = &normals;
    ASSERT_TRUE(writeSurface(m, tmp.file("n.vtp"), options).ok());
    const std::string text = fileText(tmp.file("n.vtp"));
    EXPECT_NE(text.find("Normals=\"normals\""), std::string::npos);
    EXPECT_NE(text.find("TCoords=\"uv\""), std::string::npos);
    m.faceLabels["normals"] = {0, 0, 0, 0};
    EXPECT_EQ(writeSurface(m, tmp.file("clash.vtp"), options).error().code, ErrorCode::InvalidInput);
    const std::vector<Vec3> tooFew(3, Vec3{0, 0, 1});
    m.faceLabels.clear();
    options.normals = &tooFew;
    EXPECT_EQ(writeSurface(m, tmp.file("few.vtp"), options).error().code, ErrorCode::InvalidInput);
}

TEST(TexturedVtp, KeepsFloatingPointArraysBitForBitAndRefusesBadOnes) {
    const SurfaceMesh m = tetrahedron();
    test::TempDir tmp;
    PointArrays arrays;
    arrays["weights"] = {4, {0.1, 0.2, 0.3, 0.4, 1.0 / 3.0, 1e-300, -2.5, 7.0, 0, 0, 0, 1, -0.0, 0.5, 0.25, 0.25}};
    arrays["height"] = {1, {1.5, 2.5, 3.5, 4.5}};
    const std::vector<Vec3> normals(4, Vec3{0, 0, 1});
    WriteOptions options;
    options.pointArrays = &arrays;
    options.normals = &normals;
    ASSERT_TRUE(writeSurface(m, tmp.file("a.vtp"), options).ok());
    PointArrays read;
    auto back = readSurfaceWithArrays(tmp.file("a.vtp"), read);
    ASSERT_TRUE(back.ok()) << back.error().message();
    EXPECT_EQ(back->triangles, m.triangles);
    ASSERT_EQ(read.count("weights"), 1u);
    EXPECT_EQ(read.at("weights").components, 4);
    EXPECT_EQ(read.at("weights").values, arrays.at("weights").values);
    EXPECT_EQ(read.at("height").values, arrays.at("height").values);
    ASSERT_EQ(read.count("normals"), 1u); // the normals come back as an array too
    EXPECT_EQ(read.at("normals").components, 3);
    EXPECT_FALSE(readSurfaceWithArrays(tmp.file("a.stl"), read).ok()); // VTP only

    PointArrays bad = arrays;
    bad["weights"].values.pop_back();
    options.pointArrays = &bad;
    EXPECT_EQ(writeSurface(m, tmp.file("short.vtp"), options).error().code, ErrorCode::InvalidInput);
    bad = arrays;
    bad["height"].values[2] = std::numeric_limits<double>::quiet_NaN();
    EXPECT_EQ(writeSurface(m, tmp.file("nan.vtp"), options).error().code, ErrorCode::InvalidInput);
    bad = arrays;
    bad["uv"] = {1, {0, 0, 0, 0}};
    EXPECT_EQ(writeSurface(m, tmp.file("taken.vtp"), options).error().code, ErrorCode::InvalidInput);
    bad = arrays;
    bad["bad name"] = {1, {0, 0, 0, 0}};
    EXPECT_EQ(writeSurface(m, tmp.file("name.vtp"), options).error().code, ErrorCode::InvalidInput);
    for (const char* f : {"short.vtp", "nan.vtp", "taken.vtp", "name.vtp"})
        EXPECT_FALSE(std::filesystem::exists(tmp.file(f))) << f;
}

} // namespace
} // namespace hs::io
