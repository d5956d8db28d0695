// The main window's 3-D view: the results' parts shown (and the scene tree over them), out-of-date marks, the seat
// handles, the clip plane, the camera, picking and the status bar's counts.
#include "hs/workstation/MainWindow.h"

#include "hs/widgets/panels/MeshPanel.h"
#include "hs/widgets/panels/PathologyPanel.h"
#include "hs/widgets/panels/SceneTree.h"
#include "hs/widgets/view/HysteroscopicPreview.h"
#include "hs/widgets/view/MeshDisplay.h"
#include "hs/widgets/view/SceneParts.h"
#include "hs/widgets/view/SurfaceHandles.h"

#include <QAction>
#include <QDir>
#include <QFileInfo>
#include <QLabel>
#include <QLocale>

#include <vtkCamera.h>
#include <vtkRenderer.h>

#include <memory>
#include <optional>

namespace hs::workstation {

namespace {

/// Reset Camera looks at the mesh from the front, turned by these angles (degrees) so its depth shows.
constexpr double kViewAzimuth = 30.0;
constexpr double kViewElevation = 20.0;

QString formatCount(std::size_t count) {
    return QLocale().toString(static_cast<qulonglong>(count));
}

} // namespace

void MainWindow::onResultsChanged() {
    // A mesh file the user opened stays in the view until the case is edited; a reviewed package until it is closed.
    if (!m_currentFile.isEmpty() || isReviewing())
        return;
    const bool first = m_shownLayer == widgets::ResultLayer::None;
    showResults();
    if (first && m_shownLayer != widgets::ResultLayer::None)
        onResetCamera();
}

void MainWindow::showResults() {
    const auto results = m_session.results();
    if (!results)
        return;
    // The preview shares the results' scene (no copy): it lives as long as the preview holds it.
    m_preview->setScene(results->scene ? std::shared_ptr<const scene::Scene>(results, &*results->scene) : nullptr);
    const widgets::ResultLayer layer = m_parts->show(
        results, m_pathologyPanel->isPlacing() ? std::optional(widgets::ResultLayer::Organ) : std::nullopt);
    m_sceneTree->refresh();
    if (layer == widgets::ResultLayer::None)
        return;
    m_shownLayer = layer;
    m_currentFile.clear();
    updateHandles();
    m_clipAction->setEnabled(true); // cuts a tet mesh or opens a surface (to click on the cavity's wall)
    syncClipPlane();
    m_meshPanel->applyToDisplay();
    m_sceneTree->refreshChecks();
    updateOutOfDateMarks();
    m_view->requestRender();
    updateStatus();
}

void MainWindow::showOwnMesh() {
    m_parts->clear();
    m_display->setShown(true);
    m_display->setOpacity(1.0);
    m_sceneTree->refresh();
    m_shownLayer = widgets::ResultLayer::None;
    updateOutOfDateMarks();
}

void MainWindow::updateOutOfDateMarks() {
    m_sceneTree->refreshMarks();
    const bool ownMesh = !m_currentFile.isEmpty() || isReviewing();
    const bool view =
        !ownMesh && m_shownLayer != widgets::ResultLayer::None && !m_session.isCurrent(widgets::stageOf(m_shownLayer));
    m_viewOutOfDate->setText(tr("Out of date (%1): the case has changed since this view was made. It is remade "
                                "when its stage runs again.")
                                 .arg(layerName(m_shownLayer)));
    m_viewOutOfDate->setVisible(view);
    const auto results = m_session.results();
    m_previewOutOfDate->setVisible(!ownMesh && results && results->scene &&
                                   !m_session.isCurrent(generate::Stage::Scene));
}

void MainWindow::updateHandles() {
    const auto seat = m_pathologyPanel->currentSeat();
    if (!seat || !m_pathologyPanel->isPlacing() || m_shownLayer != widgets::ResultLayer::Organ) {
        if (m_handles->isShown())
            m_handles->hide();
        return;
    }
    if (const widgets::MeshDisplay* organ = m_parts->display("organ"))
        m_handles->show(organ->actor(), seat->pointMm, seat->normal, seat->sizeMm);
}

void MainWindow::onClipToggled(bool enabled) {
    m_parts->setClipEnabled(enabled);
    syncClipPlane();
    m_view->requestRender();
    updateStatus();
}

void MainWindow::syncClipPlane() {
    const widgets::MeshDisplay& shown = m_parts->reference();
    if (m_clipAction->isChecked() && !shown.isEmpty())
        m_clipPlane->show(shown.meshBounds(), shown.clipOrigin(), shown.clipNormal());
    else
        m_clipPlane->hide();
}

void MainWindow::onResetCamera() {
    vtkCamera* camera = m_view->renderer()->GetActiveCamera();
    camera->SetFocalPoint(0.0, 0.0, 0.0);
    camera->SetPosition(0.0, 0.0, 1.0);
    camera->SetViewUp(0.0, 1.0, 0.0);
    camera->Azimuth(kViewAzimuth);
    camera->Elevation(kViewElevation);
    camera->OrthogonalizeViewUp();
    m_view->resetCamera();
}

void MainWindow::onPicked(const widgets::PickResult& result) {
    if (m_pathologyPanel->isPlacing()) {
        m_pathologyPanel->placeAt(result.hit, result.point);
        return;
    }
    if (!result.hit) {
        m_pickLabel->setText(tr("Nothing picked"));
        return;
    }
    const QLocale locale;
    QString text =
        tr("Picked (%1, %2, %3) mm")
            .arg(locale.toString(double(result.point.x()), 'f', 2), locale.toString(double(result.point.y()), 'f', 2),
                 locale.toString(double(result.point.z()), 'f', 2));
    // A pick on a pathology (grown, merged or meshed) selects it, in the list and in the scene tree.
    if (const int pathology = m_parts->pathologyAt(result.prop, result.region); pathology >= 0 && !isReviewing()) {
        const auto& pathologies = m_document.spec().pathologies;
        if (static_cast<std::size_t>(pathology) < pathologies.size())
            text += QStringLiteral("   ") +
                    tr("on %1").arg(QString::fromStdString(pathologies[static_cast<std::size_t>(pathology)].id));
        m_pathologyPanel->setCurrentIndex(pathology);
        m_sceneTree->selectPathology(pathology);
    }
    m_pickLabel->setText(text);
}

QString MainWindow::layerName(widgets::ResultLayer layer) {
    switch (layer) {
    case widgets::ResultLayer::Organ:
        return tr("Organ");
    case widgets::ResultLayer::Pathologies:
        return tr("Grown pathologies");
    case widgets::ResultLayer::Body:
        return tr("Merged body");
    case widgets::ResultLayer::Tissues:
        return tr("Tetrahedral mesh");
    case widgets::ResultLayer::Textured:
        return tr("Textured surface");
    case widgets::ResultLayer::None:
        break;
    }
    return QString();
}

void MainWindow::updateStatus() {
    // The counts of what the view shows: the first part shown of the results, else the mesh file or package.
    const widgets::MeshDisplay& shown = m_parts->reference();
    if (shown.isEmpty()) {
        m_countsLabel->setText(tr("No mesh"));
        m_fileLabel->clear();
        return;
    }
    const widgets::MeshCounts& counts = shown.counts();
    QString text;
    if (shown.isTetMesh()) {
        text = tr("Vertices: %1   Tetrahedra: %2   Regions: %3")
                   .arg(formatCount(counts.vertices), formatCount(counts.tets), formatCount(counts.regions));
        if (shown.clipEnabled())
            text += QStringLiteral("   ") + tr("Shown: %1").arg(formatCount(shown.visibleCellCount()));
    } else {
        text = tr("Vertices: %1   Triangles: %2   Regions: %3")
                   .arg(formatCount(counts.vertices), formatCount(counts.triangles), formatCount(counts.regions));
    }
    m_countsLabel->setText(text);
    if (m_shownLayer != widgets::ResultLayer::None) {
        m_fileLabel->setText(layerName(m_shownLayer));
        m_fileLabel->setToolTip(tr("The case's %1, as the pipeline made it").arg(layerName(m_shownLayer)));
        return;
    }
    m_fileLabel->setText(QFileInfo(m_currentFile).fileName());
    m_fileLabel->setToolTip(QDir::toNativeSeparators(m_currentFile));
}

} // namespace hs::workstation
