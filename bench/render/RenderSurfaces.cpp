// render_surfaces: offscreen VTK pictures of labelled surfaces side by side, for the docs (run under xvfb-run -a).
//   render_surfaces OUT.png [--label NAME] [--cut | --sagittal] [--view front|side] [--size W H]
//   SURFACE.vtp[+MORE.vtp...] [TITLE]
// A viewport may show several surfaces joined by '+': the first (the organ) is coloured by the label and cut, the
// others (pathologies) are drawn whole in fixed colours (pale ivory, pink, blue, ...).
// Each surface gets its own viewport with its title; faces are coloured by the integer face label NAME (default
// "tissue"). --cut keeps the posterior half (y < centre) so the cavity shows in a coronal section, as on 3-D
// ultrasound. All viewports share one camera distance so sizes compare.
#include <vtkActor.h>
#include <vtkCamera.h>
#include <vtkCellData.h>
#include <vtkClipPolyData.h>
#include <vtkCoordinate.h>
#include <vtkDataArray.h>
#include <vtkLookupTable.h>
#include <vtkNew.h>
#include <vtkPNGWriter.h>
#include <vtkPlane.h>
#include <vtkPolyData.h>
#include <vtkPolyDataMapper.h>
#include <vtkProperty.h>
#include <vtkRenderWindow.h>
#include <vtkRenderer.h>
#include <vtkSmartPointer.h>
#include <vtkTextActor.h>
#include <vtkTextProperty.h>
#include <vtkWindowToImageFilter.h>
#include <vtkXMLPolyDataReader.h>

#include <algorithm>
#include <array>
#include <cstdio>
#include <cstdlib>
#include <string>
#include <utility>
#include <vector>

namespace {

struct Options {
    std::string output;
    std::string label = "tissue";
    bool cut = false;
    bool sagittal = false; ///< with cut: keep x < centre and look from +x
    std::string view = "front";
    int width = 400; ///< per viewport, pixels
    int height = 480;
    std::vector<std::pair<std::string, std::string>> surfaces; ///< path, title
};

bool parse(int argc, char** argv, Options& o) {
    if (argc < 3)
        return false;
    o.output = argv[1];
    for (int i = 2; i < argc; ++i) {
        const std::string a = argv[i];
        if (a == "--label" && i + 1 < argc)
            o.label = argv[++i];
        else if (a == "--cut")
            o.cut = true;
        else if (a == "--sagittal") { // cut along the mid-sagittal plane, seen from the patient's left
            o.cut = true;
            o.sagittal = true;
            o.view = "side";
        } else if (a == "--view" && i + 1 < argc)
            o.view = argv[++i];
        else if (a == "--size" && i + 2 < argc) {
            o.width = std::atoi(argv[++i]);
            o.height = std::atoi(argv[++i]);
        } else if (a.find(".vtp") != std::string::npos) {
            std::string title =
                (i + 1 < argc && std::string(argv[i + 1]).find(".vtp") == std::string::npos && argv[i + 1][0] != '-')
                    ? argv[++i]
                    : std::string();
            o.surfaces.emplace_back(a, title);
        } else {
            return false;
        }
    }
    return !o.surfaces.empty() && o.width > 16 && o.height > 16;
}

/// Tissue colours: serosa, endometrium, cervical canal, ostium, ectocervix, then pathology regions.
void fillPalette(vtkLookupTable* lut) {
    const double colours[][3] = {{0.80, 0.80, 0.80}, {0.86, 0.62, 0.58}, {0.80, 0.30, 0.32}, {0.85, 0.55, 0.45},
                                 {0.95, 0.85, 0.30}, {0.70, 0.45, 0.50}, {0.93, 0.90, 0.80}, {0.90, 0.50, 0.60},
                                 {0.55, 0.70, 0.85}, {0.60, 0.80, 0.55}};
    lut->SetNumberOfTableValues(10);
    lut->SetTableRange(0, 9);
    for (int i = 0; i < 10; ++i)
        lut->SetTableValue(i, colours[i][0], colours[i][1], colours[i][2], 1.0);
    lut->Build();
}

} // namespace

int main(int argc, char** argv) {
    Options o;
    if (!parse(argc, argv, o)) {
        std::fprintf(stderr, "usage: render_surfaces OUT.png [--label NAME] [--cut] [--view front|side] "
                             "[--size W H] SURFACE.vtp [TITLE] ...\n");
        return 2;
    }
    const int n = static_cast<int>(o.surfaces.size());
    vtkNew<vtkRenderWindow> window;
    window->SetOffScreenRendering(1);
    window->SetMultiSamples(8);
    window->SetSize(o.width * n, o.height);
    vtkNew<vtkLookupTable> lut;
    fillPalette(lut);

    double radius = 0.0;
    std::vector<vtkRenderer*> renderers;
    std::vector<std::array<double, 3>> centres;
    for (int i = 0; i < n; ++i) {
        const std::string& spec = o.surfaces[static_cast<std::size_t>(i)].first;
        std::vector<std::string> files;
        for (std::size_t start = 0;;) {
            const auto plus = spec.find('+', start);
            files.push_back(spec.substr(start, plus == std::string::npos ? std::string::npos : plus - start));
            if (plus == std::string::npos)
                break;
            start = plus + 1;
        }
        std::vector<vtkSmartPointer<vtkActor>> actors;
        std::array<double, 3> c{};
        for (std::size_t f = 0; f < files.size(); ++f) {
            vtkNew<vtkXMLPolyDataReader> reader;
            reader->SetFileName(files[f].c_str());
            reader->Update();
            vtkPolyData* poly = reader->GetOutput();
            if (!poly || poly->GetNumberOfCells() == 0) {
                std::fprintf(stderr, "render_surfaces: %s: no surface\n", files[f].c_str());
                return 3;
            }
            vtkNew<vtkPolyDataMapper> mapper;
            if (f == 0) {
                double b[6];
                poly->GetBounds(b);
                c = {(b[0] + b[1]) / 2, (b[2] + b[3]) / 2, (b[4] + b[5]) / 2};
                radius = std::max({radius, (b[1] - b[0]) / 2, (b[3] - b[2]) / 2, (b[5] - b[4]) / 2});
                centres.push_back(c);
            }
            if (o.cut && f == 0) {
                vtkNew<vtkPlane> plane;
                plane->SetOrigin(c[0], c[1], c[2]);
                if (o.sagittal)
                    plane->SetNormal(-1, 0, 0); // keep x < centre, seen from +x
                else
                    plane->SetNormal(0, -1, 0); // keep y < centre: the posterior half, seen from the front
                vtkNew<vtkClipPolyData> clip;
                clip->SetClipFunction(plane);
                clip->SetInputData(poly);
                clip->Update();
                mapper->SetInputData(clip->GetOutput());
            } else {
                vtkNew<vtkPolyData> copy;
                copy->DeepCopy(poly);
                mapper->SetInputData(copy);
            }
            auto actor = vtkSmartPointer<vtkActor>::New();
            if (f == 0 && poly->GetCellData()->GetArray(o.label.c_str())) {
                mapper->SetScalarModeToUseCellFieldData();
                mapper->SelectColorArray(o.label.c_str());
                mapper->SetLookupTable(lut);
                mapper->UseLookupTableScalarRangeOn();
                mapper->ScalarVisibilityOn();
            } else {
                mapper->ScalarVisibilityOff();
                const double colours[][3] = {{0.93, 0.90, 0.80}, {0.95, 0.60, 0.70}, {0.55, 0.70, 0.90}};
                const auto& col = colours[(f == 0 ? 0 : f - 1) % 3];
                actor->GetProperty()->SetColor(col[0], col[1], col[2]);
            }
            actor->SetMapper(mapper);
            actor->GetProperty()->SetSpecular(0.2);
            actor->GetProperty()->SetBackfaceCulling(0);
            actors.push_back(actor);
        }
        vtkNew<vtkRenderer> renderer;
        renderer->SetViewport(double(i) / n, 0.0, double(i + 1) / n, 1.0);
        renderer->SetBackground(1.0, 1.0, 1.0);
        for (const auto& actor : actors)
            renderer->AddActor(actor);
        vtkNew<vtkTextActor> title;
        title->SetInput(o.surfaces[static_cast<std::size_t>(i)].second.c_str());
        title->GetTextProperty()->SetColor(0.1, 0.1, 0.1);
        title->GetTextProperty()->SetFontSize(16);
        title->GetTextProperty()->SetVerticalJustificationToTop();
        title->GetPositionCoordinate()->SetCoordinateSystemToNormalizedViewport();
        title->SetPosition(0.03, 0.97);
        renderer->AddActor2D(title);
        window->AddRenderer(renderer);
        renderers.push_back(renderer);
    }
    for (int i = 0; i < n; ++i) {
        vtkCamera* camera = renderers[static_cast<std::size_t>(i)]->GetActiveCamera();
        const auto& c = centres[static_cast<std::size_t>(i)];
        camera->SetFocalPoint(c[0], c[1], c[2]);
        // Far enough that the largest organ fits the narrower side of the viewport.
        const double distance = 6.0 * radius * std::max(1.0, double(o.height) / double(o.width));
        if (o.view == "side")
            camera->SetPosition(c[0] + distance, c[1], c[2]);
        else
            camera->SetPosition(c[0], c[1] + distance, c[2]);
        camera->SetViewUp(0, 0, 1);
        camera->SetViewAngle(22.0);
        renderers[static_cast<std::size_t>(i)]->ResetCameraClippingRange();
    }
    window->Render();
    vtkNew<vtkWindowToImageFilter> grab;
    grab->SetInput(window);
    vtkNew<vtkPNGWriter> writer;
    writer->SetFileName(o.output.c_str());
    writer->SetInputConnection(grab->GetOutputPort());
    writer->Write();
    std::printf("wrote %s (%d surfaces)\n", o.output.c_str(), n);
    return 0;
}
