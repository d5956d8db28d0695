// The resectoscope's loop in the world (docs/simulator.md, "Cutting"): the wire on the working element of the physics'
// scope, the tets it sweeps with the cutting pedal down removed from the tissue (hs::sim::Resection on the uterus
// model: the solver's factor downdated, the fluid's volume kept continuous), and the contact surface following the
// cut in the same step: the faces of removed tets leave it, the faces the cut bared join it. The office scope's
// scissors cut the same way, the tets their closing blades sweep; its grasper takes hold of chips.
#include "WorldImpl.h"

#include "hs/core/TriangleGeometry.h"

#include <array>

#include <algorithm>
#include <cmath>

namespace hs::sim {

using namespace detail;

namespace detail {

LoopState loopStateOf(const ScopeFrame& frame, const ScopeConfig& scope, const LoopElectrode& loop, DeviceSample body) {
    body.cameraRollDeg = 0.0;
    const ScopePose pose = scopePose(frame, scope, body);
    LoopState s;
    s.out = true;
    s.instrument = kInstrumentLoop;
    s.widthMm = loop.widthMm;
    s.travelMm = body.workingElementMm;
    s.middleMm = pose.tipMm + pose.shaft * body.workingElementMm;
    s.axis = pose.shaft;
    s.down = perpendicularTo(pose.shaft, pose.up * -1.0);
    return s;
}

std::vector<Vec3> loopWireOf(const ScopeFrame& frame, const ScopeConfig& scope, const LoopElectrode& loop,
                             DeviceSample body, Vec3& middleMm) {
    const LoopState s = loopStateOf(frame, scope, loop, body);
    middleMm = s.middleMm;
    return loopWire(loop, s.middleMm, s.axis, s.down);
}

} // namespace detail

std::vector<Vec3> World::Impl::loopWireMm(const DeviceSample& device, Vec3& middleMm) const {
    return loopWireOf(frame, options.scope, loop, physicsSample(device), middleMm);
}

void World::Impl::cut(const DeviceSample& device) {
    const bool squeezed = (device.buttons & kButtonCut) != 0;
    const bool pedal = device.instrument == kInstrumentLoop && squeezed;
    const bool jawsOut = device.instrument == kInstrumentScissors || device.instrument == kInstrumentGrasper;
    // The solver's factor follows the cuts by downdates, and its surface compliance stays in use away from them
    // (CorotationalFem::removeTets): nothing is rebuilt during a trial. (A rebuild on a thread of its own, taken in
    // at a fixed step, waited 0.5-1.6 s for it at that step with both cores stepping: docs/simulator.md, "Cutting".)
    state.loop = LoopState{};
    if (lastPedal && !pedal && stripMl > 0.0)
        releaseStrip(lastLoopMm); // the pedal up: the strip comes off the loop
    lastPedal = pedal;
    for (Chip& chip : chips) {
        chip.grasped = chip.grasped && device.instrument == kInstrumentGrasper; // put down with the grasper
        chip.hooked = chip.hooked && !jawsOut; // the loop exchanged for the office scope's instruments lets go
    }
    if (!jawsOut) {
        lastJawMm.clear();
        jawOpenDeg = jaws.openDeg; // a new instrument comes out of the channel open
    }
    if (device.instrument != kInstrumentLoop) {
        lastWireMm.clear();
        if (jawsOut)
            moveJaws(device, squeezed);
        moveChips(device);
        return;
    }
    Vec3 middle;
    std::vector<Vec3> wire = loopWireMm(device, middle);
    state.loop = loopStateOf(frame, options.scope, loop, physicsSample(device)); // drawn where the wire cuts
    state.loop.cutting = pedal;
    state.loop.coagulating = !pedal && (device.buttons & kButtonCoagulate) != 0;
    ResectionMetrics& m = metrics.resection;
    if (!pedal && (device.buttons & kButtonCoagulate) != 0) {
        m.coagulationTimeS += options.stepS;
        coagulate(wire);
    }
    if (pedal && !lastWireMm.empty()) {
        m.cuttingTimeS += options.stepS;
        m.loopPathMm += distance(middle, lastLoopMm);
        tookTissue(resection->cut(uterus, loop.sampleMm, lastWireMm, wire), true);
    }
    lastWireMm = std::move(wire);
    lastLoopMm = middle;
    moveChips(device);
}

void World::Impl::moveJaws(const DeviceSample& device, bool squeezed) {
    // Out of the working channel (below the optic) as far as the working element pushes it, the jaws in the plane of
    // the shaft and the image's up; they close at a squeeze's pace while it is held and open again when it is let go.
    LoopState s = loopStateOf(frame, options.scope, loop, physicsSample(device));
    s.instrument = device.instrument;
    s.middleMm += s.down * jaws.channelOffsetMm; // the hinge, out of the working channel
    s.widthMm = 0.0;
    s.jawLengthMm = jaws.jawLengthMm;
    const double before = jawOpenDeg;
    const double turn = jaws.openDeg / jaws.closeS * options.stepS;
    jawOpenDeg = squeezed ? std::max(0.0, before - turn) : std::min(jaws.openDeg, before + turn);
    s.jawOpenDeg = jawOpenDeg;
    std::vector<Vec3> wire = jawWire(jaws, s.middleMm, s.axis, s.down, jawOpenDeg);
    const Vec3 between = s.middleMm + s.axis * (0.5 * jaws.jawLengthMm);
    if (device.instrument == kInstrumentScissors) {
        // The blades closing cut what lies between them (the tets their edges sweep).
        s.cutting = squeezed && before > 0.0;
        if (s.cutting) {
            metrics.resection.cuttingTimeS += options.stepS;
            if (!lastJawMm.empty())
                tookTissue(resection->cut(uterus, jaws.sampleMm, lastJawMm, wire), false);
        }
    } else {
        // The grasper's jaws shutting take the nearest chip within reach; opening lets it go.
        if (squeezed && before > 0.0 && jawOpenDeg <= 0.0) {
            std::size_t nearest = chips.size();
            double best = 1e300;
            for (std::size_t k = 0; k < chips.size(); ++k) {
                const double d = distance(chips[k].positionMm, between);
                if (!chips[k].hooked && d <= chips[k].radiusMm + kChipCatchMm && d < best) {
                    best = d;
                    nearest = k;
                }
            }
            if (nearest < chips.size())
                chips[nearest].grasped = true;
        }
        if (!squeezed)
            for (Chip& chip : chips)
                chip.grasped = false;
        for (const Chip& chip : chips)
            s.holding = s.holding || chip.grasped;
    }
    lastJawMm = std::move(wire);
    state.loop = s;
}

void World::Impl::tookTissue(const CutEvent& event, bool toStrip) {
    if (event.removed.empty())
        return;
    ResectionMetrics& m = metrics.resection;
    surfaceAfterCut(event.removed);
    // The tissue cut away: pieces cut free float off at once, the rest gathers on the loop as its strip.
    std::vector<char> inPiece(tissue.tetCount(), 0);
    for (const std::vector<std::size_t>& piece : event.chips) {
        Chip chip;
        std::array<double, 5> byTissue{};
        Vec3 centre;
        double corners = 0.0;
        for (const std::size_t t : piece) {
            inPiece[t] = 1;
            const double ml = tissue.restVolumeM3(t) * 1e6;
            chip.volumeMl += ml;
            byTissue[static_cast<std::size_t>(resection->tetTissue()[t])] += ml;
            for (const std::int32_t v : tissue.tets()[t]) {
                centre += pointsMm[static_cast<std::size_t>(v)];
                corners += 1.0;
            }
        }
        chip.positionMm = centre / std::max(corners, 1.0);
        chip.radiusMm = std::cbrt(3.0 * chip.volumeMl * 1e3 / (4.0 * kPi));
        chip.tissue =
            static_cast<clinical::Tissue>(std::max_element(byTissue.begin(), byTissue.end()) - byTissue.begin());
        chips.push_back(chip);
        m.chipsMade += 1;
    }
    if (toStrip)
        for (const std::size_t t : event.removed)
            if (!inPiece[t]) {
                const double ml = tissue.restVolumeM3(t) * 1e6;
                stripMl += ml;
                stripByTissue[static_cast<std::size_t>(resection->tetTissue()[t])] += ml;
            }
    const ResectionTotals& totals = resection->totals();
    for (std::size_t k = 0; k < m.pathologies.size() && k < totals.pathologyRemovedMl.size(); ++k) {
        PathologyResection& p = m.pathologies[k];
        p.removedMl = totals.pathologyRemovedMl[k];
        p.removedPercent = p.volumeMl > 0.0 ? 100.0 * p.removedMl / p.volumeMl : 0.0;
    }
    m.healthyRemovedMl = totals.healthyMl;
    m.deepestMyometriumMm = totals.deepestMyometriumMm;
    m.perforatingCuts = totals.perforations;
    m.cutEvents = totals.events;
    m.removedTets = totals.removedTets;
    m.chips = totals.chips;
    if (m.firstCutS < 0.0)
        m.firstCutS = state.timeS;
    m.resectionTimeS = state.timeS - m.firstCutS;
}

void World::Impl::releaseStrip(const Vec3& whereMm) {
    Chip chip;
    chip.positionMm = whereMm;
    chip.volumeMl = stripMl;
    chip.radiusMm = std::cbrt(3.0 * stripMl * 1e3 / (4.0 * kPi));
    chip.tissue = static_cast<clinical::Tissue>(std::max_element(stripByTissue.begin(), stripByTissue.end()) -
                                                stripByTissue.begin());
    chips.push_back(chip);
    metrics.resection.chipsMade += 1;
    stripMl = 0.0;
    stripByTissue = {};
}

void World::Impl::moveChips(const DeviceSample& device) {
    ResectionMetrics& m = metrics.resection;
    // The loop drawn in catches the chips at its middle; caught, they go with it and leave the cavity when the tip is
    // drawn back behind the internal os.
    const bool drawnIn = state.loop.instrument == kInstrumentLoop && device.workingElementMm <= 1.0;
    const Vec3 between = state.loop.middleMm + state.loop.axis * (0.5 * state.loop.jawLengthMm);
    const bool outOfCavity = dot(state.scope.tipMm - landmarks.internalOsMm, frame.axis) <= 0.0;
    const Vec3 sink = Vec3{0.0, -kChipSinkMmPerS * options.stepS, 0.0};
    std::size_t kept = 0;
    for (std::size_t k = 0; k < chips.size(); ++k) {
        Chip chip = chips[k];
        if (!chip.hooked && drawnIn && distance(chip.positionMm, state.loop.middleMm) <= chip.radiusMm + kChipCatchMm)
            chip.hooked = true;
        if (chip.hooked || chip.grasped) {
            if (outOfCavity) {
                m.chipsCarriedOut += 1;
                continue;
            }
            if (chip.grasped)
                chip.positionMm = between;
            else
                chip.positionMm = state.loop.instrument == kInstrumentLoop ? state.loop.middleMm : state.scope.tipMm;
        } else {
            // Carried by the fluid's flow from the tip to the sheath's outflow holes while it sinks, until the wall
            // stops it (its surface at the contact surface): a chip follows the flow as a tracer would.
            const Vec3 drift = detail::flowVelocityMmPerS(chip.positionMm, state.scope.tipMm, state.scope.shaft,
                                                          state.fluid.inflowMlPerS, state.fluid.outflowMlPerS,
                                                          0.5 * options.scope.diameterMm) *
                               options.stepS;
            // Resting on the wall, the flow still takes it along the wall or away from it; one that came off the loop
            // overlapping the wall goes where that does not press it further in.
            const double reach = chip.radiusMm + 1.0;
            const double clear = std::min(clearanceMm(pointsMm, bvh, chip.positionMm, reach), chip.radiusMm);
            const Vec3 move = drift + sink;
            const auto free = [&](const Vec3& at) { return clearanceMm(pointsMm, bvh, at, reach) >= clear; };
            if (free(chip.positionMm + move)) {
                chip.positionMm = chip.positionMm + move;
            } else { // against the wall: it slides, axis by axis, where the wall lets it
                for (const Vec3& part : {Vec3{move.x, 0.0, 0.0}, Vec3{0.0, move.y, 0.0}, Vec3{0.0, 0.0, move.z}})
                    if (free(chip.positionMm + part))
                        chip.positionMm = chip.positionMm + part;
            }
        }
        chips[kept++] = chip;
    }
    chips.resize(kept);
    m.chipsLeft = chips.size();
}

detail::OpenVessels World::Impl::openVessels() const {
    detail::OpenVessels open;
    if (tetVessels.empty())
        return open;
    Vec3 weighted;
    for (std::size_t f = firstCutFace; f < faceCut.size(); ++f) {
        if (faceDead[f] || faceSealed[f])
            continue;
        const VesselDensity& v = tetVessels[static_cast<std::size_t>(faceTet[f])];
        const double arterial = faceArea[f] * v.arterialPerMm2;
        open.arterialMlPerSKpa += arterial;
        open.venousMlPerSKpa += faceArea[f] * v.venousPerMm2;
        const Triangle& t = (*triangles)[f];
        weighted = weighted + (pointsMm[static_cast<std::size_t>(t[0])] + pointsMm[static_cast<std::size_t>(t[1])] +
                               pointsMm[static_cast<std::size_t>(t[2])]) *
                                  (arterial / 3.0);
    }
    if (open.arterialMlPerSKpa > 0.0)
        open.bleedingMm = weighted * (1.0 / open.arterialMlPerSKpa);
    return open;
}

void World::Impl::coagulate(const std::vector<Vec3>& wire) {
    const double reach2 = kCoagulationReachMm * kCoagulationReachMm;
    for (std::size_t f = firstCutFace; f < faceCut.size(); ++f) {
        if (faceDead[f] || faceSealed[f])
            continue;
        const Triangle& t = (*triangles)[f];
        const Vec3& a = pointsMm[static_cast<std::size_t>(t[0])];
        const Vec3& b = pointsMm[static_cast<std::size_t>(t[1])];
        const Vec3& c = pointsMm[static_cast<std::size_t>(t[2])];
        for (const Vec3& p : wire) // the wire's points lie at most loop.sampleMm apart
            if (closestPointOnTriangle(p, a, b, c).distance2 <= reach2) {
                faceSealed[f] = 1;
                break;
            }
    }
}

void World::Impl::surfaceAfterCut(const std::vector<std::size_t>& removed) {
    // The faces whose tet went (the mesh's boundary, and faces earlier cuts bared).
    for (std::size_t f = 0; f < faceTet.size(); ++f)
        if (!faceDead[f] && faceTet[f] >= 0 && tissue.tetRemoved(static_cast<std::size_t>(faceTet[f])))
            faceDead[f] = 1;
    // The faces the cut bared: a removed tet's face against a live tet, facing out of the live tet (by its fourth
    // point at rest), wet by the fluid.
    auto tris = std::make_shared<std::vector<Triangle>>(*triangles);
    const auto& tets = tissue.tets();
    const auto& across = tissue.neighbours();
    for (const std::size_t t : removed)
        for (std::size_t k = 0; k < 4; ++k) {
            const std::int32_t u = across[t][k];
            if (u < 0 || tissue.tetRemoved(static_cast<std::size_t>(u)))
                continue;
            const Triangle face = mechanics::cutFace(tets, t, k, static_cast<std::size_t>(u), simRest.points);
            tris->push_back(face);
            faceCavity.push_back(1);
            faceInCavity.push_back(0); // the cavity's surface at rest is what the exploration measures
            faceCut.push_back(1);
            faceSealed.push_back(0);
            faceDead.push_back(0);
            faceTet.push_back(u);
            faceArea.push_back(0.5 * norm(triangleNormal(simRest.points, face)));
            faceRegion.push_back(simRest.regionOf(static_cast<std::size_t>(u)));
            facePathology.push_back(resection->tetPathology()[static_cast<std::size_t>(u)]);
            char held = 0;
            for (const std::int32_t v : face)
                held = held || uterus.pointHeld[static_cast<std::size_t>(v)];
            faceHeld.push_back(held);
            const Vec3 c = triangleCentre(simRest.points, face);
            const double along = dot(c - landmarks.internalOsMm, cavityAxis);
            const Vec3 r = c - landmarks.internalOsMm - cavityAxis * along;
            faceUnrolled.push_back({std::atan2(dot(r, cavityLeft), dot(r, cavityAnterior)) / kDeg, along, false});
            faceSeen.push_back(0);
        }
    // The bared faces' points join the solver's precomputed surface (their columns are computed over the next steps).
    std::vector<std::int32_t> bared;
    for (std::size_t f = triangles->size(); f < tris->size(); ++f)
        bared.insert(bared.end(), (*tris)[f].begin(), (*tris)[f].end());
    tissue.extendPrecomputedSurface(bared);
    triangles = tris;
    contactSurface.triangles = *tris;
    bvh.build(*tris, pointsMm, faceDead);
    // What the view draws of the cut: the removed tets (their visual faces hide) and the live faces the cuts bared.
    auto view = std::make_shared<CutView>();
    view->events = resection->totals().events;
    view->removedTets.resize(tissue.tetCount());
    for (std::size_t t = 0; t < view->removedTets.size(); ++t)
        view->removedTets[t] = tissue.tetRemoved(t) ? 1 : 0;
    for (std::size_t f = firstCutFace; f < faceCut.size(); ++f)
        if (!faceDead[f]) {
            view->faces.push_back((*tris)[f]);
            view->faceTissue.push_back(resection->tetTissue()[static_cast<std::size_t>(faceTet[f])]);
        }
    cutView = std::move(view);
}

} // namespace hs::sim
