#include "hs/generate/TissueLayers.h"

#include "hs/clinical/Tissue.h"
#include "hs/generate/CaseStages.h"

#include <gtest/gtest.h>

#include <cmath>

using namespace hs;
using namespace hs::generate;

namespace {

/// A slab of nx x ny x nz unit cubes (edge `h` mm), each cut into the 6 Kuhn tets, all in region 0. Its floor
/// (z = 0) is lined: the half x < nx * h / 2 by the cervical canal, the other half by the endometrium; every other
/// boundary face is serosa.
struct Slab {
    TetMesh tets;
    SurfaceMesh boundary;
    double halfX = 0.0;
};

Slab makeSlab(int nx, int ny, int nz, double h) {
    Slab s;
    auto id = [&](int i, int j, int k) { return static_cast<std::int32_t>((k * (ny + 1) + j) * (nx + 1) + i); };
    for (int k = 0; k <= nz; ++k)
        for (int j = 0; j <= ny; ++j)
            for (int i = 0; i <= nx; ++i)
                s.tets.points.push_back({i * h, j * h, k * h});
    const int perms[6][3] = {{0, 1, 2}, {0, 2, 1}, {1, 0, 2}, {1, 2, 0}, {2, 0, 1}, {2, 1, 0}};
    for (int k = 0; k < nz; ++k)
        for (int j = 0; j < ny; ++j)
            for (int i = 0; i < nx; ++i)
                for (const auto& p : perms) {
                    int c[3] = {i, j, k};
                    Tet t{};
                    t[0] = id(c[0], c[1], c[2]);
                    for (int s2 = 0; s2 < 3; ++s2) {
                        ++c[p[s2]];
                        t[static_cast<std::size_t>(s2 + 1)] = id(c[0], c[1], c[2]);
                    }
                    s.tets.tets.push_back(t);
                }
    s.tets.regions.assign(s.tets.tets.size(), 0);
    s.boundary = extractBoundary(s.tets);
    s.halfX = 0.5 * nx * h;
    std::vector<std::int32_t> tissue(s.boundary.triangles.size(),
                                     static_cast<std::int32_t>(clinical::SurfaceTissue::Serosa));
    for (std::size_t f = 0; f < tissue.size(); ++f) {
        const auto& tri = s.boundary.triangles[f];
        const Vec3 c =
            (s.boundary.points[static_cast<std::size_t>(tri[0])] + s.boundary.points[static_cast<std::size_t>(tri[1])] +
             s.boundary.points[static_cast<std::size_t>(tri[2])]) /
            3.0;
        if (c.z < 1e-9)
            tissue[f] = static_cast<std::int32_t>(c.x < s.halfX ? clinical::SurfaceTissue::CervicalCanal
                                                                : clinical::SurfaceTissue::Endometrium);
    }
    s.boundary.faceLabels[clinical::kSurfaceTissueLabel] = tissue;
    return s;
}

Vec3 centroidOf(const TetMesh& m, std::size_t t) {
    Vec3 c{0, 0, 0};
    for (auto p : m.tets[t])
        c = c + m.points[static_cast<std::size_t>(p)];
    return c * 0.25;
}

} // namespace

TEST(TissueLayers, CervixSurroundsTheCanalAndTheEndometriumLinesTheCavityToItsThickness) {
    const double h = 0.5;
    const Slab slab = makeSlab(20, 4, 16, h); // 10 x 2 x 8 mm
    TissueLayerParams params;
    params.endometriumThicknessMm = 2.0;
    const auto layers = tissueLayers(slab.tets, 0, slab.boundary, params);
    ASSERT_EQ(layers.layer.size(), slab.tets.tets.size());
    for (std::size_t t = 0; t < slab.tets.tets.size(); ++t) {
        const Vec3 c = centroidOf(slab.tets, t);
        if (c.x < slab.halfX - h) {
            EXPECT_EQ(layers.layer[t], WallLayer::Cervix) << c.x << " " << c.z;
        } else if (c.x > slab.halfX + 2.0 * h && c.z < params.endometriumThicknessMm - h) {
            EXPECT_EQ(layers.layer[t], WallLayer::Endometrium) << c.x << " " << c.z;
        } else if (c.x > slab.halfX + h && c.z > params.endometriumThicknessMm + h) {
            EXPECT_EQ(layers.layer[t], WallLayer::Myometrium) << c.x << " " << c.z;
        }
    }
    EXPECT_NEAR(layers.liningAreaMm2, 5.0 * 2.0, 1e-9);
    EXPECT_NEAR(layers.endometriumVolumePerLiningAreaMm(), params.endometriumThicknessMm, h);
    EXPECT_GT(layers.cervixTets, 0u);
    EXPECT_NEAR(layers.cervixVolumeMm3, 5.0 * 2.0 * 8.0, 2.0 * 8.0 * h);
}

TEST(TissueLayers, LeavesOtherRegionsAndAnUnlinedWallAlone) {
    Slab slab = makeSlab(8, 2, 4, 1.0);
    for (std::size_t t = 0; t < slab.tets.tets.size(); t += 2)
        slab.tets.regions[t] = 5; // a "pathology": never relabelled
    TissueLayerParams noCover;
    noCover.coverPathologies = false;
    const auto layers = tissueLayers(slab.tets, 0, slab.boundary, noCover);
    for (std::size_t t = 0; t < slab.tets.tets.size(); t += 2)
        EXPECT_EQ(layers.layer[t], WallLayer::Myometrium);
    // With the cover, exactly the pathology tets with a face on the cavity's floor become endometrium.
    const auto covered = tissueLayers(slab.tets, 0, slab.boundary, {});
    std::size_t onCavity = 0;
    for (std::size_t t = 0; t < slab.tets.tets.size(); t += 2) {
        int floorPoints = 0;
        bool cavitySide = true;
        for (auto p : slab.tets.tets[t]) {
            const Vec3& q = slab.tets.points[static_cast<std::size_t>(p)];
            floorPoints += q.z == 0.0 ? 1 : 0;
        }
        const Vec3 c = centroidOf(slab.tets, t);
        cavitySide = c.x > slab.halfX;
        const bool expected = floorPoints == 3 && cavitySide;
        onCavity += expected ? 1 : 0;
        EXPECT_EQ(covered.layer[t] == WallLayer::Endometrium, expected) << t;
    }
    EXPECT_EQ(covered.coverTets, onCavity);
    EXPECT_GT(onCavity, 0u);

    SurfaceMesh unlabelled = slab.boundary;
    unlabelled.faceLabels.clear();
    const auto none = tissueLayers(slab.tets, 0, unlabelled, {});
    EXPECT_EQ(none.endometriumTets + none.cervixTets, 0u);
}

TEST(TissueLayers, WithoutTheCervixTheCanalSideStaysMyometrium) {
    const Slab slab = makeSlab(10, 2, 6, 1.0);
    TissueLayerParams params;
    params.cervix = false;
    const auto layers = tissueLayers(slab.tets, 0, slab.boundary, params);
    EXPECT_EQ(layers.cervixTets, 0u);
    EXPECT_GT(layers.endometriumTets, 0u);
}

TEST(EndometrialState, TheTextureFollowsThePatientsCycleOrMenopause) {
    // The bake gets the endometrium's state from the case's patient (docs/texture.md, "The endometrium through the
    // cycle"): atrophic after the menopause, else the cycle phase, proliferative when unset.
    hs::clinical::PatientParams patient;
    patient.cyclePhase = hs::clinical::CyclePhase::Secretory;
    EXPECT_EQ(hs::generate::endometrialState(patient), hs::texture::EndometrialState::Secretory);
    patient.cyclePhase = hs::clinical::CyclePhase::Menstrual;
    EXPECT_EQ(hs::generate::endometrialState(patient), hs::texture::EndometrialState::Menstrual);
    patient.cyclePhase.reset();
    EXPECT_EQ(hs::generate::endometrialState(patient), hs::texture::EndometrialState::Proliferative);
    patient.menopausal = true;
    EXPECT_EQ(hs::generate::endometrialState(patient), hs::texture::EndometrialState::Atrophic);
    hs::scene::CaseSpec spec;
    spec.patient = patient;
    EXPECT_EQ(hs::generate::bakeParamsFor(spec, "").endometrium, hs::texture::EndometrialState::Atrophic);
}
