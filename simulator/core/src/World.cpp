#include "hs/sim/World.h"

#include "Bvh.h"
#include "Fluid.h"
#include "Tissue.h"
#include "hs/core/TetEmbedding.h"
#include "hs/scene/ScenePackage.h"
#include "hs/scene/Sha256.h"

#include <algorithm>
#include <atomic>
#include <cmath>
#include <cstdio>
#include <map>
#include <mutex>
#include <string>

namespace hs::sim {

namespace {

constexpr double kPi = 3.14159265358979323846;
constexpr double kDeg = kPi / 180.0;
constexpr double kMm = 1e-3;

/// The tip force at which the wall gives way, N (docs/simulator.md, "Perforation": an assumption of this project;
/// blunt-instrument puncture of soft tissue takes a few newtons).
constexpr double kPerforationForceN = 5.0;
/// ... held this long, s: the wall gives way under a sustained push, not a tap.
constexpr double kPerforationHoldS = 0.3;
/// Total stiffness of what holds the corpus besides the cervix (broad and round ligaments, the organs around it),
/// N/m, spread over the serosa's free points by area (docs/simulator.md, "Boundary").
constexpr double kSurroundStiffnessNPerM = 1000.0;
/// The portio: the support's points this close to the external os along the canal are fixed, mm (about the vaginal
/// part of a 25-30 mm cervix; docs/references.md [CervixParity]).
constexpr double kHeldPortioMm = 12.0;
/// Total stiffness of the cardinal and uterosacral ligaments on the supravaginal cervix, N/m, spread over its points.
constexpr double kLigamentStiffnessNPerM = 3000.0;
/// The shaft's spheres up to this far beyond the internal os (along the canal) do not collide: the canal wraps the
/// sheath, mm.
constexpr double kCanalContactFreeMm = 2.0;
/// The shaft is checked for contact from its tip back to this far behind the pivot, mm.
constexpr double kShaftCheckBehindPivotMm = 10.0;
/// The exploration script: the tip's speed inside the cavity, mm/s of its plan (scaled to the duration asked for),
/// the clearance from the walls it looks for, mm, and how far beside the cavity's axis it looks for it, mm.
constexpr double kScriptSpeedMmPerS = 10.0;
constexpr double kScriptClearanceMm = 3.0;
constexpr double kMiddleSearchMm = 8.0;
constexpr double kMiddleStepMm = 1.0;
/// The clearance of a point is looked for this far, mm: more than half the wall's thickness, so a point inside the
/// wall finds the wall's surface and its side.
constexpr double kClearanceReachMm = 12.0;
/// Contact candidates are gathered this far beyond the scope's radius, mm (covers one step's motion).
constexpr double kContactMarginMm = 1.5;
/// Visibility is updated every kVisibilityPeriodS for a tenth of the faces (all of them every 50 ms), and the
/// series sampled every kSeriesPeriodS.
constexpr double kVisibilityPeriodS = 0.005;
constexpr std::size_t kVisibilitySlices = 10;
constexpr double kSeriesPeriodS = 0.1;
/// A contact ends after this long without touching (so a sliding scope counts once), s.
constexpr double kContactGapS = 0.05;
/// A pathology's faces: cavity faces this close to the visual faces over it, mm.
constexpr double kPathologyReachMm = 3.0;
/// The fundus zone: cavity faces this close to the fundus point, mm.
constexpr double kFundusZoneMm = 10.0;
/// The pressure at which the load is calibrated against the hydrometra curve, kPa (60 mmHg).
constexpr double kCalibrationPressureKpa = 8.0;
constexpr double kCalibrationSeconds = 0.4; ///< s of settling per round (the opening settles in about 0.2 s)
constexpr int kCalibrationRounds = 4;

struct Zone {
    std::string name;
    std::vector<std::int32_t> faces;
    double area = 0.0;
};

struct Ostium {
    std::string name;
    TetEmbedding at; ///< the centre of its faces on the visual surface, bound to the simulation mesh
    Vec3 normal;     ///< into the cavity, at rest
    int target = -1; ///< index in metrics.targets
};
/// Ostium faces spread wider than this across the cavity are two ostia, mm (the intercornual distance is 41-47 mm;
/// docs/references.md [FundusMRI]).
constexpr double kOstiumSeparationMm = 15.0;
/// The coarse simulation mesh rounds the cornual recess where an ostium opens: the ostium's centre may lie this far
/// behind the contact surface and still be seen, mm.
constexpr double kOstiumOcclusionSlackMm = 2.5;

} // namespace

struct World::Impl {
    WorldOptions options;
    scene::Scene scene;
    std::string sha;
    scene::ScopeLandmarks landmarks;
    ScopeFrame frame;
    TetMesh simRest;
    SurfaceMesh contactSurface; ///< points: the simulation mesh's (mm, at rest); triangles in its point indices
    std::shared_ptr<const std::vector<Triangle>> triangles;
    std::vector<char> faceCavity;   ///< a cavity-side face (the scope sees it, the fluid presses on it)
    std::vector<char> faceInCavity; ///< beyond the internal os (the exploration's surface)
    std::vector<double> faceArea;   ///< mm^2 at rest
    std::vector<std::int32_t> faceRegion;
    std::vector<int> facePathology; ///< index into scene.clinical.pathologies, -1 none
    std::vector<SurfaceSample> faceUnrolled;
    std::vector<Zone> zones;
    std::vector<Ostium> ostia;
    Vec3 cavityAxis, cavityAnterior, cavityLeft;
    double cavityArea = 0.0;

    detail::TissueModel tissue;
    detail::TriangleBvh bvh;
    detail::FluidModel fluid;
    double pressureGain = 1.0;
    double restCavityMl = 0.0;
    /// The points as the calibration left them: the cavity opened at the calibration pressure (scripts plan with it).
    std::vector<Vec3> openPointsMm;
    double contactStiffnessNPerMm = 0.1;

    std::vector<Vec3> pointsMm;
    WorldState state;
    TrialMetrics metrics;
    std::vector<SeriesPoint> series;
    std::vector<char> faceSeen;
    std::uint64_t samplesConsumed = 0;
    std::uint32_t lastButtons = 0;
    bool haveLastTip = false;
    Vec3 lastTip;
    double horizonSum = 0.0;
    double horizonTime = 0.0;
    double lastTouchS = -1.0;
    bool inContact = false;
    double seriesForceN = 0.0;
    double nextVisibilityS = 0.0;
    double nextSeriesS = 0.0;
    int perforationIndex = -1;
    double tipPushS = 0.0;
    std::size_t visibilityRound = 0;

    mutable std::mutex frameMutex;
    std::shared_ptr<const HapticFrame> hapticFrame;

    Status build(Progress& progress);
    void setupSurfaceData();
    void setupTissue();
    void calibrateLoad();
    void pressureForces(double pressureKpa, std::vector<Vec3>& forces) const;
    double cavityVolumeMl(const std::vector<Vec3>& pts) const;
    void physics(const ScopePose& pose, double pressureKpa);
    /// Whether `point` (on `face`, -1: none) is in the view, in focus, facing the lens and not hidden (a hit within
    /// `slackMm` before it does not hide it).
    bool visible(const Vec3& point, const Vec3& normal, std::int32_t face, double slackMm = 0.5) const;
    bool visibleFrom(const ScopePose& pose, const Vec3& point, const Vec3& normal, std::int32_t face,
                     double slackMm) const;
    Vec3 ostiumPoint(const Ostium& o) const;
    bool insideRestHull(const Vec3& p) const;
    /// Signed distance from `p` to the contact surface with the points `pts` (its tree `tree` refitted to them), mm:
    /// positive on the side its faces look to (the cavity, outside the body), negative inside the tissue; `reachMm`
    /// when no face is that close.
    double clearanceMm(const std::vector<Vec3>& pts, const detail::TriangleBvh& tree, const Vec3& p,
                       double reachMm) const;
    /// The least clearance of the scope in `pose` beyond its radius (its tip, and its shaft where it can touch the
    /// wall: beyond the canal), mm; negative where it would press into the wall.
    double scopeClearanceMm(const std::vector<Vec3>& pts, const detail::TriangleBvh& tree, const ScopePose& pose) const;
    void updateVisibility();
    void mark();
    void publishFrame();
    Vec3 faceNormal(std::int32_t f) const;
    Vec3 faceCentre(std::int32_t f) const;
};

namespace {

Vec3 triangleNormal(const std::vector<Vec3>& pts, const Triangle& t) {
    return cross(pts[static_cast<std::size_t>(t[1])] - pts[static_cast<std::size_t>(t[0])],
                 pts[static_cast<std::size_t>(t[2])] - pts[static_cast<std::size_t>(t[0])]);
}

Vec3 triangleCentre(const std::vector<Vec3>& pts, const Triangle& t) {
    return (pts[static_cast<std::size_t>(t[0])] + pts[static_cast<std::size_t>(t[1])] +
            pts[static_cast<std::size_t>(t[2])]) /
           3.0;
}

} // namespace

Vec3 World::Impl::faceNormal(std::int32_t f) const {
    return normalized(triangleNormal(pointsMm, (*triangles)[static_cast<std::size_t>(f)]));
}

double World::Impl::clearanceMm(const std::vector<Vec3>& pts, const detail::TriangleBvh& tree, const Vec3& p,
                                double reachMm) const {
    std::vector<std::int32_t> near;
    tree.near(p, reachMm, near);
    double nearest = reachMm, signedDistance = reachMm, alignment = -1.0;
    for (const std::int32_t f : near) {
        const Triangle& tri = (*triangles)[static_cast<std::size_t>(f)];
        const Vec3 q =
            closestPointOnTriangle(p, pts[static_cast<std::size_t>(tri[0])], pts[static_cast<std::size_t>(tri[1])],
                                   pts[static_cast<std::size_t>(tri[2])])
                .point;
        const double d = distance(p, q);
        if (d > nearest + 1e-9)
            continue;
        // Where the nearest point is an edge or a corner several faces share, the face that looks most squarely at
        // p says on which side p lies.
        const double along = d > 1e-12 ? dot(p - q, normalized(triangleNormal(pts, tri))) / d : 0.0;
        if (d < nearest - 1e-9 || std::abs(along) > alignment) {
            nearest = std::min(nearest, d);
            alignment = std::abs(along);
            signedDistance = along >= 0.0 ? d : -d;
        }
    }
    return signedDistance;
}

double World::Impl::scopeClearanceMm(const std::vector<Vec3>& pts, const detail::TriangleBvh& tree,
                                     const ScopePose& pose) const {
    const double radius = 0.5 * options.scope.diameterMm;
    const double insertion = dot(pose.tipMm - frame.pivotMm, pose.shaft);
    double least = kClearanceReachMm;
    for (double back = 0.0; back <= insertion; back += 2.0 * radius) {
        const Vec3 c = pose.tipMm - pose.shaft * back;
        if (back > 0.0 && dot(c - landmarks.internalOsMm, frame.axis) < kCanalContactFreeMm)
            break; // the shaft in the canal: the canal wraps it
        least = std::min(least, clearanceMm(pts, tree, c, kClearanceReachMm) - radius);
    }
    return least;
}

Vec3 World::Impl::faceCentre(std::int32_t f) const {
    return triangleCentre(pointsMm, (*triangles)[static_cast<std::size_t>(f)]);
}

Status checkWorldOptions(const WorldOptions& o) {
    HS_TRY(checkScopeConfig(o.scope));
    HS_TRY(checkFluidSettings(o.fluid));
    const double ticks = o.stepS * kDeviceRateHz;
    if (!std::isfinite(o.stepS) || o.stepS < 0.001 || o.stepS > 0.02 || std::abs(ticks - std::round(ticks)) > 1e-9)
        return fail(ErrorCode::InvalidInput,
                    "world: stepS must be 0.001-0.02 s and a whole number of 1 ms device ticks");
    if (o.solverIterations < 1 || o.solverIterations > 50)
        return fail(ErrorCode::InvalidInput, "world: solverIterations must be 1-50");
    return {};
}

void World::Impl::setupSurfaceData() {
    // The contact surface: the simulation mesh's boundary, in the mesh's own point indices.
    const SurfaceMesh boundary = extractBoundary(simRest);
    const auto& source = boundary.vertexLabels.at("sourcePoint");
    auto tris = std::make_shared<std::vector<Triangle>>();
    tris->reserve(boundary.faceCount());
    for (const Triangle& t : boundary.triangles)
        tris->push_back({source[static_cast<std::size_t>(t[0])], source[static_cast<std::size_t>(t[1])],
                         source[static_cast<std::size_t>(t[2])]});
    triangles = tris;
    contactSurface.points = simRest.points;
    contactSurface.triangles = *tris;
    const auto& cavityPoints = simRest.pointLabels.at(scene::kCavityPointLabel);
    const std::size_t faces = tris->size();
    faceCavity.assign(faces, 0);
    faceInCavity.assign(faces, 0);
    faceArea.assign(faces, 0.0);
    faceRegion = boundary.faceLabels.at("region");
    facePathology.assign(faces, -1);
    faceUnrolled.assign(faces, {});
    cavityAxis = normalized(landmarks.fundusMm - landmarks.internalOsMm);
    cavityAnterior = perpendicularTo(cavityAxis, frame.anterior);
    cavityLeft = cross(cavityAxis, cavityAnterior);
    if (dot(cavityLeft, frame.left) < 0.0)
        cavityLeft = cavityLeft * -1.0;
    Zone fundus{"fundus", {}, 0.0}, anterior{"anterior", {}, 0.0}, posterior{"posterior", {}, 0.0},
        left{"left", {}, 0.0}, right{"right", {}, 0.0};
    std::vector<std::int32_t> cavityFaceIds;
    std::vector<std::int32_t> cavitySide(faces, 0);
    for (std::size_t f = 0; f < faces; ++f) {
        const Triangle& t = (*tris)[f];
        bool cavity = true;
        for (const std::int32_t v : t)
            cavity = cavity && cavityPoints[static_cast<std::size_t>(v)] == 1;
        faceCavity[f] = cavity ? 1 : 0;
        const Vec3 n = triangleNormal(simRest.points, t);
        faceArea[f] = 0.5 * norm(n);
        const Vec3 c = triangleCentre(simRest.points, t);
        const double along = dot(c - landmarks.internalOsMm, cavityAxis);
        const Vec3 r = c - landmarks.internalOsMm - cavityAxis * along;
        faceUnrolled[f].alongMm = along;
        faceUnrolled[f].aroundDeg = std::atan2(dot(r, cavityLeft), dot(r, cavityAnterior)) / kDeg;
        if (!cavity || dot(c - landmarks.internalOsMm, frame.axis) < 2.0)
            continue;
        faceInCavity[f] = 1;
        const auto fi = static_cast<std::int32_t>(f);
        cavityFaceIds.push_back(fi);
        cavityArea += faceArea[f];
        const Vec3 unit = normalized(n);
        if (distance(c, landmarks.fundusMm) < kFundusZoneMm)
            fundus.faces.push_back(fi);
        const double a = dot(unit, cavityAnterior), l = dot(unit, cavityLeft);
        if (a < -0.5)
            anterior.faces.push_back(fi); // the tissue lies anterior: the anterior wall
        if (a > 0.5)
            posterior.faces.push_back(fi);
        if (l < -0.5)
            left.faces.push_back(fi);
        if (l > 0.5)
            right.faces.push_back(fi);
    }
    for (Zone* z : {&fundus, &anterior, &posterior, &left, &right}) {
        for (const std::int32_t f : z->faces)
            z->area += faceArea[static_cast<std::size_t>(f)];
        zones.push_back(std::move(*z));
    }

    // Ostia: the visual surface's ostium faces, one or two clusters (a pathology may cover an ostium: the scene then
    // has one), each named by its side and its centre bound to the simulation mesh.
    const auto& visual = scene.surface.mesh;
    std::vector<Vec3> ostiumCentres, ostiumNormals;
    std::map<std::string, std::vector<Vec3>> contact;
    for (const auto& label : scene.labels) {
        if (label.element != scene::LabelElement::SurfaceFace)
            continue;
        for (const std::int32_t f : label.indices) {
            if (f < 0 || static_cast<std::size_t>(f) >= visual.faceCount())
                continue;
            const Triangle& vt = visual.triangles[static_cast<std::size_t>(f)];
            const Vec3 c = triangleCentre(visual.points, vt);
            if (label.kind == scene::LabelKind::Ostium) {
                ostiumCentres.push_back(c);
                ostiumNormals.push_back(triangleNormal(visual.points, vt));
            } else if (label.kind == scene::LabelKind::Contact && !label.pathologyId.empty()) {
                contact[label.pathologyId].push_back(c);
            }
        }
    }
    if (!ostiumCentres.empty()) {
        // Two clusters split at the middle of the faces' spread across the cavity, one when they lie together.
        double lo = 1e300, hi = -1e300;
        for (const Vec3& c : ostiumCentres) {
            lo = std::min(lo, dot(c - landmarks.internalOsMm, cavityLeft));
            hi = std::max(hi, dot(c - landmarks.internalOsMm, cavityLeft));
        }
        const bool two = hi - lo > kOstiumSeparationMm;
        Vec3 sums[2] = {{0, 0, 0}, {0, 0, 0}}, normals[2] = {{0, 0, 0}, {0, 0, 0}};
        double counts[2] = {0.0, 0.0};
        for (std::size_t i = 0; i < ostiumCentres.size(); ++i) {
            const int k = two && dot(ostiumCentres[i] - landmarks.internalOsMm, cavityLeft) < 0.5 * (lo + hi) ? 1 : 0;
            sums[k] = sums[k] + ostiumCentres[i];
            normals[k] = normals[k] + ostiumNormals[i];
            counts[k] += 1.0;
        }
        for (int k = 0; k < 2; ++k) {
            if (counts[k] == 0.0 || norm(normals[k]) < 1e-12)
                continue;
            const Vec3 centre = sums[k] / counts[k];
            Ostium o;
            o.name = dot(centre - landmarks.internalOsMm, cavityLeft) >= 0.0 ? "ostium-left" : "ostium-right";
            o.at = embedPoints(simRest, {centre}).front();
            o.normal = normalized(normals[k]);
            if (o.at.tet >= 0)
                ostia.push_back(o);
        }
        std::sort(ostia.begin(), ostia.end(), [](const Ostium& a, const Ostium& b) { return a.name < b.name; });
    }
    // Pathologies: the cavity faces near the visual faces over each.
    for (std::size_t p = 0; p < scene.clinical.pathologies.size(); ++p) {
        const auto it = contact.find(scene.clinical.pathologies[p].id);
        if (it == contact.end())
            continue;
        for (const std::int32_t f : cavityFaceIds) {
            const Vec3 c = triangleCentre(simRest.points, (*tris)[static_cast<std::size_t>(f)]);
            for (const Vec3& q : it->second)
                if (distance(c, q) < kPathologyReachMm) {
                    facePathology[static_cast<std::size_t>(f)] = static_cast<int>(p);
                    break;
                }
        }
    }
    faceSeen.assign(faces, 0);

    for (const Ostium& o : ostia)
        metrics.targets.push_back({o.name, 0.0, false, -1.0});
    for (std::size_t i = 0; i < ostia.size(); ++i)
        ostia[i].target = static_cast<int>(i);
    for (const Zone& z : zones)
        metrics.targets.push_back({z.name, 0.0, false, -1.0});
    for (const auto& p : scene.clinical.pathologies)
        metrics.pathologies.push_back({p.id, std::string(clinical::toString(p.kind)), false, false, -1.0});
}

void World::Impl::setupTissue() {
    const std::size_t n = simRest.points.size();
    std::vector<detail::TetMaterial> materials(simRest.tetCount());
    const auto& ids = simRest.tetLabels.at(scene::kMaterialLabel);
    for (std::size_t t = 0; t < simRest.tetCount(); ++t) {
        const auto& m = scene.materials[static_cast<std::size_t>(ids[t])].material;
        materials[t] = {m.youngsModulusKpa * 1e3, m.poissonRatio, m.densityKgPerM3};
    }
    // The held cervix: its vaginal part (the portio, gripped by the vagina and the tenaculum) is fixed; the rest of it
    // up to the internal os hangs in the cardinal and uterosacral ligaments, stiff springs that let the scope
    // straighten the canal a little (docs/simulator.md, "Boundary").
    std::vector<bool> fixed(n, false);
    std::vector<bool> ligament(n, false);
    const auto& support = simRest.tetLabels.at(scene::kSupportTetLabel);
    for (std::size_t t = 0; t < simRest.tetCount(); ++t)
        if (support[t] == 1)
            for (const std::int32_t p : simRest.tets[t]) {
                const auto pi = static_cast<std::size_t>(p);
                if (dot(simRest.points[pi] - frame.pivotMm, frame.axis) < kHeldPortioMm)
                    fixed[pi] = true;
                else
                    ligament[pi] = true;
            }
    // Tethers on the serosa's free points, by area.
    std::vector<double> pointArea(n, 0.0);
    double total = 0.0;
    for (std::size_t f = 0; f < triangles->size(); ++f) {
        if (faceCavity[f])
            continue;
        for (const std::int32_t v : (*triangles)[f])
            if (!fixed[static_cast<std::size_t>(v)]) {
                pointArea[static_cast<std::size_t>(v)] += faceArea[f] / 3.0;
                total += faceArea[f] / 3.0;
            }
    }
    std::vector<std::pair<std::int32_t, double>> tethers;
    std::size_t ligamentPoints = 0;
    for (std::size_t i = 0; i < n; ++i)
        ligamentPoints += ligament[i] && !fixed[i] ? 1 : 0;
    for (std::size_t i = 0; i < n; ++i) {
        if (fixed[i])
            continue;
        double k = pointArea[i] > 0.0 ? kSurroundStiffnessNPerM * pointArea[i] / total : 0.0;
        if (ligament[i])
            k += kLigamentStiffnessNPerM / static_cast<double>(ligamentPoints);
        if (k > 0.0)
            tethers.emplace_back(static_cast<std::int32_t>(i), k);
    }
    tissue.build(simRest, materials, fixed, tethers);
    // The wall against the tip: a flat punch of the scope's radius on a half-space of the wall's modulus,
    // k = 2 E a / (1 - nu^2) (Johnson, Contact Mechanics, 1985, eq. 3.36 for a rigid flat punch).
    double e = 30e3, nu = 0.47;
    for (const auto& m : scene.materials)
        if (m.tissue == clinical::Tissue::Endometrium || m.tissue == clinical::Tissue::Myometrium) {
            e = m.material.youngsModulusKpa * 1e3;
            nu = m.material.poissonRatio;
        }
    contactStiffnessNPerMm = 2.0 * e * (options.scope.diameterMm * 0.5 * kMm) / (1.0 - nu * nu) * kMm;
}

double World::Impl::cavityVolumeMl(const std::vector<Vec3>& pts) const {
    // Volume between the cavity's faces and the external os (the canal's open end): the faces face into the cavity.
    const Vec3 o = landmarks.externalOsMm;
    double v = 0.0;
    for (std::size_t f = 0; f < triangles->size(); ++f) {
        if (!faceCavity[f])
            continue;
        const Triangle& t = (*triangles)[f];
        const Vec3 a = pts[static_cast<std::size_t>(t[0])] - o, b = pts[static_cast<std::size_t>(t[1])] - o,
                   c = pts[static_cast<std::size_t>(t[2])] - o;
        v -= dot(a, cross(b, c)) / 6.0;
    }
    return v / 1000.0;
}

void World::Impl::pressureForces(double pressureKpa, std::vector<Vec3>& forces) const {
    forces.assign(pointsMm.size(), Vec3{0.0, 0.0, 0.0});
    if (pressureKpa <= 0.0)
        return;
    const double pa = pressureKpa * 1e3 * pressureGain;
    for (std::size_t f = 0; f < triangles->size(); ++f) {
        if (!faceCavity[f])
            continue;
        const Triangle& t = (*triangles)[f];
        // Area vector in m^2 (half the cross product), pointing into the cavity; the fluid pushes the wall back.
        const Vec3 areaVector = triangleNormal(pointsMm, t) * (0.5 * kMm * kMm);
        const Vec3 force = areaVector * (-pa / 3.0);
        for (const std::int32_t v : t)
            forces[static_cast<std::size_t>(v)] = forces[static_cast<std::size_t>(v)] + force;
    }
}

void World::Impl::calibrateLoad() {
    // The wall's opening under pressure depends on the solver and the boundary, and is not linear in the load (a slit
    // cavity opens more easily once it has opened). Scale the load so that the cavity takes the hydrometra curve's
    // volume at the calibration pressure: a few fixed-point rounds of gain *= target / opened, each settling the
    // tissue under the load (docs/simulator.md, "Distension").
    restCavityMl = cavityVolumeMl(pointsMm);
    const double target = fluid.complianceMlPerKpa() * kCalibrationPressureKpa;
    pressureGain = 1.0;
    const auto steps = static_cast<int>(std::round(kCalibrationSeconds / options.stepS));
    std::vector<Vec3> forces;
    std::vector<detail::ContactPair> none;
    for (int round = 0; round < kCalibrationRounds; ++round) {
        for (int i = 0; i < steps; ++i) {
            pressureForces(kCalibrationPressureKpa, forces);
            tissue.step(options.stepS, options.solverIterations, forces, none, *triangles);
            tissue.pointsMm(pointsMm);
        }
        const double opened = cavityVolumeMl(pointsMm) - restCavityMl;
        if (!(opened > 1e-6))
            break;
        pressureGain = std::clamp(pressureGain * target / opened, 0.01, 50.0);
    }
    openPointsMm = pointsMm;
    // Back to rest for the trial.
    setupTissue();
    tissue.pointsMm(pointsMm);
}

Status World::Impl::build(Progress& progress) {
    if (!scene.simulation)
        return fail(ErrorCode::InvalidInput, "the scene has no simulation mesh (a package of schema version 1): "
                                             "regenerate it with this version's hysteroscene-cli generate");
    HS_TRY(scene::checkScene(scene));
    auto lm = scene::findScopeLandmarks(scene);
    if (!lm)
        return fail(lm.error().code, "scope landmarks: " + lm.error().detail);
    landmarks = *lm;
    auto f = scopeFrame(landmarks);
    if (!f)
        return f.failure();
    frame = *f;
    simRest = scene.simulation->tets;
    HS_TRY(progress.check("world"));
    setupSurfaceData();
    setupTissue();
    tissue.pointsMm(pointsMm);
    bvh.build(*triangles, pointsMm);
    double compliance = 0.0;
    if (scene.hydrometra.pressureKpa > 0.0 && scene.hydrometra.cavityVolumeMl > 0.0)
        compliance = scene.hydrometra.cavityVolumeMl / scene.hydrometra.pressureKpa;
    else
        compliance = scene::hydrometraVolumeAtFitPressureMl(std::max(scene.hydrometra.uterineVolumeMl, 1.0)) /
                     scene::kHydrometraFitPressureKpa;
    fluid.reset(options.fluid, compliance);
    progress.report("world", 0.3);
    calibrateLoad();
    HS_TRY(progress.check("world"));
    state.scope = scopePose(frame, options.scope, DeviceSample{});
    state.fluid = fluid.state();
    publishFrame();
    progress.report("world", 1.0);
    return {};
}

bool World::Impl::insideRestHull(const Vec3& p) const {
    // Ray parity against the serosa at rest (the cavity's faces close the hull at the os only): odd inside.
    int crossings = 0;
    for (std::size_t f = 0; f < triangles->size(); ++f) {
        if (faceCavity[f])
            continue;
        const Triangle& t = (*triangles)[f];
        double th = 0.0, u = 0.0, v = 0.0;
        if (hs::rayTriangle(p, cavityAxis, simRest.points[static_cast<std::size_t>(t[0])],
                            simRest.points[static_cast<std::size_t>(t[1])],
                            simRest.points[static_cast<std::size_t>(t[2])], 0.0, th, u, v))
            ++crossings;
    }
    return crossings % 2 == 1;
}

Vec3 World::Impl::ostiumPoint(const Ostium& o) const {
    const Tet& t = simRest.tets[static_cast<std::size_t>(o.at.tet)];
    Vec3 p{0.0, 0.0, 0.0};
    for (std::size_t k = 0; k < 4; ++k)
        p = p + pointsMm[static_cast<std::size_t>(t[k])] * o.at.weights[k];
    return p;
}

bool World::Impl::visible(const Vec3& point, const Vec3& normal, std::int32_t face, double slackMm) const {
    return visibleFrom(state.scope, point, normal, face, slackMm);
}

bool World::Impl::visibleFrom(const ScopePose& pose, const Vec3& point, const Vec3& normal, std::int32_t face,
                              double slackMm) const {
    const Vec3 v = point - pose.tipMm;
    const double d = norm(v);
    if (d < scopeFocusNearMm(options.scope) || d > scopeFocusFarMm(options.scope))
        return false;
    const Vec3 u = v / d;
    if (std::acos(std::clamp(dot(u, pose.direction), -1.0, 1.0)) > 0.5 * scopeFieldOfViewDeg(options.scope) * kDeg)
        return false;
    if (dot(normal, u) >= 0.0) // seen from behind
        return false;
    double t = 0.0, a = 0.0, b = 0.0;
    const std::int32_t hit = bvh.raycast(pointsMm, pose.tipMm, u, d + 0.5, t, a, b);
    return hit < 0 || hit == face || t >= d - slackMm;
}

void World::Impl::updateVisibility() {
    if (state.fluid.redOut >= 1.0 || state.fluid.turbidity >= 0.9)
        return; // nothing is seen through closed walls or opaque fluid
    // A tenth of the faces each time, in turn (an even load per step): each face is checked every ten updates.
    const std::size_t slice = visibilityRound++ % kVisibilitySlices;
    for (std::size_t f = slice; f < triangles->size(); f += kVisibilitySlices) {
        if (!faceInCavity[f] || faceSeen[f])
            continue;
        const auto fi = static_cast<std::int32_t>(f);
        if (visible(faceCentre(fi), faceNormal(fi), fi)) {
            faceSeen[f] = 1;
            const int p = facePathology[f];
            if (p >= 0)
                metrics.pathologies[static_cast<std::size_t>(p)].seen = true;
        }
    }
    double seenArea = 0.0;
    for (std::size_t f = 0; f < triangles->size(); ++f)
        if (faceSeen[f])
            seenArea += faceArea[f];
    metrics.cavitySurfaceVisualizedPercent = cavityArea > 0.0 ? 100.0 * seenArea / cavityArea : 0.0;
    for (const Ostium& o : ostia) {
        ExplorationTarget& target = metrics.targets[static_cast<std::size_t>(o.target)];
        if (target.seen)
            continue;
        if (visible(ostiumPoint(o), o.normal, -1, kOstiumOcclusionSlackMm)) {
            target.seen = true;
            target.visualizedPercent = 100.0;
            target.firstSeenS = state.timeS;
        }
    }
    for (std::size_t z = 0; z < zones.size(); ++z) {
        ExplorationTarget& target = metrics.targets[ostia.size() + z];
        double area = 0.0;
        for (const std::int32_t f : zones[z].faces)
            if (faceSeen[static_cast<std::size_t>(f)])
                area += faceArea[static_cast<std::size_t>(f)];
        target.visualizedPercent = zones[z].area > 0.0 ? 100.0 * area / zones[z].area : 0.0;
        if (!target.seen && target.visualizedPercent >= kZoneSeenPercent) {
            target.seen = true;
            target.firstSeenS = state.timeS;
        }
    }
}

void World::Impl::mark() {
    const ScopePose& pose = state.scope;
    double t = 0.0, a = 0.0, b = 0.0;
    const std::int32_t hit = bvh.raycast(pointsMm, pose.tipMm, pose.direction, scopeFocusFarMm(options.scope), t, a, b);
    int p = hit >= 0 ? facePathology[static_cast<std::size_t>(hit)] : -1;
    if (p < 0 && hit >= 0) {
        // Near a pathology's faces counts too (the marked point lies on its edge).
        const Vec3 q = pose.tipMm + pose.direction * t;
        for (std::size_t f = 0; f < triangles->size() && p < 0; ++f)
            if (facePathology[f] >= 0 && distance(faceCentre(static_cast<std::int32_t>(f)), q) < kPathologyReachMm)
                p = facePathology[f];
    }
    if (p < 0) {
        ++metrics.falseMarks;
        return;
    }
    PathologyFinding& finding = metrics.pathologies[static_cast<std::size_t>(p)];
    if (!finding.found) {
        finding.found = true;
        finding.seen = true;
        finding.foundS = state.timeS;
    }
}

void World::Impl::physics(const ScopePose& pose, double pressureKpa) {
    std::vector<Vec3> forces;
    pressureForces(pressureKpa, forces);
    // Contact candidates: spheres of the scope's radius along the shaft, against the surface near each.
    const double radius = 0.5 * options.scope.diameterMm;
    const double insertion = dot(pose.tipMm - frame.pivotMm, pose.shaft);
    std::vector<detail::ContactPair> contacts;
    std::vector<std::int32_t> near;
    const Bounds box = bounds(contactSurface);
    const Perforation* perforation =
        perforationIndex >= 0 ? &metrics.perforations[static_cast<std::size_t>(perforationIndex)] : nullptr;
    for (double back = 0.0; back <= insertion + kShaftCheckBehindPivotMm; back += radius) {
        const Vec3 c = pose.tipMm - pose.shaft * back;
        if (c.x < box.min.x - radius || c.y < box.min.y - radius || c.z < box.min.z - radius ||
            c.x > box.max.x + radius || c.y > box.max.y + radius || c.z > box.max.z + radius)
            continue;
        // Through a perforation the scope meets no wall beyond the hole.
        if (perforation && dot(c - perforation->locationMm, pose.shaft) > -2.0 * radius)
            continue;
        // The cervical canal closes round the sheath (it is dilated to it): the shaft meets the wall only beyond the
        // internal os, the tip everywhere (docs/simulator.md, "Collision and contact").
        if (back > 0.0 && dot(c - landmarks.internalOsMm, frame.axis) < kCanalContactFreeMm)
            continue;
        near.clear();
        bvh.near(c, radius + kContactMarginMm, near);
        std::sort(near.begin(), near.end());
        for (const std::int32_t f : near) {
            detail::ContactPair pair;
            pair.triangle = f;
            pair.centre = c * kMm;
            pair.radius = radius * kMm;
            pair.tip = back == 0.0;
            contacts.push_back(pair);
        }
    }
    tissue.step(options.stepS, options.solverIterations, forces, contacts, *triangles);
    tissue.pointsMm(pointsMm);
    bvh.refit(pointsMm);

    // The tissue's force on the scope: the contacts' multipliers over dt^2, along their normals.
    const double dt2 = options.stepS * options.stepS;
    Vec3 total{0.0, 0.0, 0.0}, tip{0.0, 0.0, 0.0};
    double deepest = 0.0;
    Vec3 where = pose.tipMm;
    bool cavityContact = false;
    for (const auto& pair : contacts) {
        if (pair.lambda <= 0.0)
            continue;
        const Vec3 f = pair.normal * (pair.lambda / dt2);
        total = total + f;
        if (pair.tip)
            tip = tip + f;
        if (pair.lambda > deepest) {
            deepest = pair.lambda;
            where = pair.centre / kMm;
        }
        cavityContact = cavityContact || faceInCavity[static_cast<std::size_t>(pair.triangle)];
    }
    ContactState& contact = state.contact;
    contact.forceN = norm(total);
    contact.touching = contact.forceN > 1e-4;
    contact.pointMm = where;
    // Perforation: the wall gives way under the tip.
    tipPushS = norm(tip) > kPerforationForceN ? tipPushS + options.stepS : 0.0;
    // ... or the tip is through the wall's surface (a face of the cavity lies in front of it, over the tip's centre,
    // by more than the scope's radius): the wall tore around it.
    bool through = false;
    Vec3 throughAt = pose.tipMm;
    for (const auto& pair : contacts) {
        if (!pair.tip || !faceInCavity[static_cast<std::size_t>(pair.triangle)])
            continue;
        const Triangle& tri = (*triangles)[static_cast<std::size_t>(pair.triangle)];
        const ClosestPoint closest = closestPointOnTriangle(pose.tipMm, pointsMm[static_cast<std::size_t>(tri[0])],
                                                            pointsMm[static_cast<std::size_t>(tri[1])],
                                                            pointsMm[static_cast<std::size_t>(tri[2])]);
        const Vec3 q = closest.point;
        const bool over = closest.wa > 0.0 && closest.wb > 0.0 && closest.wc > 0.0;
        if (over && dot(pose.tipMm - q, faceNormal(pair.triangle)) < -radius) {
            through = true;
            throughAt = q;
        }
    }
    // ... or the tip is beyond the uterus as it lies at rest (outside its serosa, past the internal os): it has been
    // pushed further than the wall is thick.
    if (!through && dot(pose.tipMm - landmarks.internalOsMm, frame.axis) > 0.0 && !insideRestHull(pose.tipMm))
        through = true;
    if (perforationIndex < 0 && (tipPushS >= kPerforationHoldS || through)) {
        Perforation p;
        p.timeS = state.timeS;
        p.locationMm = through ? throughAt : pose.tipMm;
        p.depthMm = 0.0;
        std::int32_t region = -1;
        double best = 1e300;
        for (const auto& pair : contacts)
            if (pair.tip && pair.lambda > 0.0 && pair.lambda < best * 1e300) {
                region = faceRegion[static_cast<std::size_t>(pair.triangle)];
                best = pair.lambda;
            }
        for (const auto& r : scene.regions)
            if (r.id == region)
                p.region = r.name;
        metrics.perforations.push_back(p);
        perforationIndex = static_cast<int>(metrics.perforations.size()) - 1;
    }
    if (perforationIndex >= 0) {
        Perforation& p = metrics.perforations[static_cast<std::size_t>(perforationIndex)];
        const double depth = dot(pose.tipMm - p.locationMm, pose.shaft);
        p.depthMm = std::max(p.depthMm, depth);
        if (depth < -2.0 * radius)
            perforationIndex = -1; // withdrawn through the hole: a new push is a new perforation
    }
    contact.perforated = perforationIndex >= 0;
    // Contacts with the cavity's wall, counted once per touch.
    if (cavityContact) {
        if (!inContact)
            ++metrics.wallContacts;
        inContact = true;
        lastTouchS = state.timeS;
    } else if (inContact && state.timeS - lastTouchS > kContactGapS) {
        inContact = false;
    }
    if (contact.touching)
        metrics.contactTimeS += options.stepS;
    metrics.peakForceN = std::max(metrics.peakForceN, contact.forceN);
    seriesForceN = std::max(seriesForceN, contact.forceN);
}

void World::Impl::publishFrame() {
    auto f = std::make_shared<HapticFrame>();
    f->step = state.step;
    f->timeS = state.timeS;
    f->pivot = frame;
    f->scope = options.scope;
    f->triangles = triangles;
    f->pointsMm = pointsMm;
    f->contactStiffnessNPerMm = contactStiffnessNPerMm;
    f->perforated = state.contact.perforated;
    std::lock_guard<std::mutex> lock(frameMutex);
    hapticFrame = std::move(f);
}

World::World() : impl_(std::make_unique<Impl>()) {}
World::~World() = default;

Result<std::unique_ptr<World>> World::load(const std::string& packageFolder, const WorldOptions& options,
                                           Progress& progress) {
    HS_TRY(checkWorldOptions(options));
    auto s = scene::readScenePackage(packageFolder);
    if (!s)
        return fail(s.error().code, packageFolder + ": " + s.error().detail);
    if (!s->simulation)
        return fail(ErrorCode::InvalidInput,
                    packageFolder + ": the package has no simulation mesh (schema version 1, simulation.vtu missing); "
                                    "regenerate it with hysteroscene-cli generate");
    auto digest = scene::sha256File(packageFolder + "/" + std::string(scene::kManifestName), 1 << 20);
    if (!digest)
        return fail(digest.error().code, packageFolder + ": " + digest.error().detail);
    auto world = fromScene(std::move(*s), digest->sha256, options, progress);
    if (!world)
        return fail(world.error().code, packageFolder + ": " + world.error().detail);
    return world;
}

Result<std::unique_ptr<World>> World::fromScene(scene::Scene scene, std::string sceneSha256,
                                                const WorldOptions& options, Progress& progress) {
    HS_TRY(checkWorldOptions(options));
    std::unique_ptr<World> world(new World());
    Impl& w = *world->impl_;
    w.options = options;
    w.scene = std::move(scene);
    w.sha = std::move(sceneSha256);
    HS_TRY(w.build(progress));
    return world;
}

std::size_t World::ticksPerStep() const {
    return static_cast<std::size_t>(std::llround(impl_->options.stepS * kDeviceRateHz));
}

Status World::step(const DeviceSample* samples, std::size_t count) {
    Impl& w = *impl_;
    if (count != ticksPerStep())
        return fail(ErrorCode::InvalidInput, "world step: " + std::to_string(count) + " device samples, expected " +
                                                 std::to_string(ticksPerStep()));
    for (std::size_t i = 0; i < count; ++i) {
        if (samples[i].tick != w.samplesConsumed + i)
            return fail(ErrorCode::InvalidInput, "world step: sample tick " + std::to_string(samples[i].tick) +
                                                     ", expected " + std::to_string(w.samplesConsumed + i));
        if (!isValid(samples[i]))
            return fail(ErrorCode::InvalidInput,
                        "world step: sample at tick " + std::to_string(samples[i].tick) + " is out of range");
    }
    const double dt = w.options.stepS;
    bool markPressed = false;
    // Per tick: the tip's path and the buttons.
    for (std::size_t i = 0; i < count; ++i) {
        const DeviceSample& s = samples[i];
        const ScopePose pose = scopePose(w.frame, w.options.scope, s);
        if (s.insertionMm > 0.0) {
            if (w.haveLastTip)
                w.metrics.pathLengthMm += distance(pose.tipMm, w.lastTip);
            w.lastTip = pose.tipMm;
            w.haveLastTip = true;
        } else {
            w.haveLastTip = false;
        }
        if ((s.buttons & kButtonMark) && !(w.lastButtons & kButtonMark))
            markPressed = true;
        w.lastButtons = s.buttons;
    }
    const DeviceSample& last = samples[count - 1];
    w.samplesConsumed += count;
    w.state.sample = last;
    w.state.scope = scopePose(w.frame, w.options.scope, last);
    w.fluid.step(dt, last.inflow, last.outflow, w.state.contact.forceN);
    w.state.fluid = w.fluid.state();
    w.physics(w.state.scope, w.state.fluid.pressureKpa);
    w.state.step += 1;
    w.state.timeS = static_cast<double>(w.state.step) * dt;
    // The lens against the tissue closes the view too.
    double t = 0.0, a = 0.0, b = 0.0;
    const std::int32_t hit = w.bvh.raycast(w.pointsMm, w.state.scope.tipMm, w.state.scope.direction, 1.0, t, a, b);
    if (hit >= 0 && !w.state.contact.perforated)
        w.state.fluid.redOut = std::max(w.state.fluid.redOut, 1.0 - t);
    w.state.inCavity = dot(w.state.scope.tipMm - w.landmarks.internalOsMm, w.frame.axis) > 0.0;
    w.state.cavityOpeningMl = w.cavityVolumeMl(w.pointsMm) - w.restCavityMl;
    w.state.horizonErrorDeg = horizonErrorDeg(w.frame, w.state.scope);
    TrialMetrics& m = w.metrics;
    m.timeS = w.state.timeS;
    if (w.state.inCavity) {
        w.horizonSum += w.state.horizonErrorDeg * dt;
        w.horizonTime += dt;
        m.horizonErrorMeanDeg = w.horizonSum / w.horizonTime;
        m.horizonErrorMaxDeg = std::max(m.horizonErrorMaxDeg, w.state.horizonErrorDeg);
    }
    const FluidState& f = w.state.fluid;
    if (f.pressureKpa > w.options.fluid.meanArterialPressureKpa)
        m.timeAboveMeanArterialPressureS += dt;
    if (f.redOut >= 1.0 && w.state.inCavity)
        m.redOutTimeS += dt;
    m.maxPressureKpa = std::max(m.maxPressureKpa, f.pressureKpa);
    m.inflowMl = f.inflowTotalMl;
    m.outflowMl = f.outflowTotalMl;
    m.deficitMl = f.deficitMl;
    m.deficitWarning = m.deficitWarning || f.deficitWarning;
    m.deficitLimitReached = m.deficitLimitReached || f.deficitLimit;
    if (w.state.timeS + 1e-9 >= w.nextVisibilityS) {
        w.updateVisibility();
        w.nextVisibilityS += kVisibilityPeriodS;
    }
    if (markPressed)
        w.mark();
    if (w.state.timeS + 1e-9 >= w.nextSeriesS) {
        w.series.push_back({w.state.timeS, w.seriesForceN, f.pressureKpa, f.deficitMl});
        w.seriesForceN = 0.0;
        w.nextSeriesS += kSeriesPeriodS;
    }
    w.publishFrame();
    return {};
}

const WorldOptions& World::options() const {
    return impl_->options;
}
const scene::Scene& World::scene() const {
    return impl_->scene;
}
const std::string& World::sceneSha256() const {
    return impl_->sha;
}
const ScopeFrame& World::frame() const {
    return impl_->frame;
}
const scene::ScopeLandmarks& World::landmarks() const {
    return impl_->landmarks;
}
const TetMesh& World::simulationMesh() const {
    return impl_->simRest;
}
const SurfaceMesh& World::contactSurface() const {
    return impl_->contactSurface;
}
const WorldState& World::state() const {
    return impl_->state;
}
const std::vector<Vec3>& World::simulationPointsMm() const {
    return impl_->pointsMm;
}

WorldSnapshot World::snapshot() const {
    return {impl_->pointsMm, impl_->state};
}

std::shared_ptr<const HapticFrame> World::hapticFrame() const {
    std::lock_guard<std::mutex> lock(impl_->frameMutex);
    return impl_->hapticFrame;
}

void World::visualPoints(const std::vector<Vec3>& simulationPointsMm, std::vector<Vec3>& out) const {
    visualPoints(simulationPointsMm, out, {});
}

void World::visualPoints(const std::vector<Vec3>& simulationPointsMm, std::vector<Vec3>& out,
                         const std::vector<std::int32_t>& only) const {
    const auto& embedding = impl_->scene.simulation->surfaceEmbedding;
    const auto& tets = impl_->simRest.tets;
    out.resize(embedding.size());
    const auto place = [&](std::size_t i) {
        const TetEmbedding& e = embedding[i];
        const Tet& t = tets[static_cast<std::size_t>(e.tet)];
        out[i] = simulationPointsMm[static_cast<std::size_t>(t[0])] * e.weights[0] +
                 simulationPointsMm[static_cast<std::size_t>(t[1])] * e.weights[1] +
                 simulationPointsMm[static_cast<std::size_t>(t[2])] * e.weights[2] +
                 simulationPointsMm[static_cast<std::size_t>(t[3])] * e.weights[3];
    };
    if (only.empty()) {
        for (std::size_t i = 0; i < embedding.size(); ++i)
            place(i);
        return;
    }
    for (const std::int32_t i : only)
        if (i >= 0 && static_cast<std::size_t>(i) < embedding.size())
            place(static_cast<std::size_t>(i));
}

const TrialMetrics& World::metrics() const {
    return impl_->metrics;
}

std::string_view physicsEngine() {
    return "xpbd-fixed-corotated/1";
}

Status checkReplay(const TrialHeader& trial, const WorldOptions& options) {
    const auto differs = [](const std::string& field, const std::string& recorded, const std::string& now) {
        return fail(ErrorCode::InvalidInput, "the trial cannot be replayed bit for bit here: header." + field + " is " +
                                                 recorded + ", this world's is " + now);
    };
    const auto number = [](double v) {
        char buffer[32];
        std::snprintf(buffer, sizeof buffer, "%.17g", v);
        return std::string(buffer);
    };
    if (trial.physics.engine != physicsEngine())
        return differs("physics.engine", "\"" + trial.physics.engine + "\"",
                       "\"" + std::string(physicsEngine()) + "\"");
    if (trial.physics.stepS != options.stepS)
        return differs("physics.stepS", number(trial.physics.stepS), number(options.stepS));
    if (trial.physics.solverIterations != options.solverIterations)
        return differs("physics.solverIterations", std::to_string(trial.physics.solverIterations),
                       std::to_string(options.solverIterations));
    if (trial.seed != options.seed)
        return differs("seed", std::to_string(trial.seed), std::to_string(options.seed));
    if (trial.exercise != options.exercise)
        return differs("exercise", std::string(toString(trial.exercise)), std::string(toString(options.exercise)));
    const ScopeConfig& a = trial.scope;
    const ScopeConfig& b = options.scope;
    if (a.opticDeg != b.opticDeg || a.diameterMm != b.diameterMm || a.fieldOfViewDeg != b.fieldOfViewDeg ||
        a.focusNearMm != b.focusNearMm || a.focusFarMm != b.focusFarMm)
        return differs("scope", "another scope", "its own");
    const FluidSettings& f = trial.fluid;
    const FluidSettings& g = options.fluid;
    if (f.pumpPressureKpa != g.pumpPressureKpa || f.meanArterialPressureKpa != g.meanArterialPressureKpa ||
        f.deficitWarningMl != g.deficitWarningMl || f.deficitLimitMl != g.deficitLimitMl)
        return differs("fluid", "other fluid settings", "its own");
    return {};
}

TrialHeader World::trialHeader() const {
    TrialHeader h;
    h.sceneSha256 = impl_->sha;
    h.seed = impl_->options.seed;
    h.physics.engine = std::string(physicsEngine());
    h.physics.stepS = impl_->options.stepS;
    h.physics.solverIterations = impl_->options.solverIterations;
    h.exercise = impl_->options.exercise;
    h.scope = impl_->options.scope;
    h.fluid = impl_->options.fluid;
    return h;
}

TrialReport World::report() const {
    const Impl& w = *impl_;
    TrialReport r;
    r.header = trialHeader();
    r.samples = w.samplesConsumed;
    r.metrics = w.metrics;
    bool allTargets = !w.metrics.targets.empty();
    for (const auto& t : w.metrics.targets)
        allTargets = allTargets && t.seen;
    r.explorationComplete = allTargets && w.metrics.perforations.empty();
    bool allFound = true;
    for (const auto& p : w.metrics.pathologies)
        allFound = allFound && p.found;
    r.diagnosisComplete = allFound && w.metrics.falseMarks == 0 && w.metrics.perforations.empty();
    r.series = w.series;
    for (std::size_t f = 0; f < w.faceInCavity.size(); ++f)
        if (w.faceInCavity[f]) {
            SurfaceSample s = w.faceUnrolled[f];
            s.seen = w.faceSeen[f] != 0;
            r.surface.push_back(s);
        }
    return r;
}

World::Health World::health() const {
    Health h;
    h.elasticEnergyJ = impl_->tissue.elasticEnergyJ();
    h.minVolumeRatio = impl_->tissue.minVolumeRatio(h.invertedTets);
    h.maxSpeedMmPerS = impl_->tissue.maxSpeedMPerS() / kMm;
    return h;
}

Result<TrialReport> replayTrial(const std::string& packageFolder, const Trial& trial, Progress& progress) {
    auto digest = scene::sha256File(packageFolder + "/" + std::string(scene::kManifestName), 1 << 20);
    if (!digest)
        return fail(digest.error().code, packageFolder + ": " + digest.error().detail);
    if (digest->sha256 != trial.header.sceneSha256)
        return fail(ErrorCode::InvalidInput, "the trial was recorded on the scene " + trial.header.sceneSha256 +
                                                 ", not on " + packageFolder + " (" + digest->sha256 + ")");
    WorldOptions options;
    options.scope = trial.header.scope;
    options.fluid = trial.header.fluid;
    options.exercise = trial.header.exercise;
    options.seed = trial.header.seed;
    options.stepS = trial.header.physics.stepS;
    options.solverIterations = trial.header.physics.solverIterations;
    HS_TRY(checkReplay(trial.header, options));
    auto world = World::load(packageFolder, options, progress);
    if (!world)
        return world.failure();
    const std::size_t per = (*world)->ticksPerStep();
    const std::size_t steps = trial.samples.size() / per;
    for (std::size_t s = 0; s < steps; ++s) {
        if (s % 200 == 0) {
            HS_TRY(progress.check("replay"));
            progress.report("replay", static_cast<double>(s) / static_cast<double>(std::max<std::size_t>(steps, 1)));
        }
        HS_TRY((*world)->step(trial.samples.data() + s * per, per));
    }
    TrialReport report = (*world)->report();
    report.header = trial.header;
    return report;
}

} // namespace hs::sim

namespace hs::sim {

namespace {

/// The device sample that puts the tip at `tip` and turns the optic so it looks as nearly as possible at `target`.
DeviceSample aimAt(const World& world, const Vec3& tip, const Vec3& target) {
    DeviceSample best = sampleAiming(world.frame(), tip);
    double bestAngle = 1e300;
    for (int roll = -180; roll < 180; roll += 5) {
        DeviceSample s = sampleAiming(world.frame(), tip, roll);
        const ScopePose pose = scopePose(world.frame(), world.options().scope, s);
        const Vec3 to = target - pose.tipMm;
        if (norm(to) < 1e-9)
            continue;
        const double angle = std::acos(std::clamp(dot(normalized(to), pose.direction), -1.0, 1.0));
        if (angle < bestAngle - 1e-12) {
            bestAngle = angle;
            best = s;
        }
    }
    return best;
}

} // namespace

Script explorationScript(const World& world, double durationS) {
    const World::Impl& w = *world.impl_;
    const scene::ScopeLandmarks& lm = w.landmarks;
    const ScopeConfig& scope = w.options.scope;
    const double cavityLength = distance(lm.internalOsMm, lm.fundusMm);
    const auto onAxis = [&](double fraction) { return lm.internalOsMm + w.cavityAxis * (fraction * cavityLength); };
    const auto depthOf = [&](const Vec3& p) { return dot(p - lm.internalOsMm, w.cavityAxis) / cavityLength; };
    // Planned in the cavity opened by the fluid (as the calibration left it), where the trial's scope moves.
    detail::TriangleBvh open;
    open.build(*w.triangles, w.openPointsMm);
    const auto clearance = [&](const Vec3& tip) {
        return w.scopeClearanceMm(w.openPointsMm, open, scopePose(w.frame, scope, sampleAiming(w.frame, tip)));
    };
    // The cavity's middle at each tenth of its length: the tip's place within kMiddleSearchMm of the cavity's axis
    // farthest from the walls (up to kScriptClearanceMm; nearer the axis wins among those): the path keeps off a
    // myoma or a polyp that bulges into the cavity, and off a wall the axis runs close to.
    std::vector<Vec3> middle(10);
    for (std::size_t k = 1; k < middle.size(); ++k) {
        const Vec3 base = onAxis(0.1 * static_cast<double>(k));
        double bestScore = -1e300;
        for (double side = -kMiddleSearchMm; side <= kMiddleSearchMm + 1e-9; side += kMiddleStepMm)
            for (double up = -kMiddleSearchMm; up <= kMiddleSearchMm + 1e-9; up += kMiddleStepMm) {
                const Vec3 p = base + w.cavityLeft * side + w.cavityAnterior * up;
                const double score =
                    std::min(clearance(p), kScriptClearanceMm) - 0.05 * std::sqrt(side * side + up * up);
                if (score > bestScore + 1e-12) {
                    bestScore = score;
                    middle[k] = p;
                }
            }
    }
    middle[0] = middle[1];
    const auto middleAt = [&](double fraction) {
        return middle[static_cast<std::size_t>(std::clamp(std::lround(fraction * 10.0), 1L, 9L))];
    };

    std::vector<std::pair<double, DeviceSample>> plan; // (time on the plan, sample), scaled to durationS at the end
    double t = 0.0;
    const auto add = [&plan, &t](double afterS, DeviceSample s) {
        t += afterS;
        s.inflow = 1.0;
        s.outflow = 0.3;
        plan.emplace_back(t, s);
    };
    DeviceSample outside;
    outside.insertionMm = -5.0;
    DeviceSample inOs = outside;
    inOs.insertionMm = distance(lm.externalOsMm, lm.internalOsMm) + 2.0;
    const Vec3 inOsTip = scopePose(w.frame, scope, inOs).tipMm;
    add(0.0, outside);
    add(2.0, outside);
    add(4.0, inOs);
    // Every move inside the cavity goes along its middle: back to the middle where the tip is, along it a tenth of
    // the cavity at a time, then to the place asked for; each leg at kScriptSpeedMmPerS.
    Vec3 tipNow = inOsTip;
    double depthNow = 0.0;
    const auto leg = [&](const Vec3& to, const DeviceSample& look) {
        const double d = distance(tipNow, to);
        if (d < 0.5)
            return;
        add(std::max(0.3, d / kScriptSpeedMmPerS), look);
        tipNow = to;
    };
    const auto via = [&](const Vec3& p, const DeviceSample& s) {
        leg(p, sampleAiming(w.frame, p, s.rollDeg, s.cameraRollDeg));
    };
    const auto go = [&](const DeviceSample& s, double holdS) {
        const Vec3 tip = scopePose(w.frame, scope, s).tipMm;
        const double depth = std::clamp(depthOf(tip), 0.1, 0.9);
        const long from = std::lround(std::clamp(depthNow, 0.1, 0.9) * 10.0), to = std::lround(depth * 10.0);
        for (long k = from;; k += (to > from ? 1 : -1)) {
            via(middle[static_cast<std::size_t>(k)], s);
            if (k == to)
                break;
        }
        leg(tip, s);
        add(holdS, s);
        depthNow = depth;
    };
    // The walls: the optic turned all round at two depths.
    for (const double depth : {0.3, 0.55})
        for (int roll = -180; roll <= 180; roll += 90)
            go(sampleAiming(w.frame, middleAt(depth), roll), 1.5);
    // The fundus from near it; each ostium and each pathology from where it is in view: searched beside the middle
    // at several depths, among the places the scope reaches from the middle without touching a wall.
    go(aimAt(world, middleAt(0.6), lm.fundusMm), 2.0);
    std::vector<Vec3> vantage;
    for (const double depth : {0.6, 0.45, 0.75, 0.3, 0.85, 0.2})
        for (const double side : {0.0, 3.0, -3.0, 6.0, -6.0})
            for (const double up : {0.0, 3.0, -3.0, 6.0, -6.0}) {
                const Vec3 from = middleAt(depth);
                const Vec3 p = from + w.cavityLeft * side + w.cavityAnterior * up;
                bool clear = true;
                for (double f = 0.0; f <= 1.0 && clear; f += 0.125)
                    clear = clearance(from + (p - from) * f) >= kScriptClearanceMm * 0.5;
                if (clear)
                    vantage.push_back(p);
            }
    const auto lookAt = [&](const Vec3& target, const Vec3& normal, auto&& seen) {
        for (const Vec3& tip : vantage) {
            const DeviceSample s = aimAt(world, tip, target);
            if (seen(scopePose(w.frame, scope, s), target, normal))
                return s;
        }
        return aimAt(world, middleAt(0.6), target);
    };
    for (const auto& o : w.ostia) {
        const DeviceSample s =
            lookAt(w.ostiumPoint(o), o.normal, [&](const ScopePose& pose, const Vec3& p, const Vec3& n) {
                return w.visibleFrom(pose, p, n, -1, kOstiumOcclusionSlackMm);
            });
        go(s, 1.0);
    }
    for (std::size_t p = 0; p < w.metrics.pathologies.size(); ++p) {
        // The pathology's face nearest the cavity's axis, marked with the view's centre on it.
        std::int32_t best = -1;
        double bestDistance = 1e300;
        for (std::size_t f = 0; f < w.facePathology.size(); ++f) {
            if (w.facePathology[f] != static_cast<int>(p))
                continue;
            const Vec3 c = triangleCentre(w.simRest.points, (*w.triangles)[f]);
            const double along = dot(c - lm.internalOsMm, w.cavityAxis);
            const double off = norm(c - lm.internalOsMm - w.cavityAxis * along);
            if (off < bestDistance) {
                bestDistance = off;
                best = static_cast<std::int32_t>(f);
            }
        }
        if (best < 0)
            continue;
        const Vec3 centre = triangleCentre(w.simRest.points, (*w.triangles)[static_cast<std::size_t>(best)]);
        const DeviceSample look =
            lookAt(centre, w.faceNormal(best), [&](const ScopePose& pose, const Vec3&, const Vec3&) {
                double th = 0.0, a = 0.0, b = 0.0;
                const std::int32_t hit =
                    w.bvh.raycast(w.pointsMm, pose.tipMm, pose.direction, scopeFocusFarMm(scope), th, a, b);
                return hit >= 0 && w.facePathology[static_cast<std::size_t>(hit)] == static_cast<int>(p);
            });
        go(look, 1.0);
        DeviceSample press = look;
        press.buttons = kButtonMark;
        add(1.0, press);
        add(0.3, look);
        add(1.0, look);
    }
    // Out along the middle.
    go(sampleAiming(w.frame, middle[1]), 0.5);
    add(std::max(0.3, distance(tipNow, inOsTip) / kScriptSpeedMmPerS), inOs);
    add(3.0, outside);
    const double scale = durationS > 0.0 ? durationS / t : 1.0;
    Script script;
    for (const auto& [time, sample] : plan) {
        KeyFrame k;
        k.timeS = time * scale;
        k.sample = clamped(sample);
        if (!script.keyframes.empty() && k.timeS <= script.keyframes.back().timeS)
            k.timeS = script.keyframes.back().timeS + 0.001;
        script.keyframes.push_back(k);
    }
    return script;
}

} // namespace hs::sim
