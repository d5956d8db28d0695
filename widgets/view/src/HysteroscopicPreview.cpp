#include "hs/widgets/view/HysteroscopicPreview.h"

#include "hs/scene/ScopeView.h"
#include "hs/simrender/EndoscopicView.h"
#include "hs/widgets/view/VtkView.h"

#include <QComboBox>
#include <QFormLayout>
#include <QHBoxLayout>
#include <QLabel>
#include <QLocale>
#include <QSlider>
#include <QTimer>
#include <QVBoxLayout>

#include <cmath>

namespace hs::widgets {

namespace {

/// Insertion slider steps: 0.5 mm from 5 mm outside the external os to 70 mm in (beyond any cavity's fundus).
constexpr int kInsertionStepsPerMm = 2;
constexpr double kInsertionMinMm = -5.0;
constexpr double kInsertionMaxMm = 70.0;
/// A still picture is drawn again every this many ms, at most kSettleFrames times, while the camera's exposure settles.
constexpr int kSettleIntervalMs = 40;
constexpr int kSettleFrames = 40;

} // namespace

HysteroscopicPreview::HysteroscopicPreview(QWidget* parent) : QWidget(parent) {
    setObjectName("hysteroscopicPreview");
    auto* layout = new QVBoxLayout(this);
    layout->setContentsMargins(0, 0, 0, 0);
    m_view = new VtkView(this);
    m_view->setObjectName("previewView");
    m_view->setMinimumSize(240, 240);
    // The simulator's view (the only light is the lamp at the scope's tip), without its heads-up text.
    simrender::EndoscopicLook look;
    look.hud = false;
    m_endoscope = std::make_unique<simrender::EndoscopicView>(m_view->renderer(), look);
    m_clock.start();
    m_settleTimer = new QTimer(this);
    m_settleTimer->setSingleShot(true);
    m_settleTimer->setInterval(kSettleIntervalMs);
    connect(m_settleTimer, &QTimer::timeout, this, &HysteroscopicPreview::settleExposure);
    layout->addWidget(m_view, 1);

    m_controls = new QWidget(this);
    auto* controls = new QFormLayout(m_controls);
    controls->setContentsMargins(0, 0, 0, 0);
    m_insertionSlider = new QSlider(Qt::Horizontal, m_controls);
    m_insertionSlider->setObjectName("insertionSlider");
    m_insertionSlider->setRange(int(kInsertionMinMm * kInsertionStepsPerMm),
                                int(kInsertionMaxMm * kInsertionStepsPerMm));
    m_insertionSlider->setToolTip(tr("How far the scope's tip is beyond the external os (mm)"));
    controls->addRow(tr("&Insertion"), m_insertionSlider);
    m_opticCombo = new QComboBox(m_controls);
    m_opticCombo->setObjectName("opticCombo");
    for (int optic : {0, 12, 30, 70})
        m_opticCombo->addItem(tr("%1°").arg(optic), optic);
    m_opticCombo->setCurrentIndex(2);
    m_opticCombo->setToolTip(tr("The optic's angle off the shaft; office scopes are typically 30°"));
    controls->addRow(tr("&Optic"), m_opticCombo);
    m_rollSlider = new QSlider(Qt::Horizontal, m_controls);
    m_rollSlider->setObjectName("rollSlider");
    m_rollSlider->setRange(-180, 180);
    m_rollSlider->setToolTip(tr("The light post's rotation about the shaft (degrees; 0 looks anterior)"));
    controls->addRow(tr("&Roll"), m_rollSlider);
    layout->addWidget(m_controls);
    m_statusLabel = new QLabel(tr("Texture the case to see the cavity."), this);
    m_statusLabel->setObjectName("previewStatusLabel");
    m_statusLabel->setWordWrap(true);
    layout->addWidget(m_statusLabel);

    connect(m_insertionSlider, &QSlider::valueChanged, this, &HysteroscopicPreview::updateCamera);
    connect(m_opticCombo, &QComboBox::currentIndexChanged, this, &HysteroscopicPreview::updateCamera);
    connect(m_rollSlider, &QSlider::valueChanged, this, &HysteroscopicPreview::updateCamera);
}

HysteroscopicPreview::~HysteroscopicPreview() = default;

void HysteroscopicPreview::setScene(std::shared_ptr<const scene::Scene> scene) {
    if (scene && scene.get() == m_scene.get()) {
        m_scene = std::move(scene); // the same scene (its owner may differ): nothing to draw anew
        return;
    }
    m_scene = std::move(scene);
    m_landmarks.reset();
    if (!m_scene) {
        m_endoscope->clear();
        m_statusLabel->setText(tr("Texture the case to see the cavity."));
        render();
        return;
    }
    m_endoscope->setSurface(m_scene->surface);
    auto landmarks = scene::findScopeLandmarks(*m_scene);
    if (!landmarks) {
        m_statusLabel->setText(tr("This scene has no cervical canal or ostium labels: the scope cannot be placed."));
        render();
        return;
    }
    m_landmarks = *landmarks;
    updateCamera();
}

void HysteroscopicPreview::setControlsVisible(bool visible) {
    m_controls->setVisible(visible);
}

void HysteroscopicPreview::setInsertion(double mm) {
    m_insertionSlider->setValue(int(std::lround(mm * kInsertionStepsPerMm)));
}

double HysteroscopicPreview::insertion() const {
    return double(m_insertionSlider->value()) / kInsertionStepsPerMm;
}

void HysteroscopicPreview::setOptic(double degrees) {
    const int index = m_opticCombo->findData(int(std::lround(degrees)));
    if (index >= 0)
        m_opticCombo->setCurrentIndex(index);
}

void HysteroscopicPreview::setRoll(double degrees) {
    m_rollSlider->setValue(int(std::lround(degrees)));
}

void HysteroscopicPreview::updateCamera() {
    if (!hasScene())
        return;
    auto pose = scene::scopeView(*m_landmarks, insertion(), m_opticCombo->currentData().toDouble(),
                                 double(m_rollSlider->value()));
    if (!pose)
        return;
    m_endoscope->setPose(simrender::cameraPose(*pose, kFieldOfViewDeg));
    const QLocale locale;
    m_statusLabel->setText(tr("Tip %1 mm beyond the external os, %2 optic, roll %3°")
                               .arg(locale.toString(insertion(), 'f', 1), m_opticCombo->currentText())
                               .arg(m_rollSlider->value()));
    render();
}

bool HysteroscopicPreview::lookAtRegion(std::int32_t regionId, double distanceMm) {
    if (!hasScene())
        return false;
    auto pose = scene::viewOfRegion(*m_scene, *m_landmarks, regionId, distanceMm);
    if (!pose)
        return false;
    m_endoscope->setPose(simrender::cameraPose(*pose, kFieldOfViewDeg));
    m_statusLabel->setText(tr("Looking at region %1 from %2 mm inside the cavity")
                               .arg(regionId)
                               .arg(QLocale().toString(distanceMm, 'f', 0)));
    render();
    return true;
}

void HysteroscopicPreview::render() {
    m_endoscope->setTime(1e-3 * double(m_clock.elapsed()) + m_grabbedS);
    m_view->requestRender();
    m_settleFrames = 0;
    m_settleTimer->start();
}

void HysteroscopicPreview::settleExposure() {
    if (m_endoscope->exposureSettled() || ++m_settleFrames > kSettleFrames)
        return;
    m_endoscope->setTime(1e-3 * double(m_clock.elapsed()) + m_grabbedS);
    m_view->requestRender();
    m_settleTimer->start();
}

QImage HysteroscopicPreview::grabImage() {
    // Each grab draws a frame; the camera is given a tenth of a second between them, as if the picture were held.
    QImage image;
    for (int k = 0; k < kSettleFrames; ++k) {
        m_endoscope->setTime(1e-3 * double(m_clock.elapsed()) + m_grabbedS);
        image = m_view->grabImage();
        if (m_endoscope->exposureSettled() && k > 0)
            break;
        m_grabbedS += 0.1;
    }
    return image;
}

} // namespace hs::widgets
