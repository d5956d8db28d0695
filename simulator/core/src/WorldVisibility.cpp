// What the optic sees (the exploration's surface, the ostia, the pathologies), marking, and the clearance of the
// scope from the walls (the exploration script plans with it).
#include "WorldImpl.h"

#include <algorithm>
#include <cmath>

namespace hs::sim {

using namespace detail;

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
        if (!faceInCavity[f] || faceSeen[f] || faceDead[f])
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
            if (facePathology[f] >= 0 && !faceDead[f] &&
                distance(faceCentre(static_cast<std::int32_t>(f)), q) < kPathologyReachMm)
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

} // namespace hs::sim
