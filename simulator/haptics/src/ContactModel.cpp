// The god-object proxy of the scope's tip (ContactModel.h).
#include "hs/haptics/ContactModel.h"

#include "hs/core/TriangleGeometry.h"
#include "hs/sim/Scope.h"

#include <algorithm>
#include <cmath>

namespace hs::haptics {

namespace {

constexpr double kEpsilonMm = 1e-6;

struct Tri {
    Vec3 a, b, c;
};

Tri triangleOf(const sim::HapticFrame& frame, std::int32_t index) {
    const Triangle& t = (*frame.triangles)[static_cast<std::size_t>(index)];
    return {frame.pointsMm[static_cast<std::size_t>(t[0])], frame.pointsMm[static_cast<std::size_t>(t[1])],
            frame.pointsMm[static_cast<std::size_t>(t[2])]};
}

/// The closest point of triangle `t` to `p` (core's, the one home of this test).
Vec3 closestOnTriangle(const Vec3& p, const Tri& t) {
    return closestPointOnTriangle(p, t.a, t.b, t.c).point;
}

/// The unit normal (outward from the tissue: into the free space); zero for a degenerate triangle.
Vec3 normalOf(const Tri& t) {
    return normalized(cross(t.b - t.a, t.c - t.a));
}

/// x moved into every half-space (a few Gauss-Seidel passes: the planes are at most three).
template <class Planes>
Vec3 projectInto(Vec3 x, const Planes& planes) {
    for (int pass = 0; pass < 8; ++pass) {
        bool moved = false;
        for (const auto& plane : planes) {
            const double gap = plane.offset - dot(plane.normal, x);
            if (gap > 0.0) {
                x += plane.normal * gap;
                moved = true;
            }
        }
        if (!moved)
            break;
    }
    return x;
}

} // namespace

ContactModel::ContactModel(ContactParams params) : m_params(params) {
    m_candidates.reserve(1024);
    m_planes.reserve(8);
}

void ContactModel::reset() {
    m_hasProxy = false;
    m_state = {};
    m_velocity = {};
}

void ContactModel::gatherCandidates(const sim::HapticFrame& frame, const Vec3& from, const Vec3& to, double radius) {
    m_candidates.clear();
    if (!frame.triangles)
        return;
    const double margin = radius + m_params.searchMarginMm;
    const Vec3 lo{std::min(from.x, to.x) - margin, std::min(from.y, to.y) - margin, std::min(from.z, to.z) - margin};
    const Vec3 hi{std::max(from.x, to.x) + margin, std::max(from.y, to.y) + margin, std::max(from.z, to.z) + margin};
    const std::vector<Triangle>& triangles = *frame.triangles;
    const std::size_t pointCount = frame.pointsMm.size();
    for (std::size_t i = 0; i < triangles.size(); ++i) {
        const Triangle& t = triangles[i];
        if (static_cast<std::size_t>(t[0]) >= pointCount || static_cast<std::size_t>(t[1]) >= pointCount ||
            static_cast<std::size_t>(t[2]) >= pointCount || t[0] < 0 || t[1] < 0 || t[2] < 0)
            continue; // a malformed frame must not crash the haptics thread
        const Vec3& a = frame.pointsMm[static_cast<std::size_t>(t[0])];
        const Vec3& b = frame.pointsMm[static_cast<std::size_t>(t[1])];
        const Vec3& c = frame.pointsMm[static_cast<std::size_t>(t[2])];
        if (std::max({a.x, b.x, c.x}) < lo.x || std::min({a.x, b.x, c.x}) > hi.x || std::max({a.y, b.y, c.y}) < lo.y ||
            std::min({a.y, b.y, c.y}) > hi.y || std::max({a.z, b.z, c.z}) < lo.z || std::min({a.z, b.z, c.z}) > hi.z)
            continue;
        m_candidates.push_back(static_cast<std::int32_t>(i));
    }
}

/// Moves `p` out of the triangles the sphere overlaps from their front (the surface moved into the proxy since the
/// last tick). A centre behind a face by more than the radius is left alone: it is not this face's.
Vec3 ContactModel::pushOut(const sim::HapticFrame& frame, Vec3 p, double radius) const {
    for (int pass = 0; pass < 2; ++pass)
        for (std::int32_t index : m_candidates) {
            const Tri t = triangleOf(frame, index);
            const Vec3 n = normalOf(t);
            if (norm2(n) == 0.0)
                continue;
            const double height = dot(p - t.a, n);
            if (height <= -radius || height >= radius)
                continue;
            const Vec3 c = closestOnTriangle(p, t);
            const Vec3 d = p - c;
            const double dist = norm(d);
            if (dist >= radius)
                continue;
            p = (height > 0.0 && dist > kEpsilonMm) ? c + d * (radius / dist) : p + n * (radius - height);
        }
    return p;
}

/// Moves `p` towards `goal`, stopping at the first offset face in the way and sliding along it (and along up to
/// maxConstraints faces).
Vec3 ContactModel::slide(const sim::HapticFrame& frame, Vec3 p, const Vec3& goal, double radius) {
    m_planes.clear();
    for (int iteration = 0; iteration <= m_params.maxConstraints; ++iteration) {
        const Vec3 target = projectInto(goal, m_planes);
        const Vec3 step = target - p;
        if (norm2(step) < kEpsilonMm * kEpsilonMm)
            return p;
        double first = 1.0;
        Plane hit;
        bool found = false;
        for (std::int32_t index : m_candidates) {
            const Tri t = triangleOf(frame, index);
            const Vec3 n = normalOf(t);
            const double along = dot(n, step);
            if (along >= 0.0) // moving away from this face, or along it
                continue;
            const double offset = dot(n, t.a) + radius;
            const double start = dot(n, p) - offset;
            if (start < -kEpsilonMm) // already behind this face's offset: not in the way
                continue;
            const double s = std::max(0.0, start) / -along;
            if (s >= first)
                continue;
            // Where the path meets the offset plane must lie over the face (with some slack for its edges).
            const Vec3 meet = p + step * s - n * radius;
            if (distance(closestOnTriangle(meet, t), meet) > 0.5 * radius)
                continue;
            first = s;
            hit = {n, offset};
            found = true;
        }
        if (!found)
            return target;
        p = p + step * first + hit.normal * kEpsilonMm;
        if (static_cast<int>(m_planes.size()) >= m_params.maxConstraints)
            return p;
        m_planes.push_back(hit);
    }
    return p;
}

ForceCommand ContactModel::update(const sim::HapticFrame& frame, const sim::DeviceSample& sample, double dtS) {
    const sim::ScopePose pose = sim::scopePose(frame.pivot, frame.scope, sample);
    const Vec3 tip = pose.tipMm;
    const double radius = 0.5 * frame.scope.diameterMm;
    if (m_hasProxy && dtS > 0.0) {
        const Vec3 v = (tip - m_previousTip) / dtS;
        m_velocity = m_velocity + (v - m_velocity) * m_params.velocityFilter;
    }
    m_previousTip = tip;

    Vec3 force;
    m_state = {};
    if (frame.perforated || !frame.triangles || !(radius > 0.0) || !isFinite(tip)) {
        // Through the wall: the proxy follows the tip, and the wall holds again from wherever the tip is.
        m_proxy = isFinite(tip) ? tip : frame.pivot.pivotMm;
        m_hasProxy = true;
    } else {
        // The first time, the proxy comes in from the pivot along the shaft, as the scope did: a tip that starts
        // beyond the wall is pushed back rather than left inside.
        const Vec3 start = m_hasProxy ? m_proxy : frame.pivot.pivotMm;
        gatherCandidates(frame, start, tip, radius);
        Vec3 proxy = pushOut(frame, start, radius);
        proxy = slide(frame, proxy, tip, radius);
        m_proxy = proxy;
        m_hasProxy = true;
        const Vec3 spring = proxy - tip;
        const double depth = norm(spring);
        m_state.proxyMm = proxy;
        m_state.depthMm = depth;
        m_state.candidates = m_candidates.size();
        if (depth > 1e-9) {
            m_state.touching = true;
            const Vec3 n = spring / depth;
            const double k =
                std::isfinite(frame.contactStiffnessNPerMm) ? std::max(0.0, frame.contactStiffnessNPerMm) : 0.0;
            // Damping resists the tip's speed along the normal; it never pulls the tip into the wall.
            const double magnitude = std::max(0.0, k * depth - m_params.dampingNsPerMm * dot(m_velocity, n));
            force = n * magnitude;
        }
    }

    ForceCommand command;
    command.enabled = true;
    command.tipForceN = force;
    command.insertionForceN = dot(force, pose.shaft);
    const Vec3 torque = cross(tip - frame.pivot.pivotMm, force); // N*mm
    const Vec3 pitchAxis = normalized(cross(pose.shaft, frame.pivot.anterior));
    const Vec3 yawAxis = normalized(cross(pose.shaft, frame.pivot.left));
    const double kPivot = std::isfinite(frame.pivotStiffnessNmmPerDeg) ? frame.pivotStiffnessNmmPerDeg : 0.0;
    command.pitchTorqueNmm = dot(torque, pitchAxis) - kPivot * sample.pitchDeg;
    command.yawTorqueNmm = dot(torque, yawAxis) - kPivot * sample.yawDeg;
    command.rollTorqueNmm = 0.0; // a frictionless sphere: no torque about the shaft
    return command;
}

} // namespace hs::haptics
