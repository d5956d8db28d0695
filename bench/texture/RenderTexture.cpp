// render_texture: offscreen VTK render of a baked surface (the output folder of `hysteroscene-cli texture bake`),
// for docs/images/texture-*.png. Run under `xvfb-run -a`.
//   render_texture BAKE_DIR OUT.png [dirX dirY dirZ] [zoom] [width height]
// The camera looks at the surface's centre from the given direction; a light follows the camera like the
// endoscope's. PBR shading with the baked albedo (sRGB), normal and roughness maps.
#include <vtkActor.h>
#include <vtkCamera.h>
#include <vtkDataArray.h>
#include <vtkImageData.h>
#include <vtkLight.h>
#include <vtkNew.h>
#include <vtkPNGReader.h>
#include <vtkPNGWriter.h>
#include <vtkPointData.h>
#include <vtkPolyData.h>
#include <vtkPolyDataMapper.h>
#include <vtkPolyDataTangents.h>
#include <vtkProperty.h>
#include <vtkRenderWindow.h>
#include <vtkRenderer.h>
#include <vtkTexture.h>
#include <vtkUnsignedCharArray.h>
#include <vtkWindowToImageFilter.h>
#include <vtkXMLPolyDataReader.h>

#include <cmath>
#include <cstdio>
#include <string>

namespace {

vtkSmartPointer<vtkTexture> loadTexture(const std::string& path, bool srgb) {
    vtkNew<vtkPNGReader> reader;
    reader->SetFileName(path.c_str());
    reader->Update();
    auto texture = vtkSmartPointer<vtkTexture>::New();
    texture->SetInputConnection(reader->GetOutputPort());
    texture->InterpolateOn();
    texture->MipmapOn();
    texture->SetUseSRGBColorSpace(srgb);
    return texture;
}

/// Occlusion-roughness-metallic texture from the single-channel roughness map.
vtkSmartPointer<vtkTexture> ormTexture(const std::string& roughnessPath) {
    vtkNew<vtkPNGReader> reader;
    reader->SetFileName(roughnessPath.c_str());
    reader->Update();
    vtkImageData* rough = reader->GetOutput();
    auto orm = vtkSmartPointer<vtkImageData>::New();
    orm->SetDimensions(rough->GetDimensions());
    orm->AllocateScalars(VTK_UNSIGNED_CHAR, 3);
    const vtkIdType n = rough->GetNumberOfPoints();
    vtkDataArray* in = rough->GetPointData()->GetScalars();
    auto* out = static_cast<unsigned char*>(orm->GetScalarPointer());
    for (vtkIdType i = 0; i < n; ++i) {
        out[3 * i + 0] = 255;
        out[3 * i + 1] = static_cast<unsigned char>(in->GetComponent(i, 0));
        out[3 * i + 2] = 0;
    }
    auto texture = vtkSmartPointer<vtkTexture>::New();
    texture->SetInputData(orm);
    texture->InterpolateOn();
    texture->MipmapOn();
    return texture;
}

} // namespace

int main(int argc, char** argv) {
    if (argc < 3) {
        std::fprintf(stderr, "usage: render_texture BAKE_DIR OUT.png [dirX dirY dirZ] [zoom] [width height]\n");
        return 2;
    }
    const std::string dir = argv[1];
    double view[3] = {0.0, 1.0, 0.3};
    if (argc >= 6)
        for (int i = 0; i < 3; ++i)
            view[i] = std::stod(argv[3 + i]);
    const double zoom = argc >= 7 ? std::stod(argv[6]) : 1.0;
    const int width = argc >= 9 ? std::stoi(argv[7]) : 640;
    const int height = argc >= 9 ? std::stoi(argv[8]) : 480;

    vtkNew<vtkXMLPolyDataReader> reader;
    reader->SetFileName((dir + "/surface.vtp").c_str());
    vtkNew<vtkPolyDataTangents> tangents;
    tangents->SetInputConnection(reader->GetOutputPort());
    vtkNew<vtkPolyDataMapper> mapper;
    mapper->SetInputConnection(tangents->GetOutputPort());
    mapper->ScalarVisibilityOff();

    vtkNew<vtkActor> actor;
    actor->SetMapper(mapper);
    vtkProperty* prop = actor->GetProperty();
    prop->SetInterpolationToPBR();
    prop->SetColor(1.0, 1.0, 1.0);
    prop->SetMetallic(0.0);
    prop->SetRoughness(1.0);
    prop->SetBaseColorTexture(loadTexture(dir + "/albedo.png", true));
    prop->SetNormalTexture(loadTexture(dir + "/normal.png", false));
    prop->SetORMTexture(ormTexture(dir + "/roughness.png"));
    prop->SetNormalScale(1.0);

    vtkNew<vtkRenderer> renderer;
    renderer->AddActor(actor);
    renderer->SetBackground(0.05, 0.04, 0.04);
    renderer->AutomaticLightCreationOff();
    vtkNew<vtkLight> light;
    light->SetLightTypeToHeadlight();
    light->SetIntensity(3.0);
    renderer->AddLight(light);

    vtkNew<vtkRenderWindow> window;
    window->SetOffScreenRendering(1);
    window->AddRenderer(renderer);
    window->SetSize(width, height);
    window->SetMultiSamples(4);

    reader->Update();
    double b[6];
    reader->GetOutput()->GetBounds(b);
    const double centre[3] = {(b[0] + b[1]) / 2, (b[2] + b[3]) / 2, (b[4] + b[5]) / 2};
    const double diag =
        std::sqrt((b[1] - b[0]) * (b[1] - b[0]) + (b[3] - b[2]) * (b[3] - b[2]) + (b[5] - b[4]) * (b[5] - b[4]));
    const double len = std::sqrt(view[0] * view[0] + view[1] * view[1] + view[2] * view[2]);
    vtkCamera* camera = renderer->GetActiveCamera();
    camera->SetFocalPoint(centre);
    camera->SetPosition(centre[0] + view[0] / len * diag * 1.6, centre[1] + view[1] / len * diag * 1.6,
                        centre[2] + view[2] / len * diag * 1.6);
    camera->SetViewUp(std::fabs(view[2] / len) > 0.9 ? 0.0 : 0.0, std::fabs(view[2] / len) > 0.9 ? 1.0 : 0.0,
                      std::fabs(view[2] / len) > 0.9 ? 0.0 : 1.0);
    camera->SetViewAngle(30.0);
    camera->Zoom(zoom);
    renderer->ResetCameraClippingRange();
    window->Render();

    vtkNew<vtkWindowToImageFilter> grab;
    grab->SetInput(window);
    grab->ReadFrontBufferOff();
    vtkNew<vtkPNGWriter> writer;
    writer->SetFileName(argv[2]);
    writer->SetInputConnection(grab->GetOutputPort());
    writer->Write();
    std::printf("wrote %s\n", argv[2]);
    return 0;
}
