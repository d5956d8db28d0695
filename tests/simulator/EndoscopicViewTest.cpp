// The endoscopic view (hs/simrender/EndoscopicView.h) drawing offscreen from inside a sphere (needs an X display:
// run under xvfb-run): the detail it picks for the GL renderer, a decimated surface following the deformed points,
// and the picture (lit tissue in the middle, black outside the optic's circle) at either detail.

#include "hs/simrender/EndoscopicView.h"
#include "TestSpheres.h"
#include "hs/clinical/Tissue.h"
#include "hs/simrender/ViewDecimation.h"

#include <gtest/gtest.h>

#include <vtkActor.h>
#include <vtkMapper.h>
#include <vtkNew.h>
#include <vtkPNGWriter.h>
#include <vtkPolyData.h>
#include <vtkRenderWindow.h>
#include <vtkRenderer.h>
#include <vtkUnsignedCharArray.h>
#include <vtkWindowToImageFilter.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <vector>

namespace hs::simrender {
namespace {

/// A closed sphere of radius 20 mm around the origin, as a visual surface without maps.
scene::VisualSurface sphere() {
    scene::VisualSurface surface;
    surface.mesh = test::latitudeSphere(30, 60, false);
    return surface;
}

class EndoscopicViewTest : public ::testing::Test {
protected:
    void SetUp() override {
        if (!std::getenv("DISPLAY"))
            GTEST_SKIP() << "no X display (run under xvfb-run)";
        m_window->SetOffScreenRendering(1);
        m_window->SetMultiSamples(0);
        m_window->SetSize(160, 120);
        m_window->AddRenderer(m_renderer);
    }

    /// Draws `view` from the sphere's centre looking along +x.
    void draw(EndoscopicView& view) {
        view.setPose({{0, 0, 0}, {1, 0, 0}, {0, 0, 1}, 90.0});
        m_window->Render();
    }

    /// The red channel at pixel (x, y) of the last picture (y from the bottom).
    int red(int x, int y) { return channel(x, y, 0); }
    int channel(int x, int y, int c) {
        vtkNew<vtkUnsignedCharArray> pixels;
        m_window->GetRGBACharPixelData(x, y, x, y, 0, pixels);
        return pixels->GetValue(c);
    }

    vtkNew<vtkRenderWindow> m_window;
    vtkNew<vtkRenderer> m_renderer;
};

TEST_F(EndoscopicViewTest, ChoosesTheLightDetailOnASoftwareRasterizer) {
    const scene::VisualSurface surface = sphere();
    EndoscopicView view(m_renderer);
    view.setSurface(surface);
    EXPECT_TRUE(view.glRenderer().empty()); // known at the first render
    draw(view);
    ASSERT_FALSE(view.glRenderer().empty());
    const bool software = isSoftwareRenderer(view.glRenderer());
    EXPECT_EQ(view.lightDetail(), software) << view.glRenderer();
    if (software) // decimated by default
        EXPECT_LT(view.drawnTriangleCount(), surface.mesh.triangles.size() * 6 / 10);
    else
        EXPECT_EQ(view.drawnTriangleCount(), surface.mesh.triangles.size());
    EXPECT_EQ(view.pointCount(), surface.mesh.points.size());
}

TEST_F(EndoscopicViewTest, ADecimatedSurfaceFollowsTheDeformedPoints) {
    const scene::VisualSurface surface = sphere();
    EndoscopicLook look;
    look.detail = ViewDetail::Light;
    look.lightReduction = 0.5;
    EndoscopicView view(m_renderer, look);
    view.setSurface(surface);
    draw(view);
    EXPECT_TRUE(view.lightDetail());
    EXPECT_EQ(view.pointCount(), surface.mesh.points.size()); // the host still hands over every point
    const auto drawnBounds = [&](double out[6]) {
        vtkPolyData::SafeDownCast(view.tissueActor()->GetMapper()->GetInput())->GetBounds(out);
    };
    double rest[6], bounds[6];
    drawnBounds(rest);
    std::vector<Vec3> moved = surface.mesh.points;
    for (Vec3& p : moved)
        p = p * 1.5 + Vec3{5.0, 0.0, 0.0};
    view.setPoints(moved);
    drawnBounds(bounds);
    for (int k = 0; k < 6; ++k)
        EXPECT_NEAR(bounds[k], rest[k] * 1.5 + (k < 2 ? 5.0 : 0.0), 1e-3) << k;
    // A point list of another surface is ignored.
    moved.pop_back();
    for (Vec3& p : moved)
        p = p + Vec3{0.0, 0.0, 7.0};
    view.setPoints(moved);
    double unchanged[6];
    drawnBounds(unchanged);
    EXPECT_EQ(unchanged[4], bounds[4]);
}

TEST_F(EndoscopicViewTest, WhileTheOuterSurfaceIsHiddenOnlyTheInnerPointsAreReadAndDrawn) {
    // The sphere's southern half labelled serosa (the outer surface), the northern half endometrium.
    scene::VisualSurface surface = sphere();
    std::vector<std::int32_t> tissue(surface.mesh.triangles.size());
    for (std::size_t f = 0; f < tissue.size(); ++f) {
        const Triangle& t = surface.mesh.triangles[f];
        const double z = surface.mesh.points[static_cast<std::size_t>(t[0])].z +
                         surface.mesh.points[static_cast<std::size_t>(t[1])].z +
                         surface.mesh.points[static_cast<std::size_t>(t[2])].z;
        tissue[f] =
            clinical::labelValue(z < 0.0 ? clinical::SurfaceTissue::Serosa : clinical::SurfaceTissue::Endometrium);
    }
    surface.mesh.faceLabels[clinical::kSurfaceTissueLabel] = tissue;
    EndoscopicLook look;
    look.detail = ViewDetail::Full;
    EndoscopicView view(m_renderer, look);
    view.setSurface(surface);
    draw(view);
    const auto drawn = [&] { return vtkPolyData::SafeDownCast(view.tissueActor()->GetMapper()->GetInput()); };
    EXPECT_TRUE(view.sourcePointsInUse().empty() ||
                view.sourcePointsInUse().size() == surface.mesh.points.size()); // all of them while shown
    const vtkIdType allPoints = drawn()->GetNumberOfPoints();

    view.setOuterSurfaceVisible(false);
    const std::vector<std::int32_t> inUse = view.sourcePointsInUse();
    ASSERT_FALSE(inUse.empty());
    EXPECT_LT(inUse.size(), surface.mesh.points.size() * 7 / 10); // about the northern half
    for (const std::int32_t i : inUse)
        EXPECT_GE(surface.mesh.points[static_cast<std::size_t>(i)].z, -2.5) << i;  // no southern point but the rim
    EXPECT_EQ(drawn()->GetNumberOfPoints(), static_cast<vtkIdType>(inUse.size())); // only those are uploaded
    // Only the points in use need their deformed place: the others may be anything.
    std::vector<Vec3> moved(surface.mesh.points.size(), Vec3{1e6, 1e6, 1e6});
    for (const std::int32_t i : inUse)
        moved[static_cast<std::size_t>(i)] = surface.mesh.points[static_cast<std::size_t>(i)] + Vec3{0.0, 0.0, 3.0};
    view.setPoints(moved);
    double bounds[6];
    drawn()->GetBounds(bounds);
    EXPECT_LT(bounds[5], 20.0 + 3.0 + 1e-3);
    EXPECT_GT(bounds[4], -3.0 + 3.0 - 1.0); // the rim, moved up
    draw(view);

    // Shown again, every point is read and drawn.
    view.setOuterSurfaceVisible(true);
    EXPECT_TRUE(view.sourcePointsInUse().empty() || view.sourcePointsInUse().size() == surface.mesh.points.size());
    std::vector<Vec3> all = surface.mesh.points;
    for (Vec3& p : all)
        p = p + Vec3{0.0, 0.0, 3.0};
    view.setPoints(all);
    drawn()->GetBounds(bounds);
    EXPECT_EQ(drawn()->GetNumberOfPoints(), allPoints);
    EXPECT_NEAR(bounds[4], -20.0 + 3.0, 1e-3);
    EXPECT_NEAR(bounds[5], 20.0 + 3.0, 1e-3);
}

TEST_F(EndoscopicViewTest, BothDetailsShowTheLitWallInsideTheOpticsCircle) {
    const scene::VisualSurface surface = sphere();
    for (ViewDetail detail : {ViewDetail::Full, ViewDetail::Light}) {
        EndoscopicLook look;
        look.detail = detail;
        look.lightReduction = 0.5;
        look.hud = false;
        EndoscopicView view(m_renderer, look);
        view.setSurface(surface);
        draw(view);
        EXPECT_EQ(view.drawnTriangleCount() < surface.mesh.triangles.size(), detail == ViewDetail::Light);
        EXPECT_GT(red(80, 60), 30) << "the wall in the middle";
        EXPECT_EQ(red(1, 1), 0) << "outside the circle";
        EXPECT_EQ(red(158, 118), 0) << "outside the circle";
    }
}

TEST_F(EndoscopicViewTest, ACutHidesTheFacesOfItsTetsAndDrawsTheBaredFacesAndTheLoop) {
    const scene::VisualSurface surface = sphere();
    EndoscopicLook look;
    look.detail = ViewDetail::Full;
    look.hud = false;
    EndoscopicView view(m_renderer, look);
    view.setSurface(surface);
    draw(view);
    const auto drawn = [&] { return vtkPolyData::SafeDownCast(view.tissueActor()->GetMapper()->GetInput()); };
    const vtkIdType allFaces = drawn()->GetNumberOfPolys();
    const auto greys = [&] { // pixels of the bare metal: no tissue is grey
        int n = 0;
        for (int y = 0; y < 120; y += 2)
            for (int x = 0; x < 160; x += 2) {
                const int r = red(x, y), g = channel(x, y, 1), b = channel(x, y, 2);
                n += r > 60 && std::abs(r - g) < 12 && std::abs(g - b) < 12 ? 1 : 0;
            }
        return n;
    };
    EXPECT_EQ(greys(), 0);
    const double wallGreenOverRed = static_cast<double>(channel(80, 60, 1)) / std::max(1, red(80, 60));

    // The cap the scope looks at (x > 12 mm) cut away: its faces are not drawn.
    std::vector<char> hidden(surface.mesh.points.size(), 0);
    for (std::size_t i = 0; i < hidden.size(); ++i)
        hidden[i] = surface.mesh.points[i].x > 12.0;
    view.setHiddenPoints(hidden);
    EXPECT_LT(drawn()->GetNumberOfPolys(), allFaces);
    EXPECT_GT(drawn()->GetNumberOfPolys(), allFaces / 2);
    // In the hole, a face the cut bared: a myoma's pale interior, 15 mm ahead.
    const std::vector<Vec3> points{{15, -10, -10}, {15, 10, -10}, {15, 10, 10}, {15, -10, 10}};
    const std::vector<Triangle> faces{{0, 1, 2}, {0, 2, 3}};
    view.setCutSurface(points, points, faces, {clinical::Tissue::Myoma, clinical::Tissue::Myoma});
    draw(view);
    const double cutGreenOverRed = static_cast<double>(channel(80, 60, 1)) / std::max(1, red(80, 60));
    std::printf("green / red in the middle: the wall %.2f, the myoma's cut face %.2f\n", wallGreenOverRed,
                cutGreenOverRed);
    EXPECT_GT(red(80, 60), 30);
    EXPECT_GT(cutGreenOverRed, wallGreenOverRed + 0.1); // paler than the wall
    // Shown again: every face.
    view.setHiddenPoints({});
    EXPECT_EQ(drawn()->GetNumberOfPolys(), allFaces);
    view.setCutSurface({}, {}, {}, {});

    // The loop pushed 8 mm out, hanging below the axis: bare metal in the picture; gone when put down.
    sim::LoopState loop;
    loop.out = true;
    loop.widthMm = 4.5;
    loop.travelMm = 8.0;
    loop.middleMm = {8.0, 0.0, 0.0};
    loop.axis = {1.0, 0.0, 0.0};
    loop.down = {0.0, 0.0, -1.0};
    view.setLoop(loop);
    draw(view);
    EXPECT_GT(greys(), 0);
    // Exchanged for the office scope's scissors, 5 mm out, open: their shaft and jaws are metal too, and the open
    // jaws cover more of the picture than the shut ones.
    sim::LoopState scissors = loop;
    scissors.instrument = sim::kInstrumentScissors;
    scissors.widthMm = 0.0;
    scissors.travelMm = 5.0;
    scissors.middleMm = {5.0, 0.0, -1.5}; // out of the working channel below the optic
    scissors.jawLengthMm = 3.0;
    scissors.jawOpenDeg = 25.0;
    view.setLoop(scissors);
    draw(view);
    const int open = greys();
    EXPECT_GT(open, 0);
    scissors.jawOpenDeg = 0.0;
    view.setLoop(scissors);
    draw(view);
    EXPECT_GT(greys(), 0);
    EXPECT_LT(greys(), open);
    loop.out = false;
    view.setLoop(loop);
    draw(view);
    EXPECT_EQ(greys(), 0);
}

TEST_F(EndoscopicViewTest, DrawsTheMapsWithTheScenesUvOriginAtTheTopLeft) {
    // A wall 10 mm ahead, its upper half mapped to the image's upper half (red), its lower half to the lower (blue):
    // the scene's UVs have their origin at the image's top left (scene::VisualSurface). Drawn flipped, each half would
    // show the other's colour (the pale patches of a flipped atlas were the gutters between its charts).
    scene::VisualSurface surface;
    surface.mesh.points = {{10, -20, 20}, {10, 20, 20}, {10, 20, -20}, {10, -20, -20}};
    surface.mesh.triangles = {{0, 1, 2}, {0, 2, 3}};
    surface.uvs = {{0.0f, 0.0f}, {1.0f, 0.0f}, {1.0f, 1.0f}, {0.0f, 1.0f}};
    surface.albedo = ImageU8::create(8, 8, 3).value();
    for (int y = 0; y < 8; ++y)
        for (int x = 0; x < 8; ++x) {
            surface.albedo.at(x, y, 0) = y < 4 ? 230 : 20;
            surface.albedo.at(x, y, 2) = y < 4 ? 20 : 230;
        }
    for (ViewDetail detail : {ViewDetail::Full, ViewDetail::Light}) {
        EndoscopicLook look;
        look.detail = detail;
        look.hud = false;
        EndoscopicView view(m_renderer, look);
        view.setSurface(surface);
        draw(view); // looking along +x, +z up
        EXPECT_GT(channel(80, 85, 0), channel(80, 85, 2) + 20) << "the upper half is red";
        EXPECT_GT(channel(80, 35, 2), channel(80, 35, 0) + 20) << "the lower half is blue";
    }
}

/// A flat wall `distanceMm` ahead (x = distanceMm), square to the view along +x: a grid of 40 x 40 squares spanning
/// twice its distance either side of the axis (beyond a 90-degree field), u along -y, v along -z.
scene::VisualSurface wallGrid(double distanceMm) {
    scene::VisualSurface surface;
    const int n = 40;
    const double step = distanceMm / 10.0;
    for (int j = 0; j <= n; ++j)
        for (int i = 0; i <= n; ++i) {
            surface.mesh.points.push_back({distanceMm, (20.0 - i) * step, (20.0 - j) * step});
            surface.uvs.push_back({static_cast<float>(i) / n, static_cast<float>(j) / n});
        }
    for (int j = 0; j < n; ++j)
        for (int i = 0; i < n; ++i) {
            const std::int32_t a = j * (n + 1) + i, b = a + 1, c = a + n + 1, d = c + 1;
            surface.mesh.triangles.push_back({a, b, d});
            surface.mesh.triangles.push_back({a, d, c});
        }
    return surface;
}

/// Column of the first pixel right of the middle row's centre whose blue outweighs its red, on a picture of a flat
/// wall 10 mm ahead that is red left of y = -`edgeMm` (image right: looking along +x with +z up) and blue beyond.
int boundaryColumn(vtkRenderWindow* window, vtkRenderer* renderer, double edgeMm, double edgeMagnification) {
    // A 1 mm grid of vertices, the colour boundary on a grid line: the lens model moves vertices.
    scene::VisualSurface surface = wallGrid(10.0);
    const int texels = 400; // 10 per millimetre
    surface.albedo = ImageU8::create(texels, 8, 3).value();
    for (int y = 0; y < 8; ++y)
        for (int x = 0; x < texels; ++x) {
            const bool beyond = 20.0 - 40.0 * (x + 0.5) / texels < -edgeMm;
            surface.albedo.at(x, y, 0) = beyond ? 20 : 230;
            surface.albedo.at(x, y, 2) = beyond ? 230 : 20;
        }
    EndoscopicLook look;
    look.detail = ViewDetail::Light;
    look.hud = false;
    look.autoExposure = false;
    look.exposure = 40.0;
    look.edgeMagnification = edgeMagnification;
    look.lightReduction = 0.0; // every grid vertex drawn
    EndoscopicView view(renderer, look);
    view.setSurface(surface);
    view.setPose({{0, 0, 0}, {1, 0, 0}, {0, 0, 1}, 90.0});
    window->Render();
    vtkNew<vtkUnsignedCharArray> row;
    window->GetRGBACharPixelData(0, 60, 159, 60, 0, row);
    for (int x = 80; x < 160; ++x)
        if (row->GetValue(4 * x + 2) > row->GetValue(4 * x))
            return x;
    return -1;
}

// The optic's barrel distortion: a point the rectilinear camera puts at rho of the field's radius shows at
// atan(a rho) / atan(a) with 1 / (1 + a^2) = 0.52 (the relative size at the periphery of rigid endoscopes): a wall edge
// 5 mm off the axis at 10 mm (rho 0.5 of a 90-degree field) moves from 30 to 35.1 px of the 60 px radius, one at 8 mm
// (rho 0.8) from 48 to 51.4 px. With the magnification at 1 it stays where the rectilinear camera puts it.
TEST_F(EndoscopicViewTest, TheOpticsBarrelDistortionMovesThePictureOutwardsAsARodLensDoes) {
    const double a = std::sqrt(1.0 / 0.52 - 1.0);
    for (const double rho : {0.5, 0.8}) {
        const double centre = 79.5; // between the middle two of 160 columns
        const double distorted = centre + 60.0 * std::atan(a * rho) / std::atan(a);
        const double rectilinear = centre + 60.0 * rho;
        const int seen = boundaryColumn(m_window, m_renderer, 10.0 * rho, 0.52);
        const int straight = boundaryColumn(m_window, m_renderer, 10.0 * rho, 1.0);
        std::printf("rho %.1f: the edge at column %d (the lens model %.1f), %d without distortion (rectilinear %.1f)\n",
                    rho, seen, distorted, straight, rectilinear);
        EXPECT_NEAR(seen, distorted, 1.5) << "rho " << rho;
        EXPECT_GT(seen, rectilinear + 2.0) << "rho " << rho;
        EXPECT_NEAR(straight, rectilinear, 1.5) << "rho " << rho;
    }
}

TEST_F(EndoscopicViewTest, ACutFaceShowsItsTissuesSolidTextureCarriedWithTheTissue) {
    // A face the cut bared fills the picture, 8 mm ahead, square to the view; no wall behind it.
    const std::vector<Vec3> rest{{8, -12, -12}, {8, 12, -12}, {8, 12, 12}, {8, -12, 12}};
    const std::vector<Triangle> faces{{0, 1, 2}, {0, 2, 3}};
    m_window->SetSize(400, 300);
    constexpr int kSide = 100; // the middle kSide x kSide pixels, whose luminance `picture` returns
    const auto picture = [&](double contrast, clinical::Tissue tissue, const std::vector<Vec3>& points) {
        EndoscopicLook look;
        look.detail = ViewDetail::Full;
        look.hud = false;
        look.autoExposure = false;
        look.cutPatternContrast = contrast;
        look.edgeMagnification = 1.0; // a rectilinear picture: a face moved across the view moves in it unchanged
        m_renderer->RemoveAllViewProps();
        EndoscopicView view(m_renderer, look);
        view.setCutSurface(points, rest, faces, {tissue, tissue});
        draw(view);
        if (const char* dump = std::getenv("HS_DUMP_DIR")) { // each picture written there (the docs' picture)
            vtkNew<vtkWindowToImageFilter> grab;
            grab->SetInput(m_window);
            vtkNew<vtkPNGWriter> png;
            png->SetInputConnection(grab->GetOutputPort());
            png->SetFileName((std::string(dump) + "/cut-" + std::string(clinical::toString(tissue)) + "-" +
                              std::to_string(static_cast<int>(contrast * 100)) + (points == rest ? "" : "-moved") +
                              ".png")
                                 .c_str());
            png->Write();
        }
        std::vector<double> luminance;
        vtkNew<vtkUnsignedCharArray> pixels;
        m_window->GetRGBACharPixelData(200 - kSide / 2, 150 - kSide / 2, 199 + kSide / 2, 149 + kSide / 2, 0, pixels);
        for (vtkIdType i = 0; i < kSide * kSide; ++i)
            luminance.push_back(0.3 * pixels->GetValue(4 * i) + 0.59 * pixels->GetValue(4 * i + 1) +
                                0.11 * pixels->GetValue(4 * i + 2));
        return luminance;
    };
    const auto at = [&](const std::vector<double>& v, int x, int y) {
        return v[static_cast<std::size_t>(y * kSide + x)];
    };
    // The detail: the mean luminance difference between pixels two apart (the lamp's fall-off over the face is
    // smooth: it adds little).
    const auto detail = [&](const std::vector<double>& v) {
        double sum = 0.0;
        for (int y = 0; y + 2 < kSide; ++y)
            for (int x = 0; x + 2 < kSide; ++x)
                sum += std::abs(at(v, x + 2, y) - at(v, x, y)) + std::abs(at(v, x, y + 2) - at(v, x, y));
        return sum / ((kSide - 2) * (kSide - 2));
    };
    // Each picture over the flat one: the lamp's fall-off, which does not move with the tissue, divided out.
    const std::vector<double> flat = picture(0.0, clinical::Tissue::Myoma, rest);
    const auto pattern = [&](clinical::Tissue tissue, const std::vector<Vec3>& points) {
        std::vector<double> v = picture(0.35, tissue, points);
        for (std::size_t i = 0; i < v.size(); ++i)
            v[i] /= std::max(1.0, flat[i]);
        return v;
    };
    // Every tissue's pattern shows: at least a tenth of the face's pixels (a pattern, not a few specks) differ from
    // its median brightness by more than 2 %, the luminance contrast a viewer resolves on a large bright field
    // (docs/references.md [Blackwell1946]). Without the texture no pixel does (each picture over the flat one is 1).
    for (clinical::Tissue tissue : {clinical::Tissue::Myometrium, clinical::Tissue::Endometrium,
                                    clinical::Tissue::Cervix, clinical::Tissue::Myoma, clinical::Tissue::Polyp}) {
        const std::vector<double> v = pattern(tissue, rest);
        std::vector<double> sorted = v;
        std::sort(sorted.begin(), sorted.end());
        const double median = sorted[sorted.size() / 2];
        double visible = 0.0;
        for (double x : v)
            visible += std::abs(x / median - 1.0) > 0.02 ? 1.0 / static_cast<double>(v.size()) : 0.0;
        std::printf("a cut face of %s: %.0f %% of the pixels differ from its median by more than 2 %% (5th-95th "
                    "percentile %.3f-%.3f of the median); detail %.3f\n",
                    std::string(clinical::toString(tissue)).c_str(), 100.0 * visible,
                    sorted[sorted.size() / 20] / median, sorted[sorted.size() * 19 / 20] / median, detail(v));
        EXPECT_GE(visible, 0.1) << clinical::toString(tissue);
    }
    // The pattern is the tissue's, not the place's: the face moved 0.5 mm to the image's left shows the same
    // pattern moved with it.
    std::vector<Vec3> moved = rest;
    for (Vec3& p : moved)
        p = p + Vec3{0.0, 0.5, 0.0};
    const std::vector<double> atRest = pattern(clinical::Tissue::Myoma, rest),
                              shifted = pattern(clinical::Tissue::Myoma, moved);
    double inPlace = 0.0, bestError = 1e300;
    int bestShift = 0;
    for (int dx = -20; dx <= 20; ++dx) {
        double error = 0.0;
        int n = 0;
        for (int y = 0; y < kSide; ++y)
            for (int x = 25; x + 25 < kSide; ++x) {
                const double e = at(atRest, x, y) - at(shifted, x + dx, y);
                error += e * e;
                ++n;
            }
        error /= n;
        inPlace = dx == 0 ? error : inPlace;
        if (error < bestError) {
            bestError = error;
            bestShift = dx;
        }
    }
    std::printf("the face moved 0.5 mm: mean square difference %.5f in place, %.5f with the picture shifted %d "
                "pixels\n",
                inPlace, bestError, bestShift);
    // 0.5 mm at 8 mm in a 90 degree field 300 pixels across: 9.4 pixels to the left.
    EXPECT_GE(bestShift, -11);
    EXPECT_LE(bestShift, -8);
    EXPECT_LT(bestError, 0.05 * inPlace);
}

TEST_F(EndoscopicViewTest, ABloodCloudDarkensTheWallBehindItAndNothingBeside) {
    // Blood not yet mixed (sim::BloodCloud): 0.125 uL spread with a 1 mm standard deviation 8 mm ahead, between the
    // lens and the wall 20 mm away. Along the axis the light crosses 1000 mm^3/mL x 0.000125 mL / (2 pi 1 mm^2) =
    // 0.0199 mm of whole blood each way, which leaves exp(-2 x 23 / mm x 0.0199 mm) = 0.40 of the wall's green light
    // and 0.987 of its red (Prahl). The light the saline scatters back from near the lens does not cross the cloud.
    // The view evaluates the clouds at the vertices: a sphere with vertices 0.7 mm apart (the visual surface's are
    // about a millimetre), so the vertices round the middle pixel's ray lie within a third of the cloud's width of it.
    scene::VisualSurface surface;
    surface.mesh = test::latitudeSphere(90, 180, false);
    EndoscopicLook look;
    look.detail = ViewDetail::Full;
    look.hud = false;
    look.autoExposure = false;
    look.exposure = 36.0; // the wall below the tone curve's knee: the picture linear in the light
    EndoscopicView view(m_renderer, look);
    view.setSurface(surface);
    draw(view);
    const int redClear = red(80, 60), greenClear = channel(80, 60, 1);
    const int besideClear = channel(80 + 45, 60, 1);
    // The scattered light in green (kFluidShader's): the lamp's r0 = 2 mm, the wall 20 mm ahead.
    const double r0 = std::sqrt(look.lampAttenuation[0] / look.lampAttenuation[2]);
    const double scattered =
        255.0 * look.exposure * look.fogColour[1] * (1.0 - std::exp(-look.clearFogPerMm * r0 * std::atan(20.0 / r0)));
    sim::BloodClouds blood;
    blood.count = 1;
    blood.clouds[0].centreMm = {8.0, 0.0, 0.0};
    blood.clouds[0].sigmaMm = 1.0;
    blood.clouds[0].bloodMl = 0.000125;
    view.setBloodClouds(blood);
    draw(view);
    const double path = 1000.0 * 0.000125 / (2.0 * 3.14159265358979 * 1.0);
    const double expected = scattered + (greenClear - scattered) * std::exp(-2.0 * look.bloodAbsorptionPerMm[1] * path);
    std::printf("behind the cloud: green %d -> %d (expected %.1f: %.1f scattered before it), red %d -> %d; 45 pixels "
                "beside it: green %d -> %d\n",
                greenClear, channel(80, 60, 1), expected, scattered, redClear, red(80, 60), besideClear,
                channel(80 + 45, 60, 1));
    ASSERT_GT(greenClear, 40);
    EXPECT_NEAR(channel(80, 60, 1), expected, 3.0);
    EXPECT_GE(red(80, 60), redClear - 3);
    EXPECT_NEAR(channel(80 + 45, 60, 1), besideClear, 1); // the line 4.5 standard deviations from the cloud
    // Gone (mixed in, or washed out): the picture as before.
    view.setBloodClouds({});
    draw(view);
    EXPECT_NEAR(channel(80, 60, 1), greenClear, 1);
}

/// The middle row (red minus blue, per column) of a 640x480 picture of a flat wall `distanceMm` ahead, red left of the
/// axis and blue right of it (image right: looking along +x with +z up), with or without the optic's depth of field.
std::vector<int> edgeRow(vtkRenderWindow* window, vtkRenderer* renderer, double distanceMm, bool depthOfField) {
    scene::VisualSurface surface = wallGrid(distanceMm);
    surface.albedo = ImageU8::create(400, 8, 3).value();
    for (int y = 0; y < 8; ++y)
        for (int x = 0; x < 400; ++x) {
            surface.albedo.at(x, y, 0) = x < 200 ? 230 : 20;
            surface.albedo.at(x, y, 2) = x < 200 ? 20 : 230;
        }
    EndoscopicLook look;
    look.detail = ViewDetail::Light;
    look.hud = false;
    look.autoExposure = false;
    // The same brightness at every distance: the lamp's falloff 1 / (1 + (d / 2 mm)^2) divided out.
    look.exposure = 1.5 * (1.0 + distanceMm * distanceMm / 4.0);
    look.lightReduction = 0.0;
    look.depthOfField = depthOfField;
    window->SetSize(640, 480);
    EndoscopicView view(renderer, look);
    view.setSurface(surface);
    view.setPose({{0, 0, 0}, {1, 0, 0}, {0, 0, 1}, 90.0, 2.0, 50.0});
    window->Render();
    vtkNew<vtkUnsignedCharArray> row;
    window->GetRGBACharPixelData(0, 240, 639, 240, 0, row);
    std::vector<int> out(640);
    for (int x = 0; x < 640; ++x)
        out[static_cast<std::size_t>(x)] = row->GetValue(4 * x) - row->GetValue(4 * x + 2);
    return out;
}

/// Columns over which the row passes from 90 % to 10 % of its step between the sides (the edge's 10-90 width).
int edgeWidth(const std::vector<int>& row) {
    const double left = row[240], right = row[400]; // well inside either side at any distance tested
    const double hi = right + 0.9 * (left - right), lo = right + 0.1 * (left - right);
    int first = -1, last = -1;
    for (int x = 240; x <= 400; ++x) {
        if (first < 0 && row[static_cast<std::size_t>(x)] < hi)
            first = x;
        if (row[static_cast<std::size_t>(x)] > lo)
            last = x;
    }
    return first < 0 ? 0 : last - first + 1;
}

// The optic's depth of field (docs/simulator.md, "Depth of field"): a fixed-focus optic sharp from 2 to 50 mm draws a
// wall 10 mm ahead as it would without it, and blurs one 0.5 mm ahead by its circle of confusion: 7.25 times the
// sharp circle (|2/0.5 - 1/2 - 1/50| / (1/2 - 1/50)), one line of a 480-line picture, so a blur of radius
// (7.25 - 1) / 2 = 3.1 pixels here; an edge's 10-90 width grows from about a pixel to several.
TEST_F(EndoscopicViewTest, TheOpticsDepthOfFieldBlursWhatIsCloserThanItsFocusRangeAndNothingWithinIt) {
    const std::vector<int> sharpFar = edgeRow(m_window, m_renderer, 10.0, false);
    const std::vector<int> blurFar = edgeRow(m_window, m_renderer, 10.0, true);
    const std::vector<int> sharpNear = edgeRow(m_window, m_renderer, 0.5, false);
    const std::vector<int> blurNear = edgeRow(m_window, m_renderer, 0.5, true);
    std::printf("edge's 10-90 width, pixels: at 10 mm %d without the depth of field, %d with it; at 0.5 mm %d, %d "
                "(left %d, right %d)\n",
                edgeWidth(sharpFar), edgeWidth(blurFar), edgeWidth(sharpNear), edgeWidth(blurNear), sharpNear[240],
                sharpNear[400]);
    ASSERT_GT(sharpNear[240] - sharpNear[400], 100) << "the wall's two colours";
    EXPECT_EQ(blurFar, sharpFar) << "within the focus range the picture is untouched";
    EXPECT_LE(edgeWidth(sharpNear), 2);
    EXPECT_GE(edgeWidth(blurNear), 4); // a disc of radius 3.1 px: the 10-90 width of its edge response is 4-5 px
    EXPECT_NEAR(circleOfConfusionShare(0.5, 2.0, 50.0), 7.25, 1e-9);
    EXPECT_NEAR(circleOfConfusionShare(2.0, 2.0, 50.0), 1.0, 1e-12);
    EXPECT_NEAR(circleOfConfusionShare(50.0, 2.0, 50.0), 1.0, 1e-12);
    EXPECT_LT(circleOfConfusionShare(10.0, 2.0, 50.0), 1.0);
}

} // namespace
} // namespace hs::simrender
