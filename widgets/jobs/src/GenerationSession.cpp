#include "hs/widgets/jobs/GenerationSession.h"

#include "hs/widgets/document/CaseDocument.h"

#include <QDir>
#include <QElapsedTimer>
#include <QFile>
#include <QFileInfo>
#include <QPointer>

#include <algorithm>
#include <map>
#include <mutex>

namespace hs::widgets {

namespace {

QString stageTitle(generate::Stage stage) {
    switch (stage) {
    case generate::Stage::Organ:
        return GenerationSession::tr("Building the organ");
    case generate::Stage::Pathology:
        return GenerationSession::tr("Growing the pathologies");
    case generate::Stage::Merge:
        return GenerationSession::tr("Merging the body");
    case generate::Stage::Meshing:
    case generate::Stage::Tissue:
        return GenerationSession::tr("Meshing");
    case generate::Stage::Texture:
        return GenerationSession::tr("Texturing");
    case generate::Stage::Scene:
        break;
    }
    return GenerationSession::tr("Assembling the scene");
}

} // namespace

GenerationSession::GenerationSession(CaseDocument& document, QObject* parent)
    : QObject(parent), m_document(document), m_runner(this) {
    qRegisterMetaType<hs::widgets::ExportResult>();
    qRegisterMetaType<hs::pathology::GrowthFrame>();
    m_runner.setRevisionSource([this] { return m_document.revision(); });
    m_autoTimer.setSingleShot(true);
    m_autoTimer.setInterval(kAutoUpdateDelayMs);
    connect(&m_autoTimer, &QTimer::timeout, this, [this] { runThrough(generate::Stage::Organ); });
    connect(&m_document, &CaseDocument::changed, this, &GenerationSession::onDocumentChanged);
}

GenerationSession::~GenerationSession() {
    m_runner.cancel(); // the runner waits for its worker when it goes
}

generate::GenerateParams GenerationSession::params() {
    generate::GenerateParams p;
    p.caseFile = QFile::encodeName(m_document.filePath()).toStdString();
    p.threads = m_threads;
    // Growth frames go to the GUI thread, thinned out: a few dozen a second are all a viewer can show.
    struct Throttle {
        std::mutex mutex;
        std::map<std::size_t, QElapsedTimer> last;
    };
    auto throttle = std::make_shared<Throttle>();
    QPointer<GenerationSession> self(this);
    p.growthObserver = [self, throttle](const pathology::GrowthFrame& frame) {
        {
            std::lock_guard<std::mutex> lock(throttle->mutex);
            QElapsedTimer& timer = throttle->last[frame.pathology];
            if (!frame.last && timer.isValid() && timer.elapsed() < kGrowthFrameMs)
                return;
            timer.start();
        }
        QMetaObject::invokeMethod(
            self.data(),
            [self, frame] {
                if (self)
                    emit self->growthFrame(frame);
            },
            Qt::QueuedConnection);
    };
    return p;
}

bool GenerationSession::isCurrent(generate::Stage stage) const {
    if (!m_results || !m_results->has(stage))
        return false;
    const auto change = generate::firstChangedStage(m_results->spec, m_document.spec());
    return !change || static_cast<int>(change->stage) > static_cast<int>(stage);
}

void GenerationSession::onDocumentChanged() {
    if (m_autoUpdate)
        m_autoTimer.start();
}

void GenerationSession::runThrough(generate::Stage last) {
    m_autoTimer.stop();
    // The worker gets its own copy of the results and of the case: nothing it reads changes under it.
    auto previous = m_results;
    m_runner.start<generate::Generated>(
        stageTitle(last), m_document.revision(),
        [previous, spec = m_document.spec(), params = params(), last](Progress& progress) {
            generate::Generated base;
            if (previous)
                base = *previous;
            else
                base.spec = spec;
            return generate::updateThrough(last, std::move(base), spec, params, progress);
        },
        [this](generate::Generated&& done) {
            m_results = std::make_shared<const generate::Generated>(std::move(done));
            emit resultsChanged();
        });
}

void GenerationSession::exportPackage(const QString& folder, bool zip, int variants,
                                      const scene::PackageWriteOptions& formats) {
    m_autoTimer.stop();
    struct Exported {
        std::shared_ptr<const generate::Generated> generated; ///< the document's own case (one package only)
        ExportResult written;
    };
    generate::ExportParams exportParams;
    const QString absolute = QFileInfo(folder).absoluteFilePath();
    exportParams.folder = QFile::encodeName(absolute).toStdString();
    exportParams.variants = static_cast<std::size_t>(std::max(1, variants));
    exportParams.zip = zip;
    exportParams.formats = formats;
    exportParams.previous = m_results;
    m_runner.start<Exported>(
        tr("Exporting the scene"), m_document.revision(),
        [spec = m_document.spec(), params = params(), exportParams, absolute](Progress& progress) -> Result<Exported> {
            Exported out;
            out.written.folder = absolute;
            auto keep = exportParams;
            if (keep.variants == 1)
                keep.onExported = [&out](const generate::ExportedPackage&, generate::Generated&& generated) {
                    out.generated = std::make_shared<const generate::Generated>(std::move(generated));
                };
            auto packages = generate::exportScenes(spec, params, keep, progress);
            if (!packages)
                return packages.failure();
            HS_TRY(generate::firstFailure(*packages));
            out.written.packages = std::move(packages).value();
            return out;
        },
        [this](Exported&& done) {
            if (done.generated) {
                m_results = std::move(done.generated);
                emit resultsChanged();
            }
            emit exported(done.written);
        });
}

} // namespace hs::widgets
