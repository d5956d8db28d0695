// The optic's depth of field as a render pass (FocusBlur.h).
#include "FocusBlur.h"

#include "hs/simrender/EndoscopicView.h"

#include <vtkCamera.h>
#include <vtkObjectFactory.h>
#include <vtkOpenGLFramebufferObject.h>
#include <vtkOpenGLQuadHelper.h>
#include <vtkOpenGLRenderUtilities.h>
#include <vtkOpenGLRenderWindow.h>
#include <vtkOpenGLShaderCache.h>
#include <vtkOpenGLState.h>
#include <vtkRenderState.h>
#include <vtkRenderer.h>
#include <vtkShaderProgram.h>
#include <vtkTextureObject.h>
#include <vtk_glew.h>

#include <algorithm>
#include <cmath>
#include <string>

namespace hs::simrender::detail {

namespace {

/// Gathers the picture over each pixel's circle of confusion: 24 taps on a golden-angle spiral filling the disc
/// evenly (Vogel's sunflower), read with bilinear filtering. A pixel whose circle is under a pixel is discarded and
/// keeps the picture copied there before: a software rasterizer shades both sides of a branch for a block of pixels
/// but stops at a block whose pixels are all discarded (the gather for every pixel halved the view's frame rate).
/// The depth buffer gives the distance from the lens (a perspective projection between the clipping planes).
constexpr const char* kGatherDecl = R"(uniform sampler2D hsColour;
uniform sampler2D hsDepth;
uniform vec2 hsPixel;
uniform float hsNearClip;
uniform float hsFarClip;
uniform float hsInvFocusNear;
uniform float hsInvFocusFar;
uniform float hsSharpPx;
uniform float hsMaxRadiusPx;
//VTK::FSQ::Decl)";

constexpr const char* kGatherImpl = R"(  vec4 hsCentre = texture2D(hsColour, texCoord);
  float hsZ = texture2D(hsDepth, texCoord).r;
  float hsMm = hsNearClip * hsFarClip / (hsFarClip - hsZ * (hsFarClip - hsNearClip));
  float hsCircle = hsSharpPx * abs(2.0 / hsMm - hsInvFocusNear - hsInvFocusFar) / (hsInvFocusNear - hsInvFocusFar);
  float hsRadius = min(0.5 * max(hsCircle - hsSharpPx, 0.0), hsMaxRadiusPx);
  if (hsRadius < 0.5)
    discard; // the picture copied under this pass shows there
  vec3 hsSum = vec3(0.0);
  for (int k = 0; k < 24; ++k) {
    float hsR = hsRadius * sqrt((float(k) + 0.5) / 24.0);
    float hsA = 2.39996323 * float(k);
    hsSum += texture2D(hsColour, texCoord + hsPixel * hsR * vec2(cos(hsA), sin(hsA))).rgb;
  }
  gl_FragData[0] = vec4(hsSum / 24.0, hsCentre.a);
//VTK::FSQ::Impl)";

} // namespace

vtkStandardNewMacro(FocusBlurPass)

    FocusBlurPass::~FocusBlurPass() {
    // ReleaseGraphicsResources has run when the window went; these are only left when it never rendered.
    if (m_fbo)
        m_fbo->Delete();
    if (m_colour)
        m_colour->Delete();
    if (m_depth)
        m_depth->Delete();
    delete m_quad;
}

void FocusBlurPass::setFocus(double nearMm, double farMm) {
    if (std::isfinite(nearMm) && std::isfinite(farMm) && nearMm >= 0.5 && farMm > nearMm) {
        m_nearMm = nearMm;
        m_farMm = farMm;
    }
}

void FocusBlurPass::Render(const vtkRenderState* s) {
    NumberOfRenderedProps = 0;
    if (!DelegatePass)
        return;
    vtkRenderer* r = s->GetRenderer();
    auto* window = static_cast<vtkOpenGLRenderWindow*>(r->GetRenderWindow());
    vtkOpenGLState* state = window->GetState();
    int x = 0, y = 0, w = 0, h = 0;
    r->GetTiledSizeAndOrigin(&w, &h, &x, &y);
    if (w <= 0 || h <= 0)
        return;

    if (!m_colour) {
        m_colour = vtkTextureObject::New();
        m_colour->SetContext(window);
        m_colour->SetMinificationFilter(vtkTextureObject::Linear);
        m_colour->SetMagnificationFilter(vtkTextureObject::Linear);
        m_colour->SetWrapS(vtkTextureObject::ClampToEdge);
        m_colour->SetWrapT(vtkTextureObject::ClampToEdge);
    }
    if (m_colour->GetWidth() != static_cast<unsigned>(w) || m_colour->GetHeight() != static_cast<unsigned>(h))
        m_colour->Allocate2D(static_cast<unsigned>(w), static_cast<unsigned>(h), 4, VTK_UNSIGNED_CHAR);
    if (!m_depth) {
        m_depth = vtkTextureObject::New();
        m_depth->SetContext(window);
        m_depth->SetWrapS(vtkTextureObject::ClampToEdge);
        m_depth->SetWrapT(vtkTextureObject::ClampToEdge);
    }
    if (m_depth->GetWidth() != static_cast<unsigned>(w) || m_depth->GetHeight() != static_cast<unsigned>(h))
        m_depth->AllocateDepth(static_cast<unsigned>(w), static_cast<unsigned>(h), vtkTextureObject::Fixed24);
    if (!m_fbo) {
        m_fbo = vtkOpenGLFramebufferObject::New();
        m_fbo->SetContext(window);
    }

    state->PushFramebufferBindings();
    RenderDelegate(s, w, h, w, h, m_fbo, m_colour, m_depth);
    state->PopFramebufferBindings();

    // The sharp picture first, copied as it is (what vtkFramebufferPass does); the blur then draws over the pixels
    // outside the focus range.
    state->PushReadFramebufferBinding();
    m_fbo->Bind(m_fbo->GetReadMode());
    state->vtkglViewport(x, y, w, h);
    state->vtkglScissor(x, y, w, h);
    glBlitFramebuffer(0, 0, w, h, x, y, x + w, y + h, GL_COLOR_BUFFER_BIT, GL_NEAREST);
    state->PopReadFramebufferBinding();

    if (!m_quad) {
        std::string fs = vtkOpenGLRenderUtilities::GetFullScreenQuadFragmentShaderTemplate();
        vtkShaderProgram::Substitute(fs, "//VTK::FSQ::Decl", kGatherDecl);
        vtkShaderProgram::Substitute(fs, "//VTK::FSQ::Impl", kGatherImpl);
        m_quad = new vtkOpenGLQuadHelper(window, vtkOpenGLRenderUtilities::GetFullScreenQuadVertexShader().c_str(),
                                         fs.c_str(), "");
    } else {
        window->GetShaderCache()->ReadyShaderProgram(m_quad->Program);
    }
    if (!m_quad->Program || !m_quad->Program->GetCompiled())
        return;

    const double* clip = r->GetActiveCamera()->GetClippingRange();
    vtkShaderProgram* p = m_quad->Program;
    m_colour->Activate();
    m_depth->Activate();
    p->SetUniformi("hsColour", m_colour->GetTextureUnit());
    p->SetUniformi("hsDepth", m_depth->GetTextureUnit());
    const float pixel[2] = {1.0f / static_cast<float>(w), 1.0f / static_cast<float>(h)};
    p->SetUniform2f("hsPixel", pixel);
    p->SetUniformf("hsNearClip", static_cast<float>(clip[0]));
    p->SetUniformf("hsFarClip", static_cast<float>(clip[1]));
    p->SetUniformf("hsInvFocusNear", static_cast<float>(1.0 / m_nearMm));
    p->SetUniformf("hsInvFocusFar", static_cast<float>(1.0 / m_farMm));
    p->SetUniformf("hsSharpPx", static_cast<float>(m_sharpShare * h));
    p->SetUniformf("hsMaxRadiusPx", static_cast<float>(m_maxRadiusShare * h));

    // The overlays drawn after this pass blend over the picture (the optic's vignetting, the text).
    vtkOpenGLState::ScopedglEnableDisable blend(state, GL_BLEND);
    vtkOpenGLState::ScopedglEnableDisable depthTest(state, GL_DEPTH_TEST);
    state->vtkglDisable(GL_BLEND);
    state->vtkglDisable(GL_DEPTH_TEST);
    state->vtkglViewport(x, y, w, h);
    state->vtkglScissor(x, y, w, h);
    m_quad->Render();
    m_depth->Deactivate();
    m_colour->Deactivate();
    NumberOfRenderedProps = DelegatePass->GetNumberOfRenderedProps();
}

void FocusBlurPass::ReleaseGraphicsResources(vtkWindow* w) {
    Superclass::ReleaseGraphicsResources(w);
    delete m_quad;
    m_quad = nullptr;
    if (m_fbo) {
        m_fbo->Delete();
        m_fbo = nullptr;
    }
    if (m_colour) {
        m_colour->Delete();
        m_colour = nullptr;
    }
    if (m_depth) {
        m_depth->Delete();
        m_depth = nullptr;
    }
}

} // namespace hs::simrender::detail

namespace hs::simrender {

double circleOfConfusionShare(double distanceMm, double nearMm, double farMm) {
    const double invNear = 1.0 / nearMm, invFar = 1.0 / farMm;
    return std::abs(2.0 / distanceMm - invNear - invFar) / (invNear - invFar);
}

} // namespace hs::simrender
