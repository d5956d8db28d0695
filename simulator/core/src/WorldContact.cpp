// The scope in the physics: a body held to the device's pose by a virtual coupling (Colgate, Stanley & Brown, "Issues
// in the haptic display of tool use", IROS 1995; iMSTK's PbdObjectController), stopped by the tissue through contact
// constraints that the tissue solver resolves with its own compliance. The force the device gets is the coupling's,
// which is the tissue's reaction as the solver computed it. Contacts along the whole shaft: the cervical canal is an
// obstacle (docs/simulator.md, "Collision and contact").
#include "WorldImpl.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <tuple>

namespace hs::sim {

using namespace detail;

namespace {

/// A candidate contact of one of the shaft's spheres with a face of the contact surface.
struct Candidate {
    double gapMm = 0.0;
    std::int32_t face = -1;
    std::int32_t sphere = 0; ///< 0: the tip
    mechanics::FemConstraint row;
    std::array<double, 3> scopeGradient{};
    Vec3 normal;
    Vec3 centreMm;     ///< the sphere's centre at the target pose
    double give = 0.0; ///< m/N, the tip's sub-element give on this face (World::Impl::tipCompliance)
};

/// The coupling's stiffness per scope dof (N/m, N m/rad, N m/rad): about a pivot at the introitus, `introitusMm`
/// further from the tip, the angular spring grows with the lever's square so the tip feels the same 1 N/mm.
std::array<double, 3> couplingStiffness(double introitusMm) {
    const double lever = (kCouplingLeverMm + introitusMm) / kCouplingLeverMm;
    const double angular = kCouplingAngularNmmPerRad * lever * lever * 1e-3;
    return {kCouplingInsertionNPerMm * 1e3, angular, angular};
}

/// The sample with the scope dofs `q` (SI) in place of the sample's.
DeviceSample withDofs(DeviceSample s, const std::array<double, 3>& q) {
    s.insertionMm = q[0] / kMm;
    s.pitchDeg = q[1] / kDeg;
    s.yawDeg = q[2] / kDeg;
    return s;
}

/// The tip's sub-element give, m/N: the mean of its faces' (0 without a tip row).
double tipGive(const std::vector<Candidate>& candidates) {
    double sum = 0.0;
    std::size_t n = 0;
    for (const Candidate& k : candidates)
        if (k.sphere == 0) {
            sum += k.give;
            ++n;
        }
    return n > 0 && std::isfinite(sum) ? sum / static_cast<double>(n) : 0.0;
}

} // namespace

double World::Impl::tipCompliance(std::int32_t f, const std::array<double, 3>& weights) const {
    const auto face = static_cast<std::size_t>(f);
    if (face >= faceTet.size() || faceTet[face] < 0)
        return 0.0;
    const Triangle& t = (*triangles)[face];
    const auto& p = simRest.points;
    const double edgeMm = (distance(p[static_cast<std::size_t>(t[0])], p[static_cast<std::size_t>(t[1])]) +
                           distance(p[static_cast<std::size_t>(t[1])], p[static_cast<std::size_t>(t[2])]) +
                           distance(p[static_cast<std::size_t>(t[2])], p[static_cast<std::size_t>(t[0])])) /
                          3.0;
    const double radiusM = 0.5 * options.scope.diameterMm * kMm;
    const mechanics::FemMaterial& material = tissue.material(static_cast<std::size_t>(faceTet[face]));
    return mechanics::punchSubElementCompliance(radiusM, edgeMm * kMm, weights, material) /
           mechanics::punchDimpleStiffening(tipDimpleM, radiusM, material, tissue.settings().maxStiffening);
}

DeviceSample World::Impl::physicsSample(const DeviceSample& device) const {
    return scopePlaced ? withDofs(device, scopeDofs) : device;
}

void World::Impl::physics(const DeviceSample& device, double pressureKpa) {
    const auto searching = std::chrono::steady_clock::now();
    const ScopeConfig& config = options.scope;
    const double radius = 0.5 * config.diameterMm;
    const std::array<double, 3> wanted = scopeDofsOf(device);
    if (!scopePlaced) {
        scopeDofs = wanted;
        scopePlaced = true;
    }
    // The coupling pulls the physics' scope towards the device's pose (the target): the contacts are linearized there,
    // so a device pushed far into a wall stretches the coupling as far and the contact carries its whole force.
    const DeviceSample from = withDofs(device, scopeDofs);
    const ScopePose poseFrom = scopePose(frame, config, from);
    const std::array<double, 3> target = wanted;
    // How a point of the shaft `back` mm behind the tip moves with each dof (mm per SI unit), by differences.
    constexpr double kEpsilon = 1e-6;
    std::array<ScopePose, 3> nudged;
    for (std::size_t d = 0; d < 3; ++d) {
        std::array<double, 3> q = scopeDofs;
        q[d] += kEpsilon;
        nudged[d] = scopePose(frame, config, withDofs(device, q));
    }
    // Candidates: spheres of the scope's radius along the shaft, from the tip to behind the pivot, against the faces
    // near each, found where the physics' scope is and linearized towards the target.
    const Bounds box = bounds(contactSurface);
    const Perforation* perforation =
        perforationIndex >= 0 ? &metrics.perforations[static_cast<std::size_t>(perforationIndex)] : nullptr;
    const double insertion = dot(poseFrom.tipMm - frame.pivotMm, poseFrom.shaft);
    std::vector<Candidate> candidates;
    std::vector<std::int32_t> near;
    std::int32_t sphere = 0;
    for (double back = 0.0; back <= insertion + kShaftCheckBehindPivotMm; back += radius, ++sphere) {
        // The sphere's centre on the physics' scope; the tip's faces are looked for from where the tip would be
        // without its sub-element dimple (the last step's), where the faces are.
        const Vec3 c0 = poseFrom.tipMm - poseFrom.shaft * back;
        const Vec3 c = sphere == 0 ? c0 + tipDimpleOutMm : c0;
        const double reach = radius + kContactMarginMm;
        if (c.x < box.min.x - reach || c.y < box.min.y - reach || c.z < box.min.z - reach || c.x > box.max.x + reach ||
            c.y > box.max.y + reach || c.z > box.max.z + reach)
            continue;
        // Through a perforation the scope meets no wall beyond the hole.
        if (perforation && dot(c - perforation->locationMm, poseFrom.shaft) > -2.0 * radius)
            continue;
        std::array<Vec3, 3> dc;
        for (std::size_t d = 0; d < 3; ++d)
            dc[d] = (nudged[d].tipMm - nudged[d].shaft * back - c0) / kEpsilon;
        Vec3 centre = c0;
        for (std::size_t d = 0; d < 3; ++d)
            centre += dc[d] * (target[d] - scopeDofs[d]);
        near.clear();
        bvh.near(c, reach, near);
        std::sort(near.begin(), near.end());
        for (const std::int32_t f : near) {
            const Triangle& tri = (*triangles)[static_cast<std::size_t>(f)];
            // The held portio is where the device pivots: its canal is the one the sheath was passed through.
            if (faceHeld[static_cast<std::size_t>(f)])
                continue;
            const ClosestPoint cp = closestPointOnTriangle(c, pointsMm[static_cast<std::size_t>(tri[0])],
                                                           pointsMm[static_cast<std::size_t>(tri[1])],
                                                           pointsMm[static_cast<std::size_t>(tri[2])]);
            const Vec3 faceN = faceNormal(f);
            const double along = dot(c - cp.point, faceN);
            if (along < -radius || norm2(faceN) == 0.0)
                continue; // behind this face by more than the radius: the tissue beyond is another face's
            // Behind the face's plane but beside the face (its closest point on an edge or a corner): the plane there
            // is not this face's wall; the face whose interior lies over the centre, or in front of it, answers.
            if (along <= 0.0 && std::min({cp.wa, cp.wb, cp.wc}) < 1e-9)
                continue;
            const double d = std::sqrt(cp.distance2);
            const Vec3 n = along > 0.0 && d > 1e-9 ? (c - cp.point) / d : faceN;
            const double gap = (along > 0.0 ? d : along) - radius;
            if (gap > kContactMarginMm)
                continue;
            Candidate k;
            k.gapMm = gap;
            k.face = f;
            k.sphere = sphere;
            k.normal = n;
            k.centreMm = centre;
            for (std::size_t j = 0; j < 3; ++j)
                k.scopeGradient[j] = dot(n, dc[j]) * kMm;
            k.row =
                mechanics::contactRow({tri[0], tri[1], tri[2]}, {cp.wa, cp.wb, cp.wc}, n, (centre - n * radius) * kMm);
            // The tip's flat end on the cavity's wall (or a cut's face) presses as a punch on a half-space; in the
            // canal, a tube about its own width, its rim meets the wall side-on, and the mesh's stiffness stands.
            const auto fi = static_cast<std::size_t>(f);
            if (sphere == 0 && (faceInCavity[fi] || faceCut[fi]))
                k.give = tipCompliance(f, {cp.wa, cp.wb, cp.wc});
            // Inside the wall already: out by at most kMaxDepenetrationMm this step.
            if (gap < -kMaxDepenetrationMm)
                k.row.offset += (-kMaxDepenetrationMm - gap) * kMm;
            candidates.push_back(std::move(k));
        }
    }
    // The nearest, in a fixed order (replays are bit for bit).
    std::sort(candidates.begin(), candidates.end(), [](const Candidate& a, const Candidate& b) {
        return std::tie(a.gapMm, a.sphere, a.face) < std::tie(b.gapMm, b.sphere, b.face);
    });
    if (candidates.size() > kMaxContacts)
        candidates.resize(kMaxContacts);
    std::vector<mechanics::FemConstraint> rows;
    rows.reserve(candidates.size());
    for (const Candidate& k : candidates)
        rows.push_back(k.row);
    // The coupling gives way as G K^-1 G^T between the contacts.
    const std::array<double, 3> stiffness = couplingStiffness(frame.introitusMm);
    const std::size_t count = rows.size();
    mechanics::ObstacleCompliance coupling;
    coupling.matrix.assign(count * count, 0.0);
    for (std::size_t i = 0; i < count; ++i)
        for (std::size_t j = 0; j < count; ++j)
            for (std::size_t d = 0; d < 3; ++d)
                coupling.matrix[i * count + j] +=
                    candidates[i].scopeGradient[d] * candidates[j].scopeGradient[d] / stiffness[d];

    // The tip's flat end presses as a punch of the scope's radius, finer than the faces: the give the mesh cannot
    // show (Boussinesq's, less the mesh's own at its faces' size) is the tip's, in series with all its rows along
    // their normals (one dimple, however many faces the tip meets).
    const double give = tipGive(candidates);
    for (std::size_t i = 0; i < count; ++i)
        for (std::size_t j = 0; j < count; ++j)
            if (candidates[i].sphere == 0 && candidates[j].sphere == 0)
                coupling.matrix[i * count + j] += give * dot(candidates[i].normal, candidates[j].normal);

    std::vector<Vec3> forces;
    uterus.pressureForces(pointsMm, pressureKpa, forces);
    timings.contactSearchMs +=
        std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - searching).count();
    tissue.step(forces, rows, coupling);
    timings.tissueForcesMs += tissue.lastTimings().forcesMs;
    timings.tissueSolvesMs += tissue.lastTimings().solveMs;
    timings.contactSolveMs += tissue.lastTimings().contactsMs;
    timings.forwardContactSteps += tissue.lastTimings().forwardIterations > 0 ? 1 : 0;
    timings.volumeRowSteps += tissue.lastVolumeRows() > 0 ? 1 : 0;
    timings.searchedSteps += tissue.lastTimings().searchedIterations > 0 ? 1 : 0;
    for (std::size_t i = 0; i < pointsMm.size(); ++i)
        pointsMm[i] = tissue.positionsM()[i] / kMm;
    bvh.refit(pointsMm);

    // The physics' scope where the contacts hold it: target + K^-1 G^T lambda, its tip moving at most kContactMarginMm
    // a step: a teleporting script or device cannot carry it through a wall between two contact searches (the
    // coupling then pulls the device back).
    const bool aligned = rows.size() == count;
    std::array<double, 3> held = target;
    tipDimpleM = 0.0;
    tipDimpleOutMm = Vec3{};
    if (aligned) {
        for (std::size_t i = 0; i < count; ++i)
            for (std::size_t d = 0; d < 3; ++d)
                held[d] += candidates[i].scopeGradient[d] * rows[i].force / stiffness[d];
        // The tip sinks into the tissue by the sub-element give times its rows' net force, a dimple finer than the
        // faces that the mesh does not show. The physics' scope stays where the coupling holds it, in the dimple (its
        // shaft's contacts as they are); the next step looks for the tip's faces from out of it, and the scope is
        // drawn and sees from there (below).
        Vec3 net{0.0, 0.0, 0.0};
        for (std::size_t i = 0; i < count; ++i)
            if (candidates[i].sphere == 0 && rows[i].force > 0.0)
                net += candidates[i].normal * rows[i].force;
        tipDimpleM = give * norm(net);
        tipDimpleOutMm = net * (give / kMm);
    }
    const double move = distance(scopePose(frame, config, withDofs(device, held)).tipMm, poseFrom.tipMm);
    const std::array<double, 3> before = scopeDofs;
    for (std::size_t d = 0; d < 3; ++d)
        scopeDofs[d] =
            move > kContactMarginMm ? before[d] + (held[d] - before[d]) * (kContactMarginMm / move) : held[d];
    // Drawn and seeing from out of the dimple: drawn back along its shaft so far as the dimple goes along it (the
    // picture shows the face the tip presses, not its inside).
    std::array<double, 3> drawn = scopeDofs;
    const Vec3 shaft = scopePose(frame, config, withDofs(device, scopeDofs)).shaft;
    drawn[0] -= std::max(0.0, -dot(tipDimpleOutMm, shaft)) * kMm;
    state.scope = scopePose(frame, config, withDofs(device, drawn));

    // The local model for the haptics loop: each contact's gap at the end of the step, its gradients, its force.
    hapticContacts.clear();
    hapticCompliance.clear();
    if (aligned) {
        for (std::size_t i = 0; i < count; ++i) {
            HapticContact h;
            double gap = rows[i].offset;
            for (std::size_t a = 0; a < rows[i].points.size(); ++a)
                gap += dot(rows[i].gradient[a], tissue.positionsM()[static_cast<std::size_t>(rows[i].points[a])]);
            for (std::size_t d = 0; d < 3; ++d)
                gap += candidates[i].scopeGradient[d] * (scopeDofs[d] - target[d]);
            h.gapM = gap;
            h.scopeGradient = candidates[i].scopeGradient;
            h.forceN = rows[i].force;
            h.normal = candidates[i].normal;
            h.tip = candidates[i].sphere == 0;
            hapticContacts.push_back(h);
        }
        hapticTipGive = give;
        if (tissue.lastContactCompliance().size() == count * count)
            hapticCompliance = tissue.lastContactCompliance();
        else
            hapticContacts.clear();
    }
    std::vector<char> rowTip(count);
    std::vector<std::int32_t> rowFace(count);
    for (std::size_t i = 0; i < count; ++i) {
        rowTip[i] = candidates[i].sphere == 0 ? 1 : 0;
        rowFace[i] = candidates[i].face;
    }
    recordContact(rows, rowTip, rowFace, state.scope);
}

void World::Impl::recordContact(const std::vector<mechanics::FemConstraint>& rows, const std::vector<char>& rowTip,
                                const std::vector<std::int32_t>& rowFace, const ScopePose& pose) {
    const double radius = 0.5 * options.scope.diameterMm;
    Vec3 total{0.0, 0.0, 0.0}, tip{0.0, 0.0, 0.0};
    double strongest = 0.0;
    Vec3 where = pose.tipMm;
    bool cavityContact = false;
    std::int32_t tipFace = -1;
    double tipStrongest = 0.0;
    const std::size_t count = std::min(rows.size(), rowTip.size());
    for (std::size_t i = 0; i < count; ++i) {
        if (rows[i].force <= 0.0)
            continue;
        // The tissue's force on the scope: lambda along the contact normal (rows' gradients are -w n).
        Vec3 normal{};
        for (const Vec3& g : rows[i].gradient)
            normal -= g;
        const Vec3 f = normalized(normal) * rows[i].force;
        total += f;
        const auto face = static_cast<std::size_t>(rowFace[i]);
        if (rowTip[i]) {
            tip += f;
            if (rows[i].force > tipStrongest) {
                tipStrongest = rows[i].force;
                tipFace = rowFace[i];
            }
        }
        if (rows[i].force > strongest) {
            strongest = rows[i].force;
            where = faceCentre(rowFace[i]);
        }
        cavityContact = cavityContact || faceInCavity[face] || faceCut[face];
    }
    ContactState& contact = state.contact;
    contact.forceN = norm(total);
    contact.tipForceN = norm(tip);
    contact.touching = contact.forceN > 1e-4;
    contact.pointMm = where;
    // Perforation: the wall gives way under a sustained push of the tip ...
    tipPushS = norm(tip) > kPerforationForceN ? tipPushS + options.stepS : 0.0;
    // ... or the tip is beyond the uterus as it lies at rest (outside its serosa, past the internal os).
    const bool outside = dot(pose.tipMm - landmarks.internalOsMm, frame.axis) > 0.0 && !insideRestHull(pose.tipMm);
    if (perforationIndex < 0 && (tipPushS >= kPerforationHoldS || outside)) {
        if (tipFace < 0) {
            // Through the wall with no contact left at the tip (the wall gave way at the contact's largest force): the
            // wall's face nearest the tip.
            std::vector<std::int32_t> near;
            bvh.near(pose.tipMm, kClearanceReachMm, near);
            std::sort(near.begin(), near.end());
            double best = 1e300;
            for (const std::int32_t f : near) {
                const Triangle& tri = (*triangles)[static_cast<std::size_t>(f)];
                const double d2 = closestPointOnTriangle(pose.tipMm, pointsMm[static_cast<std::size_t>(tri[0])],
                                                         pointsMm[static_cast<std::size_t>(tri[1])],
                                                         pointsMm[static_cast<std::size_t>(tri[2])])
                                      .distance2;
                if (d2 < best) {
                    best = d2;
                    tipFace = f;
                }
            }
        }
        Perforation p;
        p.timeS = state.timeS;
        p.locationMm = tipFace >= 0 ? faceCentre(tipFace) : pose.tipMm;
        p.depthMm = 0.0;
        const std::int32_t region = tipFace >= 0 ? faceRegion[static_cast<std::size_t>(tipFace)] : -1;
        for (const auto& r : scene.regions)
            if (r.id == region)
                p.region = r.name;
        // Through the canal's wall, before the internal os: a false passage.
        p.falsePassage = dot(p.locationMm - landmarks.internalOsMm, frame.axis) < 0.0;
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
    // The time in contact is the cavity wall's, as the contacts counted above: the sheath always touches the canal it
    // dilates.
    if (cavityContact)
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
    f->scopeDofs = scopeDofs;
    f->couplingStiffness = couplingStiffness(frame.introitusMm);
    f->contacts = hapticContacts;
    f->tipComplianceMPerN = hapticTipGive;
    f->compliance = hapticCompliance;
    f->perforated = state.contact.perforated;
    std::lock_guard<std::mutex> lock(frameMutex);
    hapticFrame = std::move(f);
}

} // namespace hs::sim
