// bench_jobs: how the workstation's GUI thread fares while the pipeline runs, measured in the whole window (the main
// window with every panel and view, VTK drawing in it), as a table.
//   xvfb-run -a bench_jobs [--cancels N] [--vertices N]
// 1. GUI-thread latency: a timer asks for a tick every 5 ms on the GUI thread while the longest job runs: Export
//    (triggered through the window's Export action) of the default case from nothing, i.e. every stage, the package
//    written, read back and swept by the scope, with the panels, the 3-D view (growth frames, then each stage's
//    result) and the hysteroscopic preview updating from its results as they come. A tick's latency is how late it
//    came: p50, p99 and the worst.
// 2. Cancel latency of each job kind: the organ (rebuilt after an edit, as the window does), Grow, Mesh, Texture and
//    Export, each started by its window action after an edit that makes it rerun, and cancelled with the job bar's
//    cancel button at a spread of moments into its own stage (0-900 ms; Export's from the start of the scene's
//    hydrometra solves, its longest part after the simulation mesh); the time from the cancel request to the job's
//    end (JobRunner::cancelled). The bar: within 200 ms.
// HS_BENCH_TRACE=1 prints every progress step and where each cancel came to stderr.
#include "hs/widgets/document/CaseDocument.h"
#include "hs/widgets/jobs/GenerationSession.h"
#include "hs/widgets/jobs/JobRunner.h"
#include "hs/workstation/MainWindow.h"

#include <QAbstractButton>
#include <QAction>
#include <QApplication>
#include <QElapsedTimer>
#include <QEventLoop>
#include <QLineEdit>
#include <QTemporaryDir>
#include <QTimer>

#include <algorithm>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <functional>
#include <string>
#include <vector>

namespace {

double percentile(std::vector<double> v, double p) {
    if (v.empty())
        return 0.0;
    std::sort(v.begin(), v.end());
    const auto i = static_cast<std::size_t>(std::min<double>(double(v.size() - 1), p * double(v.size() - 1) + 0.5));
    return v[i];
}

/// Runs the event loop until `done` or `timeoutMs`.
void waitFor(const std::function<bool()>& done, int timeoutMs) {
    QElapsedTimer t;
    t.start();
    while (!done() && t.elapsed() < timeoutMs)
        QCoreApplication::processEvents(QEventLoop::AllEvents, 5);
}

/// One kind of job: the edit that makes it rerun, how the window starts it, and the progress key of its own stage.
struct JobKind {
    const char* name;
    std::function<void(hs::scene::CaseSpec&, int)> edit;
    const char* action; ///< the window action that starts it; null: the edit itself does (the organ's auto-update)
    const char* stageKey;
};

} // namespace

int main(int argc, char** argv) {
    QApplication app(argc, argv);
    QCoreApplication::setOrganizationName(QStringLiteral("hysteroscene-bench"));
    int cancels = 5;
    int vertices = 30000;
    for (int i = 1; i + 1 < argc; ++i) {
        if (std::strcmp(argv[i], "--cancels") == 0)
            cancels = std::max(1, std::atoi(argv[++i]));
        else if (std::strcmp(argv[i], "--vertices") == 0)
            vertices = std::max(500, std::atoi(argv[++i]));
    }
    QTemporaryDir out;
    hs::workstation::MainWindow window;
    window.resize(1280, 900);
    window.show();
    waitFor([] { return false; }, 500); // the window drawn once
    hs::widgets::CaseDocument& document = window.document();
    hs::widgets::GenerationSession& session = window.session();
    hs::widgets::JobRunner& runner = session.runner();
    document.edit("vertices", [vertices](hs::scene::CaseSpec& s) { s.meshing.targetVertices = vertices; });
    runner.waitForIdle(60000);
    waitFor([&] { return !runner.isRunning(); }, 60000);
    auto action = [&](const char* name) { return window.findChild<QAction*>(QString::fromLatin1(name)); };
    window.findChild<QLineEdit*>(QStringLiteral("exportFolderEdit"))->setText(out.filePath(QStringLiteral("scene")));

    bool ended = false;
    QObject::connect(&runner, &hs::widgets::JobRunner::idle, [&] { ended = true; });
    QString key;
    QObject::connect(&runner, &hs::widgets::JobRunner::progressChanged, [&](double, const QString& k) {
        if (std::getenv("HS_BENCH_TRACE") && k != key)
            std::fprintf(stderr, "  %s\n", k.toUtf8().constData());
        key = k;
    });

    // 1. GUI-thread latency during the whole export, from nothing, in the whole window.
    document.edit("seed", [](hs::scene::CaseSpec& s) { s.seed = 7; }); // nothing of the first organ is reused
    waitFor([&] { return !runner.isRunning(); }, 60000);
    std::vector<double> lateMs;
    QElapsedTimer clock;
    constexpr int kTickMs = 5;
    QTimer ticker;
    ticker.setTimerType(Qt::PreciseTimer);
    ticker.setInterval(kTickMs);
    qint64 last = 0;
    // What the GUI thread was last given to do before the worst tick: a progress step, a growth frame or results.
    QString lastEvent, worstEvent;
    double worst = -1.0;
    QObject::connect(&runner, &hs::widgets::JobRunner::progressChanged,
                     [&](double, const QString& k) { lastEvent = QStringLiteral("progress ") + k; });
    QObject::connect(&session, &hs::widgets::GenerationSession::growthFrame,
                     [&](const hs::pathology::GrowthFrame&) { lastEvent = QStringLiteral("a growth frame"); });
    QObject::connect(&session, &hs::widgets::GenerationSession::resultsChanged,
                     [&] { lastEvent = QStringLiteral("results applied to the panels and views"); });
    QObject::connect(&ticker, &QTimer::timeout, [&] {
        const qint64 now = clock.nsecsElapsed();
        const double late = std::max(0.0, double(now - last) / 1e6 - kTickMs);
        lateMs.push_back(late);
        if (late > worst) {
            worst = late;
            worstEvent = lastEvent;
        }
        last = now;
    });
    ended = false;
    clock.start();
    last = clock.nsecsElapsed();
    ticker.start();
    action("actionExport")->trigger();
    waitFor([&] { return ended; }, 900000);
    ticker.stop();
    const double jobSeconds = double(clock.nsecsElapsed()) / 1e9;
    if (!session.isCurrent(hs::generate::Stage::Scene)) {
        std::fprintf(stderr, "bench_jobs: the export did not finish\n");
        return 1;
    }

    // 2. Cancel latency of each job kind, through the job bar's cancel button.
    auto* cancelButton = window.findChild<QAbstractButton*>(QStringLiteral("jobCancelButton"));
    const std::vector<JobKind> kinds{
        {"organ (after an edit)", [](hs::scene::CaseSpec& s, int i) { s.seed = 100 + std::uint64_t(i); }, nullptr,
         "anatomy"},
        {"grow", [](hs::scene::CaseSpec& s, int i) { s.pathologies[0].sizeMm = 20.0 + 0.1 * (i % 2 + 1); },
         "actionGrow", "pathology"},
        {"mesh", [vertices](hs::scene::CaseSpec& s, int i) { s.meshing.targetVertices = vertices + 1 + i; },
         "actionMesh", "meshing"},
        {"texture", [](hs::scene::CaseSpec& s, int i) { s.texture.vesselDensity = 1.0 + 0.01 * (i + 1); },
         "actionTexture", "texture"},
        {"export (hydrometra, package)", [](hs::scene::CaseSpec& s, int i) { s.title = "bench " + std::to_string(i); },
         "actionExport", "scene.hydrometra"},
    };
    std::printf("GUI thread in the whole window while Export runs the whole chain (%d target vertices, %.1f s, %zu "
                "ticks of %d ms)\n",
                vertices, jobSeconds, lateMs.size(), kTickMs);
    std::printf("%-30s %10s %10s %10s\n", "measure", "p50 ms", "p99 ms", "max ms");
    std::printf("%-30s %10.2f %10.2f %10.2f   (worst after %s)\n", "tick latency (GUI thread)", percentile(lateMs, 0.5),
                percentile(lateMs, 0.99), percentile(lateMs, 1.0), worstEvent.toUtf8().constData());
    std::fflush(stdout);
    for (const JobKind& kind : kinds) {
        // Everything before the kind's stage current, so the cancelled job runs only its own stages.
        if (kind.action) {
            ended = false;
            action(kind.action)->trigger();
            waitFor([&] { return ended; }, 900000);
        }
        std::vector<double> cancelMs;
        QString keyAtCancel, slowestKey;
        double slowest = -1.0;
        auto connection = QObject::connect(&runner, &hs::widgets::JobRunner::cancelled, [&](const QString&, double ms) {
            cancelMs.push_back(ms);
            if (ms > slowest) {
                slowest = ms;
                slowestKey = keyAtCancel;
            }
        });
        int missed = 0;
        for (int i = 0; i < cancels; ++i) {
            key.clear();
            ended = false;
            document.edit(kind.name, [&](hs::scene::CaseSpec& s) { kind.edit(s, i); });
            if (kind.action) {
                waitFor([&] { return !runner.isRunning(); }, 60000); // the organ's auto-update, current: a no-op
                ended = false;
                key.clear();
                action(kind.action)->trigger();
            }
            waitFor([&] { return key.startsWith(QLatin1String(kind.stageKey)) || ended; }, 300000);
            QElapsedTimer pause;
            pause.start();
            waitFor([&] { return pause.elapsed() >= 100 * (i % 10) || ended; }, 2000);
            if (ended || !runner.isRunning()) {
                ++missed; // the job ended before the cancel
                continue;
            }
            keyAtCancel = key;
            if (std::getenv("HS_BENCH_TRACE"))
                std::fprintf(stderr, "%s: cancel at %s\n", kind.name, key.toUtf8().constData());
            cancelButton->click();
            waitFor([&] { return ended; }, 60000);
        }
        QObject::disconnect(connection);
        std::printf("%-30s %10.2f %10.2f %10.2f   (%zu of %d cancelled, %d ended first; slowest during '%s'; bar "
                    "200 ms)\n",
                    ("cancel: " + std::string(kind.name)).c_str(), percentile(cancelMs, 0.5),
                    percentile(cancelMs, 0.99), percentile(cancelMs, 1.0), cancelMs.size(), cancels, missed,
                    slowestKey.toUtf8().constData());
        std::fflush(stdout);
    }
    return 0;
}
