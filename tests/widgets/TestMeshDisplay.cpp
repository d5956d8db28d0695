// Qt Test for hs::widgets::MeshDisplay: counts, region colours and the tet clipping plane. Needs a display.
#include "GuiTestMeshes.h"
#include "hs/widgets/view/MeshDisplay.h"
#include "hs/widgets/view/VtkView.h"

#include <QApplication>
#include <QTest>

#include <vtkCellData.h>
#include <vtkDataArray.h>
#include <vtkPolyData.h>
#include <vtkRenderer.h>
#include <vtkUnstructuredGrid.h>

#include <memory>

using hs::widgets::MeshCounts;
using hs::widgets::MeshDisplay;
using hs::widgets::VtkView;

class TestMeshDisplay : public QObject {
    Q_OBJECT

private slots:
    void countsOfSurface_data();
    void countsOfSurface();
    void countsOfTetMesh();
    void regionsGetDifferentColours();
    void clipKeepsWholeTetsOnOneSide();
    void clipIsKeptForTheNextMesh();
    void clipChangesTheImage();
    void legendsNameTheRegionsOrTheMeasure();
};

void TestMeshDisplay::countsOfSurface_data() {
    QTest::addColumn<QString>("labels"); // where the "region" label lives
    QTest::addColumn<int>("regions");
    QTest::newRow("faces") << "faces" << 2;
    QTest::newRow("vertices") << "vertices" << 3;
    QTest::newRow("none") << "none" << 1;
}

void TestMeshDisplay::countsOfSurface() {
    QFETCH(QString, labels);
    QFETCH(int, regions);
    hs::SurfaceMesh sphere = hs::test::makeSphere(5.0, 8, 12);
    if (labels != "faces")
        sphere.faceLabels.clear();
    if (labels == "vertices") {
        std::vector<std::int32_t> vertexRegions(sphere.vertexCount());
        for (std::size_t i = 0; i < vertexRegions.size(); ++i)
            vertexRegions[i] = static_cast<std::int32_t>(i % 3);
        sphere.vertexLabels["region"] = vertexRegions;
    }
    const MeshCounts counts = hs::widgets::countsOf(sphere);
    QCOMPARE(counts.vertices, sphere.vertexCount());
    QCOMPARE(counts.triangles, sphere.faceCount());
    QCOMPARE(counts.tets, std::size_t(0));
    QCOMPARE(counts.regions, std::size_t(regions));
}

void TestMeshDisplay::countsOfTetMesh() {
    const hs::TetMesh cube = hs::test::makeTetCube(3);
    const MeshCounts counts = hs::widgets::countsOf(cube);
    QCOMPARE(counts.vertices, std::size_t(4 * 4 * 4));
    QCOMPARE(counts.tets, std::size_t(6 * 27));
    QCOMPARE(counts.triangles, std::size_t(0));
    QCOMPARE(counts.regions, std::size_t(2));
}

void TestMeshDisplay::regionsGetDifferentColours() {
    const hs::TetMesh cube = hs::test::makeTetCube(2);
    const auto grid = hs::widgets::toUnstructuredGrid(cube);
    vtkDataArray* colours = grid->GetCellData()->GetScalars();
    QVERIFY(colours);
    QCOMPARE(colours->GetNumberOfComponents(), 3);
    const std::size_t firstOfRegion1 =
        static_cast<std::size_t>(std::find(cube.regions.begin(), cube.regions.end(), 1) - cube.regions.begin());
    QVERIFY(firstOfRegion1 < cube.tetCount());
    const double* a = colours->GetTuple3(0);
    const double a0 = a[0], a1 = a[1], a2 = a[2];
    const double* b = colours->GetTuple3(static_cast<vtkIdType>(firstOfRegion1));
    QVERIFY(std::abs(a0 - b[0]) + std::abs(a1 - b[1]) + std::abs(a2 - b[2]) > 30);

    const auto poly = hs::widgets::toPolyData(hs::test::makeSphere(5.0, 8, 12));
    QVERIFY(poly->GetCellData()->GetArray("region"));
    QCOMPARE(poly->GetNumberOfPolys(), vtkIdType(2 * 8 * 12 - 2 * 12));
}

void TestMeshDisplay::clipKeepsWholeTetsOnOneSide() {
    VtkView view; // only for its renderer; nothing is shown
    MeshDisplay display(view.renderer());
    const hs::TetMesh cube = hs::test::makeTetCube(4);
    display.showTetMesh(cube);
    QVERIFY(display.isTetMesh());
    QCOMPARE(display.visibleCellCount(), cube.tetCount());
    display.setClipEnabled(true);
    const std::size_t kept = display.visibleCellCount();
    // The plane runs through the centre: one half of the cells, plus the tets that touch the plane.
    QVERIFY2(kept >= cube.tetCount() / 2 && kept < cube.tetCount(), qPrintable(QString::number(kept)));
    display.setClipEnabled(false);
    QCOMPARE(display.visibleCellCount(), cube.tetCount());
}

void TestMeshDisplay::clipIsKeptForTheNextMesh() {
    VtkView view;
    MeshDisplay display(view.renderer());
    display.setClipEnabled(true);
    display.showSurface(hs::test::makeSphere());
    QVERIFY(display.clipEnabled());
    QCOMPARE(display.visibleCellCount(), display.counts().triangles);
    const hs::TetMesh cube = hs::test::makeTetCube(3); // odd: the plane x = 0 cuts through a layer of cells
    display.showTetMesh(cube);
    QVERIFY(display.visibleCellCount() < cube.tetCount());
    display.clear();
    QVERIFY(display.isEmpty());
    QCOMPARE(display.visibleCellCount(), std::size_t(0));
}

void TestMeshDisplay::clipChangesTheImage() {
    VtkView view;
    view.setObjectName("view");
    MeshDisplay display(view.renderer());
    display.showTetMesh(hs::test::makeTetCube(4));
    view.renderer()->SetBackground(0.0, 0.0, 0.0);
    view.resize(400, 400);
    view.show();
    QVERIFY(QTest::qWaitForWindowExposed(&view));
    view.resetCamera();
    const QImage whole = view.grabImage();
    QVERIFY(hs::test::pixelsDifferentFrom(whole, qRgb(0, 0, 0)) > 1000);
    display.setClipEnabled(true);
    view.requestRender();
    const QImage cut = view.grabImage();
    const int changed = hs::test::pixelsDifferentBetween(whole, cut);
    QVERIFY2(changed > 500, qPrintable(QString::number(changed)));
}

// Coloured by region, the view's corner names each region present with its colour; coloured by a measure, a colour
// bar with the measure's name; a surface has neither. Both are drawn.
void TestMeshDisplay::legendsNameTheRegionsOrTheMeasure() {
    VtkView view;
    MeshDisplay display(view.renderer());
    view.renderer()->SetBackground(0.0, 0.0, 0.0);
    view.resize(400, 400);
    view.show();
    QVERIFY(QTest::qWaitForWindowExposed(&view));
    const hs::TetMesh cube = hs::test::makeTetCube(4); // regions 0 and 1
    display.setRegionNames({{0, "myometrium"}, {1, "myoma-1"}, {7, "not in this mesh"}});
    display.showTetMesh(cube);
    view.resetCamera();
    QCOMPARE(display.legendEntries(), (std::vector<std::string>{"myometrium", "myoma-1"}));
    QVERIFY(display.colourBarTitle().empty());
    const QImage regions = view.grabImage();

    std::vector<double> values(cube.tetCount());
    for (std::size_t i = 0; i < values.size(); ++i)
        values[i] = double(i) / double(values.size());
    display.colourTets(values, 0.0, 1.0, "radius ratio");
    QVERIFY(display.legendEntries().empty());
    QCOMPARE(display.colourBarTitle(), std::string("radius ratio"));
    view.requestRender();
    const QImage measure = view.grabImage();
    // The lower-right corner, where the legends are, changed between the two.
    const QRect corner(view.width() * 3 / 5, view.height() * 3 / 4, view.width() * 2 / 5, view.height() / 4);
    QVERIFY(regions.copy(corner) != measure.copy(corner));
    QVERIFY(hs::test::pixelsDifferentFrom(measure.copy(corner), qRgb(0, 0, 0)) > 200);

    display.colourTets({}, 0.0, 1.0);
    QCOMPARE(display.legendEntries().size(), std::size_t(2));
    display.showSurface(hs::test::makeSphere());
    QVERIFY(display.legendEntries().empty() && display.colourBarTitle().empty());
}

int main(int argc, char** argv) {
    QSurfaceFormat::setDefaultFormat(VtkView::defaultFormat());
    QApplication app(argc, argv);
    TestMeshDisplay test;
    return QTest::qExec(&test, argc, argv);
}

#include "TestMeshDisplay.moc"
