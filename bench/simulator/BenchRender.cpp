// bench_render: frames per second of the simulator's endoscopic view (hs::simrender) on a scene package, offscreen
// (run under xvfb-run -a). Each frame moves the scope, deforms the visual surface (every point moved, normals
// recomputed, as the simulator does with the world's points) and renders; the table has one row per view size,
// detail (full: the maps; light: the albedo alone, what a software rasterizer gets) and shading. The simulator aims
// at 30 fps or more for the default scene.
//   bench_render SCENE_DIR [--frames N] [--sizes 640x480,960x720] [--repeat N] [--rows mal] [--light-reduction R]
//                [--cut-face] [--blood-clouds N] [--png OUT.png]
// --repeat measures each row N times and keeps the run with the least CPU time (on a machine busy with other work);
// --rows keeps the full-detail rows with the maps (m), with the albedo (a), the light-detail rows (l);
// --light-reduction R decimates the light detail's surface by R (EndoscopicLook::lightReduction).
// --edge-magnification M sets the optic's barrel distortion in every mode (EndoscopicLook::edgeMagnification; 1: none).
// --no-depth-of-field draws every mode without the optic's depth of field (EndoscopicLook::depthOfField).
// --cut-face adds, for each row, the same row with a myoma's cut face filling the field 6 mm ahead of the lens, flat
// (EndoscopicLook::cutPatternContrast 0) and under its solid texture (the default contrast): the worst case of the
// cut surface's fragment shader, every pixel inside the optic's circle running it.
// --blood-clouds N adds to every row N blood clouds (sim::BloodCloud, at most kMaxBloodClouds) before the lens, from
// 3 mm to 15 mm ahead, 0.5 mm to 6 mm wide, as a steady bleed leaves them (9 over its 4.5 s of mixing).
//   bench_render SCENE_DIR --still FRACTION ROLL_DEG --png OUT.png [--sizes WxH] [--full | --light]
// --still draws one picture of the surface at rest in clear saline: the 30 degree optic's tip FRACTION of the way
// from the internal os to the fundus (negative: that share of the way down the cervical canal from the internal
// os), aimed about the pivot, rolled by ROLL_DEG (the docs' picture), with the detail
// the view picks for the GL renderer, or the full or the light one, once the camera's exposure has settled on it.
//   bench_render SCENE_DIR --views [--sizes WxH] [--full | --light]
// --views draws a fixed set of stills of the surface at rest in clear saline (the tip halfway down the cervical
// canal and a quarter, half and three quarters of the way from the internal os to the fundus, each rolled 0, 90, 180
// and 270 degrees), each once the camera's exposure has settled, and prints per view the mean luminance, the clipped
// and near-white shares inside the optic's circle and the time to draw a frame there, then one summary line
// (tools/picture-sweep.sh runs it over the 20-case sweep).
//   bench_render SCENE_DIR --exploration [--sizes WxH] [--fps F] [--png PREFIX] [--trace]
// --exploration plays the built-in exploration (sim::explorationScript, 60 s) on the world and draws it F times a
// second of the trial (default 15) twice, side by side: through the camera head (automatic exposure, white balance,
// tone curve, inverse-square lamp: EndoscopicLook's defaults) and as the view drew before it (a fixed exposure, the
// older lamp falloff); a table of the mean luminance, clipped and highlight shares inside the optic's circle per
// phase of the exploration and over all of it. --png writes PREFIX-camera-N.png and PREFIX-before-N.png at a few
// moments; --trace prints every frame's figures.
#include "hs/clinical/Tissue.h"
#include "hs/scene/ScenePackage.h"
#include "hs/scene/ScopePassage.h"
#include "hs/sim/Scope.h"
#include "hs/sim/World.h"
#include "hs/simrender/EndoscopicView.h"
#include "hs/simrender/Hud.h"

#include <vtkNew.h>
#include <vtkPNGWriter.h>
#include <vtkRenderWindow.h>
#include <vtkRenderer.h>
#include <vtkWindowToImageFilter.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <ctime>
#include <memory>
#include <sstream>
#include <string>
#include <vector>

namespace {

/// The optic's barrel distortion every view of this run draws with (--edge-magnification).
double edgeMagnification = hs::simrender::EndoscopicLook{}.edgeMagnification;
/// Whether the views of this run draw the optic's depth of field (--no-depth-of-field).
bool depthOfField = hs::simrender::EndoscopicLook{}.depthOfField;

struct Size {
    int width = 0, height = 0;
};

struct Kind {
    hs::simrender::ViewDetail detail = hs::simrender::ViewDetail::Full;
    bool maps = true;
    bool deform = true;
};

struct Row {
    Size size;
    std::size_t triangles = 0; ///< drawn with the outer surface shown
    double fps = 0.0;
    double msPerFrame = 0.0;
    double msDeform = 0.0;
    double cpuMsPerFrame = 0.0;     ///< process CPU time (every thread, llvmpipe's too): the cost without other load
    double mainCpuMsPerFrame = 0.0; ///< the calling thread's: the view, VTK and the GL driver's vertex work
};

constexpr int kWarmUpFrames = 5;

double threadCpuSeconds() {
    timespec t{};
    clock_gettime(CLOCK_THREAD_CPUTIME_ID, &t);
    return double(t.tv_sec) + 1e-9 * double(t.tv_nsec);
}

/// `cutContrast` < 0: no cut face; otherwise a myoma's cut face 6 mm ahead of the lens with that pattern contrast.
Row measure(const hs::scene::Scene& scene, const hs::scene::ScopeLandmarks& landmarks, const hs::sim::ScopeFrame& frame,
            Size size, Kind kind, double lightReduction, int frames, const std::string& png, double cutContrast,
            std::size_t clouds) {
    vtkNew<vtkRenderWindow> window;
    window->SetOffScreenRendering(1);
    window->SetMultiSamples(0);
    window->SetSize(size.width, size.height);
    vtkNew<vtkRenderer> renderer;
    window->AddRenderer(renderer);
    hs::simrender::EndoscopicLook look;
    look.edgeMagnification = edgeMagnification;
    look.depthOfField = depthOfField;
    look.materialMaps = kind.maps;
    look.detail = kind.detail;
    look.lightReduction = lightReduction;
    look.cutPatternContrast = std::max(cutContrast, 0.0);
    hs::simrender::EndoscopicView view(renderer, look);
    view.setSurface(scene.surface);
    view.setOuterSurfaceVisible(false); // the scope is inside the body
    hs::sim::ScopeConfig config;
    const std::vector<hs::Vec3>& rest = scene.surface.mesh.points;
    std::vector<hs::Vec3> points(rest.size());
    hs::sim::WorldState state;
    state.fluid.pressureKpa = 10.0;
    state.fluid.inflowMlPerS = 3.0;
    state.fluid.outflowMlPerS = 2.5;
    hs::simrender::ExerciseProgress progress;
    progress.targets = 7;

    // A sweep in the cavity: the tip from a third to two thirds of the way from the internal os to the fundus
    // (aimed about the pivot as a script aims it), the optic turning round, the surface breathing by up to 0.5 mm.
    const auto poseAt = [&](int i) {
        const double t = double(i) / std::max(frames - 1, 1);
        const hs::Vec3 tip = landmarks.internalOsMm + (landmarks.fundusMm - landmarks.internalOsMm) * (0.33 + 0.33 * t);
        return hs::sim::scopePose(frame, config, hs::sim::sampleAiming(frame, tip, -90.0 + 180.0 * t));
    };
    double deformS = 0.0;
    const auto render = [&](int i) {
        const auto start = std::chrono::steady_clock::now();
        const double phase = 0.3 * i;
        if (kind.deform) {
            for (std::size_t p = 0; p < rest.size(); ++p)
                points[p] = rest[p] * (1.0 + 0.01 * std::sin(phase + 0.05 * rest[p].z));
            view.setPoints(points);
        }
        state.timeS = i / 60.0;
        state.scope = poseAt(i);
        view.setPose(hs::simrender::cameraPose(state.scope, config));
        if (cutContrast >= 0.0) {
            // A square 60 mm across, square to the view 6 mm ahead: it fills the optic's circle. Its rest square
            // stays where it is, so the pattern slides over it as the scope turns (the shader's work is the same).
            const hs::Vec3 d = state.scope.direction, up = state.scope.up, side = hs::cross(d, up);
            const hs::Vec3 c = state.scope.tipMm + d * 6.0;
            const std::vector<hs::Vec3> face{c - side * 30.0 - up * 30.0, c + side * 30.0 - up * 30.0,
                                             c + side * 30.0 + up * 30.0, c - side * 30.0 + up * 30.0};
            static const std::vector<hs::Vec3> restFace{{0, -30, -30}, {0, 30, -30}, {0, 30, 30}, {0, -30, 30}};
            view.setCutSurface(face, restFace, {{0, 1, 2}, {0, 2, 3}},
                               {hs::clinical::Tissue::Myoma, hs::clinical::Tissue::Myoma});
        }
        if (clouds > 0) {
            hs::sim::BloodClouds blood;
            blood.count = std::min(clouds, hs::sim::kMaxBloodClouds);
            for (std::size_t k = 0; k < blood.count; ++k) {
                const double share = blood.count > 1 ? double(k) / double(blood.count - 1) : 0.0;
                hs::sim::BloodCloud& c = blood.clouds[k];
                c.centreMm = state.scope.tipMm + state.scope.direction * (15.0 - 12.0 * share) +
                             state.scope.up * (2.0 * std::sin(3.0 * share));
                c.sigmaMm = 6.0 - 5.5 * share; // the oldest widest
                c.bloodMl = 0.001;
            }
            view.setBloodClouds(blood);
        }
        view.setFluid(0.2 * (i % 5) / 4.0, 0.0);
        view.setHud(hs::simrender::hudText(state, {}, progress));
        deformS += std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
        window->Render();
    };
    for (int i = 0; i < kWarmUpFrames; ++i) // shaders compiled, textures uploaded, the GL driver's buffers grown
        render(i % frames);
    deformS = 0.0;
    const auto start = std::chrono::steady_clock::now();
    const std::clock_t cpuStart = std::clock();
    const double mainStart = threadCpuSeconds();
    for (int i = 0; i < frames; ++i)
        render(i);
    const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    const double cpuSeconds = double(std::clock() - cpuStart) / CLOCKS_PER_SEC;
    const double mainSeconds = threadCpuSeconds() - mainStart;
    if (!png.empty()) {
        vtkNew<vtkWindowToImageFilter> grab;
        grab->SetInput(window);
        grab->ReadFrontBufferOff();
        vtkNew<vtkPNGWriter> writer;
        writer->SetFileName(png.c_str());
        writer->SetInputConnection(grab->GetOutputPort());
        writer->Write();
    }
    return {size,
            view.drawnTriangleCount(),
            frames / seconds,
            1000.0 * seconds / frames,
            1000.0 * deformS / frames,
            1000.0 * cpuSeconds / frames,
            1000.0 * mainSeconds / frames};
}

/// An offscreen endoscopic view of the surface at rest in clear saline, aimed like the docs' pictures (--still and
/// --views share it).
class StillCamera {
public:
    StillCamera(const hs::scene::Scene& scene, const hs::scene::ScopeLandmarks& landmarks,
                const hs::sim::ScopeFrame& frame, Size size, hs::simrender::ViewDetail detail)
        : m_landmarks(landmarks), m_frame(frame) {
        m_window->SetOffScreenRendering(1);
        m_window->SetMultiSamples(0);
        m_window->SetSize(size.width, size.height);
        m_window->AddRenderer(m_renderer);
        hs::simrender::EndoscopicLook look;
        look.edgeMagnification = edgeMagnification;
        look.depthOfField = depthOfField;
        look.detail = detail;
        m_view = std::make_unique<hs::simrender::EndoscopicView>(m_renderer, look);
        m_view->setSurface(scene.surface);
    }

    /// The 30 degree optic's tip `fraction` of the way from the internal os to the fundus (negative: that share of
    /// the way down the cervical canal, towards the external os), aimed about the pivot, rolled by `rollDeg`; draws
    /// until the camera's exposure has settled (a tenth of a second of its time between frames, at most 40).
    void aim(double fraction, double rollDeg) {
        const hs::Vec3 tip =
            fraction >= 0.0
                ? m_landmarks.internalOsMm + (m_landmarks.fundusMm - m_landmarks.internalOsMm) * fraction
                : m_landmarks.internalOsMm + (m_landmarks.externalOsMm - m_landmarks.internalOsMm) * -fraction;
        hs::sim::WorldState state;
        state.scope = hs::sim::scopePose(m_frame, m_config, hs::sim::sampleAiming(m_frame, tip, rollDeg));
        state.fluid.pressureKpa = 10.0;
        m_view->setPose(hs::simrender::cameraPose(state.scope, m_config));
        m_view->setHud(hs::simrender::hudText(state, {}, {}));
        for (int k = 0; k < 40; ++k) {
            draw();
            if (k > 0 && m_view->exposureSettled())
                break;
        }
    }

    /// One more frame, a tenth of a second of the camera's time after the last.
    void draw() {
        m_view->setTime(m_timeS);
        m_timeS += 0.1;
        m_window->Render();
    }

    vtkRenderWindow* window() { return m_window; }
    const hs::simrender::EndoscopicView& view() const { return *m_view; }

private:
    const hs::scene::ScopeLandmarks& m_landmarks;
    const hs::sim::ScopeFrame& m_frame;
    hs::sim::ScopeConfig m_config;
    vtkNew<vtkRenderWindow> m_window;
    vtkNew<vtkRenderer> m_renderer;
    std::unique_ptr<hs::simrender::EndoscopicView> m_view;
    double m_timeS = 0.0;
};

int still(const hs::scene::Scene& scene, const hs::scene::ScopeLandmarks& landmarks, const hs::sim::ScopeFrame& frame,
          Size size, const double pose[2], hs::simrender::ViewDetail detail, const std::string& png) {
    StillCamera camera(scene, landmarks, frame, size, detail);
    camera.aim(pose[0], pose[1]);
    vtkNew<vtkWindowToImageFilter> grab;
    grab->SetInput(camera.window());
    grab->ReadFrontBufferOff();
    vtkNew<vtkPNGWriter> writer;
    writer->SetFileName(png.c_str());
    writer->SetInputConnection(grab->GetOutputPort());
    writer->Write();
    const auto& view = camera.view();
    std::printf("%s: %s detail (GL renderer %s), %zu triangles\n", png.c_str(), view.lightDetail() ? "light" : "full",
                view.glRenderer().c_str(), view.drawnTriangleCount());
    return 0;
}

/// The fixed views of --views: the tip's fraction (as --still) and the roll.
constexpr double kViewFractions[] = {-0.5, 0.25, 0.5, 0.75};
constexpr double kViewRollsDeg[] = {0.0, 90.0, 180.0, 270.0};

int views(const hs::scene::Scene& scene, const hs::scene::ScopeLandmarks& landmarks, const hs::sim::ScopeFrame& frame,
          Size size, hs::simrender::ViewDetail detail) {
    StillCamera camera(scene, landmarks, frame, size, detail);
    std::printf("%-9s %6s %8s %9s %11s %9s\n", "fraction", "roll", "luma", "clipped%", "nearWhite%", "ms/frame");
    double lumaMin = 1.0, lumaMax = 0.0, lumaSum = 0.0, clippedMax = 0.0, highlightSum = 0.0, msSum = 0.0;
    int count = 0, inBand = 0;
    for (double fraction : kViewFractions)
        for (double roll : kViewRollsDeg) {
            camera.aim(fraction, roll);
            const hs::simrender::CircleStats stats = camera.view().lastFrameStats();
            // Five more frames, timed.
            constexpr int kTimed = 5;
            const auto start = std::chrono::steady_clock::now();
            for (int k = 0; k < kTimed; ++k)
                camera.draw();
            const double ms =
                std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count() / kTimed;
            std::printf("%-9.2f %6.0f %8.3f %9.2f %11.3f %9.1f\n", fraction, roll, stats.meanLuminance,
                        100.0 * stats.clippedFraction, 100.0 * stats.highlightFraction, ms);
            lumaMin = std::min(lumaMin, stats.meanLuminance);
            lumaMax = std::max(lumaMax, stats.meanLuminance);
            lumaSum += stats.meanLuminance;
            inBand += stats.meanLuminance >= 0.35 && stats.meanLuminance <= 0.65 ? 1 : 0;
            clippedMax = std::max(clippedMax, stats.clippedFraction);
            highlightSum += stats.highlightFraction;
            msSum += ms;
            ++count;
        }
    std::printf("views %d (%s detail, %dx%d): luma mean %.3f min %.3f max %.3f, in 0.35-0.65 %d; clipped max %.2f %%; "
                "near white mean %.3f %%; %.1f fps\n",
                count, camera.view().lightDetail() ? "light" : "full", size.width, size.height, lumaSum / count,
                lumaMin, lumaMax, inBand, 100.0 * clippedMax, 100.0 * highlightSum / count, 1000.0 * count / msSum);
    return 0;
}

/// The luminance statistics of one look over an exploration.
struct LookSummary {
    std::vector<hs::simrender::CircleStats> frames;
    std::vector<double> exposures;
};

void printSummary(const char* name, const LookSummary& s, std::size_t from, std::size_t to) {
    std::vector<double> means;
    double clippedMax = 0.0, clippedMean = 0.0, highlight = 0.0;
    std::size_t inBand = 0;
    for (std::size_t i = from; i < to && i < s.frames.size(); ++i) {
        const auto& f = s.frames[i];
        means.push_back(f.meanLuminance);
        clippedMax = std::max(clippedMax, f.clippedFraction);
        clippedMean += f.clippedFraction;
        highlight += f.highlightFraction;
        inBand += f.meanLuminance >= 0.35 && f.meanLuminance <= 0.65 ? 1 : 0;
    }
    if (means.empty())
        return;
    const double n = static_cast<double>(means.size());
    double sum = 0.0;
    for (double m : means)
        sum += m;
    std::sort(means.begin(), means.end());
    const auto at = [&](double q) { return means[std::min(means.size() - 1, static_cast<std::size_t>(q * n))]; };
    std::printf("%-8s %6zu %8.3f %7.3f %7.3f %7.3f %7.3f %9.1f %10.2f %10.2f %10.2f\n", name, means.size(), sum / n,
                means.front(), at(0.05), at(0.95), means.back(), 100.0 * static_cast<double>(inBand) / n,
                100.0 * clippedMean / n, 100.0 * clippedMax, 100.0 * highlight / n);
}

int exploration(const std::string& folder, Size size, double fps, const std::string& png, bool trace) {
    auto loaded = hs::sim::World::load(folder, hs::sim::WorldOptions{});
    if (!loaded) {
        std::fprintf(stderr, "bench_render: %s\n", loaded.error().message().c_str());
        return 3;
    }
    hs::sim::World& world = **loaded;
    const hs::sim::Script script = hs::sim::explorationScript(world);
    struct Look {
        const char* name;
        vtkNew<vtkRenderWindow> window;
        vtkNew<vtkRenderer> renderer;
        std::unique_ptr<hs::simrender::EndoscopicView> view;
        LookSummary summary;
    };
    Look looks[2];
    looks[0].name = "camera";
    looks[1].name = "before";
    for (int k = 0; k < 2; ++k) {
        Look& l = looks[k];
        l.window->SetOffScreenRendering(1);
        l.window->SetMultiSamples(0);
        l.window->SetSize(size.width, size.height);
        l.window->AddRenderer(l.renderer);
        hs::simrender::EndoscopicLook look;
        look.edgeMagnification = edgeMagnification;
        look.depthOfField = depthOfField;
        look.depthOfField = depthOfField;
        look.hud = false; // the circle's statistics of the picture alone
        if (k == 1) {     // as the view drew before the camera head
            look.autoExposure = false;
            look.exposure = 1.0;
            look.lampAttenuation = {1.0, 0.04, 0.002};
            look.lampColour = {1.0, 1.0, 1.0};
            look.toneKnee = 0.99;
        }
        l.view = std::make_unique<hs::simrender::EndoscopicView>(l.renderer, look);
        l.view->measureFrames(true);
        l.view->setSurface(world.scene().surface);
    }
    const std::size_t per = world.ticksPerStep();
    const std::uint64_t ticks = script.tickCount();
    const double stepS = world.options().stepS;
    const std::uint64_t stepsPerFrame = std::max<std::uint64_t>(1, std::llround(1.0 / (fps * stepS)));
    std::vector<hs::sim::DeviceSample> samples(per);
    std::vector<hs::Vec3> visual;
    std::vector<double> times;
    int pictures = 0;
    for (std::uint64_t tick = 0; tick + per <= ticks; tick += per) {
        for (std::size_t i = 0; i < per; ++i) {
            samples[i] = script.sampleAt(tick + i);
            samples[i].tick = tick + i;
        }
        if (!world.step(samples.data(), per).ok()) {
            std::fprintf(stderr, "bench_render: the exploration's step %llu failed\n",
                         static_cast<unsigned long long>(world.state().step));
            return 4;
        }
        if (world.state().step % stepsPerFrame != 0)
            continue;
        const hs::sim::WorldState& state = world.state();
        times.push_back(state.timeS);
        for (Look& l : looks) {
            l.view->setOuterSurfaceVisible(state.sample.insertionMm < 0.0 || state.contact.perforated);
            world.visualPoints(world.simulationPointsMm(), visual, l.view->sourcePointsInUse());
            l.view->setPoints(visual);
            l.view->setPose(hs::simrender::cameraPose(state.scope, world.options().scope));
            l.view->setFluid(state.fluid.turbidity, state.fluid.redOut);
            l.view->setTime(state.timeS);
            l.window->Render();
            l.summary.frames.push_back(l.view->lastFrameStats());
            l.summary.exposures.push_back(l.view->exposure());
        }
        if (trace)
            std::printf(
                "trace %6.2f s: camera luma %.3f clipped %5.2f %% exposure %7.2f | before luma %.3f | tip %5.1f "
                "mm in, turbidity %.2f, red-out %.2f\n",
                state.timeS, looks[0].summary.frames.back().meanLuminance,
                100.0 * looks[0].summary.frames.back().clippedFraction, looks[0].summary.exposures.back(),
                looks[1].summary.frames.back().meanLuminance, state.sample.insertionMm, state.fluid.turbidity,
                state.fluid.redOut);
        if (!png.empty() && times.size() % static_cast<std::size_t>(std::max(1.0, 10.0 * fps)) == 0 && pictures < 6) {
            ++pictures;
            for (Look& l : looks) {
                vtkNew<vtkWindowToImageFilter> grab;
                grab->SetInput(l.window);
                grab->ReadFrontBufferOff();
                vtkNew<vtkPNGWriter> writer;
                const std::string file = png + "-" + l.name + "-" + std::to_string(pictures) + ".png";
                writer->SetFileName(file.c_str());
                writer->SetInputConnection(grab->GetOutputPort());
                writer->Write();
            }
        }
    }
    const auto gains = looks[0].view->whiteBalanceGains();
    std::printf("exploration of %s: %zu frames at %.0f per trial second, %dx%d, %s detail (GL renderer %s); white "
                "balance %.3f %.3f %.3f\n",
                folder.c_str(), times.size(), fps, size.width, size.height,
                looks[0].view->lightDetail() ? "light" : "full", looks[0].view->glRenderer().c_str(), gains[0],
                gains[1], gains[2]);
    std::printf("inside the optic's circle: luminance (Rec. 709 luma, 0..1) per frame; %% of frames in 0.35-0.65; "
                "clipped (a channel at 255) and highlight (near white) %% of the circle\n");
    const double end = times.empty() ? 0.0 : times.back();
    const std::pair<const char*, std::pair<double, double>> phases[] = {
        {"whole", {0.0, 1e300}}, {"first 8 s", {0.0, 8.0}}, {"8 s on", {8.0, 1e300}}, {"last 6 s", {end - 6.0, 1e300}}};
    for (const auto& [phase, range] : phases) {
        std::size_t from = 0, to = 0;
        while (from < times.size() && times[from] < range.first)
            ++from;
        to = from;
        while (to < times.size() && times[to] < range.second)
            ++to;
        std::printf("%s (%zu frames)\n%-8s %6s %8s %7s %7s %7s %7s %9s %10s %10s %10s\n", phase, to - from, "look",
                    "frames", "mean", "min", "p5", "p95", "max", "% in band", "clip mean", "clip max", "highlight");
        for (const Look& l : looks)
            printSummary(l.name, l.summary, from, to);
    }
    const auto [lo, hi] = std::minmax_element(looks[0].summary.exposures.begin(), looks[0].summary.exposures.end());
    if (lo != looks[0].summary.exposures.end())
        std::printf("camera exposure %.3f .. %.3f\n", *lo, *hi);
    return 0;
}

std::vector<Size> parseSizes(const std::string& text) {
    std::vector<Size> sizes;
    std::stringstream list(text);
    std::string item;
    while (std::getline(list, item, ',')) {
        Size s;
        if (std::sscanf(item.c_str(), "%dx%d", &s.width, &s.height) == 2 && s.width > 0 && s.height > 0)
            sizes.push_back(s);
    }
    return sizes;
}

} // namespace

int main(int argc, char** argv) {
    if (argc < 2) {
        std::fprintf(stderr, "usage: bench_render SCENE_DIR [--frames N] [--sizes 640x480,960x720] [--repeat N] "
                             "[--rows mal] [--light-reduction R] [--cut-face] [--blood-clouds N] [--png OUT.png]\n");
        return 2;
    }
    int frames = 120;
    int repeat = 1;
    double lightReduction = hs::simrender::EndoscopicLook{}.lightReduction;
    std::string only;
    std::vector<Size> sizes{{640, 480}, {960, 720}};
    std::string png;
    bool stillPicture = false;
    bool fixedViews = false;
    bool explore = false;
    bool trace = false;
    bool cutFace = false;
    std::size_t clouds = 0;
    double fps = 15.0;
    hs::simrender::ViewDetail detail = hs::simrender::ViewDetail::Automatic;
    double pose[2] = {0, 0};
    for (int i = 2; i < argc; ++i) {
        const std::string a = argv[i];
        if (a == "--frames" && i + 1 < argc)
            frames = std::max(1, std::atoi(argv[++i]));
        else if (a == "--repeat" && i + 1 < argc)
            repeat = std::max(1, std::atoi(argv[++i]));
        else if (a == "--light-reduction" && i + 1 < argc)
            lightReduction = std::atof(argv[++i]);
        else if (a == "--edge-magnification" && i + 1 < argc)
            edgeMagnification = std::atof(argv[++i]);
        else if (a == "--no-depth-of-field")
            depthOfField = false;
        else if (a == "--rows" && i + 1 < argc)
            only = argv[++i];
        else if (a == "--sizes" && i + 1 < argc)
            sizes = parseSizes(argv[++i]);
        else if (a == "--png" && i + 1 < argc)
            png = argv[++i];
        else if (a == "--trace")
            trace = true;
        else if (a == "--exploration")
            explore = true;
        else if (a == "--views")
            fixedViews = true;
        else if (a == "--fps" && i + 1 < argc)
            fps = std::clamp(std::atof(argv[++i]), 1.0, 200.0);
        else if (a == "--cut-face")
            cutFace = true;
        else if (a == "--blood-clouds" && i + 1 < argc)
            clouds = static_cast<std::size_t>(std::clamp(std::atoi(argv[++i]), 0, 12));
        else if (a == "--full")
            detail = hs::simrender::ViewDetail::Full;
        else if (a == "--light")
            detail = hs::simrender::ViewDetail::Light;
        else if (a == "--still" && i + 2 < argc) {
            stillPicture = true;
            for (double& p : pose)
                p = std::atof(argv[++i]);
        }
    }
    if (explore)
        return exploration(argv[1], sizes.front(), fps, png, trace);
    auto scene = hs::scene::readScenePackage(argv[1]);
    if (!scene) {
        std::fprintf(stderr, "bench_render: %s\n", scene.error().message().c_str());
        return 3;
    }
    auto landmarks = hs::scene::findScopeLandmarks(*scene);
    if (!landmarks) {
        std::fprintf(stderr, "bench_render: %s\n", landmarks.error().message().c_str());
        return 3;
    }
    auto frame = hs::sim::scopeFrame(*landmarks);
    if (!frame) {
        std::fprintf(stderr, "bench_render: %s\n", frame.error().message().c_str());
        return 3;
    }
    if (stillPicture)
        return still(*scene, *landmarks, *frame, sizes.front(), pose, detail, png);
    if (fixedViews)
        return views(*scene, *landmarks, *frame, sizes.front(), detail);
    std::printf("endoscopic view of %s: %zu points, %zu triangles, %d frames per row\n", argv[1],
                scene->surface.mesh.points.size(), scene->surface.mesh.triangles.size(), frames);
    std::printf("%-10s %-6s %-8s %-9s %-9s %9s %8s %10s %12s %14s %9s\n", "size", "detail", "shading", "surface",
                "cut face", "triangles", "fps", "ms/frame", "ms deform", "cpu ms/frame", "cpu main");
    using hs::simrender::ViewDetail;
    const Kind kinds[] = {{ViewDetail::Full, true, true},
                          {ViewDetail::Full, false, true},
                          {ViewDetail::Light, false, true},
                          {ViewDetail::Light, false, false}};
    for (const Size& size : sizes)
        for (const Kind& kind : kinds) {
            const bool light = kind.detail == ViewDetail::Light;
            if (!only.empty() && only.find(light ? 'l' : kind.maps ? 'm' : 'a') == std::string::npos)
                continue;
            const bool first = &size == &sizes.front() && &kind == &kinds[0];
            const double contrast = hs::simrender::EndoscopicLook{}.cutPatternContrast;
            for (double cut : cutFace ? std::vector<double>{-1.0, 0.0, contrast} : std::vector<double>{-1.0}) {
                Row r;
                for (int k = 0; k < repeat; ++k) { // the least CPU time: the run that other work disturbed least
                    const Row run = measure(*scene, *landmarks, *frame, size, kind, lightReduction, frames,
                                            first && cut < 0.0 ? png : "", cut, clouds);
                    if (k == 0 || run.cpuMsPerFrame < r.cpuMsPerFrame)
                        r = run;
                }
                char label[32];
                std::snprintf(label, sizeof label, "%dx%d", size.width, size.height);
                std::printf("%-10s %-6s %-8s %-9s %-9s %9zu %8.1f %10.2f %12.2f %14.2f %9.2f\n", label,
                            light ? "light" : "full", kind.maps && !light ? "maps" : "albedo",
                            kind.deform ? "deformed" : "static",
                            cut < 0.0   ? "-"
                            : cut > 0.0 ? "textured"
                                        : "flat",
                            r.triangles, r.fps, r.msPerFrame, r.msDeform, r.cpuMsPerFrame, r.mainCpuMsPerFrame);
                std::fflush(stdout);
            }
        }
    return 0;
}
