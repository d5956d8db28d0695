// Qt Test for hs::widgets::VtkView: rendering, click picking, two views side by side. Needs a display.
#include "GuiTestMeshes.h"
#include "hs/widgets/view/MeshDisplay.h"
#include "hs/widgets/view/VtkView.h"

#include <QApplication>
#include <QHBoxLayout>
#include <QSignalSpy>
#include <QTest>
#include <QWheelEvent>

#include <vtkCamera.h>
#include <vtkGenericOpenGLRenderWindow.h>
#include <vtkRenderer.h>

#include <memory>

using hs::widgets::MeshDisplay;
using hs::widgets::PickResult;
using hs::widgets::VtkView;

namespace {

constexpr double kBackground[3] = {0.1, 0.2, 0.4};
constexpr double kOtherBackground[3] = {0.3, 0.1, 0.1};
constexpr double kSphereRadius = 10.0;

QRgb toRgb(const double colour[3]) {
    return qRgb(qRound(colour[0] * 255), qRound(colour[1] * 255), qRound(colour[2] * 255));
}

} // namespace

class TestVtkView : public QObject {
    Q_OBJECT

private slots:
    void init();
    void cleanup();

    void rendersSphereOverBackground();
    void clickPicksPointOnSurface_data();
    void clickPicksPointOnSurface();
    void clickOnBackgroundMisses();
    void dragIsNotAClick();
    void wheelZoomsOnlyItsOwnView();
    void twoViewsRenderSideBySide();
    void keepsRenderingAfterResize();

private:
    std::unique_ptr<QWidget> m_window;
    VtkView* m_left = nullptr;
    VtkView* m_right = nullptr;
    std::unique_ptr<MeshDisplay> m_leftDisplay;
    std::unique_ptr<MeshDisplay> m_rightDisplay;
};

void TestVtkView::init() {
    m_window = std::make_unique<QWidget>();
    auto* layout = new QHBoxLayout(m_window.get());
    m_left = new VtkView(m_window.get());
    m_left->setObjectName("leftView");
    m_right = new VtkView(m_window.get());
    m_right->setObjectName("rightView");
    layout->addWidget(m_left);
    layout->addWidget(m_right);

    // The same mesh in both views: each view has its own display (and so its own actor).
    const hs::SurfaceMesh sphere = hs::test::makeSphere(kSphereRadius);
    m_leftDisplay = std::make_unique<MeshDisplay>(m_left->renderer());
    m_leftDisplay->showSurface(sphere);
    m_rightDisplay = std::make_unique<MeshDisplay>(m_right->renderer());
    m_rightDisplay->showSurface(sphere);
    m_left->renderer()->SetBackground(kBackground[0], kBackground[1], kBackground[2]);
    m_right->renderer()->SetBackground(kOtherBackground[0], kOtherBackground[1], kOtherBackground[2]);
    m_left->resetCamera();
    m_right->resetCamera();

    m_window->resize(820, 420);
    m_window->show();
    QVERIFY(QTest::qWaitForWindowExposed(m_window.get()));
    QTRY_VERIFY(m_left->renderCount() > 0 && m_right->renderCount() > 0);
}

void TestVtkView::cleanup() {
    // Displays remove their actors from the renderers: they go before the views.
    m_leftDisplay.reset();
    m_rightDisplay.reset();
    m_window.reset();
}

void TestVtkView::rendersSphereOverBackground() {
    const QImage image = m_left->grabImage();
    QVERIFY(!image.isNull());
    const QRgb centre = image.pixel(image.width() / 2, image.height() / 2);
    const QRgb corner = image.pixel(2, 2);
    QVERIFY2(hs::test::colourDistance(corner, toRgb(kBackground)) <= 6, "the corner shows the background");
    QVERIFY2(hs::test::colourDistance(centre, toRgb(kBackground)) > 100, "the centre shows the sphere");
    QCOMPARE(qAlpha(centre), 255); // the widget is opaque
    const int covered = hs::test::pixelsDifferentFrom(image, toRgb(kBackground));
    QVERIFY2(covered > image.width() * image.height() / 10, qPrintable(QString::number(covered)));
}

void TestVtkView::clickPicksPointOnSurface_data() {
    QTest::addColumn<QPoint>("offset"); // from the view's centre, in pixels
    QTest::newRow("centre") << QPoint(0, 0);
    QTest::newRow("upper right") << QPoint(30, -30);
    QTest::newRow("lower left") << QPoint(-40, 25);
}

void TestVtkView::clickPicksPointOnSurface() {
    QFETCH(QPoint, offset);
    QSignalSpy spy(m_left, &VtkView::picked);
    QTest::mouseClick(m_left, Qt::LeftButton, Qt::NoModifier, m_left->rect().center() + offset);
    QCOMPARE(spy.count(), 1);
    const auto result = spy.takeFirst().at(0).value<PickResult>();
    QVERIFY(result.hit);
    QVERIFY(result.cellId >= 0);
    // On the (faceted) sphere, on the side that faces the camera.
    QVERIFY2(std::abs(result.point.length() - kSphereRadius) < 0.05 * kSphereRadius,
             qPrintable(QString::number(double(result.point.length()))));
    double camera[3];
    m_left->renderer()->GetActiveCamera()->GetPosition(camera);
    QVERIFY(QVector3D::dotProduct(result.point, QVector3D(float(camera[0]), float(camera[1]), float(camera[2]))) > 0);
}

void TestVtkView::clickOnBackgroundMisses() {
    QSignalSpy spy(m_left, &VtkView::picked);
    QTest::mouseClick(m_left, Qt::LeftButton, Qt::NoModifier, QPoint(3, 3));
    QCOMPARE(spy.count(), 1);
    const auto result = spy.takeFirst().at(0).value<PickResult>();
    QVERIFY(!result.hit);
    QCOMPARE(result.cellId, qint64(-1));
}

void TestVtkView::dragIsNotAClick() {
    QSignalSpy spy(m_left, &VtkView::picked);
    double before[3];
    m_left->renderer()->GetActiveCamera()->GetPosition(before);
    const QPoint centre = m_left->rect().center();
    QTest::mousePress(m_left, Qt::LeftButton, Qt::NoModifier, centre);
    for (int i = 1; i <= 6; ++i)
        QTest::mouseMove(m_left, centre + QPoint(8 * i, 2 * i));
    QTest::mouseRelease(m_left, Qt::LeftButton, Qt::NoModifier, centre + QPoint(48, 12));
    QCOMPARE(spy.count(), 0);
    double after[3];
    m_left->renderer()->GetActiveCamera()->GetPosition(after);
    QVERIFY2(std::abs(after[0] - before[0]) + std::abs(after[1] - before[1]) + std::abs(after[2] - before[2]) > 1.0,
             "the drag rotated the camera");
}

void TestVtkView::wheelZoomsOnlyItsOwnView() {
    vtkCamera* left = m_left->renderer()->GetActiveCamera();
    vtkCamera* right = m_right->renderer()->GetActiveCamera();
    const double leftBefore = left->GetDistance();
    const double rightBefore = right->GetDistance();
    const QPointF pos = m_left->rect().center();
    QWheelEvent wheel(pos, m_left->mapToGlobal(pos), QPoint(), QPoint(0, 240), Qt::NoButton, Qt::NoModifier,
                      Qt::NoScrollPhase, false);
    QCoreApplication::sendEvent(m_left, &wheel);
    QVERIFY(left->GetDistance() < 0.9 * leftBefore);
    QCOMPARE(right->GetDistance(), rightBefore);
}

void TestVtkView::twoViewsRenderSideBySide() {
    const QImage window = m_window->grab().toImage();
    const qreal ratio = window.devicePixelRatio();
    const QPoint leftCentre = m_left->mapTo(m_window.get(), m_left->rect().center());
    const QPoint rightCentre = m_right->mapTo(m_window.get(), m_right->rect().center());
    const QPoint rightCorner = m_right->mapTo(m_window.get(), QPoint(3, 3));
    QVERIFY(hs::test::colourDistance(window.pixel(leftCentre * ratio), toRgb(kBackground)) > 100);
    QVERIFY(hs::test::colourDistance(window.pixel(rightCentre * ratio), toRgb(kOtherBackground)) > 100);
    QVERIFY(hs::test::colourDistance(window.pixel(rightCorner * ratio), toRgb(kOtherBackground)) <= 6);
}

void TestVtkView::keepsRenderingAfterResize() {
    m_window->resize(1000, 300);
    QTRY_COMPARE(m_left->renderWindow()->GetSize()[1], qRound(m_left->height() * m_left->devicePixelRatioF()));
    const QImage image = m_left->grabImage();
    QCOMPARE(image.height(), qRound(m_left->height() * m_left->devicePixelRatioF()));
    QVERIFY(hs::test::colourDistance(image.pixel(image.width() / 2, image.height() / 2), toRgb(kBackground)) > 100);
}

int main(int argc, char** argv) {
    QSurfaceFormat::setDefaultFormat(VtkView::defaultFormat());
    QApplication app(argc, argv);
    TestVtkView test;
    return QTest::qExec(&test, argc, argv);
}

#include "TestVtkView.moc"
