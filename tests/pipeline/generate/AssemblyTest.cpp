#include "hs/generate/Assembly.h"

#include "hs/anatomy/UterusGenerator.h"
#include "hs/clinical/Tissue.h"
#include "hs/meshing/BaselineMeshers.h"

#include <gtest/gtest.h>

#include <cmath>

using namespace hs;
using namespace hs::generate;

namespace {

scene::CaseSpec twoPathologyCase() {
    scene::CaseSpec spec = scene::defaultCase(); // myoma-1 (FIGO 2, left lateral), polyp-1 (sessile, right cornual)
    return spec;
}

/// Two tets sharing the face (1, 2, 3): tet 0 in body region 0 (wall), tet 1 in body region 1 (the first
/// pathology), and a third tet of region 2 touching only tet 1 at a vertex.
TetMesh threeTets() {
    TetMesh m;
    m.points = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {0, 0, 1}, {1, 1, 1}, {2, 2, 2}, {3, 2, 2}, {2, 3, 2}};
    m.tets = {{0, 1, 2, 3}, {1, 3, 2, 4}, {4, 5, 6, 7}};
    m.regions = {0, 1, 2};
    return m;
}

} // namespace

TEST(Assembly, RegionsAreTheWallTissuesPresentThenOnePerPathologyInCaseOrder) {
    TetMesh tets = threeTets();
    tets.regions = {kMyometriumRegion, kCervixRegion, pathologyRegion(0)};
    const auto regions = sceneRegions(twoPathologyCase(), tets);
    ASSERT_EQ(regions.size(), 4u);
    EXPECT_EQ(regions[0].id, kMyometriumRegion);
    EXPECT_EQ(regions[0].name, "myometrium");
    EXPECT_EQ(regions[0].tissue, clinical::Tissue::Myometrium);
    EXPECT_EQ(regions[1].id, kCervixRegion); // no endometrium tet: no endometrium region
    EXPECT_EQ(regions[1].tissue, clinical::Tissue::Cervix);
    EXPECT_EQ(regions[2].id, 4);
    EXPECT_EQ(regions[2].name, "myoma-1");
    EXPECT_EQ(regions[2].tissue, clinical::Tissue::Myoma);
    EXPECT_EQ(regions[2].pathologyId, "myoma-1");
    EXPECT_EQ(regions[3].id, 5);
    EXPECT_EQ(regions[3].tissue, clinical::Tissue::Polyp);
    EXPECT_EQ(pathologyRegion(1), 5);
}

TEST(Assembly, SceneTetsGiveTheWallItsLayersAndThePathologiesTheirOwnIds) {
    const TetMesh plain = sceneTets(threeTets());
    EXPECT_EQ(plain.regions, (std::vector<std::int32_t>{1, 4, 5}));
    EXPECT_EQ(plain.tets, threeTets().tets);
    const TetMesh layered = sceneTets(threeTets(), {WallLayer::Cervix, WallLayer::Endometrium, WallLayer::Myometrium});
    EXPECT_EQ(layered.regions, (std::vector<std::int32_t>{kCervixRegion, kEndometriumRegion, 5}));
}

TEST(Assembly, TetsTouchingFindsOnlyTetsSharingAFace) {
    const TetMesh m = sceneTets(threeTets());
    EXPECT_EQ(tetsTouching(m, 4, 1), (std::vector<std::int32_t>{1}));
    EXPECT_EQ(tetsTouching(m, 1, 4), (std::vector<std::int32_t>{0}));
    EXPECT_TRUE(tetsTouching(m, 5, 4).empty()); // shares a vertex only
    EXPECT_TRUE(tetsTouching(m, 6, 1).empty()); // no such region
}

TEST(Assembly, FacesWithListsMatchingFacesAscendingAndNothingForAMissingLabel) {
    SurfaceMesh s;
    s.points = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {0, 0, 1}};
    s.triangles = {{0, 1, 2}, {0, 1, 3}, {0, 2, 3}, {1, 2, 3}};
    s.faceLabels["tissue"] = {2, 4, 2, 3};
    EXPECT_EQ(facesWith(s, "tissue", 2), (std::vector<std::int32_t>{0, 2}));
    EXPECT_TRUE(facesWith(s, "tissue", 9).empty());
    EXPECT_TRUE(facesWith(s, "absent", 2).empty());
}

TEST(Assembly, LabelsComeInContactBaseOstiaCanalOrderAndEmptySetsAreLeftOut) {
    const auto spec = twoPathologyCase();
    const TetMesh tets = sceneTets(threeTets());
    SurfaceMesh visual;
    visual.points = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {0, 0, 1}};
    visual.triangles = {{0, 1, 2}, {0, 1, 3}, {0, 2, 3}, {1, 2, 3}};
    const auto ostium = clinical::labelValue(clinical::SurfaceTissue::TubalOstium);
    const auto canal = clinical::labelValue(clinical::SurfaceTissue::CervicalCanal);
    visual.faceLabels[clinical::kSurfaceTissueLabel] = {ostium, 2, canal, canal};
    visual.faceLabels[merge::kPathologyLabel] = {0, 1, 1, 0}; // faces 1, 2 over the myoma; none over the polyp
    const auto labels = sceneLabels(spec, tets, visual);
    ASSERT_EQ(labels.size(), 4u);
    EXPECT_EQ(labels[0].name, "contact:myoma-1");
    EXPECT_EQ(labels[0].kind, scene::LabelKind::Contact);
    EXPECT_EQ(labels[0].element, scene::LabelElement::SurfaceFace);
    EXPECT_EQ(labels[0].indices, (std::vector<std::int32_t>{1, 2}));
    EXPECT_EQ(labels[1].name, "base:myoma-1"); // the polyp's region (5) shares no face with the wall
    EXPECT_EQ(labels[1].element, scene::LabelElement::Tet);
    EXPECT_EQ(labels[1].indices, (std::vector<std::int32_t>{1}));
    EXPECT_EQ(labels[2].name, "ostia");
    EXPECT_EQ(labels[2].indices, (std::vector<std::int32_t>{0}));
    EXPECT_EQ(labels[3].name, "cervical-canal");
    EXPECT_EQ(labels[3].indices, (std::vector<std::int32_t>{2, 3}));
}

namespace {

/// The parametric organ as its own final body: the boundary is the organ surface with no pathology draped on it.
struct SyntheticBody {
    anatomy::UterusResult organ;
    SurfaceMesh boundary;
};

const SyntheticBody& syntheticBody() {
    static const SyntheticBody b = [] {
        SyntheticBody s;
        auto organ = anatomy::generateUterus(anatomy::UterusShapeParams{});
        EXPECT_TRUE(organ.ok());
        s.organ = std::move(organ).value();
        s.boundary = s.organ.mesh;
        s.boundary.faceLabels[merge::kPathologyLabel].assign(s.boundary.triangles.size(), 0);
        return s;
    }();
    return b;
}

/// A cube of `n`^3 cells of 6 tets each, side `side` mm, centred on `centre`, its axes (e1, e2, normal), all in
/// region `region`.
TetMesh tetCube(const Vec3& centre, const Vec3& normal, double side, int n, std::int32_t region) {
    Vec3 e1 = normalized(cross(normal, std::abs(normal.x) < 0.9 ? Vec3{1, 0, 0} : Vec3{0, 1, 0}));
    const Vec3 e2 = cross(normal, e1);
    TetMesh m;
    auto id = [n](int i, int j, int k) { return static_cast<std::int32_t>((k * (n + 1) + j) * (n + 1) + i); };
    for (int k = 0; k <= n; ++k)
        for (int j = 0; j <= n; ++j)
            for (int i = 0; i <= n; ++i) {
                const double h = side / n;
                m.points.push_back(centre + e1 * (i * h - side / 2) + e2 * (j * h - side / 2) +
                                   normal * (k * h - side / 2));
            }
    for (int k = 0; k < n; ++k)
        for (int j = 0; j < n; ++j)
            for (int i = 0; i < n; ++i) {
                const std::int32_t c[8] = {
                    id(i, j, k),     id(i + 1, j, k),     id(i + 1, j + 1, k),     id(i, j + 1, k),
                    id(i, j, k + 1), id(i + 1, j, k + 1), id(i + 1, j + 1, k + 1), id(i, j + 1, k + 1)};
                // Six tets around the diagonal 0-6 (Kuhn triangulation).
                const int t[6][4] = {{0, 1, 2, 6}, {0, 2, 3, 6}, {0, 3, 7, 6},
                                     {0, 7, 4, 6}, {0, 4, 5, 6}, {0, 5, 1, 6}};
                for (const auto& q : t)
                    m.tets.push_back({c[q[0]], c[q[1]], c[q[2]], c[q[3]]});
            }
    m.regions.assign(m.tets.size(), region);
    return m;
}

/// A seat on the posterior endometrium half way up the cavity: the vertex and the unit normal into the cavity.
std::pair<Vec3, Vec3> posteriorSeat(const SyntheticBody& b) {
    const auto& l = b.organ.layout;
    const auto v = static_cast<std::size_t>(l.vertex(l.internalOsRing() + l.cavityRings / 2, 3 * l.around / 4));
    Vec3 n;
    for (const auto& t : b.boundary.triangles)
        if (t[0] == static_cast<std::int32_t>(v) || t[1] == static_cast<std::int32_t>(v) ||
            t[2] == static_cast<std::int32_t>(v)) {
            const Vec3& a = b.boundary.points[static_cast<std::size_t>(t[0])];
            n += cross(b.boundary.points[static_cast<std::size_t>(t[1])] - a,
                       b.boundary.points[static_cast<std::size_t>(t[2])] - a);
        }
    return {b.boundary.points[v], normalized(n)};
}

/// The default case with its myoma only, asked as `figo` and the size of an 8 mm cube (its diagonal).
scene::CaseSpec cubeMyomaCase(int figo) {
    scene::CaseSpec spec = scene::defaultCase();
    spec.pathologies.resize(1);
    spec.pathologies[0].figo = clinical::FigoType{figo, -1};
    spec.pathologies[0].sizeMm = 8.0 * std::sqrt(3.0);
    return spec;
}

/// The body with an 8 mm cube of myoma tets sunk `depthMm` (its centre) below the posterior endometrium; the
/// cavity faces above it are draped over it (pathology label 1) when `draped`. The cube's top `liningMm` (whole 1 mm
/// cells) is a tet layer of the endometrium's region over the myoma, as the scene's tissue layers lay it.
MeasuredDescriptors cubeMyoma(double depthMm, bool draped, int askedFigo, double liningMm = 0.0) {
    SyntheticBody b = syntheticBody();
    const auto [seat, normal] = posteriorSeat(b);
    const Vec3 centre = seat - normal * depthMm;
    if (draped) {
        auto& over = b.boundary.faceLabels[merge::kPathologyLabel];
        const auto& tissue = b.boundary.faceLabels.at(clinical::kSurfaceTissueLabel);
        for (std::size_t f = 0; f < b.boundary.triangles.size(); ++f) {
            const auto& t = b.boundary.triangles[f];
            const Vec3 c =
                (b.boundary.points[static_cast<std::size_t>(t[0])] + b.boundary.points[static_cast<std::size_t>(t[1])] +
                 b.boundary.points[static_cast<std::size_t>(t[2])]) /
                3.0;
            const Vec3 d = c - seat;
            if (tissue[f] == clinical::labelValue(clinical::SurfaceTissue::Endometrium) &&
                norm(d - normal * dot(d, normal)) < 6.0 && std::abs(dot(d, normal)) < 3.0)
                over[f] = 1;
        }
    }
    TetMesh tets = tetCube(centre, normal, 8.0, 8, pathologyRegion(0));
    for (std::size_t t = 0; t < tets.tets.size(); ++t) {
        Vec3 c;
        for (const auto v : tets.tets[t])
            c += tets.points[static_cast<std::size_t>(v)] * 0.25;
        if (dot(c - centre, normal) > 4.0 - liningMm)
            tets.regions[t] = kEndometriumRegion;
    }
    return clinicalDescriptors(cubeMyomaCase(askedFigo), b.organ.mesh, b.organ.layout, tets, b.boundary);
}

bool hasWarning(const MeasuredDescriptors& m, const std::string& text) {
    for (const auto& w : m.warnings)
        if (w.find(text) != std::string::npos)
            return true;
    return false;
}

} // namespace

TEST(Assembly, OrganDimensionsOfAnUnchangedBodyAreTheGeneratorsOwn) {
    const auto& b = syntheticBody();
    scene::CaseSpec spec = scene::defaultCase();
    spec.pathologies.clear();
    const auto m = clinicalDescriptors(spec, b.organ.mesh, b.organ.layout, TetMesh{}, b.boundary);
    const auto d = anatomy::measureUterus(b.organ.mesh, b.organ.layout);
    ASSERT_TRUE(d.ok());
    EXPECT_TRUE(m.warnings.empty()) << m.warnings.front();
    const auto& o = m.clinical.organ;
    EXPECT_NEAR(o.lengthMm, d->lengthMm, 0.01 * d->lengthMm);
    EXPECT_NEAR(o.widthMm, d->widthMm, 0.01 * d->widthMm);
    EXPECT_NEAR(o.apMm, d->apDepthMm, 0.01 * d->apDepthMm);
    EXPECT_NEAR(o.cavityLengthMm, d->cavityLengthMm, 0.02 * d->cavityLengthMm);
    EXPECT_NEAR(o.cavityWidthMm, d->cavityWidthMm, 0.02 * d->cavityWidthMm);
    EXPECT_NEAR(o.uterineVolumeMl, anatomy::ellipsoidVolumeMl(o.lengthMm, o.widthMm, o.apMm), 1e-9);
}

// A user's shape model has a template layout of its own: the organ is measured with it, not with the default one
// (before, such an organ got zero dimensions and a warning).
TEST(Assembly, OrganDimensionsAreMeasuredWithTheModelsOwnTemplateLayout) {
    anatomy::TemplateLayout layout;
    layout.around = 32;
    layout.outerRings = 30;
    ASSERT_NE(layout.vertexCount(), anatomy::TemplateLayout{}.vertexCount());
    auto organ = anatomy::generateUterus(anatomy::UterusShapeParams{}, layout);
    ASSERT_TRUE(organ.ok()) << organ.error().message();
    scene::CaseSpec spec = scene::defaultCase();
    spec.pathologies.clear();
    const auto m = clinicalDescriptors(spec, organ->mesh, layout, TetMesh{}, organ->mesh);
    const auto d = anatomy::measureUterus(organ->mesh, layout);
    ASSERT_TRUE(d.ok()) << d.error().message();
    for (const auto& w : m.warnings)
        EXPECT_EQ(w.find("were not measured"), std::string::npos) << w;
    EXPECT_NEAR(m.clinical.organ.lengthMm, d->lengthMm, 0.01 * d->lengthMm);
    EXPECT_NEAR(m.clinical.organ.widthMm, d->widthMm, 0.01 * d->widthMm);
    EXPECT_GT(m.clinical.organ.cavityLengthMm, 0.0);
}

TEST(Assembly, OrganDimensionsFollowTheFinalBodyNotTheOrganItGrewFrom) {
    // The final body 10 % larger than the organ about the external os (the organ frame's origin). The organ's
    // vertices follow it along their normals (anatomy::measureBody), which is how a pathology's push moves a wall:
    // the outer dimensions measure 10 % more to 1 %; the small, curved cavity moves along its wall as well, which
    // normals do not follow, and measures 7 % (width) and 18 % (length) more.
    const auto& b = syntheticBody();
    SurfaceMesh larger = b.boundary;
    for (auto& p : larger.points)
        p = p * 1.1;
    scene::CaseSpec spec = scene::defaultCase();
    spec.pathologies.clear();
    const auto m = clinicalDescriptors(spec, b.organ.mesh, b.organ.layout, TetMesh{}, larger);
    const auto d = anatomy::measureUterus(b.organ.mesh, b.organ.layout);
    ASSERT_TRUE(d.ok());
    const auto& o = m.clinical.organ;
    EXPECT_NEAR(o.lengthMm, 1.1 * d->lengthMm, 0.01 * d->lengthMm);
    EXPECT_NEAR(o.widthMm, 1.1 * d->widthMm, 0.01 * d->widthMm);
    EXPECT_NEAR(o.apMm, 1.1 * d->apDepthMm, 0.01 * d->apDepthMm);
    EXPECT_NEAR(o.cavityLengthMm, 1.1 * d->cavityLengthMm, 0.1 * d->cavityLengthMm);
    EXPECT_GT(o.cavityLengthMm, 1.04 * d->cavityLengthMm);
    EXPECT_NEAR(o.cavityWidthMm, 1.1 * d->cavityWidthMm, 0.05 * d->cavityWidthMm);
    EXPECT_GT(o.cavityWidthMm, 1.04 * d->cavityWidthMm);
    EXPECT_NEAR(o.uterineVolumeMl, 1.331 * d->ellipsoidVolumeMl, 0.03 * d->ellipsoidVolumeMl);
}

// A template vertex that finds no body surface along its normal keeps the displaced organ's position: never silently.
TEST(Assembly, NamesTheTemplateVerticesThatFoundNoBodySurface) {
    const auto& b = syntheticBody();
    scene::CaseSpec spec = scene::defaultCase();
    spec.pathologies.clear();
    SurfaceMesh far = b.boundary; // twice the organ about the external os: the fundus lies far beyond 20 mm
    for (auto& p : far.points)
        p = p * 2.0;
    const auto m = clinicalDescriptors(spec, b.organ.mesh, b.organ.layout, TetMesh{}, far);
    bool named = false;
    for (const auto& w : m.measurementWarnings)
        named =
            named || (w.rfind("organ: ", 0) == 0 && w.find("found no body surface within 20 mm") != std::string::npos);
    EXPECT_TRUE(named);
    // On the organ itself every vertex finds its surface: no such warning.
    const auto same = clinicalDescriptors(spec, b.organ.mesh, b.organ.layout, TetMesh{}, b.boundary);
    EXPECT_TRUE(same.measurementWarnings.empty());
}

TEST(Assembly, DescriptorsOfTheCaseAskWarnWhenTheBodyDiffers) {
    const auto& b = syntheticBody();
    scene::CaseSpec spec = scene::defaultCase();
    spec.pathologies.clear();
    const auto d = anatomy::measureUterus(b.organ.mesh, b.organ.layout);
    ASSERT_TRUE(d.ok());
    spec.anatomy.dimensions.lengthMm = d->lengthMm;     // as measured: no warning
    spec.anatomy.dimensions.widthMm = 1.3 * d->widthMm; // beyond the tolerance
    const auto m = clinicalDescriptors(spec, b.organ.mesh, b.organ.layout, TetMesh{}, b.boundary);
    ASSERT_EQ(m.warnings.size(), 1u);
    EXPECT_EQ(m.warnings[0].rfind("organ: asked width ", 0), 0u) << m.warnings[0];
}

TEST(Assembly, AMyomaStandingAQuarterIntoTheCavityMeasuresFigo2) {
    // Centre 2 mm below the endometrium: a quarter of the 8 mm cube stands beyond the wall's surface.
    const auto m = cubeMyoma(2.0, true, 2);
    ASSERT_EQ(m.clinical.pathologies.size(), 1u);
    const auto& p = m.clinical.pathologies[0];
    ASSERT_TRUE(p.figo && p.lasmar);
    EXPECT_EQ(p.figo->toString(), "2");
    EXPECT_NEAR(p.sizeMm, 8.0 * std::sqrt(3.0), 1e-6);
    EXPECT_NEAR(p.volumeMl, 0.512, 1e-6);
    EXPECT_EQ(p.lasmar->size, 0);
    EXPECT_EQ(p.lasmar->penetration, 2);
    EXPECT_EQ(p.lasmar->topography, 1);
    EXPECT_EQ(p.regionId, 4);
    EXPECT_EQ(p.location, "left-lateral");
    EXPECT_FALSE(hasWarning(m, "FIGO")) << m.warnings.front();
}

TEST(Assembly, AMyomaMostlyInTheCavityMeasuresFigo1) {
    const auto m = cubeMyoma(-2.0, true, 2); // three quarters beyond the endometrium
    const auto& p = m.clinical.pathologies.at(0);
    ASSERT_TRUE(p.figo);
    EXPECT_EQ(p.figo->toString(), "1");
    EXPECT_TRUE(hasWarning(m, "myoma-1: asked FIGO 2, the final body measures FIGO 1"));
}

TEST(Assembly, AMyomaUnderTheEndometriumMeasuresFigo3AndIsReported) {
    // Its top 0.5 mm under the cavity's surface, nothing draped; the cube's top millimetre is the lining.
    const auto m = cubeMyoma(4.5, false, 2, 1.0);
    const auto& p = m.clinical.pathologies.at(0);
    ASSERT_TRUE(p.figo);
    EXPECT_EQ(p.figo->toString(), "3");
    EXPECT_TRUE(hasWarning(m, "myoma-1: asked FIGO 2, the final body measures FIGO 3"));
}

// FIGO 3 against 4 is contact with the endometrium as the tets have it (the layer is laid after placement), not a
// distance to the cavity's surface: a myoma 2.5 mm deep (beyond the 1 mm tolerance) that borders the lining's tets is
// FIGO 3; one 0.5 mm deep with no lining tet against it is FIGO 4.
TEST(Assembly, Figo3Against4IsContactWithTheEndometriumsTets) {
    const auto bordered = cubeMyoma(4.5, false, 4, 2.0); // its top 2.5 mm deep under a 2 mm lining of tets
    ASSERT_TRUE(bordered.clinical.pathologies.at(0).figo);
    EXPECT_EQ(bordered.clinical.pathologies[0].figo->toString(), "3");
    EXPECT_TRUE(hasWarning(bordered, "myoma-1: asked FIGO 4, the final body measures FIGO 3"));
    const auto clear = cubeMyoma(4.5, false, 4); // its top 0.5 mm deep, no lining tet
    ASSERT_TRUE(clear.clinical.pathologies.at(0).figo);
    EXPECT_EQ(clear.clinical.pathologies[0].figo->toString(), "4");
    EXPECT_FALSE(hasWarning(clear, "FIGO"));
}

TEST(Assembly, AMyomaDeepInTheWallMeasuresFigo4) {
    const auto m = cubeMyoma(7.0, false, 4); // 3 mm under the endometrium
    const auto& p = m.clinical.pathologies.at(0);
    ASSERT_TRUE(p.figo);
    EXPECT_EQ(p.figo->toString(), "4");
    EXPECT_FALSE(hasWarning(m, "FIGO"));
}

TEST(Assembly, DescriptorWarningsNameEveryValueBeyondTheTolerance) {
    scene::CaseSpec spec = cubeMyomaCase(2);
    spec.pathologies[0].sizeMm = 20.0;
    spec.anatomy.dimensions.lengthMm = 70.0;
    spec.anatomy.dimensions.widthMm = 50.0;
    scene::ClinicalDescriptors measured;
    measured.organ.lengthMm = 72.0; // within 10 %
    measured.organ.widthMm = 40.0;  // beyond
    scene::PathologyDescriptor p;
    p.id = "myoma-1";
    p.sizeMm = 17.4;
    p.figo = clinical::FigoType{3, -1};
    measured.pathologies.push_back(p);
    const auto w = descriptorWarnings(spec, measured);
    ASSERT_EQ(w.size(), 3u);
    EXPECT_EQ(w[0], "organ: asked width 50.0 mm, the final body measures 40.0 mm");
    EXPECT_EQ(w[1], "myoma-1: asked size 20.0 mm, the final body measures 17.4 mm");
    EXPECT_EQ(w[2], "myoma-1: asked FIGO 2, the final body measures FIGO 3");
    const auto table = descriptorTable(spec, measured);
    EXPECT_NE(table.find("myoma-1 FIGO"), std::string::npos);
    EXPECT_NE(table.find("17.4"), std::string::npos);
}

TEST(Assembly, QualityCarriesEveryFigureOfTheReport) {
    meshing::QualityReport q;
    q.vertexCount = 10;
    q.tetCount = 20;
    q.meanRadiusRatio = 0.9;
    q.minDihedralDeg = 17.0;
    q.radiusRatioHistogram[9] = 20;
    q.sliverCount = 1;
    q.hasReference = true;
    q.hausdorffDistance = 0.5;
    q.hausdorffRelative = 0.01;
    q.volumeError = 0.002;
    const auto m = qualityOf(q);
    EXPECT_EQ(m.vertexCount, 10u);
    EXPECT_EQ(m.tetCount, 20u);
    EXPECT_EQ(m.meanRadiusRatio, 0.9);
    EXPECT_EQ(m.minDihedralDeg, 17.0);
    ASSERT_EQ(m.radiusRatioHistogram.size(), 10u);
    EXPECT_EQ(m.radiusRatioHistogram[9], 20u);
    EXPECT_EQ(m.minDihedralHistogram.size(), 9u);
    EXPECT_EQ(m.sliverCount, 1u);
    EXPECT_TRUE(m.hasReference);
    EXPECT_EQ(m.hausdorffDistanceMm, 0.5);
    EXPECT_EQ(m.hausdorffRelative, 0.01);
    EXPECT_EQ(m.volumeError, 0.002);
}

TEST(Assembly, ToolVersionsNameEveryLibraryThatShapesTheScene) {
    const auto versions = toolVersionsFor(twoPathologyCase());
    for (const char* library : {"hysteroscene", "compiler", "cgal", "eigen", "hdf5", "minizip", "nlohmann-json",
                                "opencv", "openimageio", "tinygltf", "vtk", "zlib"}) {
        const auto it = versions.find(library);
        ASSERT_NE(it, versions.end()) << library;
        EXPECT_FALSE(it->second.empty()) << library;
        EXPECT_LE(it->second.size(), 64u) << library;
    }
    EXPECT_EQ(versions.at("hysteroscene"), HS_VERSION);
    EXPECT_EQ(versions.count("tetgen"), 0u) << "the default case meshes with the particle mesher";
    EXPECT_EQ(toolVersionsFor(twoPathologyCase()), versions) << "one build, the same versions every time";
}

TEST(Assembly, ToolVersionsNameTetGenWhenTheCaseMeshesWithIt) {
    scene::CaseSpec spec = twoPathologyCase();
    spec.meshing.method = scene::MeshingMethod::TetGen;
    if (!meshing::methodAvailable(meshing::MeshMethod::TetGen))
        GTEST_SKIP() << "this build has no TetGen";
    const auto versions = toolVersionsFor(spec);
    ASSERT_EQ(versions.count("tetgen"), 1u);
    EXPECT_FALSE(versions.at("tetgen").empty());
}

TEST(Assembly, SupportLabelMarksTheTetsWithinTheCervixLengthOfTheExternalOs) {
    const auto label = supportLabel(threeTets(), 1.8); // tets 0 and 1 reach at most sqrt(3) from the origin
    EXPECT_EQ(label.name, scene::kSupportLabel);
    EXPECT_EQ(label.kind, scene::LabelKind::Other);
    EXPECT_EQ(label.element, scene::LabelElement::Tet);
    EXPECT_EQ(label.indices, (std::vector<std::int32_t>{0, 1}));
    EXPECT_EQ(supportLabel(threeTets(), 1.0).indices, (std::vector<std::int32_t>{0}));
    EXPECT_TRUE(supportLabel(threeTets(), 0.5).indices.empty());
}
