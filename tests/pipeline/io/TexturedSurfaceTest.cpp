#include "hs/io/TexturedSurface.h"
#include "TestSupport.h"
#include "hs/io/MeshIO.h"

#include <gtest/gtest.h>

#include <array>
#include <filesystem>
#include <fstream>
#include <iterator>
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

} // namespace
} // namespace hs::io
