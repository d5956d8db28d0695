// The built-in exploration: in through the canal, the walls, the fundus, each ostium and each pathology, and out.
#include "WorldImpl.h"

#include "hs/core/Rng.h"
#include "hs/core/TriangleGeometry.h"

#include <algorithm>
#include <cmath>
#include <limits>

namespace hs::sim {

using namespace detail;

namespace {

/// The entry is looked for within this angle of the canal's axis, in steps of kEntryStepDeg.
constexpr double kEntrySearchDeg = 15.0;
constexpr double kEntryStepDeg = 1.0;
/// A press: the tip stands this far off the face before it (mm), moves in at this speed (mm/s), and a face of the
/// wall keeps this far from every pathology's faces (mm).
constexpr double kPressStandOffMm = 3.0;
constexpr double kPressSpeedMmPerS = 2.0;
constexpr double kPressPathologyClearanceMm = 10.0;
/// ... the scope, its tip standing off, keeps this far from every wall (mm), so only the tip presses, and the face
/// is met at most this obliquely (degrees between the shaft and its normal).
constexpr double kPressClearanceMm = 1.0;
constexpr double kPressMostObliqueDeg = 60.0;
/// A rough trial: the tip's speeds (mm/s; a hand moves a hysteroscope at up to about 50), how far beyond a face it
/// presses at most (mm), and where on the cavity's axis its moves start at the least (mm beyond the internal os).
/// The entry script pushes the scope in at this speed, mm/s.
constexpr double kEntrySpeedMmPerS = 5.0;
constexpr double kRoughSlowMmPerS = 10.0;
constexpr double kRoughFastMmPerS = 50.0;
constexpr double kRoughDeepestMm = 3.0;
constexpr double kRoughAxisStartMm = 3.0;

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

// The canal curves a little and the internal os lies off its middle: the clearest straight line is the line of least
// resistance a hysteroscopist looks for.
DeviceSample World::Impl::canalEntry(const TriangleBvh& open) const {
    const World::Impl& w = *this;
    const double canalMm = distance(w.landmarks.externalOsMm, w.landmarks.internalOsMm);
    DeviceSample outside;
    outside.insertionMm = -5.0;
    double best = -1e300;
    for (double pitch = -kEntrySearchDeg; pitch <= kEntrySearchDeg + 1e-9; pitch += kEntryStepDeg)
        for (double yaw = -kEntrySearchDeg; yaw <= kEntrySearchDeg + 1e-9; yaw += kEntryStepDeg) {
            DeviceSample s;
            s.pitchDeg = pitch;
            s.yawDeg = yaw;
            s.insertionMm = canalMm + 2.0;
            const ScopePose pose = scopePose(w.frame, w.options.scope, s);
            double least = 1e300;
            for (double back = 0.0; back <= canalMm + 2.0; back += 1.0)
                least = std::min(
                    least, w.clearanceMm(w.openPointsMm, open, pose.tipMm - pose.shaft * back, kClearanceReachMm));
            const double score = least - 1e-3 * std::hypot(pitch, yaw); // the axis wins a tie
            if (score > best + 1e-12) {
                best = score;
                outside.pitchDeg = pitch;
                outside.yawDeg = yaw;
            }
        }
    return outside;
}

namespace {

/// A script's plan: samples on its own clock, each after the last, with the inflow open and the outflow a little.
struct Plan {
    std::vector<std::pair<double, DeviceSample>> keys;
    double time = 0.0;
    void add(double afterS, DeviceSample s) {
        time += afterS;
        s.inflow = 1.0;
        s.outflow = 0.3;
        keys.emplace_back(time, s);
    }
};

/// Key frames on a plan's clock, scaled to `durationS` (0: as planned), times strictly increasing.
Script toScript(const std::vector<std::pair<double, DeviceSample>>& plan, double durationS) {
    const double end = plan.empty() ? 0.0 : plan.back().first;
    const double scale = durationS > 0.0 && end > 0.0 ? durationS / end : 1.0;
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

    Plan plan; // scaled to durationS at the end
    const auto add = [&plan](double afterS, const DeviceSample& s) { plan.add(afterS, s); };
    const double canalMm = distance(lm.externalOsMm, lm.internalOsMm);
    DeviceSample outside = w.canalEntry(open);
    DeviceSample inOs = outside;
    inOs.insertionMm = canalMm + 2.0;
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
    return toScript(plan.keys, durationS);
}

Result<PressPlan> pressScript(const World& world, int pathology, double depthMm, double holdS, std::size_t rank) {
    const World::Impl& w = *world.impl_;
    if (pathology < -1 || pathology >= static_cast<int>(w.metrics.pathologies.size()))
        return fail(ErrorCode::InvalidInput, "press: pathology " + std::to_string(pathology) + " is not one of the " +
                                                 std::to_string(w.metrics.pathologies.size()) + " of the scene");
    if (!std::isfinite(depthMm) || depthMm < 0.0 || depthMm > 10.0 || !std::isfinite(holdS) || holdS < 0.0 ||
        holdS > 60.0)
        return fail(ErrorCode::InvalidInput, "press: the depth must be 0-10 mm and the hold 0-60 s");
    const ScopeConfig& scope = w.options.scope;
    const double radius = 0.5 * scope.diameterMm;
    detail::TriangleBvh open;
    open.build(*w.triangles, w.openPointsMm);
    // The face met most nearly head-on by a shaft from the pivot, with the whole scope clear of the walls when its tip
    // stands kPressStandOffMm off it; the wall's faces keep kPressPathologyClearanceMm from every pathology's.
    std::vector<Vec3> pathologyCentres;
    for (std::size_t f = 0; f < w.facePathology.size(); ++f)
        if (w.facePathology[f] >= 0)
            pathologyCentres.push_back(triangleCentre(w.openPointsMm, (*w.triangles)[f]));
    // A pathology's own faces (its region's, not the wall's round it that lie near it).
    std::int32_t ownRegion = -1;
    if (pathology >= 0)
        for (const auto& r : w.scene.regions)
            if (r.pathologyId == w.metrics.pathologies[static_cast<std::size_t>(pathology)].id)
                ownRegion = r.id;
    // The faces within kPressMostObliqueDeg of head-on, most head-on first (ties in face order); each in turn the
    // first whose scope pose is clear, skipping those within a tip's diameter of a face taken before, `rank` times.
    std::vector<std::pair<double, std::int32_t>> candidates;
    for (std::size_t f = 0; f < w.triangles->size(); ++f) {
        if (!w.faceInCavity[f] || w.facePathology[f] != pathology)
            continue;
        if (pathology >= 0 && w.faceRegion[f] != ownRegion)
            continue;
        const Triangle& t = (*w.triangles)[f];
        const Vec3 c = triangleCentre(w.openPointsMm, t);
        if (pathology < 0) {
            bool apart = true;
            for (const Vec3& p : pathologyCentres)
                apart = apart && distance(p, c) >= kPressPathologyClearanceMm;
            if (!apart)
                continue;
        }
        const Vec3 n = normalized(triangleNormal(w.openPointsMm, t));
        const double alignment = -dot(normalized(c - w.frame.pivotMm), n);
        if (alignment > std::cos(kPressMostObliqueDeg * kDeg))
            candidates.emplace_back(alignment, static_cast<std::int32_t>(f));
    }
    std::stable_sort(candidates.begin(), candidates.end(),
                     [](const auto& a, const auto& b) { return a.first > b.first; });
    double best = 0.0;
    std::int32_t chosen = -1;
    std::vector<Vec3> taken;
    for (const auto& [alignment, f] : candidates) {
        const Vec3 c = triangleCentre(w.openPointsMm, (*w.triangles)[static_cast<std::size_t>(f)]);
        bool apart = true;
        for (const Vec3& p : taken)
            apart = apart && distance(p, c) >= scope.diameterMm;
        if (!apart)
            continue;
        const Vec3 d = normalized(c - w.frame.pivotMm);
        const ScopePose pose = scopePose(w.frame, scope, sampleAiming(w.frame, c - d * (radius + kPressStandOffMm)));
        if (w.scopeClearanceMm(w.openPointsMm, open, pose) < kPressClearanceMm)
            continue;
        if (taken.size() == rank) {
            best = alignment;
            chosen = f;
            break;
        }
        taken.push_back(c);
    }
    if (chosen < 0)
        return fail(ErrorCode::InvalidInput,
                    std::string("press: no face of ") +
                        (pathology < 0 ? "the cavity's wall"
                                       : "pathology " + w.metrics.pathologies[static_cast<std::size_t>(pathology)].id) +
                        " can be reached head-on with the scope clear of the walls");
    PressPlan plan;
    const Triangle& t = (*w.triangles)[static_cast<std::size_t>(chosen)];
    plan.surfaceMm = triangleCentre(w.openPointsMm, t);
    plan.normal = normalized(triangleNormal(w.openPointsMm, t));
    plan.alignment = best;
    const std::int32_t region = w.faceRegion[static_cast<std::size_t>(chosen)];
    for (const auto& r : w.scene.regions)
        if (r.id == region)
            plan.region = r.name;
    for (const auto& m : w.scene.materials)
        if (m.regionId == region) {
            plan.youngsModulusKpa = m.material.youngsModulusKpa;
            plan.poissonRatio = m.material.poissonRatio;
        }
    const Vec3 d = normalized(plan.surfaceMm - w.frame.pivotMm);
    Plan keys;
    const auto add = [&keys](double afterS, const DeviceSample& s) { keys.add(afterS, s); };
    const double canalMm = distance(w.landmarks.externalOsMm, w.landmarks.internalOsMm);
    const DeviceSample outside = w.canalEntry(open);
    DeviceSample inOs = outside;
    inOs.insertionMm = canalMm + 2.0;
    const DeviceSample standOff = sampleAiming(w.frame, plan.surfaceMm - d * (radius + kPressStandOffMm));
    const DeviceSample pressed = sampleAiming(w.frame, plan.surfaceMm - d * (radius - depthMm));
    add(0.0, outside);
    add(2.0, outside);
    add(4.0, inOs);
    add(std::max(0.5, distance(scopePose(w.frame, scope, inOs).tipMm, scopePose(w.frame, scope, standOff).tipMm) /
                          kScriptSpeedMmPerS),
        standOff);
    add(1.0, standOff);
    plan.pressFromS = keys.time;
    add(std::max(0.5, (kPressStandOffMm + depthMm) / kPressSpeedMmPerS), pressed);
    plan.holdFromS = keys.time;
    add(holdS, pressed);
    plan.script = toScript(keys.keys, 0.0);
    return plan;
}

double pressFaceOffsetMm(const World& world, const PressPlan& plan) {
    const std::vector<Vec3>& now = world.simulationPointsMm();
    double best = 1e300, offset = 0.0;
    for (const Triangle& t : world.contactSurface().triangles) {
        const ClosestPoint c =
            closestPointOnTriangle(plan.surfaceMm, now[static_cast<std::size_t>(t[0])],
                                   now[static_cast<std::size_t>(t[1])], now[static_cast<std::size_t>(t[2])]);
        if (c.distance2 < best) {
            best = c.distance2;
            offset = dot(c.point - plan.surfaceMm, plan.normal);
        }
    }
    return offset;
}

double pressIndentationMm(const World& world, const PressPlan& plan, double faceOffsetMm) {
    const auto frame = world.hapticFrame();
    if (!frame)
        return 0.0;
    DeviceSample physics = world.state().sample;
    physics.insertionMm = frame->scopeDofs[0] * 1e3;
    physics.pitchDeg = frame->scopeDofs[1] / kDeg;
    physics.yawDeg = frame->scopeDofs[2] / kDeg;
    const Vec3 tip = scopePose(world.frame(), world.options().scope, physics).tipMm;
    const Vec3 face = plan.surfaceMm + plan.normal * faceOffsetMm;
    return 0.5 * world.options().scope.diameterMm - dot(tip - face, plan.normal);
}

Vec3 entryShaft(const World& world, double offAxisDeg, double towardDeg) {
    const World::Impl& w = *world.impl_;
    detail::TriangleBvh open;
    open.build(*w.triangles, w.openPointsMm);
    const ScopePose clearest = scopePose(w.frame, w.options.scope, w.canalEntry(open));
    const double off = std::clamp(offAxisDeg, 0.0, 45.0) * kDeg, toward = towardDeg * kDeg;
    const Vec3 side = w.frame.anterior * std::cos(toward) + w.frame.left * std::sin(toward);
    return normalized(clearest.shaft * std::cos(off) + perpendicularTo(clearest.shaft, side) * std::sin(off));
}

Script entryScript(const World& world, double offAxisDeg, double towardDeg) {
    return entryScriptAlong(world, entryShaft(world, offAxisDeg, towardDeg));
}

Script entryScriptAlong(const World& world, const Vec3& shaft) {
    const World::Impl& w = *world.impl_;
    const double canalMm = distance(w.landmarks.externalOsMm, w.landmarks.internalOsMm);
    const double inMm = canalMm + 5.0;
    DeviceSample outside = sampleAiming(w.frame, w.frame.pivotMm + shaft * (10.0 + w.frame.introitusMm));
    outside.insertionMm = -5.0;
    DeviceSample in = outside;
    in.insertionMm = inMm / std::max(0.2, dot(shaft, w.frame.axis)); // its tip 5 mm beyond the internal os's plane
    Plan plan;
    plan.add(0.0, outside);
    plan.add(1.0, outside);
    plan.add((in.insertionMm - outside.insertionMm) / kEntrySpeedMmPerS, in);
    plan.add(1.0, in);
    return toScript(plan.keys, 0.0);
}

Script roughScript(const World& world, double durationS, std::uint64_t seed) {
    const World::Impl& w = *world.impl_;
    const scene::ScopeLandmarks& lm = w.landmarks;
    const ScopeConfig& scope = w.options.scope;
    detail::TriangleBvh open;
    open.build(*w.triangles, w.openPointsMm);
    std::vector<std::int32_t> wall, pathology;
    for (std::size_t f = 0; f < w.triangles->size(); ++f)
        if (w.faceInCavity[f])
            (w.facePathology[f] >= 0 ? pathology : wall).push_back(static_cast<std::int32_t>(f));
    Rng rng(seed);
    Plan plan;
    const double canalMm = distance(lm.externalOsMm, lm.internalOsMm);
    const DeviceSample outside = w.canalEntry(open);
    DeviceSample inOs = outside;
    inOs.insertionMm = canalMm + 2.0;
    plan.add(0.0, outside);
    plan.add(1.0, outside);
    plan.add(3.0, inOs);
    Vec3 tip = scopePose(w.frame, scope, inOs).tipMm;
    const auto axisAt = [&](const Vec3& p) {
        return lm.internalOsMm + w.cavityAxis * std::max(kRoughAxisStartMm, dot(p - lm.internalOsMm, w.cavityAxis));
    };
    double roll = 0.0;
    const auto moveTo = [&](const Vec3& to, double speed) {
        plan.add(std::max(0.05, distance(tip, to) / speed), sampleAiming(w.frame, to, roll));
        tip = to;
    };
    const double exitS = 4.0;
    while (!wall.empty() && plan.time < durationS - exitS) {
        const auto& from = !pathology.empty() && rng.below(3) == 0 ? pathology : wall;
        const std::int32_t f = from[static_cast<std::size_t>(rng.below(from.size()))];
        const Triangle& t = (*w.triangles)[static_cast<std::size_t>(f)];
        const Vec3 c = triangleCentre(w.openPointsMm, t);
        const Vec3 n = normalized(triangleNormal(w.openPointsMm, t));
        const double speed = rng.uniform(kRoughSlowMmPerS, kRoughFastMmPerS);
        roll = rng.uniform(-180.0, 180.0);
        moveTo(axisAt(tip), speed);
        moveTo(axisAt(c), speed);
        moveTo(c + n * (0.5 * scope.diameterMm + 1.0), speed);
        moveTo(c - n * rng.uniform(0.0, kRoughDeepestMm), speed);
        plan.add(rng.uniform(0.2, 1.0), sampleAiming(w.frame, tip, roll));
    }
    roll = 0.0;
    moveTo(axisAt(tip), kRoughSlowMmPerS);
    plan.add(std::max(0.3, distance(tip, scopePose(w.frame, scope, inOs).tipMm) / kRoughSlowMmPerS), inOs);
    plan.add(2.0, outside);
    return toScript(plan.keys, 0.0);
}

namespace {

/// A resection's strokes: the loop drawn back at this speed (mm/s; strip by strip, a few millimetres a second is
/// the pace of loop resection), pushed out and moved between strokes at these.
constexpr double kCutSpeedMmPerS = 15.0;
constexpr double kLoopOutSpeedMmPerS = 30.0;
constexpr double kStrokeMoveSpeedMmPerS = 15.0;
/// The working element's positions a stroke's plan checks, mm apart, and the margin the strokes reach beyond the
/// pathology, mm.
constexpr double kStrokeCheckMm = 0.5;
constexpr double kStrokeMarginMm = 2.0;
/// The plan keeps the pedal off where the wire, or the wire moved this far towards the pathology's base or to either
/// side, would pass through myometrium or cervix, mm (the trial's tissue lies a little off the plan's).
constexpr double kPlanMarginMm = 1.5;
constexpr std::size_t kPlanOffsets = 4;
/// A wire point lies in a tet when its smallest barycentric weight there is at least minus this (the tet's faces, with
/// a rounding's margin).
constexpr double kInsideWeight = 1e-9;
/// Where a located wire point lies when it is in no tet.
constexpr std::int32_t kInCavity = -1;
constexpr std::int32_t kOutsideTheOrgan = -2;

} // namespace

Result<Script> resectionScript(const World& world, int pathology) {
    const World::Impl& w = *world.impl_;
    if (!w.resection)
        return fail(ErrorCode::InvalidInput, "resection script: the world's exercise (" +
                                                 std::string(toString(w.options.exercise)) + ") does not cut");
    const auto& pathologies = w.scene.clinical.pathologies;
    if (pathology < 0 || static_cast<std::size_t>(pathology) >= pathologies.size())
        return fail(ErrorCode::InvalidInput, "resection script: pathology " + std::to_string(pathology) +
                                                 " is outside 0.." + std::to_string(pathologies.size()) + "-1");
    const scene::ScopeLandmarks& lm = w.landmarks;
    const ScopeConfig& scope = w.options.scope;
    const std::vector<Vec3>& open = w.openPointsMm;
    const auto& tetPathology = w.resection->tetPathology();
    const auto& tets = w.simRest.tets;
    // The pathology in the opened cavity: its centre, its reach from it, and its base (its points on other tissue).
    std::vector<char> inside(open.size(), 0), outside(open.size(), 0);
    for (std::size_t t = 0; t < tets.size(); ++t)
        for (const std::int32_t p : tets[t])
            (tetPathology[t] == pathology ? inside : outside)[static_cast<std::size_t>(p)] = 1;
    Vec3 centre, base;
    double count = 0.0, baseCount = 0.0;
    for (std::size_t i = 0; i < open.size(); ++i)
        if (inside[i]) {
            centre += open[i];
            count += 1.0;
            if (outside[i]) {
                base += open[i];
                baseCount += 1.0;
            }
        }
    if (count == 0.0)
        return fail(ErrorCode::InvalidInput, "resection script: pathology " +
                                                 pathologies[static_cast<std::size_t>(pathology)].id +
                                                 " has no tets in the simulation mesh");
    centre = centre / count;
    double radius = 0.0;
    for (std::size_t i = 0; i < open.size(); ++i)
        if (inside[i])
            radius = std::max(radius, distance(open[i], centre));
    const Vec3 axis = normalized(centre - w.frame.pivotMm);
    Vec3 down = baseCount > 0.0 ? base / baseCount - centre : Vec3{};
    down = down - axis * dot(down, axis);
    down = norm(down) > 1e-6 ? normalized(down) : perpendicularTo(axis, w.frame.anterior);
    const Vec3 side = normalized(cross(axis, down));

    // Where the wire would be, as planned: located in the opened mesh. A position is safe when no wire point lies in
    // a tet of another tissue.
    TetMesh openMesh = w.simRest;
    openMesh.points = open;
    struct Stroke {
        DeviceSample at; ///< the tip where the stroke ends, the loop drawn in
        double lengthMm = 0.0;
        double towardsBaseMm = 0.0; ///< its row: how far from the pathology's centre towards its base
        std::size_t firstPoint = 0, wirePoints = 0, positions = 0;
    };
    std::vector<Stroke> strokes;
    std::vector<Vec3> located;
    const double r = 0.5 * w.loop.widthMm;
    const double reach = std::min(kMaxWorkingElementMm, 2.0 * (radius + kStrokeMarginMm));
    for (double d = -radius - r; d <= radius + 1e-9; d += 0.5 * r)
        for (double s = -radius; s <= radius + 1e-9; s += 0.8 * w.loop.widthMm) {
            const Vec3 middle = centre + down * d + side * s;
            const Vec3 shaft = normalized(middle - w.frame.pivotMm);
            // The tip stands half the loop's travel in front of the strip's middle, but at least 2 mm beyond the
            // internal os (the loop is not drawn back into the canal): a pathology near the os gets shorter strokes.
            const double beyond =
                dot(middle - lm.internalOsMm, w.frame.axis) / std::max(1e-9, dot(shaft, w.frame.axis));
            const double back = std::min(0.5 * reach, beyond - 2.0);
            if (back < 1.0)
                continue;
            const Vec3 tip = middle - shaft * back;
            // The scope rolled so the loop hangs towards the pathology's base.
            const Vec3 want = perpendicularTo(shaft, down);
            Stroke stroke;
            double best = -2.0;
            for (int rollDeg = -180; rollDeg < 180; rollDeg += 5) {
                DeviceSample sample = sampleAiming(w.frame, tip, rollDeg);
                sample.instrument = kInstrumentLoop;
                Vec3 m;
                const std::vector<Vec3> wire = loopWireOf(w.frame, scope, w.loop, sample, m);
                const double fit = dot(normalized(wire[wire.size() / 2] - m), want);
                if (fit > best) {
                    best = fit;
                    stroke.at = sample;
                }
            }
            stroke.lengthMm = std::min(reach, 2.0 * back);
            stroke.towardsBaseMm = d;
            stroke.firstPoint = located.size();
            for (double we = 0.0; we <= stroke.lengthMm + 1e-9; we += kStrokeCheckMm) {
                DeviceSample sample = stroke.at;
                sample.workingElementMm = we;
                Vec3 m;
                const std::vector<Vec3> wire = loopWireOf(w.frame, scope, w.loop, sample, m);
                // The wire where planned, and moved kPlanMarginMm towards the base and to either side: the tissue
                // the trial meets lies a little off the plan (the pump's pressure, the sheath's contacts).
                const Vec3 offsets[kPlanOffsets] = {Vec3{}, down * kPlanMarginMm, side * kPlanMarginMm,
                                                    side * -kPlanMarginMm};
                for (const Vec3& offset : offsets)
                    for (std::size_t k = 0; k < wire.size(); k += 2)
                        located.push_back(wire[k] + offset);
                stroke.wirePoints = (wire.size() + 1) / 2;
                ++stroke.positions;
            }
            strokes.push_back(stroke);
        }
    const std::vector<TetEmbedding> where = embedPoints(openMesh, located);
    // The endometrium the pathology stands on (its tets that share a point with the pathology's) may be shaved with
    // the base; nothing else that is not the pathology is cut.
    const auto& tetTissue = w.resection->tetTissue();
    std::vector<char> allowed(tets.size(), 0);
    for (std::size_t t = 0; t < tets.size(); ++t) {
        if (tetPathology[t] == pathology) {
            allowed[t] = 1;
            continue;
        }
        if (tetTissue[t] != clinical::Tissue::Endometrium)
            continue;
        for (const std::int32_t p : tets[t])
            allowed[t] = allowed[t] || inside[static_cast<std::size_t>(p)];
    }
    // The tet each located wire point lies in; kInCavity in the cavity's fluid, kOutsideTheOrgan beyond the serosa.
    // embedPoints gives a point off the mesh the boundary tet nearest it, with a weight below zero: such a point lies
    // in the fluid when the boundary face nearest it is the cavity's, and outside the organ otherwise.
    detail::TriangleBvh openTree;
    openTree.build(*w.triangles, open);
    std::vector<std::int32_t> tetOf(where.size(), kInCavity);
    std::vector<std::int32_t> nearFaces;
    for (std::size_t i = 0; i < where.size(); ++i) {
        const TetEmbedding& e = where[i];
        if (e.tet < 0)
            continue;
        if (*std::min_element(e.weights.begin(), e.weights.end()) >= -kInsideWeight) {
            tetOf[i] = e.tet;
            continue;
        }
        double best = std::numeric_limits<double>::max();
        bool cavity = false;
        for (double radiusMm = 2.0; best == std::numeric_limits<double>::max() && radiusMm < 1e4; radiusMm *= 2.0) {
            nearFaces.clear();
            openTree.near(located[i], radiusMm, nearFaces);
            for (const std::int32_t f : nearFaces) {
                const Triangle& t = (*w.triangles)[static_cast<std::size_t>(f)];
                const double d2 =
                    closestPointOnTriangle(located[i], open[static_cast<std::size_t>(t[0])],
                                           open[static_cast<std::size_t>(t[1])], open[static_cast<std::size_t>(t[2])])
                        .distance2;
                if (d2 < best || (d2 == best && w.faceCavity[static_cast<std::size_t>(f)])) {
                    best = d2;
                    cavity = w.faceCavity[static_cast<std::size_t>(f)] != 0;
                }
            }
        }
        tetOf[i] = cavity ? kInCavity : kOutsideTheOrgan;
    }
    const auto tetAt = [&](const Stroke& stroke, std::size_t position, std::size_t offset, std::size_t k) {
        return tetOf[stroke.firstPoint + (position * kPlanOffsets + offset) * stroke.wirePoints + k];
    };
    const auto safe = [&](const Stroke& stroke, std::size_t position) {
        for (std::size_t o = 0; o < kPlanOffsets; ++o)
            for (std::size_t k = 0; k < stroke.wirePoints; ++k) {
                const std::int32_t t = tetAt(stroke, position, o, k);
                if (t == kOutsideTheOrgan || (t >= 0 && !allowed[static_cast<std::size_t>(t)]))
                    return false;
            }
        return true;
    };
    // A stroke whose wire, where planned or off it by the margins, never passes through the pathology is not made:
    // the grid of strips is a square round the pathology's reach, the pathology's outline is not.
    const auto meets = [&](const Stroke& stroke) {
        for (std::size_t i = 0; i < stroke.positions; ++i)
            for (std::size_t o = 0; o < kPlanOffsets; ++o)
                for (std::size_t k = 0; k < stroke.wirePoints; ++k) {
                    const std::int32_t t = tetAt(stroke, i, o, k);
                    if (t >= 0 && tetPathology[static_cast<std::size_t>(t)] == pathology)
                        return true;
                }
        return false;
    };
    strokes.erase(std::remove_if(strokes.begin(), strokes.end(), [&](const Stroke& s) { return !meets(s); }),
                  strokes.end());
    if (strokes.empty())
        return fail(ErrorCode::InvalidInput, "resection script: no stroke of the loop from the scope's pivot meets "
                                             "pathology " +
                                                 pathologies[static_cast<std::size_t>(pathology)].id);

    Plan plan;
    DeviceSample out = w.canalEntry(openTree);
    out.instrument = kInstrumentLoop;
    const double canalMm = distance(lm.externalOsMm, lm.internalOsMm);
    DeviceSample inOs = out;
    inOs.insertionMm = canalMm + 2.0;
    plan.add(0.0, out);
    plan.add(2.0, out);
    plan.add(4.0, inOs);
    Vec3 tipNow = scopePose(w.frame, scope, inOs).tipMm;
    // To a stroke's place, the loop drawn in, then pushed out to its length: the sample there.
    const auto pushOut = [&](const Stroke& stroke) {
        const Vec3 tip = scopePose(w.frame, scope, stroke.at).tipMm;
        plan.add(std::max(0.2, distance(tipNow, tip) / kStrokeMoveSpeedMmPerS), stroke.at);
        tipNow = tip;
        DeviceSample s = stroke.at;
        s.workingElementMm = stroke.lengthMm;
        plan.add(stroke.lengthMm / kLoopOutSpeedMmPerS, s);
        return s;
    };
    for (const Stroke& stroke : strokes) {
        DeviceSample s = pushOut(stroke);
        // Drawn back position by position, the pedal down over each step between two safe positions.
        for (std::size_t i = stroke.positions - 1; i > 0; --i) {
            const bool pedal = safe(stroke, i) && safe(stroke, i - 1);
            // The buttons of a key frame hold until the next: the frame at position i carries the pedal for the way
            // to position i - 1.
            plan.keys.back().second.buttons = pedal ? kButtonCut : 0u;
            s.workingElementMm = static_cast<double>(i - 1) * kStrokeCheckMm;
            s.buttons = 0;
            plan.add(kStrokeCheckMm / kCutSpeedMmPerS, s);
        }
    }
    // The bed coagulated: the strokes of the row at the base once more, the loop drawn back with the coagulating
    // pedal down (its vessels bleed most: a polyp's pedicle artery, a myoma's pseudocapsule).
    double baseRow = -1e300;
    for (const Stroke& stroke : strokes)
        baseRow = std::max(baseRow, stroke.towardsBaseMm);
    for (const Stroke& stroke : strokes) {
        if (stroke.towardsBaseMm < baseRow)
            continue;
        DeviceSample s = pushOut(stroke);
        plan.keys.back().second.buttons = kButtonCoagulate;
        s.workingElementMm = 0.0;
        plan.add(stroke.lengthMm / kCutSpeedMmPerS, s);
    }
    DeviceSample back = inOs;
    plan.add(std::max(0.3, distance(tipNow, scopePose(w.frame, scope, inOs).tipMm) / kStrokeMoveSpeedMmPerS), back);
    plan.add(2.0, out);
    return toScript(plan.keys, 0.0);
}

Result<Script> demonstrationScript(const World& world) {
    const Exercise exercise = world.options().exercise;
    if (!isOperative(exercise))
        return explorationScript(world);
    const auto& pathologies = world.scene().clinical.pathologies;
    for (std::size_t k = 0; k < pathologies.size(); ++k) {
        const auto& p = pathologies[k];
        const bool fits = exercise == Exercise::Polypectomy ? p.kind == clinical::PathologyKind::Polyp
                                                            : p.kind == clinical::PathologyKind::Myoma && p.figo &&
                                                                  p.figo->isHysteroscopicallyResectable();
        if (fits)
            return resectionScript(world, static_cast<int>(k));
    }
    return fail(ErrorCode::InvalidInput,
                "demonstration: the scene has no " +
                    std::string(exercise == Exercise::Polypectomy ? "polyp" : "myoma of FIGO type 0-2") + " for the " +
                    std::string(toString(exercise)) + " exercise");
}

} // namespace hs::sim
