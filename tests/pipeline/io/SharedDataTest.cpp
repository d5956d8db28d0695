#include "TestSupport.h"
#include "hs/io/MeshIO.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <filesystem>

namespace hs::io {
namespace {

std::vector<std::filesystem::path> meshFiles(const std::filesystem::path& dir) {
    std::vector<std::filesystem::path> files;
    if (!std::filesystem::is_directory(dir))
        return files;
    for (const auto& entry : std::filesystem::directory_iterator(dir)) {
        const auto ext = entry.path().extension();
        if (entry.is_regular_file() && (ext == ".off" || ext == ".obj"))
            files.push_back(entry.path());
    }
    std::sort(files.begin(), files.end());
    return files;
}

TEST(SharedData, ReadsEveryGoodSurfaceAsClosed) {
    const auto shared = test::sharedDataDir();
    const auto files = meshFiles(shared / "meshes");
    if (files.empty())
        GTEST_SKIP() << "shared test surfaces not present";
    for (const auto& file : files) {
        const auto mesh = readSurface(file.string());
        ASSERT_TRUE(mesh.ok()) << mesh.error().message();
        const SurfaceTopology topology = analyzeTopology(*mesh);
        EXPECT_TRUE(topology.isClosed()) << file << ": " << topology.boundaryEdges << " boundary edges";
        EXPECT_GT(mesh->triangles.size(), 1000u) << file;
    }
}

TEST(SharedData, ReadsEveryBadSurfaceAndSeesItsHoles) {
    const auto shared = test::sharedDataDir();
    const auto files = meshFiles(shared / "meshes" / "bad");
    if (files.empty())
        GTEST_SKIP() << "shared test surfaces not present";
    for (const auto& file : files) {
        const auto mesh = readSurface(file.string());
        ASSERT_TRUE(mesh.ok()) << mesh.error().message();
        EXPECT_GT(analyzeTopology(*mesh).boundaryEdges, 0u) << file;
    }
}

TEST(SharedData, RoundTripsARealSurfaceThroughEveryLabelFreeFormat) {
    const auto shared = test::sharedDataDir();
    const auto source = shared / "meshes" / "spot.obj";
    if (shared.empty() || !std::filesystem::exists(source))
        GTEST_SKIP() << "shared test surfaces not present";
    const auto original = readSurface(source.string());
    ASSERT_TRUE(original.ok()) << original.error().message();
    test::TempDir dir;
    for (const char* ext : {".obj", ".off", ".ply", ".vtp", ".stl"}) {
        const std::string path = dir.file(std::string("spot") + ext);
        ASSERT_TRUE(writeSurface(*original, path).ok()) << ext;
        const auto read = readSurface(path);
        ASSERT_TRUE(read.ok()) << read.error().message();
        EXPECT_EQ(read->triangles.size(), original->triangles.size()) << ext;
        EXPECT_TRUE(analyzeTopology(*read).isClosed()) << ext;
        EXPECT_NEAR(enclosedVolume(*read), enclosedVolume(*original), 1e-6 * std::abs(enclosedVolume(*original)))
            << ext;
    }
}

} // namespace
} // namespace hs::io
