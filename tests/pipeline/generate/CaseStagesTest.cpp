// What the stages take from a case: paths the case gives are read from the case file's folder.
#include "hs/generate/CaseStages.h"

#include <gtest/gtest.h>

#include <filesystem>

using namespace hs;

TEST(CaseStages, ExemplarPathsAreReadFromTheCaseFilesFolder) {
    // docs/case-format.md: an exemplar's path is relative to the case file's folder; the cervical canal's exemplar is
    // a field of its own (schema version 3).
    scene::CaseSpec spec;
    spec.texture.exemplars.endometrium = "images/endometrium.png";
    spec.texture.exemplars.cervicalCanal = "images/canal.png";
    spec.texture.exemplars.polyp = "/abs/polyp.png";
    const auto index = [](texture::Appearance a) { return static_cast<std::size_t>(a); };
    const texture::BakeParams p = generate::bakeParamsFor(spec, "/cases/patient-7/case.json");
    EXPECT_EQ(std::filesystem::path(p.exemplarFiles[index(texture::Appearance::Endometrium)]),
              std::filesystem::path("/cases/patient-7/images/endometrium.png"));
    EXPECT_EQ(std::filesystem::path(p.exemplarFiles[index(texture::Appearance::CervicalCanal)]),
              std::filesystem::path("/cases/patient-7/images/canal.png"));
    EXPECT_EQ(p.exemplarFiles[index(texture::Appearance::Polyp)], "/abs/polyp.png");
    EXPECT_EQ(p.exemplarFiles[index(texture::Appearance::Myoma)], ""); // unset: the bundled exemplar
    // Without a case file (a case built in memory) the paths are taken as given.
    const texture::BakeParams q = generate::bakeParamsFor(spec, "");
    EXPECT_EQ(q.exemplarFiles[index(texture::Appearance::CervicalCanal)], "images/canal.png");
}
