#include "hs/anatomy/TrainingData.h"
#include "hs/anatomy/ShapeModel.h"
#include "hs/io/MeshIO.h"

#include "TestSupport.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <fstream>

using namespace hs::anatomy;

namespace {

/// Writes `count` cohort organs as VTP files plus a params CSV into `dir`; returns the CSV path.
std::string writeTrainingFiles(const hs::test::TempDir& dir, int count) {
    CohortParams params;
    params.size = std::max(count, 10); // the cohort generator needs at least 10 members
    params.seed = 5;
    auto cohort = generateCohort(params);
    EXPECT_TRUE(cohort.ok());
    std::ofstream csv(dir.file("params.csv"));
    csv << "file,ageYears,parity,gravidity,heightCm,weightKg,menopausal\n";
    for (int i = 0; i < count; ++i) {
        hs::SurfaceMesh mesh = cohort->training.reference;
        mesh.points = cohort->training.shapes[static_cast<std::size_t>(i)];
        const std::string name = "organ-" + std::to_string(i) + ".vtp";
        EXPECT_TRUE(hs::io::writeSurface(mesh, dir.file(name)).ok());
        const auto& p = cohort->training.patients[static_cast<std::size_t>(i)];
        csv << name << ',' << p.ageYears << ',' << p.parity << ',' << p.gravidity << ',' << p.heightCm << ','
            << p.weightKg << ',' << (p.menopausal ? "yes" : "no") << '\n';
    }
    return dir.file("params.csv");
}

void writeText(const std::string& path, const std::string& text) {
    std::ofstream(path) << text;
}

} // namespace

TEST(TrainingData, ReadsMeshesAndParametersAndBuildsAModel) {
    hs::test::TempDir dir;
    const std::string csv = writeTrainingFiles(dir, 12);
    auto set = loadTrainingSet(dir.path().string(), csv);
    ASSERT_TRUE(set.ok()) << set.error().message();
    EXPECT_EQ(set->shapes.size(), 12u);
    EXPECT_EQ(set->patients.size(), 12u);
    auto built = buildShapeModel(*set);
    ASSERT_TRUE(built.ok()) << built.error().message();
    EXPECT_GT(built->model.modeCount(), 0);
}

TEST(TrainingData, NamesTheLineAndColumnOfABadValue) {
    hs::test::TempDir dir;
    const std::string csv = writeTrainingFiles(dir, 2);
    writeText(csv, "file,ageYears,parity,gravidity,heightCm,weightKg,menopausal\norgan-0.vtp,abc,0,0,160,60,no\n");
    auto set = loadTrainingSet(dir.path().string(), csv);
    ASSERT_FALSE(set.ok());
    EXPECT_NE(set.error().detail.find("line 2, column 'ageYears'"), std::string::npos) << set.error().detail;
}

TEST(TrainingData, RejectsAPatientOutsideTheSupportedRange) {
    hs::test::TempDir dir;
    const std::string csv = writeTrainingFiles(dir, 2);
    writeText(csv, "file,ageYears,parity,gravidity,heightCm,weightKg,menopausal\norgan-0.vtp,130,0,0,160,60,no\n");
    auto set = loadTrainingSet(dir.path().string(), csv);
    ASSERT_FALSE(set.ok());
    EXPECT_NE(set.error().detail.find("ageYears"), std::string::npos) << set.error().detail;
    EXPECT_NE(set.error().detail.find("130"), std::string::npos) << set.error().detail;
}

TEST(TrainingData, RejectsAWrongHeaderAndAMissingMesh) {
    hs::test::TempDir dir;
    writeText(dir.file("a.csv"), "name,age\n");
    EXPECT_FALSE(loadTrainingSet(dir.path().string(), dir.file("a.csv")).ok());
    writeText(dir.file("b.csv"),
              "file,ageYears,parity,gravidity,heightCm,weightKg,menopausal\nnone.vtp,30,0,0,160,60,no\n");
    auto missing = loadTrainingSet(dir.path().string(), dir.file("b.csv"));
    ASSERT_FALSE(missing.ok());
    EXPECT_NE(missing.error().detail.find("none.vtp"), std::string::npos);
}

TEST(TrainingData, RejectsMeshesOutOfCorrespondence) {
    hs::test::TempDir dir;
    const std::string csv = writeTrainingFiles(dir, 2);
    hs::SurfaceMesh tetra;
    tetra.points = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {0, 0, 1}};
    tetra.triangles = {{0, 2, 1}, {0, 1, 3}, {0, 3, 2}, {1, 2, 3}};
    ASSERT_TRUE(hs::io::writeSurface(tetra, dir.file("organ-1.vtp")).ok());
    auto set = loadTrainingSet(dir.path().string(), csv);
    ASSERT_FALSE(set.ok());
    EXPECT_NE(set.error().detail.find("not in correspondence"), std::string::npos) << set.error().detail;
}
