#include "WorldImpl.h"

#include "hs/scene/ScenePackage.h"
#include "hs/scene/Sha256.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <string>

namespace hs::sim {

using namespace detail;

Status checkWorldOptions(const WorldOptions& o) {
    HS_TRY(checkScopeConfig(o.scope));
    HS_TRY(checkFluidSettings(o.fluid));
    const double ticks = o.stepS * kDeviceRateHz;
    if (!std::isfinite(o.stepS) || o.stepS < 0.001 || o.stepS > 0.02 || std::abs(ticks - std::round(ticks)) > 1e-9)
        return fail(ErrorCode::InvalidInput,
                    "world: stepS must be 0.001-0.02 s and a whole number of 1 ms device ticks");
    if (o.solverIterations < 1 || o.solverIterations > 50)
        return fail(ErrorCode::InvalidInput, "world: solverIterations must be 1-50");
    if (!std::isfinite(o.introitusMm) || (o.introitusMm != 0.0 && (o.introitusMm < 40.0 || o.introitusMm > 120.0)))
        return fail(ErrorCode::InvalidInput, "world: introitusMm must be 0 or 40-120 mm");
    return {};
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
    if (options.introitusMm > 0.0) {
        frame.introitusMm = options.introitusMm;
        frame.pivotMm = landmarks.externalOsMm - frame.axis * options.introitusMm;
    }
    simRest = scene.simulation->tets;
    HS_TRY(progress.check("world"));
    HS_TRY(setupTissue());
    setupSurfaceData();
    pointsMm = simRest.points;
    bvh.build(*triangles, pointsMm);
    if (isOperative(options.exercise)) {
        auto made = Resection::make(scene, simRest, uterus.boundary, uterus.faceCavity);
        if (!made)
            return fail(made.error().code, "resection: " + made.error().detail);
        resection = std::make_unique<Resection>(std::move(*made));
        tetVessels = vesselDensities(resection->tetTissue(), resection->tetPathology(), tissue.neighbours());
        firstCutFace = faceCut.size();
        const auto& pathologies = scene.clinical.pathologies;
        for (std::size_t k = 0; k < pathologies.size(); ++k)
            metrics.resection.pathologies.push_back({pathologies[k].id,
                                                     std::string(clinical::toString(pathologies[k].kind)),
                                                     resection->totals().pathologyMl[k], 0.0, 0.0});
    }
    fluid.reset(options.fluid);
    progress.report("world", 0.3);
    HS_TRY(measureCavity());
    HS_TRY(progress.check("world"));
    state.scope = scopePose(frame, options.scope, DeviceSample{});
    state.fluid = fluid.state();
    publishFrame();
    progress.report("world", 1.0);
    return {};
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
    const auto started = std::chrono::steady_clock::now();
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
        const std::uint32_t pressed = s.buttons & ~w.lastButtons;
        if (pressed & kButtonMark)
            markPressed = true;
        if (pressed & kButtonPumpUp)
            w.fluid.setPumpPressure(w.fluid.state().pumpSetKpa + kPumpStepKpa);
        if (pressed & kButtonPumpDown)
            w.fluid.setPumpPressure(w.fluid.state().pumpSetKpa - kPumpStepKpa);
        w.lastButtons = s.buttons;
    }
    const DeviceSample& last = samples[count - 1];
    w.samplesConsumed += count;
    w.state.sample = last;
    // The fluid's pressure for this step from the cavity as the tissue lies (two-way coupling), then the tissue and
    // the scope under it; state.scope is then the physics' scope, held off the wall by the tissue (drawn out of the
    // tip's sub-element dimple).
    const double cavityMl = w.uterus.cavityVolumeMl(w.pointsMm) - w.uterus.restCavityMl;
    const double bloodBeforeMl = w.fluid.state().bloodInCavityMl;
    const detail::OpenVessels open = w.openVessels();
    const double pressureKpa =
        w.fluid.step(dt, last.inflow, last.outflow, cavityMl, w.cavityComplianceMlPerKpa, w.state.contact.forceN, open);
    w.state.fluid = w.fluid.state();
    {
        // The blood the vessels gave this step leaves them as a cloud, carried and spread by the fluid.
        const FluidState& f = w.state.fluid;
        const double bledMl = dt * f.bleedingMlPerS;
        const double held = bloodBeforeMl + bledMl; // what the washout acted on
        const detail::FlowField flow{w.state.scope.tipMm, w.state.scope.shaft, f.inflowMlPerS, f.outflowMlPerS,
                                     0.5 * w.options.scope.diameterMm};
        detail::advanceBloodClouds(w.state.blood, dt, bledMl, open.bleedingMm, flow,
                                   held > 0.0 ? f.bloodInCavityMl / held : 1.0, f.bloodInCavityMl, f.bloodFraction);
    }
    w.physics(last, pressureKpa);
    w.state.step += 1;
    w.state.timeS = static_cast<double>(w.state.step) * dt;
    if (w.resection) {
        const auto cutting = std::chrono::steady_clock::now();
        w.cut(last);
        w.timings.cutMs +=
            std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - cutting).count();
    }
    // The lens against the tissue closes the view too.
    double t = 0.0, a = 0.0, b = 0.0;
    const std::int32_t hit = w.bvh.raycast(w.pointsMm, w.state.scope.tipMm, w.state.scope.direction, 1.0, t, a, b);
    if (hit >= 0 && !w.state.contact.perforated)
        w.state.fluid.redOut = std::max(w.state.fluid.redOut, 1.0 - t);
    w.state.inCavity = dot(w.state.scope.tipMm - w.landmarks.internalOsMm, w.frame.axis) > 0.0;
    w.state.cavityOpeningMl = w.uterus.cavityVolumeMl(w.pointsMm) - w.uterus.restCavityMl;
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
    m.intravasationMl = f.intravasationTotalMl;
    m.bloodLossMl = f.bloodLossMl;
    m.finalPumpPressureKpa = f.pumpSetKpa;
    m.deficitWarning = m.deficitWarning || f.deficitWarning;
    m.deficitLimitReached = m.deficitLimitReached || f.deficitLimit;
    const auto seeing = std::chrono::steady_clock::now();
    if (w.state.timeS + 1e-9 >= w.nextVisibilityS) {
        w.updateVisibility();
        w.nextVisibilityS += kVisibilityPeriodS;
    }
    if (markPressed)
        w.mark();
    const auto seen = std::chrono::steady_clock::now();
    w.timings.visibilityMs += std::chrono::duration<double, std::milli>(seen - seeing).count();
    if (w.state.timeS + 1e-9 >= w.nextSeriesS) {
        w.series.push_back({w.state.timeS, w.seriesForceN, f.pressureKpa, f.deficitMl, f.bloodLossMl, f.pumpSetKpa});
        w.seriesForceN = 0.0;
        w.nextSeriesS += kSeriesPeriodS;
    }
    w.publishFrame();
    w.timings.steps += 1;
    w.timings.totalMs += std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - started).count();
    return {};
}

bool World::surfacePrecomputed() const {
    return impl_->tissue.surfacePrecomputed();
}

const World::StepTimings& World::stepTimings() const {
    return impl_->timings;
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

Status World::setApproach(const Vec3& shaft) {
    Impl& w = *impl_;
    if (!(w.frame.introitusMm > 0.0) || w.state.step != 0 || !(norm(shaft) > 1e-9) || !isFinite(shaft))
        return fail(ErrorCode::InvalidInput, "world: an approach needs introitusMm > 0, a finite direction and no step "
                                             "taken yet");
    w.frame.pivotMm = w.landmarks.externalOsMm - normalized(shaft) * w.frame.introitusMm;
    return {};
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
    return {impl_->pointsMm, impl_->state, impl_->cutView, impl_->chips};
}

std::vector<char> World::visualPointsCut(const CutView* cut) const {
    const auto& embedding = impl_->scene.simulation->surfaceEmbedding;
    std::vector<char> out(embedding.size(), 0);
    if (!cut)
        return out;
    for (std::size_t i = 0; i < embedding.size(); ++i) {
        const auto t = static_cast<std::size_t>(embedding[i].tet);
        out[i] = t < cut->removedTets.size() && cut->removedTets[t] != 0;
    }
    return out;
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
    return "corotational-fem/11";
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
        f.deficitWarningMl != g.deficitWarningMl || f.deficitLimitMl != g.deficitLimitMl || f.medium != g.medium ||
        f.elderlyOrComorbid != g.elderlyOrComorbid)
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

double World::tissueModulusNearKpa(const Vec3& pointMm, double radiusMm, bool stiffened) const {
    const mechanics::CorotationalFem& fem = impl_->tissue;
    const std::vector<Vec3>& x = fem.positionsM();
    const Vec3 p = pointMm * kMm;
    const double r2 = radiusMm * kMm * radiusMm * kMm;
    double weighted = 0.0, volume = 0.0;
    for (std::size_t t = 0; t < fem.tetCount(); ++t) {
        if (fem.tetRemoved(t))
            continue;
        bool near = false;
        for (const std::int32_t k : fem.tets()[t])
            near = near || norm2(x[static_cast<std::size_t>(k)] - p) <= r2;
        if (!near)
            continue;
        const double v = fem.restVolumeM3(t);
        weighted += v * fem.material(t).youngsModulusPa * (stiffened ? fem.stiffeningAt(t) : 1.0);
        volume += v;
    }
    return volume > 0.0 ? weighted / volume * 1e-3 : 0.0;
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
