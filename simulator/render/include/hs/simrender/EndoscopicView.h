#pragma once
/// The endoscopic view: what a rigid hysteroscope shows of a scene, drawn by VTK into a renderer that a host owns
/// (the simulator's window, the workstation's preview, an offscreen benchmark). It draws the package's visual
/// surface with its maps (albedo; normal and roughness maps through VTK's PBR shading), its points replaced every
/// frame as the tissue deforms, from a camera at the scope's tip lit only by the lamp at the tip (a positional light
/// whose light falls as the inverse square of the distance); the distension fluid as haze that thickens with
/// turbidity and depth; red-out as the picture turning red; the camera head (automatic exposure metered in the
/// optic's circle, white balance, a tone curve with a soft shoulder: Exposure.h); the optic's circular field with its
/// vignetting as a 2-D mask over the image, its barrel distortion on the tissue's vertices; and a heads-up text
/// (docs/simulator.md, "Endoscopic view").
///
/// No Qt: the host calls the setters on its render thread, then renders. VTK types stay out of the interface except
/// the renderer the view draws into.

#include "hs/core/Optics.h"
#include "hs/core/Vec3.h"
#include "hs/scene/Scene.h"
#include "hs/scene/ScopeView.h"
#include "hs/sim/Scope.h"
#include "hs/sim/World.h"
#include "hs/simrender/Exposure.h"

#include <array>
#include <memory>
#include <string>
#include <vector>

class vtkActor;
class vtkRenderer;

namespace hs::simrender {

/// Where the camera stands and looks.
struct CameraPose {
    Vec3 eyeMm;                  ///< the lens at the scope's tip
    Vec3 direction{0, 0, 1};     ///< unit, where the optic looks
    Vec3 up{0, 1, 0};            ///< unit, the image's up
    double fieldOfViewDeg = 90.; ///< degrees, the full angle across the optic's circular field
    double focusNearMm = 2.0;    ///< mm, the nearest sharp distance (sim::scopeFocusNearMm)
    double focusFarMm = 50.0;    ///< mm, the farthest sharp distance (sim::scopeFocusFarMm)
};
/// The simulator's scope: at the tip, looking along the optic, the field of view of the configuration.
CameraPose cameraPose(const sim::ScopePose& pose, const sim::ScopeConfig& config);
/// The workstation's preview pose (scene::scopeView, scene::viewOfRegion).
CameraPose cameraPose(const scene::ScopeView& view, double fieldOfViewDeg);

/// How much the view draws. A software rasterizer (Mesa's llvmpipe on a machine without a GPU) shades every pixel on
/// the CPU, where the PBR shading, mipmapped sampling of a deforming surface and every triangle cost: the light detail
/// keeps the view above 30 frames per second there (docs/simulator.md, "Endoscopic view").
enum class ViewDetail {
    Automatic, ///< Light when the GL renderer is a software one (isSoftwareRenderer), Full on a GPU
    Full,      ///< the maps when `materialMaps` (PBR shading)
    Light,     ///< the albedo alone (Phong shading, no mipmaps); the surface decimated by `lightReduction`
};

struct EndoscopicLook {
    double nearClipMm = 0.3;  ///< mm; the lens sees tissue this close
    double farClipMm = 300.0; ///< mm; beyond any cavity
    double lampIntensity = 1.4;
    /// Constant, linear (per mm) and quadratic (per mm^2) attenuation of the lamp: the light guide's end is a small
    /// source beside the lens, so the irradiance falls as the inverse square of the distance beyond a few mm:
    /// 1 / (1 + (d / 2 mm)^2).
    std::array<double, 3> lampAttenuation{1.0, 0.0, 0.25};
    /// The lamp's colour (linear RGB): a xenon arc source, about 6000 K. The camera's white balance, set once at the
    /// start as a "white" button on a white target under this lamp does, divides it out (whiteBalanceGains).
    std::array<double, 3> lampColour{1.0, 0.93, 0.87};
    /// The camera head's automatic exposure (driven by the picture inside the optic's circle); off: `exposure` fixed.
    bool autoExposure = true;
    AutoExposureSettings exposureSettings;
    double exposure = 16.0; ///< the automatic exposure's start (the tissue at about a centimetre)
    /// The camera's tone curve: linear up to this share of full scale, then a shoulder that approaches full scale
    /// without reaching it (a camera head's knee; x / (1 + x) in units of the headroom above the knee, Reinhard et al.
    /// 2002): a wall five times brighter than the knee still shows at 98 % of full scale, with its texture.
    double toneKnee = 0.7;
    bool materialMaps = true; ///< PBR shading with the normal and roughness maps; false: albedo only (Phong)
    ViewDetail detail = ViewDetail::Automatic;
    /// Share of the triangles the light detail leaves out (decimateForView); 0: none.
    double lightReduction = 0.5;
    /// The optic's barrel distortion: the radial magnification at the edge of the field relative to its centre. Rigid
    /// rod-lens endoscopes show an image at the periphery at 52 % of its size in the middle (docs/references.md
    /// [RigidEndoscopeDistortion2015]); 1: a rectilinear image. The field's angle stays at the circle's edge.
    double edgeMagnification = 0.52;
    /// The optic's depth of field: what lies outside the pose's focus range blurs by its circle of confusion (a thin
    /// lens focused between the range's limits, docs/references.md [Potmesil1981]); the overlays stay sharp.
    bool depthOfField = true;
    /// The circle a point at either limit of the focus range blurs into, as a share of the picture's height: one line
    /// of a 480-line picture, what the view's own resolution shows as sharp.
    double sharpCircleShare = 1.0 / 480.0;
    double largestBlurShare = 0.03; ///< the largest blur's radius, as a share of the picture's height
    bool opticMask = true;          ///< the circular field and its vignetting
    bool hud = true;                ///< the heads-up text
    double clearFogPerMm = 0.004;   ///< 1/mm, extinction of clear saline (a faint haze at the cavity's far end)
    double turbidFogPerMm = 0.12;   ///< 1/mm, added at turbidity 1 (blood and debris: opaque beyond ~2 cm)
    std::array<double, 3> fogColour{0.42, 0.16, 0.12}; ///< linear RGB of lamp light scattered back by the medium
    std::array<double, 3> redOutColour{0.45, 0.03, 0.04};
    /// 1/mm, absorption of whole blood at 630, 550 and 470 nm for red, green and blue (hs::kWholeBloodAbsorptionPerMm,
    /// docs/references.md [Prahl1999]); scaled by blood's share of the fluid.
    std::array<double, 3> bloodAbsorptionPerMm = kWholeBloodAbsorptionPerMm;
    /// Linear RGB of the faces a cut bares, by clinical::Tissue (myometrium, endometrium, cervix, myoma, polyp): flat
    /// colours of this project's choice after the atlases' descriptions (a myoma's interior pale and whorled, a
    /// polyp's stroma pink, the muscle red).
    std::array<std::array<double, 3>, 5> cutColour{
        {{0.62, 0.30, 0.27}, {0.70, 0.33, 0.30}, {0.72, 0.50, 0.46}, {0.82, 0.74, 0.68}, {0.80, 0.55, 0.48}}};
    /// 0-1: how far the cut faces' solid texture (a myoma's whorls, a polyp's glands and vessels, the muscle's
    /// bundles: docs/simulator.md, "The cut in the picture") darkens or pales their colour; 0: flat colours.
    double cutPatternContrast = 0.35;
    double loopWireRadiusMm = 0.15; ///< mm, the loop's wire drawn (a 0.3 mm electrode)
    double jawRadiusMm = 0.4;       ///< mm, the 5 Fr scissors' and grasper's shaft and jaws drawn (a 0.8 mm jaw)
};

/// The circle of confusion's diameter of a point `distanceMm` from the lens, in units of the circle a fixed-focus optic
/// sharp from `nearMm` to `farMm` allows at those limits: a thin lens focused at their harmonic mean, whose blur
/// grows as |1/d - 1/d_focus| (Potmesil & Chakravarty 1981, docs/references.md [Potmesil1981]). 1 at either limit,
/// under 1 between them, growing as 1/d in front of the near one. The view's depth of field blurs a pixel by
/// (this - 1) / 2 sharp circles in radius (EndoscopicLook::depthOfField).
double circleOfConfusionShare(double distanceMm, double nearMm, double farMm);

/// Text of the heads-up display (one line each; empty lines are skipped).
struct HudText {
    std::string status;  ///< pressure, flows, deficit, time, force
    std::string warning; ///< drawn in red (deficit, perforation); empty: none
};

class EndoscopicView {
public:
    /// Draws into `renderer` (the host keeps it alive longer than the view). Turns off the renderer's automatic
    /// lights: the lamp at the tip is the only light.
    explicit EndoscopicView(vtkRenderer* renderer, const EndoscopicLook& look = {});
    ~EndoscopicView();
    EndoscopicView(const EndoscopicView&) = delete;
    EndoscopicView& operator=(const EndoscopicView&) = delete;

    /// The surface to draw (topology, UVs, normals, maps); replaces the previous one. Its points are the rest
    /// points until setPoints(). The detail is decided at the first render, when the GL renderer is known.
    void setSurface(const scene::VisualSurface& surface);
    void clear();
    bool hasSurface() const;
    std::size_t pointCount() const;

    /// The surface's current points (mm; as many as the surface's): the tissue deformed. Normals follow.
    /// Ignored when the count differs.
    void setPoints(const std::vector<Vec3>& pointsMm);
    void setPose(const CameraPose& pose);
    /// Whether the organ's outer surface (faces whose "tissue" label is serosa) is drawn. From inside the body it is
    /// hidden behind the wall, and leaving it out halves the triangles to draw; the simulator shows it while the tip
    /// is outside the external os or has perforated the wall. Default: drawn.
    void setOuterSurfaceVisible(bool visible);
    /// The points of the visual surface setPoints reads now (indices into it; empty: every point): the ones drawn,
    /// of the inner faces alone while the outer surface is hidden. A caller that computes the deformed points may
    /// compute just these (sim::World::visualPoints); the others may be left as they were.
    const std::vector<std::int32_t>& sourcePointsInUse() const;
    /// Turbidity 0 (clear) .. 1 (opaque); red-out 0 .. 1; blood's share of the fluid 0 .. 1, mixed through it
    /// (BloodClouds::mixedFraction; FluidState::bloodFraction without clouds).
    void setFluid(double turbidity, double redOut, double bloodFraction = 0.0);
    /// The blood not yet mixed through the fluid: clouds that absorb the light on its way through them (none: none).
    void setBloodClouds(const sim::BloodClouds& clouds);
    void setHud(const HudText& text);
    /// Hides the faces on the visual surface's points flagged in `hidden` (their tet was cut away:
    /// sim::World::visualPointsCut); empty: nothing hidden.
    void setHiddenPoints(const std::vector<char>& hidden);
    /// The faces the cuts bared (`faces` in indices of `simulationPointsMm`, the simulation mesh's current points;
    /// `restPointsMm` the same points at rest, as many), coloured by `tissue` (cutColour) under its solid texture
    /// (cutPatternContrast) of the rest positions, through the same fluid and optic as the tissue; no faces, or rest
    /// points that are not as many: none drawn.
    void setCutSurface(const std::vector<Vec3>& simulationPointsMm, const std::vector<Vec3>& restPointsMm,
                       const std::vector<Triangle>& faces, const std::vector<clinical::Tissue>& tissue);
    /// The chips in the fluid, drawn as small polyhedra of their size in their tissue's colour with the cut faces
    /// (call before setCutSurface, which draws both).
    void setChips(const std::vector<sim::Chip>& chips);
    /// The resectoscope's loop: the wire and its two arms back to the sheath, glowing while it cuts or coagulates;
    /// not drawn when `loop.out` is false.
    void setLoop(const sim::LoopState& loop);
    /// The host's clock (s; the trial's time in the simulator) that the camera's exposure adapts by; without it the
    /// view reads the wall clock at each render.
    void setTime(double seconds);

    /// The exposure the next frame is shot with (a factor on the light reaching the sensor).
    double exposure() const;
    /// Whether the automatic exposure has settled on what the last frame showed (always with a fixed exposure): a
    /// host that draws only on demand (a still preview) draws again until it has.
    bool exposureSettled() const;
    /// The white balance's gains per channel (1 on green).
    std::array<double, 3> whiteBalanceGains() const;
    /// The last rendered frame inside the optic's circle (measured when the automatic exposure is on, or after
    /// measureFrames(true)).
    const CircleStats& lastFrameStats() const;
    /// Measures every frame's circle even when the exposure is fixed (the benchmark's baseline).
    void measureFrames(bool on);

    const EndoscopicLook& look() const;
    /// The GL renderer's name (glGetString(GL_RENDERER)); empty before the first render.
    const std::string& glRenderer() const;
    /// Whether the light detail is drawn (ViewDetail; Automatic decides at the first render).
    bool lightDetail() const;
    /// Triangles drawn with the outer surface shown: the visual surface's, or fewer when decimated.
    std::size_t drawnTriangleCount() const;
    vtkActor* tissueActor() const;

private:
    struct Impl;
    std::unique_ptr<Impl> m_impl;
};

} // namespace hs::simrender
