// The scope against the tissue: contacts along the shaft, the tissue's force on the scope, perforation, and the frame
// the haptics loop renders (docs/simulator.md, "Collision and contact", "Perforation", "Haptics").
#include "WorldImpl.h"

#include <algorithm>
#include <cmath>

namespace hs::sim {

using namespace detail;

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

} // namespace hs::sim
