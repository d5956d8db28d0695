// render_endoscope: the view a hysteroscope has of a scene package's cavity, offscreen, for the docs and for
// judging the visual surface at close range (run under xvfb-run -a).
//   render_endoscope SCENE_DIR OUT.png [--size W H] [--fov DEG] [--smooth] [--advance MM]
// The camera stands at the internal os (the scene's landmark, hs::scene::findScopeLandmarks) and looks at the
// centre of the cavity (the endometrium faces); the only light is at the camera, as with a scope's light guide.
// The surface is drawn as the package stores it (surface.vtp with its UVs, normals and maps/albedo.png): without
// stored normals VTK shades each facet flat, which is what a simulator that loads such a package as-is shows.
// --smooth computes vertex normals first; --advance moves the camera that far along the view direction (mm;
// negative: back down the canal); --eye puts the camera at X Y Z looking at FX FY FZ instead (mm).
#include "hs/clinical/Tissue.h"
#include "hs/scene/ScenePackage.h"
#include "hs/scene/ScopePassage.h"

#include <vtkActor.h>
#include <vtkCamera.h>
#include <vtkCellData.h>
#include <vtkDataArray.h>
#include <vtkLight.h>
#include <vtkNew.h>
#include <vtkPNGReader.h>
#include <vtkPNGWriter.h>
#include <vtkPolyData.h>
#include <vtkPolyDataMapper.h>
#include <vtkPolyDataNormals.h>
#include <vtkProperty.h>
#include <vtkRenderWindow.h>
#include <vtkRenderer.h>
#include <vtkTexture.h>
#include <vtkTriangle.h>
#include <vtkWindowToImageFilter.h>
#include <vtkXMLPolyDataReader.h>

#include <array>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <string>
#include <vector>

namespace {

// Values of the organ's surface tissue label, carried onto the visual surface.
constexpr int kEndometrium = hs::clinical::labelValue(hs::clinical::SurfaceTissue::Endometrium);

struct Options {
    std::string scene;
    std::string output;
    int width = 640;
    int height = 640;
    double fovDeg = 90.0; ///< office hysteroscopes see 70-110 degrees
    bool smooth = false;
    double advanceMm = 0.0;
    bool view = false; ///< --eye: camera and focal point given (mm, scene frame)
    std::array<double, 3> eye{}, focal{};
};

bool parse(int argc, char** argv, Options& o) {
    if (argc < 3)
        return false;
    o.scene = argv[1];
    o.output = argv[2];
    for (int i = 3; i < argc; ++i) {
        const std::string a = argv[i];
        if (a == "--size" && i + 2 < argc) {
            o.width = std::atoi(argv[++i]);
            o.height = std::atoi(argv[++i]);
        } else if (a == "--fov" && i + 1 < argc)
            o.fovDeg = std::atof(argv[++i]);
        else if (a == "--advance" && i + 1 < argc)
            o.advanceMm = std::atof(argv[++i]);
        else if (a == "--eye" && i + 6 < argc) {
            o.view = true;
            for (int k = 0; k < 3; ++k)
                o.eye[static_cast<std::size_t>(k)] = std::atof(argv[++i]);
            for (int k = 0; k < 3; ++k)
                o.focal[static_cast<std::size_t>(k)] = std::atof(argv[++i]);
        } else if (a == "--smooth")
            o.smooth = true;
        else
            return false;
    }
    return o.width > 16 && o.width <= 4096 && o.height > 16 && o.height <= 4096 && o.fovDeg > 10.0 && o.fovDeg < 170.0;
}

using P3 = std::array<double, 3>;

P3 centroid(vtkPolyData* poly, vtkIdType cell) {
    vtkCell* c = poly->GetCell(cell);
    P3 sum{0, 0, 0};
    for (vtkIdType k = 0; k < c->GetNumberOfPoints(); ++k) {
        double p[3];
        poly->GetPoint(c->GetPointId(k), p);
        for (int d = 0; d < 3; ++d)
            sum[static_cast<std::size_t>(d)] += p[d];
    }
    for (auto& s : sum)
        s /= static_cast<double>(c->GetNumberOfPoints());
    return sum;
}

double dist2(const P3& a, const P3& b) {
    return (a[0] - b[0]) * (a[0] - b[0]) + (a[1] - b[1]) * (a[1] - b[1]) + (a[2] - b[2]) * (a[2] - b[2]);
}

/// The focal point: the area-weighted centre of the endometrium faces (the cavity's centre).
bool cavityCentreOf(vtkPolyData* poly, P3& cavityCentre) {
    vtkDataArray* tissue = poly->GetCellData()->GetArray(hs::clinical::kSurfaceTissueLabel);
    if (!tissue)
        return false;
    P3 cavity{0, 0, 0};
    double cavityArea = 0.0;
    for (vtkIdType f = 0; f < poly->GetNumberOfCells(); ++f) {
        if (static_cast<int>(tissue->GetTuple1(f)) == kEndometrium) {
            vtkCell* c = poly->GetCell(f);
            double a[3], b[3], d[3];
            poly->GetPoint(c->GetPointId(0), a);
            poly->GetPoint(c->GetPointId(1), b);
            poly->GetPoint(c->GetPointId(2), d);
            const double area = vtkTriangle::TriangleArea(a, b, d);
            const P3 m = centroid(poly, f);
            for (std::size_t k = 0; k < 3; ++k)
                cavity[k] += area * m[k];
            cavityArea += area;
        }
    }
    if (cavityArea <= 0.0)
        return false;
    for (auto& c : cavity)
        c /= cavityArea;
    cavityCentre = cavity;
    return true;
}

} // namespace

int main(int argc, char** argv) {
    Options o;
    if (!parse(argc, argv, o)) {
        std::fprintf(stderr, "usage: render_endoscope SCENE_DIR OUT.png [--size W H] [--fov DEG] [--smooth] "
                             "[--advance MM] [--eye X Y Z FX FY FZ]\n");
        return 2;
    }
    const std::filesystem::path scene(o.scene);
    const std::string surfacePath = (scene / "surface.vtp").string();
    const std::string albedoPath = (scene / "maps" / "albedo.png").string();
    if (!std::filesystem::is_regular_file(surfacePath) || !std::filesystem::is_regular_file(albedoPath)) {
        std::fprintf(stderr, "render_endoscope: %s: no surface.vtp or maps/albedo.png\n", o.scene.c_str());
        return 3;
    }
    vtkNew<vtkXMLPolyDataReader> reader;
    reader->SetFileName(surfacePath.c_str());
    reader->Update();
    vtkPolyData* poly = reader->GetOutput();
    // The internal os as the package's other readers (validate's scope passage) find it.
    auto package = hs::scene::readScenePackage(o.scene);
    if (!package) {
        std::fprintf(stderr, "render_endoscope: %s\n", package.error().message().c_str());
        return 3;
    }
    auto found = hs::scene::findScopeLandmarks(*package);
    if (!found) {
        std::fprintf(stderr, "render_endoscope: %s: %s\n", o.scene.c_str(), found.error().message().c_str());
        return 3;
    }
    P3 eye{found->internalOsMm.x, found->internalOsMm.y, found->internalOsMm.z}, focal{};
    if (o.view) {
        eye = o.eye;
        focal = o.focal;
    } else if (!cavityCentreOf(poly, focal)) {
        std::fprintf(stderr, "render_endoscope: %s: no endometrium faces\n", surfacePath.c_str());
        return 3;
    }
    P3 dir{focal[0] - eye[0], focal[1] - eye[1], focal[2] - eye[2]};
    const double len = std::sqrt(dist2(eye, focal));
    for (std::size_t k = 0; k < 3; ++k)
        eye[k] += o.advanceMm * dir[k] / len;

    vtkNew<vtkPNGReader> png;
    png->SetFileName(albedoPath.c_str());
    vtkNew<vtkTexture> texture;
    texture->SetInputConnection(png->GetOutputPort());
    texture->InterpolateOn();
    texture->UseSRGBColorSpaceOn();

    vtkNew<vtkPolyDataMapper> mapper;
    vtkNew<vtkPolyDataNormals> normals;
    if (o.smooth) {
        normals->SetInputData(poly);
        normals->SplittingOff();
        normals->ConsistencyOff();
        normals->ComputePointNormalsOn();
        normals->ComputeCellNormalsOff();
        mapper->SetInputConnection(normals->GetOutputPort());
    } else {
        mapper->SetInputData(poly);
    }
    mapper->ScalarVisibilityOff();
    vtkNew<vtkActor> actor;
    actor->SetMapper(mapper);
    actor->SetTexture(texture);
    actor->GetProperty()->SetInterpolationToGouraud();
    actor->GetProperty()->SetSpecular(0.3);
    actor->GetProperty()->SetSpecularPower(30.0);
    // The cavity is seen from inside the organ's closed surface: draw both sides.
    actor->GetProperty()->BackfaceCullingOff();

    vtkNew<vtkRenderer> renderer;
    renderer->AddActor(actor);
    renderer->SetBackground(0.0, 0.0, 0.0);
    renderer->AutomaticLightCreationOff();
    vtkNew<vtkLight> light;
    light->SetLightTypeToHeadlight();
    light->SetIntensity(1.0);
    renderer->AddLight(light);
    vtkCamera* camera = renderer->GetActiveCamera();
    camera->SetPosition(eye.data());
    camera->SetFocalPoint(focal.data());
    camera->SetViewUp(0.0, 1.0, 0.0);
    camera->SetViewAngle(o.fovDeg);
    camera->SetClippingRange(0.05, 200.0);

    vtkNew<vtkRenderWindow> window;
    window->SetOffScreenRendering(1);
    window->SetSize(o.width, o.height);
    window->AddRenderer(renderer);
    window->Render();
    vtkNew<vtkWindowToImageFilter> grab;
    grab->SetInput(window);
    grab->Update();
    vtkNew<vtkPNGWriter> writer;
    const std::string tmp = o.output + ".tmp.png";
    writer->SetFileName(tmp.c_str());
    writer->SetInputConnection(grab->GetOutputPort());
    writer->Write();
    std::error_code ec;
    std::filesystem::rename(tmp, o.output, ec);
    if (ec) {
        std::fprintf(stderr, "render_endoscope: %s: %s\n", o.output.c_str(), ec.message().c_str());
        return 4;
    }
    std::printf("camera %.1f %.1f %.1f -> %.1f %.1f %.1f (%.1f mm), fov %.0f deg, %lld faces\n", eye[0], eye[1], eye[2],
                focal[0], focal[1], focal[2], len, o.fovDeg, static_cast<long long>(poly->GetNumberOfCells()));
    return 0;
}
