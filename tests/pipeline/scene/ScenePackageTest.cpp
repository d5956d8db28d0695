// The scene package: deterministic files, round trips, refusal of tampered packages, atomic replacement.

#include "hs/scene/ScenePackage.h"
#include "SyntheticScene.h"
#include "TestSupport.h"
#include "hs/io/MeshIO.h"
#include "hs/scene/Sha256.h"

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include <zlib.h>

#include <algorithm>
#include <cstdint>
#include <filesystem>
#include <fstream>
#include <string>
#include <vector>

using namespace hs;
using namespace hs::scene;
namespace fs = std::filesystem;

namespace {

std::string readText(const fs::path& path) {
    std::ifstream in(path, std::ios::binary);
    return std::string(std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>());
}

void writeText(const fs::path& path, const std::string& text) {
    std::ofstream out(path, std::ios::binary | std::ios::trunc);
    out << text;
}

/// Rewrites manifest.json through `edit`.
template <class F>
void editManifest(const fs::path& folder, F edit) {
    auto j = nlohmann::json::parse(readText(folder / "manifest.json"));
    edit(j);
    writeText(folder / "manifest.json", j.dump(2));
}

/// Expects the package to be refused with `code` and a message naming each of `words`.
void expectRefused(const fs::path& folder, ErrorCode code, std::initializer_list<const char*> words) {
    const auto verified = verifyScenePackage(folder.string());
    ASSERT_FALSE(verified.ok()) << "accepted a tampered package";
    EXPECT_EQ(verified.error().code, code) << verified.error().message();
    for (const char* word : words)
        EXPECT_NE(verified.error().detail.find(word), std::string::npos)
            << "'" << word << "' missing in: " << verified.error().detail;
    EXPECT_FALSE(readScenePackage(folder.string()).ok());
}

class ScenePackage : public ::testing::Test {
protected:
    void SetUp() override {
        const auto written = writeScenePackage(test::syntheticScene(), m_dir.file("scene"));
        ASSERT_TRUE(written.ok()) << written.error().message();
        m_manifest = written->manifest;
    }
    fs::path package() const { return m_dir.path() / "scene"; }

    test::TempDir m_dir{"hs-scene-package"};
    PackageManifest m_manifest;
};

} // namespace

TEST_F(ScenePackage, HoldsEveryDocumentedFileAndAManifestOfThem) {
    std::vector<std::string> paths;
    for (const auto& f : m_manifest.files)
        paths.push_back(f.path);
    // By default what the simulator and the workstation read; the formats of other tools on request.
    const std::vector<std::string> expected{"case.json",       "labels.json",        "maps/albedo.png",
                                            "maps/normal.png", "maps/roughness.png", "report.json",
                                            "scene.json",      "surface.vtp",        "tets.vtu"};
    EXPECT_EQ(paths, expected);
    const auto all = writeScenePackage(test::syntheticScene(), m_dir.file("all"), PackageWriteOptions::all());
    ASSERT_TRUE(all.ok()) << all.error().message();
    std::vector<std::string> allPaths;
    for (const auto& f : all->manifest.files)
        allPaths.push_back(f.path);
    const std::vector<std::string> expectedAll{
        "case.json",   "labels.json", "maps/albedo.png", "maps/normal.png", "maps/roughness.png",
        "mesh.msh",    "report.json", "scene.json",      "scene.scn",       "surface.glb",
        "surface.obj", "surface.vtp", "tets.vtu"};
    EXPECT_EQ(allPaths, expectedAll);
    // Both read back as the same scene.
    const auto small = readScenePackage(package().string());
    const auto full = readScenePackage(m_dir.file("all"));
    ASSERT_TRUE(small.ok() && full.ok());
    EXPECT_EQ(small->surface.uvs, full->surface.uvs);
    EXPECT_EQ(small->surface.mesh.points, full->surface.mesh.points);
    for (const auto& f : m_manifest.files) {
        EXPECT_EQ(static_cast<std::int64_t>(fs::file_size(package() / f.path)), f.bytes) << f.path;
        EXPECT_EQ(sha256Hex(readText(package() / f.path)), f.sha256) << f.path;
    }
    EXPECT_EQ(m_manifest.schemaVersion, kPackageSchemaVersion);
    EXPECT_EQ(m_manifest.toolVersion, HS_VERSION);
    const auto verified = verifyScenePackage(package().string());
    ASSERT_TRUE(verified.ok()) << verified.error().message();
    EXPECT_EQ(verified->toolVersions, test::syntheticScene().toolVersions) << "the manifest carries every version";
    EXPECT_FALSE(verified->toolVersions.empty());
}

TEST_F(ScenePackage, IsByteIdenticalWhenTheSameSceneIsWrittenAgain) {
    test::SyntheticSceneOptions options;
    options.heterogeneity = 0.2;
    const Scene scene = test::syntheticScene(options);
    const auto a = writeScenePackage(scene, m_dir.file("a"));
    const auto b = writeScenePackage(scene, m_dir.file("b"));
    const auto again = writeScenePackage(test::syntheticScene(options), m_dir.file("a")); // replaces a
    ASSERT_TRUE(a.ok() && b.ok() && again.ok());
    ASSERT_EQ(a->manifest.files.size(), b->manifest.files.size());
    for (std::size_t i = 0; i < a->manifest.files.size(); ++i) {
        EXPECT_EQ(a->manifest.files[i].sha256, b->manifest.files[i].sha256) << a->manifest.files[i].path;
        EXPECT_EQ(a->manifest.files[i].sha256, again->manifest.files[i].sha256) << a->manifest.files[i].path;
    }
    EXPECT_EQ(readText(m_dir.path() / "a" / "manifest.json"), readText(m_dir.path() / "b" / "manifest.json"));
}

TEST_F(ScenePackage, WritesTheVisualSurfacesUvsInEachFormatsConvention) {
    // The scene's UVs have their origin at the maps' top left (glTF's convention, surface.glb); surface.vtp holds
    // VTK's, origin at the bottom left: v there is 1 - the scene's.
    const Scene original = test::syntheticScene();
    io::PointArrays arrays;
    const auto vtp = io::readSurfaceWithArrays((package() / "surface.vtp").string(), arrays);
    ASSERT_TRUE(vtp.ok()) << vtp.error().message();
    const auto uv = arrays.find("uv");
    ASSERT_NE(uv, arrays.end());
    ASSERT_EQ(uv->second.components, 2);
    ASSERT_EQ(uv->second.values.size(), 2 * original.surface.uvs.size());
    bool flipped = false;
    for (std::size_t i = 0; i < original.surface.uvs.size(); ++i) {
        EXPECT_FLOAT_EQ(static_cast<float>(uv->second.values[2 * i]), original.surface.uvs[i][0]) << i;
        EXPECT_FLOAT_EQ(static_cast<float>(uv->second.values[2 * i + 1]), 1.0f - original.surface.uvs[i][1]) << i;
        flipped = flipped || original.surface.uvs[i][1] != 0.5f;
    }
    EXPECT_TRUE(flipped); // the scene's UVs tell the conventions apart
}

// Packages of schema version 2 and before wrote the bake's texture coordinates, origin at the bottom left, where the
// scene's have theirs at the top left: every viewer read the maps upside down. The reader turns them the right way up.
TEST_F(ScenePackage, ReadsTheUvsOfAPackageWrittenBeforeVersion3TheRightWayUp) {
    const Scene original = test::syntheticScene();
    // Packages before version 4 held surface.glb, and their UVs were read from it.
    ASSERT_TRUE(writeScenePackage(original, package().string(), PackageWriteOptions::all()).ok());
    editManifest(package(), [](auto& j) { j["schemaVersion"] = 3; });
    const auto three = readScenePackage(package().string());
    ASSERT_TRUE(three.ok()) << three.error().message();
    EXPECT_EQ(three->surface.uvs, original.surface.uvs);
    editManifest(package(), [](auto& j) { j["schemaVersion"] = 2; });
    const auto read = readScenePackage(package().string());
    ASSERT_TRUE(read.ok()) << read.error().message();
    ASSERT_EQ(read->surface.uvs.size(), original.surface.uvs.size());
    for (std::size_t i = 0; i < original.surface.uvs.size(); ++i) {
        EXPECT_EQ(read->surface.uvs[i][0], original.surface.uvs[i][0]) << i;
        EXPECT_EQ(read->surface.uvs[i][1], 1.0f - original.surface.uvs[i][1]) << i;
    }
}

TEST_F(ScenePackage, ReadsBackTheSceneItWasWrittenFrom) {
    const Scene original = test::syntheticScene();
    const auto read = readScenePackage(package().string());
    ASSERT_TRUE(read.ok()) << read.error().message();
    EXPECT_EQ(read->tets.tetCount(), original.tets.tetCount());
    EXPECT_EQ(read->tets.regions, original.tets.regions);
    EXPECT_EQ(read->tets.tetLabels.at(kMaterialLabel), original.tets.tetLabels.at(kMaterialLabel));
    EXPECT_EQ(read->surface.mesh.triangles, original.surface.mesh.triangles);
    EXPECT_EQ(read->surface.uvs, original.surface.uvs);
    EXPECT_EQ(read->surface.albedo.data(), original.surface.albedo.data());
    EXPECT_EQ(read->surface.roughness.data(), original.surface.roughness.data());
    ASSERT_EQ(read->materials.size(), 2u);
    EXPECT_EQ(read->materials[1].material.youngsModulusKpa, 65.0);
    EXPECT_EQ(read->materials[1].tissue, clinical::Tissue::Myoma);
    ASSERT_EQ(read->labels.size(), original.labels.size());
    EXPECT_EQ(read->labels[0].indices, original.labels[0].indices);
    EXPECT_EQ(read->caseSpec, original.caseSpec);
    EXPECT_EQ(read->hydrometra.cavityVolumeMl, original.hydrometra.cavityVolumeMl);
    ASSERT_EQ(read->hydrometra.modelCurve.size(), 3u);
    EXPECT_EQ(read->hydrometra.modelCurve[2].pressureKpa, 10.0);
    EXPECT_EQ(read->hydrometra.modelCurve[2].cavityOpeningMl, 4.125);
    EXPECT_EQ(modelOpeningMl(read->hydrometra, 7.5), 2.875); // between its points, linearly
    ASSERT_EQ(read->clinical.pathologies.size(), 1u);
    EXPECT_EQ(read->clinical.pathologies[0].lasmar->total(), 6);
    EXPECT_EQ(read->clinical.pathologies[0].figo->toString(), "2");
    EXPECT_EQ(read->toolVersions, original.toolVersions);
    EXPECT_EQ(read->quality.tetCount, original.tets.tetCount());
    // Written without an embedding (as packages were before the surface was bound to the tets): computed on read.
    ASSERT_EQ(read->surface.embedding.size(), read->surface.mesh.vertexCount());
    for (std::size_t i = 0; i < read->surface.embedding.size(); ++i)
        EXPECT_LT(distance(embeddedPoint(read->tets, read->surface.embedding[i]), read->surface.mesh.points[i]), 1e-9);
}

TEST_F(ScenePackage, KeepsTheSurfacesNormalsAndItsEmbeddingInTheTets) {
    Scene original = test::syntheticScene();
    original.surface.embedding = embedPoints(original.tets, original.surface.mesh.points);
    original.surface.embedding[0].weights = {0.1, 0.2, 0.3, 0.4}; // any weights that give the point back
    original.surface.mesh.points[0] = embeddedPoint(original.tets, original.surface.embedding[0]);
    for (const Vec3& n : vertexNormals(original.surface.mesh))
        original.surface.normals.push_back(n / norm(n));
    const auto written = writeScenePackage(original, m_dir.file("bound"));
    ASSERT_TRUE(written.ok()) << written.error().message();
    const auto read = readScenePackage(m_dir.file("bound"));
    ASSERT_TRUE(read.ok()) << read.error().message();
    ASSERT_EQ(read->surface.embedding.size(), original.surface.embedding.size());
    for (std::size_t i = 0; i < original.surface.embedding.size(); ++i) {
        EXPECT_EQ(read->surface.embedding[i].tet, original.surface.embedding[i].tet);
        EXPECT_EQ(read->surface.embedding[i].weights, original.surface.embedding[i].weights); // Float64, bit for bit
    }
    EXPECT_TRUE(read->surface.mesh.vertexLabels.count("embedTet") == 0); // taken out of the labels
    ASSERT_EQ(read->surface.normals.size(), original.surface.normals.size());
    for (std::size_t i = 0; i < original.surface.normals.size(); ++i)
        EXPECT_LT(distance(read->surface.normals[i], original.surface.normals[i]), 1e-6); // Float32 in the file
    // Written again from what was read: the same bytes.
    ASSERT_TRUE(writeScenePackage(*read, m_dir.file("again")).ok());
    EXPECT_EQ(readText(m_dir.path() / "bound" / "surface.vtp"), readText(m_dir.path() / "again" / "surface.vtp"));
}

TEST_F(ScenePackage, RefusesAnEmbeddingThatDoesNotGiveThePointBack) {
    Scene scene = test::syntheticScene();
    scene.surface.embedding = embedPoints(scene.tets, scene.surface.mesh.points);
    Scene far = scene;
    far.surface.embedding[3].weights = {0.25, 0.25, 0.25, 0.25};
    auto refused = writeScenePackage(far, m_dir.file("far"));
    ASSERT_FALSE(refused.ok());
    EXPECT_NE(refused.error().detail.find("surface point 3"), std::string::npos) << refused.error().detail;
    Scene wild = scene;
    wild.surface.embedding[5].weights = {50.0, -49.0, 0.0, 0.0};
    refused = writeScenePackage(wild, m_dir.file("wild"));
    ASSERT_FALSE(refused.ok());
    EXPECT_NE(refused.error().detail.find("outside the allowed"), std::string::npos) << refused.error().detail;
    Scene missing = scene;
    missing.surface.embedding[7].tet = static_cast<std::int32_t>(scene.tets.tetCount());
    EXPECT_FALSE(writeScenePackage(missing, m_dir.file("missing")).ok());
    EXPECT_FALSE(fs::exists(m_dir.path() / "missing"));
}

// A package of schema version 3 without surface.glb is refused, naming it: its UVs would be lost.
TEST_F(ScenePackage, RefusesAVersion3PackageWithoutItsGlb) {
    editManifest(package(), [](auto& j) { j["schemaVersion"] = 3; });
    expectRefused(package(), ErrorCode::InvalidInput, {"manifest.json", "surface.glb", "schema version 3"});
}

// The UVs round-trip through surface.vtp bit for bit, also below 0.5 where 1 - v in single precision would round.
TEST_F(ScenePackage, ReadsBackEveryUvBitForBit) {
    Scene scene = test::syntheticScene();
    std::uint32_t state = 12345;
    for (auto& uv : scene.surface.uvs) {
        state = state * 1664525u + 1013904223u;
        uv[0] = static_cast<float>(state >> 8) / 16777216.0f;
        state = state * 1664525u + 1013904223u;
        uv[1] = static_cast<float>(state >> 8) / 16777216.0f * 0.5f; // every v in [0, 0.5)
    }
    ASSERT_TRUE(writeScenePackage(scene, m_dir.file("uvs")).ok());
    const auto read = readScenePackage(m_dir.file("uvs"));
    ASSERT_TRUE(read.ok()) << read.error().message();
    EXPECT_EQ(read->surface.uvs, scene.surface.uvs);
}

TEST_F(ScenePackage, WritesASofaSceneWithOneForceFieldPerRegion) {
    ASSERT_TRUE(writeScenePackage(test::syntheticScene(), package().string(), *parsePackageFormats("sofa,gltf")).ok());
    const std::string scn = readText(package() / "scene.scn");
    EXPECT_NE(scn.find("<MeshGmshLoader name=\"loader\" filename=\"mesh.msh\"/>"), std::string::npos);
    EXPECT_NE(scn.find("youngModulus=\"30\" poissonRatio=\"0.47\""), std::string::npos);
    EXPECT_NE(scn.find("youngModulus=\"65\" poissonRatio=\"0.47\""), std::string::npos);
    EXPECT_NE(scn.find("texturename=\"maps/albedo.png\""), std::string::npos);
    const std::string glb = readText(package() / "surface.glb");
    ASSERT_GE(glb.size(), 12u);
    EXPECT_EQ(glb.substr(0, 4), "glTF");
}

TEST_F(ScenePackage, RefusesAChangedByteWithAChecksumError) {
    std::string text = readText(package() / "report.json");
    text[text.size() / 2] = text[text.size() / 2] == 'x' ? 'y' : 'x';
    writeText(package() / "report.json", text);
    expectRefused(package(), ErrorCode::InvalidInput, {"report.json", "checksum"});
}

TEST_F(ScenePackage, RefusesAManifestWhoseLibraryVersionsAreNotStrings) {
    editManifest(package(), [](auto& j) { j["toolVersions"]["vtk"] = 9; });
    expectRefused(package(), ErrorCode::InvalidInput, {"manifest.json", "toolVersions"});
}

TEST_F(ScenePackage, ReadsAManifestWrittenBeforeItNamedTheLibraryVersions) {
    editManifest(package(), [](auto& j) { j.erase("toolVersions"); });
    const auto verified = verifyScenePackage(package().string());
    ASSERT_TRUE(verified.ok()) << verified.error().message();
    EXPECT_TRUE(verified->toolVersions.empty());
}

TEST_F(ScenePackage, RefusesAPathThatLeavesTheFolder) {
    writeText(m_dir.path() / "outside.json", "{}");
    editManifest(package(), [](auto& j) {
        j["files"].push_back({{"path", "../outside.json"}, {"bytes", 2}, {"sha256", sha256Hex("{}")}});
    });
    expectRefused(package(), ErrorCode::InvalidInput, {"../outside.json", "escapes"});
}

TEST_F(ScenePackage, RefusesAnAbsolutePath) {
    editManifest(package(), [](auto& j) { j["files"][0]["path"] = "/etc/passwd"; });
    expectRefused(package(), ErrorCode::InvalidInput, {"/etc/passwd", "absolute"});
}

TEST_F(ScenePackage, RefusesASymbolicLinkInPlaceOfAFile) {
    fs::copy_file(package() / "maps" / "albedo.png", m_dir.path() / "albedo.png");
    fs::remove(package() / "maps" / "albedo.png");
    fs::create_symlink(m_dir.path() / "albedo.png", package() / "maps" / "albedo.png");
    expectRefused(package(), ErrorCode::InvalidInput, {"maps/albedo.png", "symbolic link"});
}

TEST_F(ScenePackage, RefusesASymbolicLinkedFolderOnTheWay) {
    fs::rename(package() / "maps", m_dir.path() / "maps");
    fs::create_directory_symlink(m_dir.path() / "maps", package() / "maps");
    expectRefused(package(), ErrorCode::InvalidInput, {"maps", "symbolic link"});
}

TEST_F(ScenePackage, RefusesAFileLargerThanDeclared) {
    std::ofstream(package() / "tets.vtu", std::ios::binary | std::ios::app) << std::string(4096, '\0');
    expectRefused(package(), ErrorCode::InvalidInput, {"tets.vtu", "larger than"});
}

TEST_F(ScenePackage, RefusesAFileLargerThanTheReadersLimit) {
    PackageReadLimits limits;
    limits.maxFileBytes = 1000;
    const auto verified = verifyScenePackage(package().string(), limits);
    ASSERT_FALSE(verified.ok());
    EXPECT_EQ(verified.error().code, ErrorCode::LimitExceeded);
    EXPECT_NE(verified.error().detail.find("above the limit"), std::string::npos);
}

TEST_F(ScenePackage, RefusesAnUnknownSchemaVersion) {
    editManifest(package(), [](auto& j) { j["schemaVersion"] = 99; });
    expectRefused(package(), ErrorCode::Unsupported, {"manifest.json", "schema version 99"});
}

TEST_F(ScenePackage, TakesTheFormatsAsACommaSeparatedList) {
    const auto none = parsePackageFormats("");
    ASSERT_TRUE(none.ok());
    EXPECT_FALSE(none->gltf || none->gmsh || none->obj || none->sofa);
    const auto some = parsePackageFormats("msh,obj");
    ASSERT_TRUE(some.ok());
    EXPECT_TRUE(some->gmsh && some->obj && !some->gltf && !some->sofa);
    const auto all = parsePackageFormats("all");
    ASSERT_TRUE(all.ok());
    EXPECT_TRUE(all->gltf && all->gmsh && all->obj && all->sofa);
    for (const char* bad : {"stl", "gltf,", ",msh", "GLTF"}) {
        const auto refused = parsePackageFormats(bad);
        ASSERT_FALSE(refused.ok()) << bad;
        EXPECT_NE(refused.error().detail.find("allowed: gltf, msh, obj, sofa, all"), std::string::npos);
    }
}

TEST_F(ScenePackage, RefusesAMissingFileNamingIt) {
    ASSERT_TRUE(writeScenePackage(test::syntheticScene(), package().string(), PackageWriteOptions::all()).ok());
    fs::remove(package() / "scene.scn");
    expectRefused(package(), ErrorCode::NotFound, {"scene.scn", "missing"});
}

TEST_F(ScenePackage, RefusesAManifestThatOmitsARequiredFile) {
    editManifest(package(), [](auto& j) {
        auto& files = j["files"];
        for (std::size_t i = 0; i < files.size(); ++i)
            if (files[i]["path"] == "tets.vtu")
                files.erase(i);
    });
    expectRefused(package(), ErrorCode::InvalidInput, {"tets.vtu", "does not list"});
}

TEST_F(ScenePackage, RefusesAGarbledManifest) {
    for (const char* garbage : {"{{{not json", "[]", "{\"format\": \"hysteroscene-scene\"}", "", "\x89PNG"}) {
        writeText(package() / "manifest.json", garbage);
        expectRefused(package(), ErrorCode::InvalidInput, {"manifest.json"});
    }
    fs::remove(package() / "manifest.json");
    expectRefused(package(), ErrorCode::NotFound, {"manifest.json"});
}

TEST_F(ScenePackage, RefusesABadManifestEntry) {
    editManifest(package(), [](auto& j) { j["files"][1]["sha256"] = "XYZ"; });
    expectRefused(package(), ErrorCode::InvalidInput, {"sha256"});
    editManifest(package(), [](auto& j) { j["files"][1] = j["files"][0]; });
    expectRefused(package(), ErrorCode::InvalidInput, {"listed twice"});
}

TEST_F(ScenePackage, NeverReplacesAFolderThatIsNotAPackage) {
    fs::create_directory(m_dir.path() / "documents");
    writeText(m_dir.path() / "documents" / "thesis.txt", "precious");
    const auto written = writeScenePackage(test::syntheticScene(), m_dir.file("documents"));
    ASSERT_FALSE(written.ok());
    EXPECT_EQ(written.error().code, ErrorCode::InvalidInput);
    EXPECT_EQ(readText(m_dir.path() / "documents" / "thesis.txt"), "precious");
}

TEST_F(ScenePackage, RecoveryRestoresAPackageMovedAsideByAnInterruptedReplace) {
    // The state a crash between "rename old aside" and "rename new into place" leaves behind.
    fs::rename(package(), m_dir.path() / ".scene.hs-old");
    fs::create_directory(m_dir.path() / ".scene.hs-tmp-999999999-0");
    EXPECT_EQ(verifyScenePackage(package().string()).error().code, ErrorCode::NotFound);
    ASSERT_TRUE(recoverScenePackage(package().string()).ok());
    EXPECT_TRUE(verifyScenePackage(package().string()).ok());
    EXPECT_FALSE(fs::exists(m_dir.path() / ".scene.hs-old"));
    EXPECT_FALSE(fs::exists(m_dir.path() / ".scene.hs-tmp-999999999-0"));
}

TEST_F(ScenePackage, TemporaryFoldersAreNeverTakenForPackages) {
    fs::copy(package(), m_dir.path() / ".scene.hs-tmp-12345-0", fs::copy_options::recursive);
    fs::copy(package(), m_dir.path() / ".scene.hs-old", fs::copy_options::recursive);
    for (const char* name : {".scene.hs-tmp-12345-0", ".scene.hs-old"}) {
        const auto verified = verifyScenePackage((m_dir.path() / name).string());
        ASSERT_FALSE(verified.ok()) << name;
        EXPECT_NE(verified.error().detail.find("temporary folder"), std::string::npos);
        EXPECT_TRUE(isPackageTempName(name));
    }
    EXPECT_FALSE(isPackageTempName("scene"));
    EXPECT_FALSE(writeScenePackage(test::syntheticScene(), m_dir.file(".x.hs-old")).ok());
}

TEST_F(ScenePackage, ZipsDeterministically) {
    ASSERT_TRUE(zipScenePackage(package().string(), m_dir.file("a.zip")).ok());
    ASSERT_TRUE(zipScenePackage(package().string(), m_dir.file("b.zip")).ok());
    const std::string a = readText(m_dir.path() / "a.zip");
    EXPECT_EQ(a.substr(0, 2), "PK");
    EXPECT_EQ(a, readText(m_dir.path() / "b.zip"));
}

// ---- Zipped packages: untrusted archives (zip slip, links, bombs) ----

namespace {

/// One entry of a hand-made zip: what a hostile archive may say, lies included.
struct ZipEntry {
    std::string name;
    std::string data; ///< stored as is, or deflated when `deflate`
    bool deflate = false;
    std::uint32_t unixMode = 0100644;
    std::int64_t declaredSize = -1; ///< the uncompressed size the headers claim; -1: the true size
};

std::uint32_t crc32Of(const std::string& bytes) {
    std::uint32_t crc = 0xffffffffu;
    for (const unsigned char c : bytes) {
        crc ^= c;
        for (int k = 0; k < 8; ++k)
            crc = (crc >> 1) ^ (0xedb88320u & (0u - (crc & 1u)));
    }
    return ~crc;
}

std::string rawDeflate(const std::string& bytes) {
    z_stream z{};
    deflateInit2(&z, 9, Z_DEFLATED, -15, 9, Z_DEFAULT_STRATEGY);
    std::string out(deflateBound(&z, static_cast<uLong>(bytes.size())), '\0');
    z.next_in = reinterpret_cast<Bytef*>(const_cast<char*>(bytes.data()));
    z.avail_in = static_cast<uInt>(bytes.size());
    z.next_out = reinterpret_cast<Bytef*>(out.data());
    z.avail_out = static_cast<uInt>(out.size());
    deflate(&z, Z_FINISH);
    out.resize(z.total_out);
    deflateEnd(&z);
    return out;
}

void put(std::string& out, std::uint32_t value, int bytes) {
    for (int i = 0; i < bytes; ++i)
        out.push_back(static_cast<char>((value >> (8 * i)) & 0xffu));
}

/// A zip archive holding `entries` in order (no zip64, no extra fields).
std::string makeZip(const std::vector<ZipEntry>& entries) {
    std::string out;
    std::string central;
    for (const auto& e : entries) {
        const std::string body = e.deflate ? rawDeflate(e.data) : e.data;
        const auto size = static_cast<std::uint32_t>(e.declaredSize < 0 ? e.data.size() : e.declaredSize);
        const auto offset = static_cast<std::uint32_t>(out.size());
        const std::uint32_t method = e.deflate ? 8 : 0;
        put(out, 0x04034b50, 4);
        put(out, 20, 2);
        put(out, 0, 2);
        put(out, method, 2);
        put(out, 0, 2);
        put(out, 0x21, 2);
        put(out, crc32Of(e.data), 4);
        put(out, static_cast<std::uint32_t>(body.size()), 4);
        put(out, size, 4);
        put(out, static_cast<std::uint32_t>(e.name.size()), 2);
        put(out, 0, 2);
        out += e.name + body;
        put(central, 0x02014b50, 4);
        put(central, (3u << 8) | 20u, 2);
        put(central, 20, 2);
        put(central, 0, 2);
        put(central, method, 2);
        put(central, 0, 2);
        put(central, 0x21, 2);
        put(central, crc32Of(e.data), 4);
        put(central, static_cast<std::uint32_t>(body.size()), 4);
        put(central, size, 4);
        put(central, static_cast<std::uint32_t>(e.name.size()), 2);
        put(central, 0, 4); // extra and comment lengths
        put(central, 0, 4); // disk, internal attributes
        put(central, e.unixMode << 16, 4);
        put(central, offset, 4);
        central += e.name;
    }
    const auto centralOffset = static_cast<std::uint32_t>(out.size());
    out += central;
    put(out, 0x06054b50, 4);
    put(out, 0, 4);
    put(out, static_cast<std::uint32_t>(entries.size()), 2);
    put(out, static_cast<std::uint32_t>(entries.size()), 2);
    put(out, static_cast<std::uint32_t>(central.size()), 4);
    put(out, centralOffset, 4);
    put(out, 0, 2);
    return out;
}

/// The entries of the package folder, manifest first (as zipScenePackage orders them).
std::vector<ZipEntry> packageEntries(const fs::path& folder, const PackageManifest& manifest) {
    std::vector<ZipEntry> entries{{"manifest.json", readText(folder / "manifest.json")}};
    for (const auto& f : manifest.files)
        entries.push_back({f.path, readText(folder / f.path)});
    return entries;
}

class ZippedPackage : public ScenePackage {
protected:
    /// Writes `entries` as a zip, expects unzipScenePackage to refuse it with `code` and a message naming each of
    /// `words`, and checks that nothing was left: no extraction folder, nothing beside it.
    void expectZipRefused(const std::vector<ZipEntry>& entries, ErrorCode code,
                          std::initializer_list<const char*> words, const PackageReadLimits& limits = {}) {
        const std::string zip = m_dir.file("hostile.zip");
        writeText(zip, makeZip(entries));
        const auto before = listing();
        const auto unzipped = unzipScenePackage(zip, m_dir.file("out"), limits);
        ASSERT_FALSE(unzipped.ok()) << "accepted a hostile zip";
        EXPECT_EQ(unzipped.error().code, code) << unzipped.error().message();
        EXPECT_NE(unzipped.error().detail.find(zip), std::string::npos) << unzipped.error().detail;
        for (const char* word : words)
            EXPECT_NE(unzipped.error().detail.find(word), std::string::npos)
                << "'" << word << "' missing in: " << unzipped.error().detail;
        EXPECT_FALSE(fs::exists(m_dir.path() / "out"));
        EXPECT_EQ(listing(), before);
        EXPECT_FALSE(readScenePackage(zip, limits).ok());
    }

    /// Everything in the test's folder, and the readers' extraction folders in the system temp folder.
    std::vector<std::string> listing() const {
        std::vector<std::string> names;
        for (const auto& e : fs::recursive_directory_iterator(m_dir.path()))
            names.push_back(e.path().string());
        for (const auto& e : fs::directory_iterator(fs::temp_directory_path()))
            if (e.path().filename().string().rfind("hs-unzip-", 0) == 0)
                names.push_back(e.path().string());
        std::sort(names.begin(), names.end());
        return names;
    }
};

} // namespace

TEST_F(ZippedPackage, ReadsBackWhatZipScenePackageWrote) {
    ASSERT_TRUE(zipScenePackage(package().string(), m_dir.file("scene.zip")).ok());
    const auto unzipped = unzipScenePackage(m_dir.file("scene.zip"), m_dir.file("out"));
    ASSERT_TRUE(unzipped.ok()) << unzipped.error().message();
    ASSERT_EQ(unzipped->files.size(), m_manifest.files.size());
    for (std::size_t i = 0; i < m_manifest.files.size(); ++i)
        EXPECT_EQ(unzipped->files[i].sha256, m_manifest.files[i].sha256) << m_manifest.files[i].path;
    const auto scene = readScenePackage(m_dir.file("scene.zip"));
    ASSERT_TRUE(scene.ok()) << scene.error().message();
    EXPECT_EQ(scene->tets.tetCount(), readScenePackage(package().string())->tets.tetCount());
    EXPECT_TRUE(verifyScenePackage(m_dir.file("scene.zip")).ok());
    // An existing folder is never extracted into.
    EXPECT_FALSE(unzipScenePackage(m_dir.file("scene.zip"), m_dir.file("out")).ok());
}

TEST_F(ZippedPackage, RefusesEntriesThatLeaveTheFolder) {
    auto entries = packageEntries(package(), m_manifest);
    for (const char* name : {"../escaped.txt", "maps/../../escaped.txt", "/tmp/escaped.txt", "..\\escaped.txt",
                             "./case.json", "maps//albedo.png"}) {
        auto hostile = entries;
        hostile.push_back({name, "pwned"});
        expectZipRefused(hostile, ErrorCode::InvalidInput, {"entry"});
        EXPECT_FALSE(fs::exists(m_dir.path().parent_path() / "escaped.txt"));
        EXPECT_FALSE(fs::exists("/tmp/escaped.txt"));
    }
}

TEST_F(ZippedPackage, RefusesSymbolicLinksRepeatedNamesAndOtherMethods) {
    auto link = packageEntries(package(), m_manifest);
    link.push_back({"passwd", "/etc/passwd", false, 0120777});
    expectZipRefused(link, ErrorCode::InvalidInput, {"symbolic link"});
    auto repeated = packageEntries(package(), m_manifest);
    repeated.push_back(repeated[1]);
    expectZipRefused(repeated, ErrorCode::InvalidInput, {"repeated"});
    expectZipRefused({{"manifest.json", "{}"}}, ErrorCode::InvalidInput, {"manifest.json"});
    writeText(m_dir.file("not.zip"), "PK\x03\x04 but not a zip at all");
    EXPECT_EQ(unzipScenePackage(m_dir.file("not.zip"), m_dir.file("out")).error().code, ErrorCode::InvalidInput);
    EXPECT_FALSE(fs::exists(m_dir.path() / "out"));
}

TEST_F(ZippedPackage, RefusesZipBombsByCountSizeAndRatio) {
    PackageReadLimits limits;
    limits.maxZipEntries = 3;
    expectZipRefused(packageEntries(package(), m_manifest), ErrorCode::LimitExceeded, {"entries", "limit of 3"},
                     limits);
    // 4 MiB of zeros deflate to about 4 KiB: a ratio near 1000:1.
    auto bomb = packageEntries(package(), m_manifest);
    bomb.push_back({"zeros.bin", std::string(4 << 20, '\0'), true});
    expectZipRefused(bomb, ErrorCode::LimitExceeded, {"zeros.bin", "compression ratio of 200:1"});
    limits = {};
    limits.maxFileBytes = 1000;
    expectZipRefused(packageEntries(package(), m_manifest), ErrorCode::LimitExceeded, {"above the limit of 1000"},
                     limits);
    // A header that under-declares its size: inflating stops at the declared size, and the entry is refused.
    auto liar = packageEntries(package(), m_manifest);
    liar.push_back({"liar.bin", std::string(100000, 'x'), true, 0100644, 10});
    expectZipRefused(liar, ErrorCode::InvalidInput, {"liar.bin"});
}
