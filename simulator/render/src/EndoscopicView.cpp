// The endoscopic view's VTK pipeline: the textured, deforming tissue surface (lighter on a software rasterizer), the
// lamp at the tip, the fluid's haze and red-out in the surface's fragment shader, and the optic's mask and the
// heads-up text as 2-D overlays.
#include "hs/simrender/EndoscopicView.h"

#include "FocusBlur.h"

#include "hs/clinical/Tissue.h"
#include "hs/sim/Resection.h"
#include "hs/simrender/ViewDecimation.h"

#include <vtkActor.h>
#include <vtkActor2D.h>
#include <vtkCallbackCommand.h>
#include <vtkCamera.h>
#include <vtkCameraPass.h>
#include <vtkCellArray.h>
#include <vtkCellData.h>
#include <vtkFloatArray.h>
#include <vtkImageData.h>
#include <vtkLight.h>
#include <vtkLightsPass.h>
#include <vtkMatrix4x4.h>
#include <vtkOpaquePass.h>
#include <vtkOpenGLRenderWindow.h>
#include <vtkOverlayPass.h>
#include <vtkPointData.h>
#include <vtkPoints.h>
#include <vtkPolyData.h>
#include <vtkPolyDataMapper.h>
#include <vtkPolyDataMapper2D.h>
#include <vtkPolyDataTangents.h>
#include <vtkProperty.h>
#include <vtkProperty2D.h>
#include <vtkRenderPassCollection.h>
#include <vtkRenderWindow.h>
#include <vtkRenderer.h>
#include <vtkSequencePass.h>
#include <vtkShaderProperty.h>
#include <vtkSmartPointer.h>
#include <vtkTextActor.h>
#include <vtkTextProperty.h>
#include <vtkTexture.h>
#include <vtkTranslucentPass.h>
#include <vtkTubeFilter.h>
#include <vtkUniforms.h>
#include <vtkUnsignedCharArray.h>
#include <vtkVolumetricPass.h>

#include <algorithm>
#include <chrono>
#include <cmath>

namespace hs::simrender {

namespace {

constexpr double kPi = 3.14159265358979323846;

/// Applied after VTK's own texturing (so after lighting and the albedo): the medium between lens and tissue dims the
/// tissue's light (Beer-Lambert) and scatters the lamp's light back; the lamp's light falls as 1 / (1 + (r / r0)^2)
/// along the ray, so the scattered light sums to sigma r0 atan(depth / r0) (single scattering; near the lens most of
/// it), at most sigma r0 pi / 2 however far the wall; blood mixed into the fluid absorbs per colour along the light's
/// way from the lamp to the wall and back (the scattered light's along about r0); red-out covers everything; then the
/// camera head: its exposure and white balance, and its tone curve (linear to the knee, above it a shoulder
/// x / (1 + x) in units of the headroom, Reinhard et al. 2002, that nears full scale without reaching it).
constexpr const char* kFluidShader = R"(//VTK::TCoord::Impl
  {
    gl_FragData[0].rgb *= exp(-hsBloodAbsorption * 2.0 * hsCloudPathVSOutput);
    float hsNdcZ = gl_FragCoord.z * 2.0 - 1.0;
    float hsDepth = 2.0 * hsNear * hsFar / (hsFar + hsNear - hsNdcZ * (hsFar - hsNear));
    float hsTransmitted = exp(-hsFogPerMm * hsDepth);
    float hsScattered = 1.0 - exp(-hsFogPerMm * hsLampMm * atan(hsDepth / hsLampMm));
    gl_FragData[0].rgb = gl_FragData[0].rgb * hsTransmitted * exp(-hsBloodPerMm * 2.0 * hsDepth) +
                         hsFogColour * hsScattered * exp(-hsBloodPerMm * hsLampMm);
    gl_FragData[0].rgb = mix(gl_FragData[0].rgb, hsRedOutColour, hsRedOut);
    vec3 hsSensor = gl_FragData[0].rgb * hsExposure * hsWhite;
    vec3 hsOver = max(hsSensor - vec3(hsKnee), vec3(0.0)) / (1.0 - hsKnee);
    gl_FragData[0].rgb = min(hsSensor, vec3(hsKnee)) + (1.0 - hsKnee) * hsOver / (vec3(1.0) + hsOver);
  }
)";

/// The faces a cut bares are carved from a block of their tissue: a solid texture of the rest position (Peachey,
/// "Solid texturing of complex surfaces", and Perlin, "An image synthesizer", SIGGRAPH 1985), so the pattern stays
/// with the tissue as it moves, and a later cut through the same place shows the same pattern one layer deeper. It
/// modulates each face's tissue colour (cutColour) before the lighting, after the gross pathology's descriptions of
/// cut surfaces (docs/references.md [Robbins2020]): a myoma's fascicles of smooth muscle in whorls round centres a
/// few millimetres apart, darker bands in a pale ground; a polyp's oedematous stroma with dilated glands (pale round
/// spaces) and thick-walled vessels (dark red points); the myometrium's interlacing bundles as streaks; the
/// endometrium's glands, smaller and denser; the cervix's fibrous stroma, faint streaks. Value noise and its
/// turbulence (Perlin 1985) bend the bands, jittered feature points (Worley, "A cellular texture basis function",
/// SIGGRAPH 1996) place whorls, glands and vessels. hsPatternVSOutput is the clinical::Tissue value (-1: plain).
constexpr const char* kCutVertexDec = R"(//VTK::Color::Dec
in vec3 hsRestMC;
in float hsPatternMC;
out vec3 hsRestVSOutput;
out float hsPatternVSOutput;
)";
constexpr const char* kCutVertexImpl = R"(//VTK::Color::Impl
  hsRestVSOutput = hsRestMC;
  hsPatternVSOutput = hsPatternMC;
)";
constexpr const char* kCutFragmentDec = R"(//VTK::Color::Dec
in vec3 hsRestVSOutput;
in float hsPatternVSOutput;
float hsHash(vec3 p) {
  p = fract(p * vec3(0.1031, 0.1030, 0.0973));
  p += dot(p, p.yxz + 33.33);
  return fract((p.x + p.y) * p.z);
}
vec3 hsHash3(vec3 p) {
  return vec3(hsHash(p), hsHash(p + vec3(17.0, 59.0, 23.0)), hsHash(p + vec3(41.0, 7.0, 89.0)));
}
float hsNoise(vec3 x) {
  vec3 i = floor(x);
  vec3 f = fract(x);
  vec3 u = f * f * (3.0 - 2.0 * f);
  return mix(mix(mix(hsHash(i), hsHash(i + vec3(1.0, 0.0, 0.0)), u.x),
                 mix(hsHash(i + vec3(0.0, 1.0, 0.0)), hsHash(i + vec3(1.0, 1.0, 0.0)), u.x), u.y),
             mix(mix(hsHash(i + vec3(0.0, 0.0, 1.0)), hsHash(i + vec3(1.0, 0.0, 1.0)), u.x),
                 mix(hsHash(i + vec3(0.0, 1.0, 1.0)), hsHash(i + vec3(1.0, 1.0, 1.0)), u.x), u.y), u.z);
}
float hsTurbulence(vec3 p) {
  float t = 0.0;
  float a = 0.5;
  for (int k = 0; k < 4; ++k) {
    t += a * abs(2.0 * hsNoise(p) - 1.0);
    p = p * 2.03 + vec3(5.1, 1.7, 3.3);
    a *= 0.5;
  }
  return t;
}
// The distance (in cells) from p to the nearest feature point of a unit lattice with one jittered point per cell;
// `cell` the nearest point's cell.
float hsCells(vec3 p, out vec3 cell) {
  vec3 i = floor(p);
  float best = 8.0;
  cell = i;
  for (int z = -1; z <= 1; ++z)
    for (int y = -1; y <= 1; ++y)
      for (int x = -1; x <= 1; ++x) {
        vec3 c = i + vec3(float(x), float(y), float(z));
        float d = length(c + hsHash3(c) - p);
        if (d < best) {
          best = d;
          cell = c;
        }
      }
  return best;
}
// Round spaces `sizeMm` apart, radius rMm to 2 rMm each: 1 inside, 0 outside.
float hsSpaces(vec3 p, float sizeMm, float rMm, vec3 seed) {
  vec3 cell;
  float dMm = sizeMm * hsCells(p / sizeMm + seed, cell);
  float r = rMm * (1.0 + hsHash(cell + vec3(11.0)));
  return 1.0 - smoothstep(0.8 * r, r, dMm);
}
// The tissue's colour factor at rest position p (mm); 1 where the ground shows.
vec3 hsCutPattern(vec3 p, float kind, float contrast) {
  vec3 ground = vec3(1.0);
  if (kind < -0.5 || contrast <= 0.0)
    return ground;
  float mottle = 1.0 + contrast * 0.3 * (hsNoise(p * 1.7) - 0.5);
  if (kind > 2.5 && kind < 3.5) { // myoma: whorled fascicles round centres 4 mm apart
    vec3 cell;
    float rMm = 4.0 * hsCells(p / 4.0, cell);
    float band = 0.5 + 0.5 * sin(6.2831853 * (rMm / 0.9 + 2.0 * hsTurbulence(p / 2.0)));
    return mottle * mix(ground, vec3(0.78, 0.70, 0.70), contrast * 1.4 * smoothstep(0.3, 0.9, band));
  }
  if (kind > 3.5) { // polyp: oedematous stroma, dilated glands, thick-walled vessels
    float gland = hsSpaces(p, 1.0, 0.12, vec3(3.1, 0.0, 0.0));
    float vessel = hsSpaces(p, 2.2, 0.07, vec3(0.0, 7.3, 0.0));
    vec3 c = mix(ground, vec3(1.18, 1.22, 1.20), min(1.0, contrast * 2.0) * gland);
    return mottle * mix(c, vec3(0.60, 0.28, 0.28), min(1.0, contrast * 3.0) * vessel);
  }
  if (kind > 0.5 && kind < 1.5) { // endometrium: glands, smaller and denser
    float gland = hsSpaces(p, 0.5, 0.06, vec3(0.0, 0.0, 5.7));
    return mottle * mix(ground, vec3(1.15, 1.17, 1.15), min(1.0, contrast * 2.0) * gland);
  }
  // myometrium and cervix: interlacing bundles, the cervix's fainter
  float streak = 0.5 + 0.5 * sin(6.2831853 * (dot(p, vec3(0.55, 0.35, 0.76)) / 1.1 + 2.0 * hsTurbulence(p / 2.5)));
  float depth = kind > 1.5 ? 0.7 : 1.2;
  return mottle * mix(ground, vec3(0.80, 0.76, 0.78), depth * contrast * smoothstep(0.3, 1.0, streak));
}
)";
constexpr const char* kCutFragmentImpl = R"(//VTK::Color::Impl
  {
    vec3 hsPattern = hsCutPattern(hsRestVSOutput, hsPatternVSOutput, hsCutContrast);
    diffuseColor *= hsPattern;
    ambientColor *= hsPattern;
  }
)";

/// The blood clouds (sim::BloodCloud, docs/simulator.md "Blood clouds") on the way from the lens to a vertex: each a
/// Gaussian of its blood (mL) about its centre (view coordinates, mm; w its standard deviation), whose integral along
/// the ray from the lens (the origin) to the vertex at `rayVC` is the blood's share of the fluid times the path, in
/// mm: exp(-b^2 / 2 s^2) / (2 pi s^2) across the ray at the distance b of the centre from it, times the part of the
/// Gaussian between the lens and the vertex along it (erf by docs/references.md [AbramowitzStegun1964], 7.1.26: error
/// below 2e-7); rays more than 5 s from a centre skip it (exp(-12.5)). The fragments interpolate it between the
/// vertices (a cloud is at least 0.5 mm wide, the surface's triangles about a millimetre: per fragment it cost half
/// the frame on a software rasterizer) and absorb as that much whole blood would, on the lamp's way there and back
/// (hsBloodAbsorption, 1/mm).
constexpr const char* kBloodCloudVertexDec = R"(//VTK::Light::Dec
out float hsCloudPathVSOutput;
float hsErf(float x) {
  float t = 1.0 / (1.0 + 0.3275911 * abs(x));
  float y = 1.0 - (((((1.061405429 * t - 1.453152027) * t) + 1.421413741) * t - 0.284496736) * t + 0.254829592) *
                      t * exp(-x * x);
  return sign(x) * y;
}
float hsCloudPath(vec3 rayVC, vec4 centre[12], float blood[12], int count) {
  float len = length(rayVC);
  vec3 dir = rayVC / max(len, 1.0e-6);
  float path = 0.0;
  for (int i = 0; i < 12; ++i) {
    if (i >= count)
      break;
    float s = max(centre[i].w, 1.0e-3);
    float t0 = dot(centre[i].xyz, dir);
    float b2 = max(dot(centre[i].xyz, centre[i].xyz) - t0 * t0, 0.0);
    if (b2 > 25.0 * s * s || blood[i] <= 0.0)
      continue;
    float across = exp(-0.5 * b2 / (s * s)) / (6.2831853 * s * s);
    float along = 0.5 * (hsErf((len - t0) / (1.4142136 * s)) + hsErf(t0 / (1.4142136 * s)));
    path += 1000.0 * blood[i] * across * along;
  }
  return path;
}
)";
constexpr const char* kBloodCloudFragmentDec = R"(//VTK::Light::Dec
in float hsCloudPathVSOutput;
)";
static_assert(sim::kMaxBloodClouds == 12, "kBloodCloudVertexDec's arrays hold kMaxBloodClouds clouds");

/// The optic's barrel distortion, applied to the tissue's vertices after VTK's projection (a vertex-shader lens
/// model: the visual surface is refined to about a millimetre where the scope sees it, so its triangles stay small
/// against the curvature of the map). In units of the optic's circle (rho = 1 at its edge; hsFieldScale turns the
/// viewport's normalized coordinates into them), a point the rectilinear camera puts at rho goes to
/// atan(a rho) / atan(a): monotone for every rho, so nothing outside the field folds into it, the edge stays at the
/// field's angle, and the radial magnification at the edge is 1 / (1 + a^2) of the centre's. The clipper cuts a
/// triangle that crosses the near plane after this shader, at points it does not move: so that those and their
/// neighbours agree, the map fades in over the first hsFadeMm of depth (a wall that close fills the field anyway).
/// Otherwise a sliver of the background showed at the field's edge with the lens against the canal.
constexpr const char* kOpticVertexShader = R"(//VTK::PositionVC::Impl
  if (hsBarrel > 0.0 && gl_Position.w > hsNear) {
    float hsRho = length(gl_Position.xy / gl_Position.w * hsFieldScale);
    float hsFade = smoothstep(hsNear, hsFadeMm, gl_Position.w);
    if (hsRho > 1.0e-6)
      gl_Position.xy *= mix(1.0, atan(hsBarrel * hsRho) / (atan(hsBarrel) * hsRho), hsFade);
  }
  hsCloudPathVSOutput = hsCloudPath(vertexVCVSOutput.xyz, hsCloudCentre, hsCloudBlood, hsCloudCount);
)";

/// mm beyond the blur's onset within which a drawn point turns the depth of field on (gateFocusBlur): a triangle's
/// reach (the visual surface's edges are about a millimetre), so a face whose corners lie beyond the onset but whose
/// middle lies before it still blurs.
constexpr double kFocusGateMarginMm = 1.0;

/// mm of depth over which the optic's distortion fades in from the near plane (kOpticVertexShader).
constexpr double kDistortionFadeMm = 2.0;

/// a of the optic's map atan(a rho) / atan(a), whose radial magnification at the field's edge is `edgeMagnification`
/// of the centre's, 1 / (1 + a^2); 0 (a rectilinear image) at 1 or above.
double barrelCoefficient(double edgeMagnification) {
    if (!std::isfinite(edgeMagnification) || edgeMagnification >= 1.0)
        return 0.0;
    return std::sqrt(1.0 / std::max(edgeMagnification, 0.05) - 1.0);
}

/// The optic's vignetting: opacity of the mask at fractions of the field's radius (a rod-lens optic's relative
/// illumination: even over most of the field, falling in its outer tenth; black beyond it).
constexpr std::array<std::array<double, 2>, 7> kVignette{
    {{0.0, 0.0}, {0.7, 0.0}, {0.85, 0.08}, {0.93, 0.22}, {0.97, 0.45}, {1.0, 1.0}, {4.0, 1.0}}};
constexpr int kMaskSegments = 96;
/// The occluder's distance from the lens, in near clipping distances: in front of any tissue that is drawn.
constexpr double kOccluderDepth = 1.05;

vtkSmartPointer<vtkImageData> imageOf(const ImageU8& image, int channels) {
    auto data = vtkSmartPointer<vtkImageData>::New();
    data->SetDimensions(image.width(), image.height(), 1);
    data->AllocateScalars(VTK_UNSIGNED_CHAR, channels);
    auto* pixels = static_cast<unsigned char*>(data->GetScalarPointer());
    const auto w = static_cast<std::size_t>(image.width());
    for (int y = 0; y < image.height(); ++y) // VTK's images start at the bottom row
        for (int x = 0; x < image.width(); ++x)
            for (int c = 0; c < channels; ++c)
                pixels[(static_cast<std::size_t>(image.height() - 1 - y) * w + static_cast<std::size_t>(x)) *
                           static_cast<std::size_t>(channels) +
                       static_cast<std::size_t>(c)] = image.at(x, y, std::min(c, image.channels() - 1));
    return data;
}

vtkSmartPointer<vtkTexture> textureOf(vtkImageData* image, bool srgb, bool mipmap = true) {
    auto texture = vtkSmartPointer<vtkTexture>::New();
    texture->SetInputData(image);
    texture->InterpolateOn();
    texture->SetMipmap(mipmap);
    texture->RepeatOff();
    texture->EdgeClampOn();
    texture->SetUseSRGBColorSpace(srgb);
    return texture;
}

/// Occlusion (1), roughness (the package's map), metallic (0): VTK's ORM texture.
vtkSmartPointer<vtkImageData> ormOf(const ImageU8& roughness) {
    auto data = vtkSmartPointer<vtkImageData>::New();
    data->SetDimensions(roughness.width(), roughness.height(), 1);
    data->AllocateScalars(VTK_UNSIGNED_CHAR, 3);
    auto* pixels = static_cast<unsigned char*>(data->GetScalarPointer());
    const auto w = static_cast<std::size_t>(roughness.width());
    for (int y = 0; y < roughness.height(); ++y)
        for (int x = 0; x < roughness.width(); ++x) {
            unsigned char* p =
                pixels + (static_cast<std::size_t>(roughness.height() - 1 - y) * w + static_cast<std::size_t>(x)) * 3;
            p[0] = 255;
            p[1] = roughness.at(x, y, 0);
            p[2] = 0;
        }
    return data;
}

/// Area-weighted vertex normals of `points` over `triangles`.
/// Point normals from the first `triangleCount` triangles over the first `pointCount` points (the triangles use no
/// other points).
void faceNormals(const std::vector<Triangle>& triangles, const std::vector<Vec3>& points, std::vector<Vec3>& out,
                 std::size_t triangleCount, std::size_t pointCount) {
    out.assign(pointCount, Vec3{});
    for (std::size_t f = 0; f < triangleCount; ++f) {
        const Triangle& t = triangles[f];
        const auto a = static_cast<std::size_t>(t[0]), b = static_cast<std::size_t>(t[1]),
                   c = static_cast<std::size_t>(t[2]);
        const Vec3 n = cross(points[b] - points[a], points[c] - points[a]);
        out[a] += n;
        out[b] += n;
        out[c] += n;
    }
    for (Vec3& n : out) {
        const double length = norm(n);
        n = length > 0.0 ? n / length : Vec3{};
    }
}

} // namespace

CameraPose cameraPose(const sim::ScopePose& pose, const sim::ScopeConfig& config) {
    return {pose.tipMm,
            pose.direction,
            pose.up,
            sim::scopeFieldOfViewDeg(config),
            sim::scopeFocusNearMm(config),
            sim::scopeFocusFarMm(config)};
}

CameraPose cameraPose(const scene::ScopeView& view, double fieldOfViewDeg) {
    return {view.eyeMm, view.direction, view.up, fieldOfViewDeg};
}

/// What setSurface() was given, kept to build the drawn surface from when the detail is decided at the first render.
struct SourceSurface {
    std::vector<Vec3> points; ///< mm, at rest
    std::vector<Triangle> triangles;
    std::vector<bool> outer; ///< per triangle: the organ's outer surface (serosa of no pathology); empty: unlabelled
    std::vector<std::array<float, 2>> uvs;
    std::vector<Vec3> normals; ///< the package's (smooth across the texture's seams), or recomputed
    vtkSmartPointer<vtkTexture> albedo, albedoSrgb, orm, normalMap;
    vtkSmartPointer<vtkTexture> albedoUnfiltered; ///< without mipmaps: the light detail's (see applyShading)
};

enum class Renderer { Unknown, Hardware, Software };

struct EndoscopicView::Impl {
    vtkRenderer* renderer = nullptr;
    EndoscopicLook look;
    vtkSmartPointer<detail::FocusBlurPass> focusBlur; ///< the optic's depth of field (FocusBlur.h); null: off
    vtkSmartPointer<vtkSequencePass> focusSteps;      ///< VTK's steps with focusBlur between scene and overlays
    double focusNearMm = 2.0, focusFarMm = 50.0;      ///< the pose's focus range
    vtkSmartPointer<vtkActor> actor;
    vtkSmartPointer<vtkPolyDataMapper> mapper;
    vtkSmartPointer<vtkPolyData> surface; ///< what is drawn; null without a surface
    vtkSmartPointer<vtkLight> lamp;
    vtkSmartPointer<vtkActor2D> mask;
    vtkSmartPointer<vtkActor> occluder; ///< the mask's black ring, in depth in front of the tissue (see fitOccluder)
    vtkSmartPointer<vtkPolyData> occluderGeometry;
    vtkSmartPointer<vtkPolyData> maskGeometry;
    vtkSmartPointer<vtkTextActor> hud;
    vtkSmartPointer<vtkTextActor> warning;
    vtkSmartPointer<vtkCellArray> allFaces;
    vtkSmartPointer<vtkCellArray> innerFaces; ///< all but the serosa's; null without a tissue label
    /// The inner faces alone over their own points (a copy of the drawn points' prefix they use), drawn while the
    /// outer surface is hidden: each frame then uploads only their points and normals, a quarter of all.
    vtkSmartPointer<vtkPolyData> innerSurface;
    /// The polydata drawn now.
    vtkPolyData* active() const { return !outerVisible && innerSurface ? innerSurface.Get() : surface.Get(); }
    bool outerVisible = true;
    vtkSmartPointer<vtkCallbackCommand> startObserver;
    unsigned long startTag = 0;
    SourceSurface source;
    Renderer glKind = Renderer::Unknown;
    std::string glName;
    bool light = false;                    ///< the drawn surface is the decimated one, shaded with the albedo alone
    std::vector<std::size_t> sourceIndex;  ///< per drawn point, the source point; empty: the same points
    std::size_t innerTriangles = 0;        ///< the inner faces: a prefix of `triangles`
    std::size_t innerPoints = 0;           ///< the points the inner faces use: a prefix of the drawn points
    std::vector<std::int32_t> sourceInUse; ///< the source points setPoints reads now (empty: all of them)
    void updateSourceInUse();
    /// The drawn points (a prefix) and triangles (a prefix) that setPoints moves: the inner ones while the outer
    /// surface is hidden.
    std::size_t pointsInUse() const { return !outerVisible && innerFaces ? innerPoints : drawnPoints.size(); }
    std::size_t trianglesInUse() const { return !outerVisible && innerFaces ? innerTriangles : triangles.size(); }
    std::vector<Triangle> triangles; ///< over the drawn points
    std::vector<Vec3> storedNormals; ///< per drawn point, the source's
    std::vector<Vec3> restNormals;   ///< recomputed from the rest points, to carry deformation onto storedNormals
    std::vector<Vec3> drawnPoints, scratch;
    int maskWidth = -1, maskHeight = -1;
    double fieldOfViewDeg = 90.0;
    std::array<double, 2> fieldScale{1.0, 1.0}; ///< the viewport's normalized coordinates per radius of the circle
    double occluderFieldOfViewDeg = -1.0;       ///< degrees; the field the occluder was built for
    double turbidity = 0.0, redOut = 0.0, bloodFraction = 0.0;
    AutoExposure autoExposure;
    std::array<double, 3> white{1.0, 1.0, 1.0};
    CircleStats stats;
    bool measure = false;
    double hostTimeS = -1.0;  ///< s, the host's clock (setTime); < 0: the wall clock
    double lastFrameS = -1.0; ///< s, when the last frame was measured
    vtkSmartPointer<vtkUnsignedCharArray> readBack;
    vtkSmartPointer<vtkCallbackCommand> endObserver;
    unsigned long endTag = 0;
    void measureFrame();
    /// mm, r0 of the lamp's falloff 1 / (1 + (r / r0)^2) (from its quadratic attenuation; 1 mm without one).
    double lampSourceMm() const {
        return look.lampAttenuation[2] > 0.0
                   ? std::sqrt(std::max(look.lampAttenuation[0], 1e-6) / look.lampAttenuation[2])
                   : 1.0;
    }
    void updateBackground();

    bool wantsLight() const;
    void gateFocusBlur();
    void probeRenderer();
    void buildSurface();
    void applyShading();
    void fitOverlays();
    void buildMask(int width, int height);
    void buildOccluder(int width, int height);
    void fitOccluder();
    void updateUniforms();
    sim::BloodClouds clouds; ///< setBloodClouds
    void updateClouds();
    void setNormals(const std::vector<Vec3>& normals, std::size_t count); ///< the first `count` points'

    // The cut (setCut, setCutSurface) and the loop (setLoop).
    std::vector<char> hiddenSource; ///< per source point: its tet was cut away (faces on it are not drawn)
    void applyHidden();
    std::vector<sim::Chip> chips; ///< drawn with the cut faces
    vtkSmartPointer<vtkActor> cutActor;
    vtkSmartPointer<vtkPolyData> cutGeometry;
    vtkSmartPointer<vtkActor> loopActor;
    vtkSmartPointer<vtkPolyData> loopGeometry;
    /// The shader properties that carry the fluid's and the optic's uniforms (the tissue's and the cut's).
    std::vector<vtkShaderProperty*> fluidShaders() const {
        return {actor->GetShaderProperty(), cutActor->GetShaderProperty()};
    }
};

EndoscopicView::EndoscopicView(vtkRenderer* renderer, const EndoscopicLook& look) : m_impl(std::make_unique<Impl>()) {
    Impl& d = *m_impl;
    d.renderer = renderer;
    d.look = look;
    renderer->AutomaticLightCreationOff();
    renderer->RemoveAllLights();
    d.lamp = vtkSmartPointer<vtkLight>::New();
    d.lamp->SetLightTypeToHeadlight(); // at the camera: the light guide ends beside the lens
    d.lamp->PositionalOn();
    d.lamp->SetConeAngle(89.0);
    d.lamp->SetAttenuationValues(look.lampAttenuation[0], look.lampAttenuation[1], look.lampAttenuation[2]);
    d.lamp->SetIntensity(look.lampIntensity);
    d.lamp->SetColor(look.lampColour[0], look.lampColour[1], look.lampColour[2]);
    renderer->AddLight(d.lamp);
    // The "white" button: a white target under the lamp shows the lamp's colour; the gains make it grey.
    for (std::size_t c = 0; c < 3; ++c)
        d.white[c] = look.lampColour[c] > 0.0 ? look.lampColour[1] / look.lampColour[c] : 1.0;
    d.autoExposure = AutoExposure(look.exposureSettings, look.exposure);
    if (look.depthOfField) {
        // The scene (lights, opaque, translucent, volumes) through the depth of field, then the overlays, sharp: VTK's
        // own steps (vtkRenderStepsPass) with the blur between the scene and the overlays.
        auto scene = vtkSmartPointer<vtkRenderPassCollection>::New();
        scene->AddItem(vtkSmartPointer<vtkLightsPass>::New());
        scene->AddItem(vtkSmartPointer<vtkOpaquePass>::New());
        scene->AddItem(vtkSmartPointer<vtkTranslucentPass>::New());
        scene->AddItem(vtkSmartPointer<vtkVolumetricPass>::New());
        auto sceneSteps = vtkSmartPointer<vtkSequencePass>::New();
        sceneSteps->SetPasses(scene);
        auto camera = vtkSmartPointer<vtkCameraPass>::New();
        camera->SetDelegatePass(sceneSteps);
        d.focusBlur = vtkSmartPointer<detail::FocusBlurPass>::New();
        d.focusBlur->SetDelegatePass(camera);
        d.focusBlur->setSharpCircle(look.sharpCircleShare);
        d.focusBlur->setLargestRadius(look.largestBlurShare);
        auto all = vtkSmartPointer<vtkRenderPassCollection>::New();
        all->AddItem(d.focusBlur);
        all->AddItem(vtkSmartPointer<vtkOverlayPass>::New());
        d.focusSteps = vtkSmartPointer<vtkSequencePass>::New();
        d.focusSteps->SetPasses(all); // the renderer's pass while something is out of focus (gateFocusBlur)
    }

    // Drawn before the tissue, so the tissue's fragments behind the mask's black ring fail the depth test early.
    d.occluderGeometry = vtkSmartPointer<vtkPolyData>::New();
    auto occluderMapper = vtkSmartPointer<vtkPolyDataMapper>::New();
    occluderMapper->SetInputData(d.occluderGeometry);
    occluderMapper->ScalarVisibilityOff();
    d.occluder = vtkSmartPointer<vtkActor>::New();
    d.occluder->SetMapper(occluderMapper);
    d.occluder->GetProperty()->LightingOff();
    d.occluder->GetProperty()->SetColor(0.0, 0.0, 0.0);
    d.occluder->UseBoundsOff(); // not part of the scene: the camera's clipping range ignores it
    d.occluder->PickableOff();
    d.occluder->SetVisibility(look.opticMask);
    renderer->AddActor(d.occluder);

    d.mapper = vtkSmartPointer<vtkPolyDataMapper>::New();
    d.mapper->ScalarVisibilityOff();
    d.actor = vtkSmartPointer<vtkActor>::New();
    d.actor->SetMapper(d.mapper);
    d.actor->VisibilityOff();
    d.actor->GetProperty()->BackfaceCullingOff(); // inside the organ the scope sees the backs of surfaces too
    vtkShaderProperty* shader = d.actor->GetShaderProperty();
    shader->AddFragmentShaderReplacement("//VTK::TCoord::Impl", true, kFluidShader, false);
    shader->AddFragmentShaderReplacement("//VTK::Light::Dec", true, kBloodCloudFragmentDec, false);
    shader->AddVertexShaderReplacement("//VTK::Light::Dec", true, kBloodCloudVertexDec, false);
    shader->AddVertexShaderReplacement("//VTK::PositionVC::Impl", true, kOpticVertexShader, false);
    renderer->AddActor(d.actor);

    // The faces the cuts bared, coloured by their tissue, seen through the same fluid and optic as the tissue.
    d.cutGeometry = vtkSmartPointer<vtkPolyData>::New();
    auto cutMapper = vtkSmartPointer<vtkPolyDataMapper>::New();
    cutMapper->SetInputData(d.cutGeometry);
    cutMapper->SetScalarModeToUsePointData();
    cutMapper->SetColorModeToDirectScalars();
    cutMapper->MapDataArrayToVertexAttribute("hsRestMC", "restMm", vtkDataObject::FIELD_ASSOCIATION_POINTS, -1);
    cutMapper->MapDataArrayToVertexAttribute("hsPatternMC", "pattern", vtkDataObject::FIELD_ASSOCIATION_POINTS, -1);
    d.cutActor = vtkSmartPointer<vtkActor>::New();
    d.cutActor->SetMapper(cutMapper);
    d.cutActor->GetProperty()->BackfaceCullingOff();
    d.cutActor->GetProperty()->SetInterpolationToFlat();
    d.cutActor->VisibilityOff();
    vtkShaderProperty* cutShader = d.cutActor->GetShaderProperty();
    cutShader->AddFragmentShaderReplacement("//VTK::TCoord::Impl", true, kFluidShader, false);
    cutShader->AddFragmentShaderReplacement("//VTK::Light::Dec", true, kBloodCloudFragmentDec, false);
    cutShader->AddVertexShaderReplacement("//VTK::Light::Dec", true, kBloodCloudVertexDec, false);
    cutShader->AddVertexShaderReplacement("//VTK::PositionVC::Impl", true, kOpticVertexShader, false);
    cutShader->AddVertexShaderReplacement("//VTK::Color::Dec", true, kCutVertexDec, false);
    cutShader->AddVertexShaderReplacement("//VTK::Color::Impl", true, kCutVertexImpl, false);
    cutShader->AddFragmentShaderReplacement("//VTK::Color::Dec", true, kCutFragmentDec, false);
    cutShader->AddFragmentShaderReplacement("//VTK::Color::Impl", true, kCutFragmentImpl, false);
    renderer->AddActor(d.cutActor);

    // The loop: a wire in front of the lens, metal, glowing while it carries current.
    d.loopGeometry = vtkSmartPointer<vtkPolyData>::New();
    auto loopMapper = vtkSmartPointer<vtkPolyDataMapper>::New();
    loopMapper->SetInputData(d.loopGeometry);
    loopMapper->ScalarVisibilityOff();
    d.loopActor = vtkSmartPointer<vtkActor>::New();
    d.loopActor->SetMapper(loopMapper);
    d.loopActor->GetProperty()->SetRepresentationToSurface();
    d.loopActor->VisibilityOff();
    renderer->AddActor(d.loopActor);

    d.maskGeometry = vtkSmartPointer<vtkPolyData>::New();
    auto maskMapper = vtkSmartPointer<vtkPolyDataMapper2D>::New();
    maskMapper->SetInputData(d.maskGeometry);
    maskMapper->SetColorModeToDirectScalars();
    d.mask = vtkSmartPointer<vtkActor2D>::New();
    d.mask->SetMapper(maskMapper);
    d.mask->SetVisibility(look.opticMask);
    renderer->AddActor2D(d.mask);

    d.hud = vtkSmartPointer<vtkTextActor>::New();
    d.hud->GetTextProperty()->SetColor(0.85, 0.95, 0.85);
    d.hud->GetTextProperty()->SetFontFamilyToCourier();
    d.hud->GetTextProperty()->ShadowOn();
    d.hud->GetTextProperty()->SetVerticalJustificationToTop();
    d.hud->VisibilityOff();
    renderer->AddActor2D(d.hud);
    d.warning = vtkSmartPointer<vtkTextActor>::New();
    d.warning->GetTextProperty()->SetColor(1.0, 0.3, 0.25);
    d.warning->GetTextProperty()->BoldOn();
    d.warning->GetTextProperty()->ShadowOn();
    d.warning->GetTextProperty()->SetJustificationToCentered();
    d.warning->VisibilityOff();
    renderer->AddActor2D(d.warning);

    // The overlays follow the viewport's size: refitted at the start of every render when it changed.
    d.startObserver = vtkSmartPointer<vtkCallbackCommand>::New();
    d.startObserver->SetClientData(&d);
    d.startObserver->SetCallback([](vtkObject*, unsigned long, void* client, void*) {
        auto* impl = static_cast<Impl*>(client);
        impl->probeRenderer();
        impl->gateFocusBlur();
        impl->fitOverlays();
        impl->updateClouds(); // in the camera's coordinates as this render has it
    });
    d.startTag = renderer->AddObserver(vtkCommand::StartEvent, d.startObserver);
    // The camera head meters the frame just drawn (before the window shows it).
    d.endObserver = vtkSmartPointer<vtkCallbackCommand>::New();
    d.endObserver->SetClientData(&d);
    d.endObserver->SetCallback(
        [](vtkObject*, unsigned long, void* client, void*) { static_cast<Impl*>(client)->measureFrame(); });
    d.endTag = renderer->AddObserver(vtkCommand::EndEvent, d.endObserver);
    d.updateBackground();
    d.updateUniforms();
}

EndoscopicView::~EndoscopicView() {
    Impl& d = *m_impl;
    d.renderer->RemoveObserver(d.startTag);
    d.renderer->RemoveObserver(d.endTag);
    d.renderer->RemoveActor(d.actor);
    d.renderer->RemoveActor(d.occluder);
    d.renderer->RemoveActor2D(d.mask);
    d.renderer->RemoveActor2D(d.hud);
    d.renderer->RemoveActor2D(d.warning);
    d.renderer->RemoveLight(d.lamp);
    if (d.focusSteps && d.renderer->GetPass() == d.focusSteps.Get())
        d.renderer->SetPass(nullptr);
}

void EndoscopicView::setSurface(const scene::VisualSurface& v) {
    Impl& d = *m_impl;
    const SurfaceMesh& mesh = v.mesh;
    SourceSurface& s = d.source;
    s = {};
    s.points = mesh.points;
    s.triangles = mesh.triangles;
    const auto tissue = mesh.faceLabels.find(clinical::kSurfaceTissueLabel);
    const bool labelled = tissue != mesh.faceLabels.end() && tissue->second.size() == mesh.triangles.size();
    // A pathology's faces stay whatever their tissue: a submucous myoma shows in the cavity.
    const auto pathology = mesh.faceLabels.find("pathology");
    const bool pathologies = pathology != mesh.faceLabels.end() && pathology->second.size() == mesh.triangles.size();
    if (labelled) {
        s.outer.resize(mesh.triangles.size());
        for (std::size_t f = 0; f < mesh.triangles.size(); ++f)
            s.outer[f] = tissue->second[f] == clinical::labelValue(clinical::SurfaceTissue::Serosa) &&
                         !(pathologies && pathology->second[f] != 0);
    }
    if (v.uvs.size() == mesh.points.size())
        s.uvs = v.uvs;
    if (v.normals.size() == mesh.points.size())
        s.normals = v.normals;
    else
        faceNormals(mesh.triangles, mesh.points, s.normals, mesh.triangles.size(), mesh.points.size());
    if (!s.uvs.empty() && !v.albedo.empty() && v.albedo.channels() >= 3) {
        vtkSmartPointer<vtkImageData> albedo = imageOf(v.albedo, 3);
        s.albedo = textureOf(albedo, false);
        s.albedoSrgb = textureOf(albedo, true);
        s.albedoUnfiltered = textureOf(albedo, false, false);
        if (!v.normal.empty() && !v.roughness.empty()) {
            s.orm = textureOf(ormOf(v.roughness), false);
            s.normalMap = textureOf(imageOf(v.normal, 3), false);
        }
    }
    d.light = d.wantsLight();
    d.buildSurface();
    d.actor->VisibilityOn();
}

bool EndoscopicView::Impl::wantsLight() const {
    return look.detail == ViewDetail::Light || (look.detail == ViewDetail::Automatic && glKind == Renderer::Software);
}

void EndoscopicView::Impl::buildSurface() {
    const SourceSurface& s = source;
    sourceIndex.clear();
    triangles.clear();
    innerSurface = nullptr;
    // The points in the order the triangles first use them (neighbouring triangles' points close together in the
    // buffers), the inner faces first (a prefix drawn while the outer surface is hidden).
    ViewDecimationParams params;
    params.targetReduction = light ? look.lightReduction : 0.0;
    DecimatedSurface drawn = decimateForView({s.points, s.triangles, {}, {}}, s.outer, params);
    sourceIndex = std::move(drawn.sourcePoints);
    triangles = std::move(drawn.triangles);
    const std::size_t innerCount = drawn.innerTriangles;
    innerTriangles = innerCount;
    innerPoints = 0;
    for (std::size_t f = 0; f < innerCount; ++f)
        for (const std::int32_t p : triangles[f])
            innerPoints = std::max(innerPoints, static_cast<std::size_t>(p) + 1);
    const auto sourceOf = [&](std::size_t i) { return sourceIndex.empty() ? i : sourceIndex[i]; };
    const std::size_t count = sourceIndex.empty() ? s.points.size() : sourceIndex.size();

    auto points = vtkSmartPointer<vtkPoints>::New();
    points->SetDataTypeToFloat();
    points->SetNumberOfPoints(static_cast<vtkIdType>(count));
    drawnPoints.resize(count);
    storedNormals.resize(count);
    for (std::size_t i = 0; i < count; ++i) {
        drawnPoints[i] = s.points[sourceOf(i)];
        storedNormals[i] = s.normals[sourceOf(i)];
        points->SetPoint(static_cast<vtkIdType>(i), drawnPoints[i].x, drawnPoints[i].y, drawnPoints[i].z);
    }
    allFaces = vtkSmartPointer<vtkCellArray>::New();
    innerFaces = s.outer.empty() ? nullptr : vtkSmartPointer<vtkCellArray>::New();
    for (std::size_t f = 0; f < triangles.size(); ++f) {
        const vtkIdType ids[3] = {triangles[f][0], triangles[f][1], triangles[f][2]};
        allFaces->InsertNextCell(3, ids);
        if (innerFaces && f < innerCount)
            innerFaces->InsertNextCell(3, ids);
    }
    surface = vtkSmartPointer<vtkPolyData>::New();
    surface->SetPoints(points);
    surface->SetPolys(allFaces);
    faceNormals(triangles, drawnPoints, restNormals, triangles.size(), drawnPoints.size());
    setNormals(storedNormals, storedNormals.size());
    if (!s.uvs.empty()) {
        auto tcoords = vtkSmartPointer<vtkFloatArray>::New();
        tcoords->SetName("uv");
        tcoords->SetNumberOfComponents(2);
        tcoords->SetNumberOfTuples(static_cast<vtkIdType>(count));
        for (std::size_t i = 0; i < count; ++i) // VTK's texture origin is the image's bottom left
            tcoords->SetTuple2(static_cast<vtkIdType>(i), s.uvs[sourceOf(i)][0], 1.0f - s.uvs[sourceOf(i)][1]);
        surface->GetPointData()->SetTCoords(tcoords);
    }
    applyShading();
    innerSurface = nullptr;
    if (innerFaces) {
        // The prefix of every point array (points, normals, texture coordinates, tangents) the inner faces use.
        innerSurface = vtkSmartPointer<vtkPolyData>::New();
        auto innerPointSet = vtkSmartPointer<vtkPoints>::New();
        innerPointSet->SetDataTypeToFloat();
        innerPointSet->SetNumberOfPoints(static_cast<vtkIdType>(innerPoints));
        for (std::size_t i = 0; i < innerPoints; ++i)
            innerPointSet->SetPoint(static_cast<vtkIdType>(i), drawnPoints[i].x, drawnPoints[i].y, drawnPoints[i].z);
        innerSurface->SetPoints(innerPointSet);
        innerSurface->SetPolys(innerFaces);
        vtkPointData* from = surface->GetPointData();
        vtkPointData* to = innerSurface->GetPointData();
        const auto prefix = [&](vtkDataArray* array) -> vtkSmartPointer<vtkDataArray> {
            if (!array)
                return nullptr;
            vtkSmartPointer<vtkDataArray> copy;
            copy.TakeReference(array->NewInstance());
            copy->SetName(array->GetName());
            copy->SetNumberOfComponents(array->GetNumberOfComponents());
            copy->SetNumberOfTuples(static_cast<vtkIdType>(innerPoints));
            for (vtkIdType i = 0; i < static_cast<vtkIdType>(innerPoints); ++i)
                copy->SetTuple(i, i, array);
            return copy;
        };
        to->SetNormals(prefix(from->GetNormals()));
        to->SetTCoords(prefix(from->GetTCoords()));
        to->SetTangents(prefix(from->GetTangents()));
    }
    if (!hiddenSource.empty())
        applyHidden(); // the cuts so far, on the surface built anew
    mapper->SetInputData(active());
    updateSourceInUse();
}

void EndoscopicView::Impl::updateSourceInUse() {
    sourceInUse.clear();
    const std::size_t n = pointsInUse();
    if (sourceIndex.empty() && n == source.points.size())
        return;
    sourceInUse.resize(n);
    for (std::size_t i = 0; i < n; ++i)
        sourceInUse[i] = static_cast<std::int32_t>(sourceIndex.empty() ? i : sourceIndex[i]);
}

void EndoscopicView::Impl::applyShading() {
    const SourceSurface& s = source;
    vtkProperty* property = actor->GetProperty();
    actor->SetTexture(nullptr);
    property->RemoveAllTextures();
    property->SetInterpolationToPhong();
    property->SetColor(0.85, 0.55, 0.5);
    if (s.albedo && s.orm && look.materialMaps && !light) {
        // Physically based shading: the albedo (sRGB), roughness and tangent-space normals the texture stage baked.
        auto tangents = vtkSmartPointer<vtkPolyDataTangents>::New();
        tangents->SetInputData(surface);
        tangents->Update();
        surface->GetPointData()->SetTangents(tangents->GetOutput()->GetPointData()->GetTangents());
        property->SetInterpolationToPBR();
        property->SetColor(1.0, 1.0, 1.0);
        property->SetMetallic(0.0);
        property->SetRoughness(1.0);
        property->SetBaseColorTexture(s.albedoSrgb);
        property->SetORMTexture(s.orm);
        property->SetNormalTexture(s.normalMap);
        property->SetNormalScale(1.0);
    } else if (s.albedo) {
        // On llvmpipe, mipmapped sampling on a deforming surface made some frames cost ten times the others (at
        // 960x720 up to seconds; docs/simulator.md): the light detail samples the full-size albedo only. Seen from
        // inside the cavity the albedo is mostly magnified, where mipmaps change nothing.
        actor->SetTexture(light ? s.albedoUnfiltered : s.albedo);
        property->SetColor(1.0, 1.0, 1.0);
        property->SetSpecular(0.25);
        property->SetSpecularPower(30.0);
    }
}

/// The depth of field only runs when something drawn may lie closer than where its blur reaches half a pixel: the
/// nearest point ahead of the lens (along the optic's axis, the depth the blur reads) within that distance plus a
/// triangle's reach. A frame with everything in focus is drawn by VTK's own steps, straight to the window, exactly as
/// without it (a software rasterizer pays about 11 ms a frame at 640 x 480 for the framebuffer and the full-screen
/// pass alone).
void EndoscopicView::Impl::gateFocusBlur() {
    if (!focusBlur)
        return;
    int width = 0, height = 0;
    renderer->GetTiledSize(&width, &height);
    const double sharpPx = look.sharpCircleShare * height;
    const double invNear = 1.0 / focusNearMm, invFar = 1.0 / focusFarMm;
    // Blur radius (circle - sharp) / 2 reaches half a pixel where the circle is sharp + 1 px.
    const double onsetMm = sharpPx > 0.0 ? 2.0 / ((1.0 + 1.0 / sharpPx) * (invNear - invFar) + invNear + invFar) : 0.0;
    const double gateMm = onsetMm + kFocusGateMarginMm;
    vtkCamera* camera = renderer->GetActiveCamera();
    double eye[3], focal[3];
    camera->GetPosition(eye);
    camera->GetFocalPoint(focal);
    const Vec3 e{eye[0], eye[1], eye[2]};
    const Vec3 axis = normalized(Vec3{focal[0], focal[1], focal[2]} - e);
    // Within the optic's circle (its half angle; the barrel distortion keeps the field's angle at the circle's edge),
    // widened by the same margin.
    const double spread = std::tan(0.5 * kPi / 180.0 * std::clamp(fieldOfViewDeg, 1.0, 170.0));
    bool inReach = false;
    const auto check = [&](const Vec3& p) {
        const Vec3 q = p - e;
        const double depth = dot(q, axis);
        if (depth > 0.0 && depth < gateMm && norm(q - axis * depth) < depth * spread + kFocusGateMarginMm)
            inReach = true;
    };
    const std::size_t n = std::min(pointsInUse(), drawnPoints.size());
    for (std::size_t i = 0; i < n && !inReach; ++i)
        check(drawnPoints[i]);
    if (cutActor->GetVisibility() && cutGeometry && cutGeometry->GetPoints()) {
        vtkPoints* points = cutGeometry->GetPoints();
        for (vtkIdType i = 0; i < points->GetNumberOfPoints() && !inReach; ++i) {
            double q[3];
            points->GetPoint(i, q);
            check({q[0], q[1], q[2]});
        }
    }
    // VTK's own steps otherwise: the picture exactly as without the depth of field.
    if (inReach != (renderer->GetPass() == focusSteps.Get()))
        renderer->SetPass(inReach ? focusSteps.Get() : nullptr);
}

void EndoscopicView::Impl::probeRenderer() {
    if (glKind != Renderer::Unknown)
        return;
    auto* window = vtkOpenGLRenderWindow::SafeDownCast(renderer->GetRenderWindow());
    if (!window)
        return;
    const char* report = window->ReportCapabilities();
    const std::string text = report ? report : "";
    const std::string key = "OpenGL renderer string:";
    const std::size_t at = text.find(key);
    if (at == std::string::npos)
        return; // no context yet
    const std::size_t begin = text.find_first_not_of(' ', at + key.size());
    glName = text.substr(begin, text.find('\n', begin) - begin);
    glKind = isSoftwareRenderer(glName) ? Renderer::Software : Renderer::Hardware;
    if (surface && wantsLight() != light) {
        light = wantsLight();
        buildSurface(); // before the tissue is drawn in this render
    }
}

void EndoscopicView::setHiddenPoints(const std::vector<char>& hidden) {
    Impl& d = *m_impl;
    if (hidden == d.hiddenSource)
        return;
    d.hiddenSource = hidden;
    d.applyHidden();
}

void EndoscopicView::Impl::applyHidden() {
    if (!surface)
        return;
    const auto hiddenDrawn = [&](std::int32_t p) {
        const std::size_t at =
            sourceIndex.empty() ? static_cast<std::size_t>(p) : sourceIndex[static_cast<std::size_t>(p)];
        return at < hiddenSource.size() && hiddenSource[at] != 0;
    };
    allFaces = vtkSmartPointer<vtkCellArray>::New();
    if (innerFaces)
        innerFaces = vtkSmartPointer<vtkCellArray>::New();
    for (std::size_t f = 0; f < triangles.size(); ++f) {
        const Triangle& t = triangles[f];
        if (hiddenDrawn(t[0]) || hiddenDrawn(t[1]) || hiddenDrawn(t[2]))
            continue;
        const vtkIdType ids[3] = {t[0], t[1], t[2]};
        allFaces->InsertNextCell(3, ids);
        if (innerFaces && f < innerTriangles)
            innerFaces->InsertNextCell(3, ids);
    }
    surface->SetPolys(allFaces);
    if (innerSurface)
        innerSurface->SetPolys(innerFaces);
}

void EndoscopicView::setChips(const std::vector<sim::Chip>& chips) {
    m_impl->chips = chips;
}

void EndoscopicView::setCutSurface(const std::vector<Vec3>& pointsMm, const std::vector<Vec3>& restPointsMm,
                                   const std::vector<Triangle>& faces, const std::vector<clinical::Tissue>& tissue) {
    Impl& d = *m_impl;
    if ((faces.empty() || tissue.size() != faces.size()) && d.chips.empty()) {
        d.cutActor->VisibilityOff();
        return;
    }
    // The faces' own points (a few hundred faces: built anew each frame), each with its rest position, which the
    // solid texture reads (kCutFragmentDec), and its tissue.
    auto points = vtkSmartPointer<vtkPoints>::New();
    points->SetDataTypeToFloat();
    auto cells = vtkSmartPointer<vtkCellArray>::New();
    auto colours = vtkSmartPointer<vtkUnsignedCharArray>::New();
    colours->SetNumberOfComponents(3);
    auto rest = vtkSmartPointer<vtkFloatArray>::New();
    rest->SetName("restMm");
    rest->SetNumberOfComponents(3);
    auto pattern = vtkSmartPointer<vtkFloatArray>::New();
    pattern->SetName("pattern");
    pattern->SetNumberOfComponents(1);
    const auto colourOf = [&](clinical::Tissue kind) {
        const std::array<double, 3>& c =
            d.look.cutColour[std::min(static_cast<std::size_t>(kind), d.look.cutColour.size() - 1)];
        // Direct scalars are taken as the colour before lighting: the linear colour in 8 bits.
        return std::array<unsigned char, 3>{
            static_cast<unsigned char>(std::lround(255.0 * std::clamp(c[0], 0.0, 1.0))),
            static_cast<unsigned char>(std::lround(255.0 * std::clamp(c[1], 0.0, 1.0))),
            static_cast<unsigned char>(std::lround(255.0 * std::clamp(c[2], 0.0, 1.0)))};
    };
    const auto addPoint = [&](const Vec3& at, const Vec3& restAt, clinical::Tissue kind) {
        const vtkIdType id = points->InsertNextPoint(at.x, at.y, at.z);
        colours->InsertNextTypedTuple(colourOf(kind).data());
        const float r[3] = {static_cast<float>(restAt.x), static_cast<float>(restAt.y), static_cast<float>(restAt.z)};
        rest->InsertNextTypedTuple(r);
        pattern->InsertNextValue(static_cast<float>(static_cast<int>(kind)));
        return id;
    };
    const std::size_t faceCount =
        tissue.size() == faces.size() && restPointsMm.size() == pointsMm.size() ? faces.size() : 0;
    for (std::size_t f = 0; f < faceCount; ++f) {
        bool inside = true;
        for (int k = 0; k < 3; ++k)
            inside = inside && static_cast<std::size_t>(faces[f][static_cast<std::size_t>(k)]) < pointsMm.size();
        if (!inside)
            continue;
        vtkIdType ids[3];
        for (int k = 0; k < 3; ++k) {
            const auto p = static_cast<std::size_t>(faces[f][static_cast<std::size_t>(k)]);
            ids[k] = addPoint(pointsMm[p], restPointsMm[p], tissue[f]);
        }
        cells->InsertNextCell(3, ids);
    }
    // Each chip an octahedron of its radius (eight faces: enough for a piece a millimetre or two across), its pattern
    // carried with it: the corners' offsets from its centre, placed in the block by its volume (a chip's own).
    for (const sim::Chip& chip : d.chips) {
        const double r = std::max(chip.radiusMm, 0.05);
        const Vec3& c = chip.positionMm;
        const Vec3 offset[6] = {Vec3{r, 0, 0},  Vec3{-r, 0, 0}, Vec3{0, r, 0},
                                Vec3{0, -r, 0}, Vec3{0, 0, r},  Vec3{0, 0, -r}};
        const Vec3 inBlock{std::fmod(chip.volumeMl * 7.3e4, 97.0), std::fmod(chip.volumeMl * 3.1e4, 89.0), 0.0};
        vtkIdType id[6];
        for (int k = 0; k < 6; ++k)
            id[k] = addPoint(c + offset[k], inBlock + offset[k], chip.tissue);
        const int octahedron[8][3] = {{0, 2, 4}, {2, 1, 4}, {1, 3, 4}, {3, 0, 4},
                                      {2, 0, 5}, {1, 2, 5}, {3, 1, 5}, {0, 3, 5}};
        for (const auto& f : octahedron) {
            const vtkIdType tri[3] = {id[f[0]], id[f[1]], id[f[2]]};
            cells->InsertNextCell(3, tri);
        }
    }
    d.cutGeometry->SetPoints(points);
    d.cutGeometry->SetPolys(cells);
    d.cutGeometry->GetPointData()->SetScalars(colours);
    d.cutGeometry->GetPointData()->AddArray(rest);
    d.cutGeometry->GetPointData()->AddArray(pattern);
    d.cutActor->SetVisibility(cells->GetNumberOfCells() > 0);
}

void EndoscopicView::setLoop(const sim::LoopState& loop) {
    Impl& d = *m_impl;
    const bool jaws = loop.instrument == sim::kInstrumentScissors || loop.instrument == sim::kInstrumentGrasper;
    if (!loop.out || !(jaws ? loop.jawLengthMm > 0.0 : loop.widthMm > 0.0)) {
        d.loopActor->VisibilityOff();
        return;
    }
    std::vector<Vec3> path;
    if (jaws) {
        // The instrument's shaft from the scope's tip to the hinge, then the jaws: one tip, the hinge, the other.
        sim::JawInstrument instrument;
        instrument.jawLengthMm = loop.jawLengthMm;
        const std::vector<Vec3> wire = sim::jawWire(instrument, loop.middleMm, loop.axis, loop.down, loop.jawOpenDeg);
        path.push_back(loop.middleMm - loop.axis * loop.travelMm);
        path.push_back(loop.middleMm);
        path.insert(path.end(), wire.begin(), wire.end());
    } else {
        sim::LoopElectrode electrode;
        electrode.widthMm = loop.widthMm;
        const std::vector<Vec3> wire = sim::loopWire(electrode, loop.middleMm, loop.axis, loop.down);
        if (wire.size() < 2) {
            d.loopActor->VisibilityOff();
            return;
        }
        // The arms from the wire's ends back along the sheath to its tip, then the wire.
        path.push_back(wire.front() - loop.axis * loop.travelMm);
        path.insert(path.end(), wire.begin(), wire.end());
        path.push_back(wire.back() - loop.axis * loop.travelMm);
    }
    auto points = vtkSmartPointer<vtkPoints>::New();
    auto line = vtkSmartPointer<vtkCellArray>::New();
    line->InsertNextCell(static_cast<int>(path.size()));
    for (const Vec3& p : path)
        line->InsertCellPoint(points->InsertNextPoint(p.x, p.y, p.z));
    auto polyline = vtkSmartPointer<vtkPolyData>::New();
    polyline->SetPoints(points);
    polyline->SetLines(line);
    auto tube = vtkSmartPointer<vtkTubeFilter>::New();
    tube->SetInputData(polyline);
    tube->SetRadius(jaws ? d.look.jawRadiusMm : d.look.loopWireRadiusMm);
    tube->SetNumberOfSides(8);
    tube->Update();
    d.loopGeometry->ShallowCopy(tube->GetOutput());
    // Unlit: the wire is a few millimetres from the lamp and would be drawn at full scale whatever its shading; bare
    // metal grey, or the orange of the vapour pocket round a wire carrying current in saline (dimmer coagulating).
    vtkProperty* property = d.loopActor->GetProperty();
    property->LightingOff();
    if (loop.cutting && !jaws) // cold steel does not glow
        property->SetColor(1.0, 0.78, 0.45);
    else if (loop.coagulating)
        property->SetColor(0.9, 0.62, 0.4);
    else
        property->SetColor(0.55, 0.56, 0.58);
    d.loopActor->VisibilityOn();
}

void EndoscopicView::setOuterSurfaceVisible(bool visible) {
    Impl& d = *m_impl;
    if (visible == d.outerVisible)
        return;
    d.outerVisible = visible;
    if (d.surface)
        d.mapper->SetInputData(d.active());
    d.updateSourceInUse();
}

const std::vector<std::int32_t>& EndoscopicView::sourcePointsInUse() const {
    return m_impl->sourceInUse;
}

void EndoscopicView::clear() {
    Impl& d = *m_impl;
    d.actor->VisibilityOff();
    d.mapper->SetInputData(nullptr);
    d.surface = nullptr;
    d.innerSurface = nullptr;
    d.source = {};
    d.sourceIndex.clear();
    d.triangles.clear();
    d.storedNormals.clear();
    d.restNormals.clear();
    d.drawnPoints.clear();
}

bool EndoscopicView::hasSurface() const {
    return m_impl->surface != nullptr;
}

std::size_t EndoscopicView::pointCount() const {
    return m_impl->surface ? m_impl->source.points.size() : 0;
}

std::size_t EndoscopicView::drawnTriangleCount() const {
    return m_impl->surface ? m_impl->triangles.size() : 0;
}

void EndoscopicView::setPoints(const std::vector<Vec3>& pointsMm) {
    Impl& d = *m_impl;
    if (!d.surface || pointsMm.size() != pointCount())
        return;
    // While the outer surface is hidden only the inner faces' points move (a prefix of the drawn points): the others
    // are not drawn, and setOuterSurfaceVisible(true) wants the next setPoints before the next render.
    const std::size_t n = d.pointsInUse();
    vtkPoints* points = d.active()->GetPoints();
    auto* xyz = static_cast<float*>(points->GetVoidPointer(0));
    for (std::size_t i = 0; i < n; ++i) {
        const Vec3& p = pointsMm[d.sourceIndex.empty() ? i : d.sourceIndex[i]];
        d.drawnPoints[i] = p;
        xyz[3 * i] = static_cast<float>(p.x);
        xyz[3 * i + 1] = static_cast<float>(p.y);
        xyz[3 * i + 2] = static_cast<float>(p.z);
    }
    points->Modified();
    // The deformation turns each normal by what it turns the normal recomputed from the points; the stored normals
    // stay smooth across the texture's seams (where recomputed ones would show the split).
    faceNormals(d.triangles, d.drawnPoints, d.scratch, d.trianglesInUse(), n);
    for (std::size_t i = 0; i < n; ++i) {
        const Vec3 v = d.storedNormals[i] + (d.scratch[i] - d.restNormals[i]);
        const double length = norm(v);
        d.scratch[i] = length > 0.0 ? v / length : d.storedNormals[i];
    }
    d.setNormals(d.scratch, n);
}
void EndoscopicView::Impl::setNormals(const std::vector<Vec3>& normals, std::size_t count) {
    vtkPolyData* target = active();
    vtkDataArray* existing = target->GetPointData()->GetNormals();
    vtkSmartPointer<vtkFloatArray> array = vtkFloatArray::SafeDownCast(existing);
    const vtkIdType all = target->GetNumberOfPoints();
    if (!array || array->GetNumberOfTuples() != all) {
        array = vtkSmartPointer<vtkFloatArray>::New();
        array->SetName("normals");
        array->SetNumberOfComponents(3);
        array->SetNumberOfTuples(all);
        target->GetPointData()->SetNormals(array);
    }
    float* n = array->GetPointer(0);
    for (std::size_t i = 0; i < count; ++i) {
        n[3 * i] = static_cast<float>(normals[i].x);
        n[3 * i + 1] = static_cast<float>(normals[i].y);
        n[3 * i + 2] = static_cast<float>(normals[i].z);
    }
    array->Modified();
}

void EndoscopicView::setPose(const CameraPose& pose) {
    Impl& d = *m_impl;
    const auto finite = [](const Vec3& v) { return std::isfinite(v.x) && std::isfinite(v.y) && std::isfinite(v.z); };
    if (!finite(pose.eyeMm) || !finite(pose.direction) || !finite(pose.up) || !std::isfinite(pose.fieldOfViewDeg))
        return; // keeps the last pose rather than a camera VTK cannot draw from
    vtkCamera* camera = d.renderer->GetActiveCamera();
    const Vec3 focal = pose.eyeMm + pose.direction * 10.0;
    camera->SetPosition(pose.eyeMm.x, pose.eyeMm.y, pose.eyeMm.z);
    camera->SetFocalPoint(focal.x, focal.y, focal.z);
    camera->SetViewUp(pose.up.x, pose.up.y, pose.up.z);
    camera->SetClippingRange(d.look.nearClipMm, d.look.farClipMm);
    d.fieldOfViewDeg = pose.fieldOfViewDeg;
    camera->SetViewAngle(pose.fieldOfViewDeg);
    if (d.focusBlur && std::isfinite(pose.focusNearMm) && std::isfinite(pose.focusFarMm) && pose.focusNearMm >= 0.5 &&
        pose.focusFarMm > pose.focusNearMm) {
        d.focusNearMm = pose.focusNearMm;
        d.focusFarMm = pose.focusFarMm;
        d.focusBlur->setFocus(pose.focusNearMm, pose.focusFarMm);
    }
    // The lamp's cone reaches a little beyond the field: the light guide's fibres spread wider than the lens sees.
    d.lamp->SetConeAngle(std::min(89.0, 0.5 * pose.fieldOfViewDeg + 20.0));
}

void EndoscopicView::setFluid(double turbidity, double redOut, double bloodFraction) {
    Impl& d = *m_impl;
    d.bloodFraction = std::isfinite(bloodFraction) ? std::clamp(bloodFraction, 0.0, 1.0) : 0.0;
    d.turbidity = std::isfinite(turbidity) ? std::clamp(turbidity, 0.0, 1.0) : 1.0;
    d.redOut = std::isfinite(redOut) ? std::clamp(redOut, 0.0, 1.0) : 1.0;
    d.updateUniforms();
    d.updateBackground();
}

void EndoscopicView::setBloodClouds(const sim::BloodClouds& clouds) {
    m_impl->clouds = clouds;
    m_impl->updateClouds();
}

void EndoscopicView::Impl::updateClouds() {
    // The centres in the camera's view coordinates (the fragment shader's vertexVC), unused entries without blood.
    float centre[sim::kMaxBloodClouds][4] = {};
    float blood[sim::kMaxBloodClouds] = {};
    int count = 0; // the first `count` entries carry the clouds
    vtkMatrix4x4* view = renderer->GetActiveCamera()->GetViewTransformMatrix();
    for (std::size_t i = 0; i < std::min(clouds.count, sim::kMaxBloodClouds); ++i) {
        const sim::BloodCloud& c = clouds.clouds[i];
        if (!(c.bloodMl > 0.0) || !std::isfinite(c.bloodMl) || !(c.sigmaMm > 0.0) || !std::isfinite(c.sigmaMm))
            continue;
        const double world[4] = {c.centreMm.x, c.centreMm.y, c.centreMm.z, 1.0};
        double inView[4];
        view->MultiplyPoint(world, inView);
        for (int k = 0; k < 3; ++k)
            centre[i][k] = static_cast<float>(inView[k]);
        centre[i][3] = static_cast<float>(c.sigmaMm);
        blood[i] = static_cast<float>(c.bloodMl);
        count = static_cast<int>(i) + 1;
    }
    for (vtkShaderProperty* property : fluidShaders()) {
        vtkUniforms* u = property->GetVertexCustomUniforms();
        u->SetUniform4fv("hsCloudCentre", static_cast<int>(sim::kMaxBloodClouds), centre);
        u->SetUniform1fv("hsCloudBlood", static_cast<int>(sim::kMaxBloodClouds), blood);
        u->SetUniformi("hsCloudCount", count);
    }
}

void EndoscopicView::Impl::updateBackground() {
    // Where no surface is drawn the medium itself is seen, through the same camera.
    double background[3];
    const double e = autoExposure.exposure();
    for (int k = 0; k < 3; ++k) {
        const auto c = static_cast<std::size_t>(k);
        // The light the medium scatters back along a ray that meets no wall (the shader's at infinite depth).
        const double sigma = look.clearFogPerMm + turbidity * look.turbidFogPerMm;
        background[k] = look.fogColour[c] * (1.0 - std::exp(-sigma * lampSourceMm() * 0.5 * kPi)) *
                        std::exp(-bloodFraction * look.bloodAbsorptionPerMm[c] * lampSourceMm());
        background[k] += (look.redOutColour[c] - background[k]) * redOut;
        background[k] = std::min(1.0, background[k] * e * white[c]);
    }
    renderer->SetBackground(background);
}

void EndoscopicView::Impl::updateUniforms() {
    for (vtkShaderProperty* property : fluidShaders()) {
        vtkUniforms* v = property->GetVertexCustomUniforms();
        v->SetUniformf("hsBarrel", static_cast<float>(barrelCoefficient(look.edgeMagnification)));
        v->SetUniformf("hsNear", static_cast<float>(look.nearClipMm));
        v->SetUniformf("hsFadeMm", static_cast<float>(std::max(kDistortionFadeMm, 2.0 * look.nearClipMm)));
        const float scale[2] = {static_cast<float>(fieldScale[0]), static_cast<float>(fieldScale[1])};
        v->SetUniform2f("hsFieldScale", scale);
        vtkUniforms* u = property->GetFragmentCustomUniforms();
        u->SetUniformf("hsNear", static_cast<float>(look.nearClipMm));
        u->SetUniformf("hsFar", static_cast<float>(look.farClipMm));
        u->SetUniformf("hsFogPerMm", static_cast<float>(look.clearFogPerMm + turbidity * look.turbidFogPerMm));
        const float fog[3] = {static_cast<float>(look.fogColour[0]), static_cast<float>(look.fogColour[1]),
                              static_cast<float>(look.fogColour[2])};
        const float red[3] = {static_cast<float>(look.redOutColour[0]), static_cast<float>(look.redOutColour[1]),
                              static_cast<float>(look.redOutColour[2])};
        u->SetUniform3f("hsFogColour", fog);
        u->SetUniform3f("hsRedOutColour", red);
        const float blood[3] = {static_cast<float>(bloodFraction * look.bloodAbsorptionPerMm[0]),
                                static_cast<float>(bloodFraction * look.bloodAbsorptionPerMm[1]),
                                static_cast<float>(bloodFraction * look.bloodAbsorptionPerMm[2])};
        u->SetUniform3f("hsBloodPerMm", blood);
        const float absorption[3] = {static_cast<float>(look.bloodAbsorptionPerMm[0]),
                                     static_cast<float>(look.bloodAbsorptionPerMm[1]),
                                     static_cast<float>(look.bloodAbsorptionPerMm[2])};
        u->SetUniform3f("hsBloodAbsorption", absorption);
        u->SetUniformf("hsRedOut", static_cast<float>(redOut));
        u->SetUniformf("hsLampMm", static_cast<float>(lampSourceMm()));
        u->SetUniformf("hsExposure", static_cast<float>(autoExposure.exposure()));
        const float gains[3] = {static_cast<float>(white[0]), static_cast<float>(white[1]),
                                static_cast<float>(white[2])};
        u->SetUniform3f("hsWhite", gains);
        u->SetUniformf("hsKnee", static_cast<float>(std::clamp(look.toneKnee, 0.05, 0.99)));
    }
    cutActor->GetShaderProperty()->GetFragmentCustomUniforms()->SetUniformf(
        "hsCutContrast", static_cast<float>(std::clamp(look.cutPatternContrast, 0.0, 1.0)));
}

void EndoscopicView::Impl::measureFrame() {
    if (!look.autoExposure && !measure)
        return;
    vtkRenderWindow* window = renderer->GetRenderWindow();
    const int* size = renderer->GetSize();
    const int* origin = renderer->GetOrigin();
    if (!window || size[0] <= 0 || size[1] <= 0)
        return;
    // The optic's circle (fitOverlays) within its bounding square: what the camera head meters.
    const int side = std::min(size[0], size[1]);
    const int x0 = origin[0] + (size[0] - side) / 2, y0 = origin[1] + (size[1] - side) / 2;
    if (!readBack)
        readBack = vtkSmartPointer<vtkUnsignedCharArray>::New();
    if (window->GetRGBACharPixelData(x0, y0, x0 + side - 1, y0 + side - 1, 0, readBack) == VTK_ERROR)
        return;
    const double radius = 0.5 * side;
    stats = circleStats(readBack->GetPointer(0), side, side, 4, radius, radius, radius, side > 400 ? 2 : 1);
    if (!look.autoExposure)
        return;
    const double now = hostTimeS >= 0.0
                           ? hostTimeS
                           : std::chrono::duration<double>(std::chrono::steady_clock::now().time_since_epoch()).count();
    const double elapsed = lastFrameS < 0.0 ? 0.0 : std::max(0.0, now - lastFrameS);
    lastFrameS = now;
    autoExposure.update(stats, elapsed);
    updateUniforms();
    updateBackground();
}

void EndoscopicView::setTime(double seconds) {
    if (std::isfinite(seconds) && seconds >= 0.0)
        m_impl->hostTimeS = seconds;
}

double EndoscopicView::exposure() const {
    return m_impl->autoExposure.exposure();
}

bool EndoscopicView::exposureSettled() const {
    return !m_impl->look.autoExposure || m_impl->autoExposure.settled();
}

std::array<double, 3> EndoscopicView::whiteBalanceGains() const {
    return m_impl->white;
}

const CircleStats& EndoscopicView::lastFrameStats() const {
    return m_impl->stats;
}

void EndoscopicView::measureFrames(bool on) {
    m_impl->measure = on;
}

void EndoscopicView::setHud(const HudText& text) {
    Impl& d = *m_impl;
    d.hud->SetInput(text.status.c_str());
    d.hud->SetVisibility(d.look.hud && !text.status.empty());
    d.warning->SetInput(text.warning.c_str());
    d.warning->SetVisibility(d.look.hud && !text.warning.empty());
}

const EndoscopicLook& EndoscopicView::look() const {
    return m_impl->look;
}

const std::string& EndoscopicView::glRenderer() const {
    return m_impl->glName;
}

bool EndoscopicView::lightDetail() const {
    return m_impl->wantsLight();
}

vtkActor* EndoscopicView::tissueActor() const {
    return m_impl->actor;
}

void EndoscopicView::Impl::fitOverlays() {
    const int* size = renderer->GetSize();
    const int width = size[0], height = size[1];
    if (width <= 0 || height <= 0)
        return;
    // The optic's field is the largest circle the viewport holds; the camera's angle spans that circle.
    vtkCamera* camera = renderer->GetActiveCamera();
    camera->SetUseHorizontalViewAngle(width < height);
    camera->SetViewAngle(fieldOfViewDeg);
    const double shorter = std::min(width, height);
    if (fieldScale[0] != width / shorter || fieldScale[1] != height / shorter) {
        fieldScale = {width / shorter, height / shorter};
        updateUniforms();
    }
    if (width != maskWidth || height != maskHeight || fieldOfViewDeg != occluderFieldOfViewDeg)
        buildOccluder(width, height);
    fitOccluder();
    if (width == maskWidth && height == maskHeight)
        return;
    maskWidth = width;
    maskHeight = height;
    buildMask(width, height);
    const int font = std::max(10, std::min(width, height) / 36);
    hud->GetTextProperty()->SetFontSize(font);
    hud->SetDisplayPosition(font / 2, height - font / 2);
    warning->GetTextProperty()->SetFontSize(font + 2);
    warning->SetDisplayPosition(width / 2, font);
}

void EndoscopicView::Impl::buildMask(int width, int height) {
    const double cx = 0.5 * width, cy = 0.5 * height;
    const double radius = 0.5 * std::min(width, height);
    auto points = vtkSmartPointer<vtkPoints>::New();
    auto colours = vtkSmartPointer<vtkUnsignedCharArray>::New();
    colours->SetNumberOfComponents(4);
    colours->SetName("colours");
    auto cells = vtkSmartPointer<vtkCellArray>::New();
    for (const auto& [fraction, opacity] : kVignette) {
        for (int s = 0; s < kMaskSegments; ++s) {
            const double angle = 2.0 * kPi * s / kMaskSegments;
            // The outer ring lies beyond the viewport's corners.
            const double r = fraction * radius;
            points->InsertNextPoint(cx + r * std::cos(angle), cy + r * std::sin(angle), 0.0);
            const unsigned char colour[4] = {0, 0, 0, static_cast<unsigned char>(std::lround(255.0 * opacity))};
            colours->InsertNextTypedTuple(colour);
        }
    }
    for (std::size_t ring = 0; ring + 1 < kVignette.size(); ++ring) {
        if (kVignette[ring][1] == 0.0 && kVignette[ring + 1][1] == 0.0)
            continue; // fully clear
        for (int s = 0; s < kMaskSegments; ++s) {
            const auto inner = static_cast<vtkIdType>(ring) * kMaskSegments;
            const auto outer = inner + kMaskSegments;
            const vtkIdType a = inner + s, b = inner + (s + 1) % kMaskSegments;
            const vtkIdType c = outer + (s + 1) % kMaskSegments, e = outer + s;
            const vtkIdType first[3] = {a, b, c}, second[3] = {a, c, e};
            cells->InsertNextCell(3, first);
            cells->InsertNextCell(3, second);
        }
    }
    maskGeometry->Initialize();
    maskGeometry->SetPoints(points);
    maskGeometry->SetPolys(cells);
    maskGeometry->GetPointData()->SetScalars(colours);
    maskGeometry->Modified();
}

void EndoscopicView::Impl::buildOccluder(int width, int height) {
    occluderFieldOfViewDeg = fieldOfViewDeg;
    // In the camera's frame (looking down -z), just beyond the near plane: a ring from a pixel and a half outside the
    // mask's circle (where the mask is opaque black) to beyond the viewport's corners.
    const double depth = kOccluderDepth * look.nearClipMm;
    const double radiusPx = 0.5 * std::min(width, height);
    const double radius = depth * std::tan(0.5 * fieldOfViewDeg * kPi / 180.0);
    const double inner = radius * (1.0 + 1.5 / radiusPx) / std::cos(kPi / kMaskSegments);
    const double outer = radius * 4.0 * std::max(width, height) / std::min(width, height);
    auto points = vtkSmartPointer<vtkPoints>::New();
    auto cells = vtkSmartPointer<vtkCellArray>::New();
    for (const double r : {inner, outer})
        for (int s = 0; s < kMaskSegments; ++s) {
            const double angle = 2.0 * kPi * s / kMaskSegments;
            points->InsertNextPoint(r * std::cos(angle), r * std::sin(angle), -depth);
        }
    for (vtkIdType s = 0; s < kMaskSegments; ++s) {
        const vtkIdType a = s, b = (s + 1) % kMaskSegments, c = kMaskSegments + b, e = kMaskSegments + s;
        const vtkIdType first[3] = {a, b, c}, second[3] = {a, c, e};
        cells->InsertNextCell(3, first);
        cells->InsertNextCell(3, second);
    }
    occluderGeometry->Initialize();
    occluderGeometry->SetPoints(points);
    occluderGeometry->SetPolys(cells);
    occluderGeometry->Modified();
}

void EndoscopicView::Impl::fitOccluder() {
    // The camera's frame to the world's: the inverse of its view transform.
    auto toWorld = vtkSmartPointer<vtkMatrix4x4>::New();
    vtkMatrix4x4::Invert(renderer->GetActiveCamera()->GetViewTransformMatrix(), toWorld);
    occluder->SetUserMatrix(toWorld);
}

} // namespace hs::simrender
