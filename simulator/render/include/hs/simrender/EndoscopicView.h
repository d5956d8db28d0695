#pragma once
/// The endoscopic view: what a rigid hysteroscope shows of a scene, drawn by VTK into a renderer that a host owns
/// (the simulator's window, the workstation's preview, an offscreen benchmark). It draws the package's visual
/// surface with its maps (albedo; normal and roughness maps through VTK's PBR shading), its points replaced every
/// frame as the tissue deforms, from a camera at the scope's tip lit only by the lamp at the tip (a positional light
/// whose intensity falls off with distance); the distension fluid as haze that thickens with turbidity and depth;
/// red-out as the picture turning red; the optic's circular field with its vignetting as a 2-D mask over the image;
/// and a heads-up text (docs/simulator.md, "Endoscopic view").
///
/// No Qt: the host calls the setters on its render thread, then renders. VTK types stay out of the interface except
/// the renderer the view draws into.

#include "hs/core/Vec3.h"
#include "hs/scene/Scene.h"
#include "hs/scene/ScopeView.h"
#include "hs/sim/Scope.h"

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
    /// Constant, linear (per mm) and quadratic (per mm^2) attenuation of the lamp: half the light at about 14 mm.
    std::array<double, 3> lampAttenuation{1.0, 0.04, 0.002};
    bool materialMaps = true; ///< PBR shading with the normal and roughness maps; false: albedo only (Phong)
    ViewDetail detail = ViewDetail::Automatic;
    /// Share of the triangles the light detail leaves out (decimateForView); 0: none.
    double lightReduction = 0.5;
    bool opticMask = true;        ///< the circular field and its vignetting
    bool hud = true;              ///< the heads-up text
    double clearFogPerMm = 0.004; ///< 1/mm, extinction of clear saline (a faint haze at the cavity's far end)
    double turbidFogPerMm = 0.12; ///< 1/mm, added at turbidity 1 (blood and debris: opaque beyond ~2 cm)
    std::array<double, 3> fogColour{0.42, 0.16, 0.12}; ///< linear RGB of lamp light scattered back by the medium
    std::array<double, 3> redOutColour{0.45, 0.03, 0.04};
};

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
    /// Turbidity 0 (clear) .. 1 (opaque); red-out 0 .. 1 (FluidState).
    void setFluid(double turbidity, double redOut);
    void setHud(const HudText& text);

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
