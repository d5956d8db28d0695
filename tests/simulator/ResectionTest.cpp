// The resectoscope's loop (hs::sim::Resection) on a block of tissue built for it: what the wire takes, what is counted.
#include "hs/sim/Resection.h"
#include "hs/mechanics/UterusModel.h"

#include <gtest/gtest.h>

#include <cmath>
#include <set>

namespace {

using namespace hs;

/// A block 20 x 20 x 10 mm of cubes of 2 mm, six tets each, its top (z = 0) the cavity's side, held at its base; the
/// cubes of the top layer with |x|, |y| < 4 mm a polyp.
struct TestTissue {
    scene::Scene scene;
    TetMesh mesh; ///< mm
    std::vector<Triangle> boundary;
    std::vector<char> faceCavity;
    mechanics::UterusModel model; ///< its solver; the fluid's faces are not set (no volume is measured here)
    mechanics::CorotationalFem& fem = model.fem;
};

void makeTissue(TestTissue& out) {
    const int nx = 11, nz = 6;
    const auto at = [nx](int i, int j, int k) { return static_cast<std::int32_t>((k * nx + j) * nx + i); };
    for (int k = 0; k < nz; ++k)
        for (int j = 0; j < nx; ++j)
            for (int i = 0; i < nx; ++i)
                out.mesh.points.push_back(Vec3{2.0 * i - 10.0, 2.0 * j - 10.0, -2.0 * (nz - 1 - k)});
    for (int k = 0; k + 1 < nz; ++k)
        for (int j = 0; j + 1 < nx; ++j)
            for (int i = 0; i + 1 < nx; ++i) {
                const std::int32_t v[8] = {
                    at(i, j, k),     at(i + 1, j, k),     at(i + 1, j + 1, k),     at(i, j + 1, k),
                    at(i, j, k + 1), at(i + 1, j, k + 1), at(i + 1, j + 1, k + 1), at(i, j + 1, k + 1)};
                const int kuhn[6][4] = {{0, 1, 2, 6}, {0, 2, 3, 6}, {0, 3, 7, 6},
                                        {0, 7, 4, 6}, {0, 4, 5, 6}, {0, 5, 1, 6}};
                const double x = 2.0 * i - 9.0, y = 2.0 * j - 9.0;
                const bool polyp = k == nz - 2 && std::abs(x) < 4.0 && std::abs(y) < 4.0;
                for (const auto& t : kuhn) {
                    out.mesh.tets.push_back({v[t[0]], v[t[1]], v[t[2]], v[t[3]]});
                    out.mesh.regions.push_back(polyp ? 1 : 0);
                }
            }
    out.scene.regions = {{0, "myometrium", clinical::Tissue::Myometrium, ""},
                         {1, "polyp-1", clinical::Tissue::Polyp, "polyp-1"}};
    scene::PathologyDescriptor polyp;
    polyp.id = "polyp-1";
    polyp.kind = clinical::PathologyKind::Polyp;
    polyp.regionId = 1;
    out.scene.clinical.pathologies = {polyp};
    const SurfaceMesh b = extractBoundary(out.mesh);
    const auto& source = b.vertexLabels.at("sourcePoint");
    for (const Triangle& t : b.triangles) {
        const Triangle f{source[static_cast<std::size_t>(t[0])], source[static_cast<std::size_t>(t[1])],
                         source[static_cast<std::size_t>(t[2])]};
        out.boundary.push_back(f);
        bool top = true;
        for (const std::int32_t v : f)
            top = top && out.mesh.points[static_cast<std::size_t>(v)].z > -1e-9;
        out.faceCavity.push_back(top ? 1 : 0);
    }
    std::vector<Vec3> pointsM;
    std::vector<std::array<bool, 3>> fixed;
    for (const Vec3& p : out.mesh.points) {
        pointsM.push_back(p * 1e-3);
        const bool base = p.z < -9.0;
        fixed.push_back({base, base, base});
    }
    const std::vector<mechanics::FemMaterial> materials(out.mesh.tets.size(),
                                                        mechanics::FemMaterial{30e3, 0.47, 1050.0});
    ASSERT_TRUE(out.fem.build(pointsM, out.mesh.tets, materials, fixed, {}, mechanics::FemSettings{}));
}

bool inside(const Vec3& p, const TetMesh& mesh, std::size_t t) {
    const auto q = [&](int k) {
        return mesh.points[static_cast<std::size_t>(mesh.tets[t][static_cast<std::size_t>(k)])];
    };
    const Vec3 a = q(0), b = q(1), c = q(2), d = q(3);
    const double v = dot(b - a, cross(c - a, d - a));
    const double s = v > 0.0 ? 1.0 : -1.0;
    const double eps = -1e-9 * std::abs(v);
    return s * dot(b - p, cross(c - p, d - p)) >= eps && s * dot(a - p, cross(d - p, c - p)) >= eps &&
           s * dot(a - p, cross(b - p, d - p)) >= eps && s * dot(a - p, cross(c - p, b - p)) >= eps;
}

/// Adds to `out` every tet of `mesh` that holds a point of `points` (the check's own sweep, finer than the cut's).
void addTetsContaining(const std::vector<Vec3>& points, const TetMesh& mesh, std::set<std::size_t>& out) {
    for (const Vec3& p : points)
        for (std::size_t t = 0; t < mesh.tets.size(); ++t)
            if (inside(p, mesh, t))
                out.insert(t);
}

} // namespace

TEST(Resection, TheLoopsWireIsAHalfCircleAcrossTheSheath) {
    sim::LoopElectrode loop;
    loop.widthMm = 4.0;
    loop.sampleMm = 0.2;
    const Vec3 centre{1.0, 2.0, 3.0}, axis{0.0, 0.0, 1.0}, down{0.0, -1.0, 0.0};
    const std::vector<Vec3> wire = sim::loopWire(loop, centre, axis, down);
    ASSERT_GE(wire.size(), 3u);
    for (const Vec3& p : wire) {
        EXPECT_NEAR(norm(p - centre), 2.0, 1e-12);      // on the half circle of 4 mm
        EXPECT_NEAR(dot(p - centre, axis), 0.0, 1e-12); // across the sheath's axis
        EXPECT_GE(dot(p - centre, down), -1e-12);       // on the side it hangs to
    }
    EXPECT_NEAR(norm(wire.front() - wire.back()), 4.0, 1e-12); // its ends span its width
    EXPECT_NEAR(dot(wire[wire.size() / 2] - centre, down), 2.0, 0.01);
    for (std::size_t k = 1; k < wire.size(); ++k)
        EXPECT_LE(norm(wire[k] - wire[k - 1]), loop.sampleMm + 1e-12);
}

TEST(Resection, TheLoopTakesTheTetsItsWirePassesThroughAndCountsThem) {
    // The loop drawn along x through the block's top (x from 7 to -7 mm, clear of its sides), hanging 1.5 mm into it:
    // it takes every tet its wire passes
    // through (checked on a four times finer sampling of the same sweep), nothing more than a tet from it, and the
    // volumes it counts are those tets'.
    TestTissue tissue;
    makeTissue(tissue);
    auto made = sim::Resection::make(tissue.scene, tissue.mesh, tissue.boundary, tissue.faceCavity);
    ASSERT_TRUE(made) << made.error().detail;
    sim::Resection resection = std::move(*made);
    EXPECT_NEAR(resection.totals().pathologyMl[0], 8.0 * 8.0 * 2.0 * 1e-3, 1e-12); // 16 cubes of 8 mm^3
    sim::LoopElectrode loop;
    loop.widthMm = 4.0;
    const Vec3 axis{-1.0, 0.0, 0.0}, down{0.0, 0.0, -1.0};
    std::vector<Vec3> from = sim::loopWire(loop, Vec3{7.0, 1.0, 0.5}, axis, down);
    std::set<std::size_t> taken;
    double pathologyMl = 0.0, healthyMl = 0.0, deepest = 0.0;
    for (int s = 1; s <= 28; ++s) {
        const double x = 7.0 - 0.5 * s;
        const std::vector<Vec3> to = sim::loopWire(loop, Vec3{x, 1.0, 0.5}, axis, down);
        const sim::CutEvent event = resection.cut(tissue.model, loop.sampleMm, from, to);
        taken.insert(event.removed.begin(), event.removed.end());
        pathologyMl += event.pathologyMl;
        healthyMl += event.healthyMl;
        deepest = std::max(deepest, event.deepestMyometriumMm);
        EXPECT_FALSE(event.perforation);
        from = to;
    }
    // What the wire passed through (the tissue has not moved: no step was taken).
    std::set<std::size_t> swept;
    for (int s = 0; s <= 4 * 28; ++s)
        addTetsContaining(sim::loopWire(sim::LoopElectrode{4.0, 0.05}, Vec3{7.0 - 0.125 * s, 1.0, 0.5}, axis, down),
                          tissue.mesh, swept);
    ASSERT_FALSE(swept.empty());
    for (const std::size_t t : swept)
        EXPECT_TRUE(taken.count(t)) << "tet " << t << " was passed through and left";
    double volume = 0.0, polypVolume = 0.0;
    for (const std::size_t t : taken) {
        volume += std::abs(signedVolume(tissue.mesh, t)) * 1e-3;
        if (tissue.mesh.regions[t] == 1)
            polypVolume += std::abs(signedVolume(tissue.mesh, t)) * 1e-3;
        // Within a cube's diagonal of the swept band (|y - 1| <= 2 mm, z >= -1.5 mm).
        for (const std::int32_t v : tissue.mesh.tets[t]) {
            const Vec3& p = tissue.mesh.points[static_cast<std::size_t>(v)];
            EXPECT_LE(std::abs(p.y - 1.0), 2.0 + 3.5);
            EXPECT_GE(p.z, -1.5 - 3.5);
        }
    }
    EXPECT_NEAR(pathologyMl + healthyMl, volume, 1e-12);
    EXPECT_NEAR(pathologyMl, polypVolume, 1e-12);
    EXPECT_GT(pathologyMl, 0.0);
    EXPECT_NEAR(resection.totals().pathologyRemovedMl[0], pathologyMl, 1e-12);
    EXPECT_NEAR(resection.totals().healthyMl, healthyMl, 1e-12);
    // The deepest healthy tet taken reaches no deeper than two layers of cubes: 4 mm.
    EXPECT_GT(deepest, 0.0);
    EXPECT_LE(deepest, 4.0 + 1e-9);
    EXPECT_EQ(resection.totals().perforations, 0);
    EXPECT_TRUE(tissue.fem.singularPoints().empty());
    EXPECT_EQ(tissue.fem.looseLivePieces(), 0u);
}

TEST(Resection, TheScissorsJawsOpenSymmetricallyAndTheirClosingCutsWhatLiesBetweenThem) {
    sim::JawInstrument jaws;
    const Vec3 hinge{-4.0, 1.0, -1.0}, axis{1.0, 0.0, 0.0}, down{0.0, 0.0, -1.0};
    const std::vector<Vec3> open = sim::jawWire(jaws, hinge, axis, down, jaws.openDeg);
    const std::vector<Vec3> shut = sim::jawWire(jaws, hinge, axis, down, 0.0);
    ASSERT_EQ(open.size(), shut.size()); // a closing is a sweep of the same points
    ASSERT_EQ(open.size() % 2, 1u);
    EXPECT_NEAR(norm(open[open.size() / 2] - hinge), 0.0, 1e-12);
    const double a = jaws.openDeg * 3.14159265358979323846 / 180.0;
    for (const Vec3& tip : {open.front(), open.back()}) {
        EXPECT_NEAR(norm(tip - hinge), jaws.jawLengthMm, 1e-12);
        EXPECT_NEAR(dot(tip - hinge, axis), jaws.jawLengthMm * std::cos(a), 1e-12);
        EXPECT_NEAR(tip.y, hinge.y, 1e-12); // in the plane of the shaft and down
    }
    EXPECT_NEAR(dot(open.back() - hinge, down), jaws.jawLengthMm * std::sin(a), 1e-12);
    EXPECT_NEAR(dot(open.front() - hinge, down), -jaws.jawLengthMm * std::sin(a), 1e-12);
    for (std::size_t k = 1; k < open.size(); ++k)
        EXPECT_LE(norm(open[k] - open[k - 1]), jaws.sampleMm + 1e-12);
    for (const Vec3& p : shut)
        EXPECT_NEAR(norm(cross(p - hinge, axis)), 0.0, 1e-12);

    // The hinge 1 mm deep in the block's polyp, the jaws in the x-z plane: closing them in ten steps takes every tet
    // their edges pass through, and only tets within a cube's diagonal of the wedge they close over.
    TestTissue tissue;
    makeTissue(tissue);
    auto made = sim::Resection::make(tissue.scene, tissue.mesh, tissue.boundary, tissue.faceCavity);
    ASSERT_TRUE(made) << made.error().detail;
    sim::Resection resection = std::move(*made);
    std::set<std::size_t> taken;
    std::vector<Vec3> from = open;
    for (int s = 1; s <= 10; ++s) {
        const std::vector<Vec3> to = sim::jawWire(jaws, hinge, axis, down, jaws.openDeg * (1.0 - 0.1 * s));
        const sim::CutEvent event = resection.cut(tissue.model, jaws.sampleMm, from, to);
        taken.insert(event.removed.begin(), event.removed.end());
        from = to;
    }
    std::set<std::size_t> swept;
    sim::JawInstrument fine = jaws;
    fine.sampleMm = 0.05;
    for (int s = 0; s <= 100; ++s)
        addTetsContaining(sim::jawWire(fine, hinge, axis, down, jaws.openDeg * (1.0 - 0.01 * s)), tissue.mesh, swept);
    ASSERT_FALSE(swept.empty());
    for (const std::size_t t : swept)
        EXPECT_TRUE(taken.count(t)) << "tet " << t << " lay between the blades and was left";
    bool polyp = false;
    for (const std::size_t t : taken) {
        polyp = polyp || tissue.mesh.regions[t] == 1;
        for (const std::int32_t v : tissue.mesh.tets[t]) {
            const Vec3& p = tissue.mesh.points[static_cast<std::size_t>(v)];
            EXPECT_LE(std::abs(p.y - hinge.y), 3.5); // the blades' plane, y = 1
            EXPECT_GE(p.x, hinge.x - 3.5);
            EXPECT_LE(p.x, hinge.x + jaws.jawLengthMm + 3.5);
        }
    }
    EXPECT_TRUE(polyp);
    EXPECT_GT(resection.totals().pathologyRemovedMl[0], 0.0);
    EXPECT_TRUE(tissue.fem.singularPoints().empty());
    EXPECT_EQ(tissue.fem.looseLivePieces(), 0u);
}

TEST(Resection, ACutThroughTheOuterWallIsAPerforation) {
    // The loop drawn down through the block's side (x = -10 mm, the serosa here).
    TestTissue tissue;
    makeTissue(tissue);
    auto made = sim::Resection::make(tissue.scene, tissue.mesh, tissue.boundary, tissue.faceCavity);
    ASSERT_TRUE(made);
    sim::Resection resection = std::move(*made);
    const Vec3 axis{0.0, 0.0, -1.0}, down{1.0, 0.0, 0.0};
    sim::LoopElectrode loop;
    const sim::CutEvent event =
        resection.cut(tissue.model, loop.sampleMm, sim::loopWire(loop, Vec3{-11.0, 0.0, 1.0}, axis, down),
                      sim::loopWire(loop, Vec3{-11.0, 0.0, -3.0}, axis, down));
    EXPECT_FALSE(event.removed.empty());
    EXPECT_TRUE(event.perforation);
    EXPECT_EQ(resection.totals().perforations, 1);
    EXPECT_EQ(event.pathologyMl, 0.0);
}

TEST(Resection, CuttingARegionsLastTetAndSeveringTheTopFromTheHeldBaseLeaveASolverThatSteps) {
    // Bad input for the solver: a loop as wide as the block drawn through its top layer takes all of the polyp (a
    // region left without a tet), then through the layer below it, which cuts the rest of the top off what holds it
    // (as a cut through the isthmus would part the corpus from the held cervix, were the corpus not tethered). The
    // severed part goes as chips; the tissue left stays a valid solid and steps with finite, bounded motion.
    TestTissue tissue;
    makeTissue(tissue);
    auto made = sim::Resection::make(tissue.scene, tissue.mesh, tissue.boundary, tissue.faceCavity);
    ASSERT_TRUE(made) << made.error().detail;
    sim::Resection resection = std::move(*made);
    sim::LoopElectrode loop;
    loop.widthMm = 40.0;
    const Vec3 axis{-1.0, 0.0, 0.0}, down{0.0, 0.0, -1.0};
    const auto sweep = [&](double depthMm) {
        // The half circle's lowest point `depthMm` below the top, where it leaves the block's sides (|y| = 10 mm)
        // still in it: a cut across all of it.
        std::vector<Vec3> from = sim::loopWire(loop, Vec3{12.0, 0.0, 20.0 - depthMm}, axis, down);
        std::size_t chips = 0;
        for (int s = 1; s <= 48; ++s) {
            const std::vector<Vec3> to = sim::loopWire(loop, Vec3{12.0 - 0.5 * s, 0.0, 20.0 - depthMm}, axis, down);
            chips += resection.cut(tissue.model, loop.sampleMm, from, to).chips.size();
            from = to;
        }
        return chips;
    };
    sweep(1.0);
    EXPECT_NEAR(resection.totals().pathologyRemovedMl[0], resection.totals().pathologyMl[0], 1e-12);
    EXPECT_TRUE(tissue.fem.singularPoints().empty());
    EXPECT_EQ(tissue.fem.looseLivePieces(), 0u);
    const std::size_t liveBefore = tissue.fem.liveTetCount();
    EXPECT_GT(sweep(4.0), 0u); // what lies above the cut, held by nothing, went as chips
    EXPECT_LT(tissue.fem.liveTetCount(), liveBefore);
    EXPECT_GT(tissue.fem.liveTetCount(), 0u);
    EXPECT_TRUE(tissue.fem.singularPoints().empty());
    EXPECT_EQ(tissue.fem.looseLivePieces(), 0u);
    // A push on the top of what is left: the solver steps, the motion stays finite and small.
    std::vector<Vec3> forces(tissue.fem.pointCount());
    for (std::size_t i = 0; i < forces.size(); ++i)
        if (tissue.mesh.points[i].z > -5.0)
            forces[i] = Vec3{0.0, 0.0, -0.01};
    std::vector<mechanics::FemConstraint> none;
    for (int k = 0; k < 50; ++k)
        tissue.fem.step(forces, none);
    for (std::size_t i = 0; i < tissue.fem.pointCount(); ++i) {
        const Vec3 moved = tissue.fem.positionsM()[i] - tissue.fem.restM()[i];
        ASSERT_TRUE(std::isfinite(moved.x) && std::isfinite(moved.y) && std::isfinite(moved.z)) << i;
        EXPECT_LT(norm(moved), 5e-3) << "point " << i; // less than 5 mm
    }
}

TEST(Resection, ARegionTheSceneDoesNotListIsRefusedByName) {
    TestTissue tissue;
    makeTissue(tissue);
    tissue.mesh.regions[7] = 5;
    const auto made = sim::Resection::make(tissue.scene, tissue.mesh, tissue.boundary, tissue.faceCavity);
    ASSERT_FALSE(made);
    EXPECT_NE(made.error().detail.find("tet 7 has region 5"), std::string::npos) << made.error().detail;
}
