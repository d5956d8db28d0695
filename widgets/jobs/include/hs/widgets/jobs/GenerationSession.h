#pragma once
/// The pipeline's results for the document being authored. Each request runs on a worker thread through the
/// JobRunner and calls hs::generate::updateThrough, which reruns only the stages the edits since the last run
/// touched: the GUI holds no pipeline logic. A result computed for an older revision of the document is dropped.
///
/// After an edit of the case the organ is rebuilt in the background on its own (a short pause lets a slider drag
/// end first); the later stages run when the user asks (Grow, Merge, Mesh, Texture, Export).

#include "hs/generate/Export.h"
#include "hs/generate/Generate.h"
#include "hs/scene/ScenePackage.h"
#include "hs/widgets/jobs/JobRunner.h"

#include <QObject>
#include <QString>
#include <QTimer>

#include <cstdint>
#include <memory>
#include <optional>
#include <vector>

namespace hs::widgets {

class CaseDocument;

/// What an export wrote: one package, or one per variant (folder/variant-NNN), each as generate::exportScenes
/// checked it (files read back, the scene's warnings, the scope's verdict).
struct ExportResult {
    QString folder;
    std::vector<generate::ExportedPackage> packages;
};

class GenerationSession : public QObject {
    Q_OBJECT

public:
    explicit GenerationSession(CaseDocument& document, QObject* parent = nullptr);
    ~GenerationSession() override;

    JobRunner& runner() { return m_runner; }
    CaseDocument& document() { return m_document; }

    /// The latest results applied; null before the first job ends. Their `spec` may be older than the document's
    /// case: see isCurrent().
    std::shared_ptr<const generate::Generated> results() const { return m_results; }
    /// Whether the results have `stage` and it was made from the document's case as it is now.
    bool isCurrent(generate::Stage stage) const;

    /// Runs, on a worker thread, what the case needs through `last` (nothing when it is current already).
    void runThrough(generate::Stage last);
    /// Runs every stage, writes the scene package to `folder` (and `folder`.zip when `zip`), verifies it and checks
    /// that a 2.9 mm scope passes (generate::exportScenes, as the command line's generate). With `variants` > 1, writes
    /// folder/variant-NNN for each variant seed instead (as `hysteroscene-cli generate --variants` does). `formats`:
    /// the other tools' formats written besides (glTF, MSH, OBJ, SOFA; none by default, as `generate --formats`).
    void exportPackage(const QString& folder, bool zip, int variants = 1,
                       const scene::PackageWriteOptions& formats = {});
    /// Rebuilds the organ after each edit (default on); the delay lets edits in a row end first.
    void setAutoUpdate(bool enabled) { m_autoUpdate = enabled; }
    static constexpr int kAutoUpdateDelayMs = 250;
    /// Shortest time between two growth frames of one pathology shown to the GUI (ms).
    static constexpr int kGrowthFrameMs = 60;

    /// Threads of the parallel stages (0: all cores; see scene::MeshingParams::threads). Never changes a result.
    void setThreads(std::optional<int> threads) { m_threads = threads; }

signals:
    /// New results were applied: the view and the panels redraw from results().
    void resultsChanged();
    /// A package was written and verified.
    void exported(const hs::widgets::ExportResult& result);
    /// A step of a pathology's growth while the pathology stage runs (at most one every kGrowthFrameMs per
    /// pathology, and each model's last one); results of the stage follow with resultsChanged.
    void growthFrame(const hs::pathology::GrowthFrame& frame);

private:
    void onDocumentChanged();
    generate::GenerateParams params();

    CaseDocument& m_document;
    JobRunner m_runner;
    std::shared_ptr<const generate::Generated> m_results;
    QTimer m_autoTimer;
    bool m_autoUpdate = true;
    std::optional<int> m_threads;
};

} // namespace hs::widgets

Q_DECLARE_METATYPE(hs::widgets::ExportResult)
Q_DECLARE_METATYPE(hs::pathology::GrowthFrame)
