#pragma once
/// The optic's depth of field: a render pass that draws the scene into a framebuffer with its depth, then blurs each
/// pixel by the circle of confusion of its distance from the lens (docs/simulator.md, "Depth of field"). The 2-D
/// overlays (the optic's mask, the heads-up text) are drawn after it, sharp.

#include <vtkDepthImageProcessingPass.h>

class vtkOpenGLFramebufferObject;
class vtkOpenGLQuadHelper;
class vtkTextureObject;

namespace hs::simrender::detail {

class FocusBlurPass : public vtkDepthImageProcessingPass {
public:
    static FocusBlurPass* New();
    vtkTypeMacro(FocusBlurPass, vtkDepthImageProcessingPass)

        void Render(const vtkRenderState* s) override;
    void ReleaseGraphicsResources(vtkWindow* w) override;

    /// The optic's focus range, mm (0.5 <= near < far).
    void setFocus(double nearMm, double farMm);
    /// The circle a sharp point may blur into, as a share of the picture's height: the picture's own resolution.
    void setSharpCircle(double share) { m_sharpShare = share; }
    /// The largest blur's radius, as a share of the picture's height.
    void setLargestRadius(double share) { m_maxRadiusShare = share; }

protected:
    FocusBlurPass() = default;
    ~FocusBlurPass() override;

private:
    FocusBlurPass(const FocusBlurPass&) = delete;
    void operator=(const FocusBlurPass&) = delete;

    vtkOpenGLFramebufferObject* m_fbo = nullptr;
    vtkTextureObject* m_colour = nullptr;
    vtkTextureObject* m_depth = nullptr;
    vtkOpenGLQuadHelper* m_quad = nullptr;
    double m_nearMm = 2.0, m_farMm = 50.0;
    double m_sharpShare = 1.0 / 480.0;
    double m_maxRadiusShare = 0.03;
};

} // namespace hs::simrender::detail
