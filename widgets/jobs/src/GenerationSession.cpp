#include "hs/widgets/jobs/GenerationSession.h"

#include "hs/scene/ScopePassage.h"
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

namespace {

/// Writes `scene` to `folder`, verifies it and checks the scope's passage.
Result<ExportedPackage> writeAndCheck(const scene::Scene& scene, const QString& folder, bool zip,
                                      const scene::PackageWriteOptions& formats, Progress& progress) {
    const std::string path = QFile::encodeName(folder).toStdString();
    auto writeSub = progress.sub(0.0, 0.7);
    auto written = scene::writeScenePackage(scene, path, formats, writeSub);
    if (!written)
        return written.failure();
    auto verified = scene::verifyScenePackage(path);
    if (!verified)
        return verified.failure();
    ExportedPackage out;
    out.folder = folder;
    out.seed = scene.caseSpec.seed;
    out.files = verified->files.size();
    out.warnings = scene.warnings;
    if (zip) {
        out.zipPath = folder + QStringLiteral(".zip");
        HS_TRY(scene::zipScenePackage(path, QFile::encodeName(out.zipPath).toStdString()));
    }
    if (auto landmarks = scene::findScopeLandmarks(scene)) {
        auto scopeSub = progress.sub(0.7, 1.0);
        auto passage = scene::checkScopePassage(scene.tets, *landmarks, {}, scopeSub);
        if (!passage)
            return passage.failure();
        out.scopeChecked = true;
        out.scopePasses = passage->open && passage->ballPasses;
        out.narrowestMm = passage->narrowest.freeWidthMm;
    }
    return out;
}

} // namespace

void GenerationSession::exportPackage(const QString& folder, bool zip, int variants,
                                      const scene::PackageWriteOptions& formats) {
    m_autoTimer.stop();
    auto previous = m_results;
    struct Exported {
        std::optional<generate::Generated> generated; ///< the document's own case (one package only)
        ExportResult written;
    };
    const QString absolute = QFileInfo(folder).absoluteFilePath();
    const auto count = static_cast<std::size_t>(std::max(1, variants));
    m_runner.start<Exported>(
        tr("Exporting the scene"), m_document.revision(),
        [previous, spec = m_document.spec(), params = params(), absolute, zip, formats,
         count](Progress& progress) -> Result<Exported> {
            Exported out;
            out.written.folder = absolute;
            if (count > 1 && !QDir().mkpath(absolute))
                return fail(ErrorCode::IoError,
                            QFile::encodeName(absolute).toStdString() + ": cannot create the folder");
            for (std::size_t i = 0; i < count; ++i) {
                auto part = progress.sub(double(i) / double(count), double(i + 1) / double(count));
                scene::CaseSpec variant = spec;
                variant.seed = generate::exportSeed(spec.seed, i, count);
                // One package reuses what the session has; variants are new patients, generated whole.
                generate::Generated base;
                if (count == 1 && previous)
                    base = *previous;
                else
                    base.spec = variant;
                auto generateSub = part.sub(0.0, 0.85);
                auto generated =
                    generate::updateThrough(generate::Stage::Scene, std::move(base), variant, params, generateSub);
                if (!generated)
                    return generated.failure();
                const QString target =
                    count == 1 ? absolute
                               : QDir(absolute).filePath(QString::fromStdString(generate::variantFolderName(i)));
                auto writeSub = part.sub(0.85, 1.0);
                auto package = writeAndCheck(*generated->scene, target, zip, formats, writeSub);
                if (!package)
                    return package.failure();
                out.written.packages.push_back(std::move(package).value());
                if (count == 1)
                    out.generated = std::move(generated).value();
            }
            return out;
        },
        [this](Exported&& done) {
            if (done.generated) {
                m_results = std::make_shared<const generate::Generated>(std::move(*done.generated));
                emit resultsChanged();
            }
            emit exported(done.written);
        });
}

} // namespace hs::widgets
