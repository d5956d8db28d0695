#include "hs/mechanics/UterusModel.h"

#include "hs/core/TetMesh.h"
#include "hs/scene/ScopePassage.h"

#include <algorithm>
#include <cmath>
#include <map>
#include <string>

namespace hs::mechanics {

namespace {

constexpr double kMm = 1e-3;
/// A static solve's settle: steps this long (the inertia and the damping vanish against the stiffness), until the
/// cavity's volume changes by less than kStaticToleranceMl in a step, at most kStaticSteps; the pressure is raised
/// over kStaticRampSteps (the stiffening tissue is followed, not jumped to; on the default scene a 5-step ramp ends
/// each of the curve's pressures within 0.02 mL (0.12 %) of a 20-step one, in half the steps).
constexpr double kStaticStepS = 1.0;
constexpr int kStaticSteps = 60;
constexpr int kStaticRampSteps = 5;
constexpr int kStaticIterations = 4;
constexpr double kStaticToleranceMl = 1e-4;

Vec3 areaNormal(const std::vector<Vec3>& pts, const Triangle& t) {
    return cross(pts[static_cast<std::size_t>(t[1])] - pts[static_cast<std::size_t>(t[0])],
                 pts[static_cast<std::size_t>(t[2])] - pts[static_cast<std::size_t>(t[0])]);
}

} // namespace

Triangle cutFace(const std::vector<Tet>& tets, std::size_t removed, std::size_t k, std::size_t live,
                 const std::vector<Vec3>& pts) {
    Triangle face{tets[removed][static_cast<std::size_t>(kTetFacePoints[k][0])],
                  tets[removed][static_cast<std::size_t>(kTetFacePoints[k][1])],
                  tets[removed][static_cast<std::size_t>(kTetFacePoints[k][2])]};
    std::int32_t inside = tets[live][0];
    for (const std::int32_t q : tets[live])
        if (q != face[0] && q != face[1] && q != face[2])
            inside = q;
    const Vec3 a = pts[static_cast<std::size_t>(face[0])];
    const Vec3 n = cross(pts[static_cast<std::size_t>(face[1])] - a, pts[static_cast<std::size_t>(face[2])] - a);
    if (dot(n, pts[static_cast<std::size_t>(inside)] - a) > 0.0)
        std::swap(face[1], face[2]);
    return face;
}

double UterusModel::cavityVolumeMl(const std::vector<Vec3>& pts) const {
    // The cavity's faces face into it: the volume between them and the external os.
    const Vec3 o = externalOsMm;
    double v = 0.0;
    const auto add = [&](const Triangle& t) {
        const Vec3 a = pts[static_cast<std::size_t>(t[0])] - o, b = pts[static_cast<std::size_t>(t[1])] - o,
                   c = pts[static_cast<std::size_t>(t[2])] - o;
        v -= dot(a, cross(b, c)) / 6.0;
    };
    const bool cut = fem.liveTetCount() < fem.tetCount();
    for (std::size_t f = 0; f < boundary.size(); ++f)
        if (faceCavity[f] && !(cut && f < faceTet.size() && fem.tetRemoved(static_cast<std::size_t>(faceTet[f]))))
            add(boundary[f]);
    if (!cut)
        return v / 1000.0;
    forEachCutFace(pts, add);
    return v / 1000.0 - cutSpaceMl;
}

CorotationalFem::Removal UterusModel::cutTets(const std::vector<std::size_t>& tets, const std::vector<Vec3>& pts,
                                              CorotationalFem::Refactor refactor) {
    const double before = cavityVolumeMl(pts);
    CorotationalFem::Removal removal = fem.removeTets(tets, refactor);
    if (!removal.removed.empty())
        cutSpaceMl += cavityVolumeMl(pts) - before;
    return removal;
}

void UterusModel::pressureForces(const std::vector<Vec3>& pts, double pressureKpa, std::vector<Vec3>& forces) const {
    forces.assign(pts.size(), Vec3{0.0, 0.0, 0.0});
    if (!(pressureKpa > 0.0))
        return;
    const double pa = pressureKpa * 1e3;
    // Area vector in m^2 (half the cross product), pointing into the fluid; the fluid pushes the wall back. Per pascal
    // this is also the gradient of the cavity's volume (m^3 per m) at the face's points.
    const auto load = [&](const Triangle& face) {
        const Vec3 force = areaNormal(pts, face) * (0.5 * kMm * kMm) * (-pa / 3.0);
        for (const std::int32_t v : face)
            forces[static_cast<std::size_t>(v)] += force;
    };
    for (std::size_t f = 0; f < boundary.size(); ++f)
        if (faceCavity[f] && !(f < faceTet.size() && fem.tetRemoved(static_cast<std::size_t>(faceTet[f]))))
            load(boundary[f]);
    // The faces a cut opened: the fluid in the removed tets' place pushes them in (without it the tissue round a cut
    // would carry the pressure's whole load on the faces left, unbalanced).
    forEachCutFace(pts, load);
}

Status buildUterusModel(const scene::Scene& scene, const FemSettings& settings, UterusModel& out, bool portioHeld,
                        bool stiffening) {
    if (!scene.simulation)
        return fail(ErrorCode::InvalidInput, "uterus model: the scene has no simulation mesh");
    const TetMesh& mesh = scene.simulation->tets;
    const auto materialIds = mesh.tetLabels.find(scene::kMaterialLabel);
    const auto supportIds = mesh.tetLabels.find(scene::kSupportTetLabel);
    const auto cavityIds = mesh.pointLabels.find(scene::kCavityPointLabel);
    if (materialIds == mesh.tetLabels.end() || supportIds == mesh.tetLabels.end() ||
        cavityIds == mesh.pointLabels.end() || materialIds->second.size() != mesh.tetCount() ||
        supportIds->second.size() != mesh.tetCount() || cavityIds->second.size() != mesh.vertexCount())
        return fail(ErrorCode::InvalidInput, std::string("uterus model: the simulation mesh lacks its '") +
                                                 scene::kMaterialLabel + "', '" + scene::kSupportTetLabel + "' or '" +
                                                 scene::kCavityPointLabel + "' arrays");
    auto landmarks = scene::findScopeLandmarks(scene);
    if (!landmarks)
        return fail(landmarks.error().code, "uterus model: scope landmarks: " + landmarks.error().detail);
    out.externalOsMm = landmarks->externalOsMm;
    out.internalOsMm = landmarks->internalOsMm;
    const Vec3 canal = out.internalOsMm - out.externalOsMm;
    if (!(norm(canal) > 1e-6))
        return fail(ErrorCode::InvalidInput, "uterus model: the external and internal os coincide");
    const Vec3 axis = normalized(canal);
    const std::size_t n = mesh.vertexCount();
    out.restMm = mesh.points;

    // The boundary in the mesh's own point indices; a face of the cavity has all its points marked.
    const SurfaceMesh b = extractBoundary(mesh);
    const auto& source = b.vertexLabels.at("sourcePoint");
    out.boundary.clear();
    out.boundary.reserve(b.faceCount());
    for (const Triangle& t : b.triangles)
        out.boundary.push_back({source[static_cast<std::size_t>(t[0])], source[static_cast<std::size_t>(t[1])],
                                source[static_cast<std::size_t>(t[2])]});
    out.region = b.faceLabels.at("region");
    {
        std::map<std::array<std::int32_t, 3>, std::int32_t> tetOfFace;
        for (std::size_t t = 0; t < mesh.tetCount(); ++t)
            for (const auto& k : kTetFacePoints)
                tetOfFace[sortedFace(mesh.tets[t][static_cast<std::size_t>(k[0])],
                                     mesh.tets[t][static_cast<std::size_t>(k[1])],
                                     mesh.tets[t][static_cast<std::size_t>(k[2])])] = static_cast<std::int32_t>(t);
        out.faceTet.assign(out.boundary.size(), -1);
        for (std::size_t f = 0; f < out.boundary.size(); ++f) {
            const auto it = tetOfFace.find(sortedFace(out.boundary[f][0], out.boundary[f][1], out.boundary[f][2]));
            if (it != tetOfFace.end())
                out.faceTet[f] = it->second;
        }
    }
    const auto& cavityPoints = cavityIds->second;
    out.faceCavity.assign(out.boundary.size(), 0);
    for (std::size_t f = 0; f < out.boundary.size(); ++f) {
        bool cavity = true;
        for (const std::int32_t v : out.boundary[f])
            cavity = cavity && cavityPoints[static_cast<std::size_t>(v)] == 1;
        out.faceCavity[f] = cavity ? 1 : 0;
    }

    std::vector<FemMaterial> materials(mesh.tetCount());
    for (std::size_t t = 0; t < mesh.tetCount(); ++t) {
        const auto id = materialIds->second[t];
        if (id < 0 || static_cast<std::size_t>(id) >= scene.materials.size())
            return fail(ErrorCode::InvalidInput, "uterus model: tet " + std::to_string(t) + " has material " +
                                                     std::to_string(id) + ", the scene has " +
                                                     std::to_string(scene.materials.size()));
        const auto& m = scene.materials[static_cast<std::size_t>(id)].material;
        materials[t] = {m.youngsModulusKpa * 1e3, m.poissonRatio, m.densityKgPerM3,
                        stiffening ? kUterusStiffeningStrain : 0.0};
    }
    // The held cervix: its vaginal part (the portio, gripped by the vagina and the tenaculum) is fixed; the rest of it
    // up to the internal os hangs in the cardinal and uterosacral ligaments, stiff springs that let the corpus tilt
    // when the scope pushes it.
    // The portio is held by its outer surface (the vagina's grip): its canal's lining and its stroma are free, so the
    // sheath dilates the canal and an entry off the canal's axis meets the cervix's tissue.
    std::vector<char> outer(n, 0);
    for (std::size_t f = 0; f < out.boundary.size(); ++f)
        if (!out.faceCavity[f])
            for (const std::int32_t v : out.boundary[f])
                outer[static_cast<std::size_t>(v)] = 1;
    std::vector<std::array<bool, 3>> fixed(n, {false, false, false});
    std::vector<bool> ligament(n, false);
    for (std::size_t t = 0; t < mesh.tetCount(); ++t)
        if (supportIds->second[t] == 1)
            for (const std::int32_t p : mesh.tets[t]) {
                const auto pi = static_cast<std::size_t>(p);
                if (dot(mesh.points[pi] - out.externalOsMm, axis) >= kHeldPortioMm)
                    ligament[pi] = true;
                else if (outer[pi] && portioHeld)
                    fixed[pi] = {true, true, true};
                else if (outer[pi])
                    ligament[pi] = true;
            }
    out.pointHeld.assign(n, 0);
    for (std::size_t i = 0; i < n; ++i)
        out.pointHeld[i] = fixed[i][0] ? 1 : 0;
    // Tethers on the serosa's free points, by area.
    std::vector<double> pointArea(n, 0.0);
    double total = 0.0;
    for (std::size_t f = 0; f < out.boundary.size(); ++f) {
        if (out.faceCavity[f])
            continue;
        const double area = 0.5 * norm(areaNormal(mesh.points, out.boundary[f]));
        for (const std::int32_t v : out.boundary[f])
            if (!fixed[static_cast<std::size_t>(v)][0]) {
                pointArea[static_cast<std::size_t>(v)] += area / 3.0;
                total += area / 3.0;
            }
    }
    std::size_t ligamentPoints = 0;
    for (std::size_t i = 0; i < n; ++i)
        ligamentPoints += ligament[i] && !fixed[i][0] ? 1 : 0;
    std::vector<std::pair<std::int32_t, double>> tethers;
    for (std::size_t i = 0; i < n; ++i) {
        if (fixed[i][0])
            continue;
        double k = pointArea[i] > 0.0 && total > 0.0 ? kSurroundStiffnessNPerM * pointArea[i] / total : 0.0;
        if (ligament[i])
            k += kLigamentStiffnessNPerM / static_cast<double>(ligamentPoints);
        if (k > 0.0)
            tethers.emplace_back(static_cast<std::int32_t>(i), k);
    }
    std::vector<Vec3> pointsM(n);
    for (std::size_t i = 0; i < n; ++i)
        pointsM[i] = mesh.points[i] * kMm;
    HS_TRY(out.fem.build(pointsM, mesh.tets, materials, fixed, tethers, settings));
    out.restCavityMl = out.cavityVolumeMl(out.restMm);
    return {};
}

namespace {

/// Raises the pressure on `still` from `fromKpa` to `toKpa` and lets the cavity settle; `pts` follows, mm.
Status settle(const UterusModel& model, CorotationalFem& still, double fromKpa, double toKpa, std::vector<Vec3>& pts,
              Progress& progress) {
    if (!std::isfinite(toKpa) || toKpa < 0.0 || toKpa > 40.0)
        return fail(ErrorCode::InvalidInput,
                    "static cavity: pressure " + std::to_string(toKpa) + " kPa is outside 0-40 kPa");
    std::vector<Vec3> forces;
    std::vector<FemConstraint> none;
    double last = model.cavityVolumeMl(pts);
    for (int s = 0; s < kStaticSteps; ++s) {
        HS_TRY(progress.check("static cavity", "settling the tissue"));
        const double ramp = std::min(1.0, static_cast<double>(s + 1) / kStaticRampSteps);
        model.pressureForces(pts, fromKpa + (toKpa - fromKpa) * ramp, forces);
        still.step(forces, none);
        for (std::size_t i = 0; i < pts.size(); ++i)
            pts[i] = still.positionsM()[i] / kMm;
        const double volume = model.cavityVolumeMl(pts);
        if (s >= kStaticRampSteps && std::abs(volume - last) < kStaticToleranceMl)
            break;
        last = volume;
    }
    if (still.recoveries() > 0)
        return fail(ErrorCode::InvalidInput,
                    "the tissue found no equilibrium at " + std::to_string(toKpa) + " kPa in the cavity");
    return {};
}

} // namespace

Status buildStaticSolver(const UterusModel& model, CorotationalFem& still) {
    FemSettings settings = model.fem.settings();
    settings.stepS = kStaticStepS;
    settings.iterations = kStaticIterations;
    settings.lineSearch = true; // long steps stiffen the tissue beyond what one chord step follows
    return still.buildLike(model.fem, settings);
}

Status staticOpen(const UterusModel& model, double pressureKpa, std::vector<Vec3>& pts, Progress& progress) {
    CorotationalFem still;
    HS_TRY(buildStaticSolver(model, still));
    pts = model.restMm;
    return settle(model, still, 0.0, pressureKpa, pts, progress);
}

Result<std::vector<double>> hydrometraCurve(const UterusModel& model, const std::vector<double>& pressuresKpa,
                                            Progress& progress) {
    CorotationalFem still;
    HS_TRY(buildStaticSolver(model, still));
    HS_TRY(progress.check("hydrometra curve"));
    std::vector<Vec3> pts = model.restMm;
    std::vector<double> opening;
    double last = 0.0;
    for (std::size_t i = 0; i < pressuresKpa.size(); ++i) {
        const double p = pressuresKpa[i];
        if (p < last)
            return fail(ErrorCode::InvalidInput, "hydrometra curve: the pressures must ascend");
        progress.report("scene.hydrometra", double(i) / double(pressuresKpa.size()));
        HS_TRY(settle(model, still, last, p, pts, progress));
        opening.push_back(model.cavityVolumeMl(pts) - model.restCavityMl);
        last = p;
    }
    return opening;
}

} // namespace hs::mechanics
