// bench_jobs: how the workstation's GUI thread fares while the pipeline runs (widgets::JobRunner and
// GenerationSession), as a table.
//   bench_jobs [--cancels N] [--vertices N]
// 1. GUI-thread latency: a timer asks for a tick every 5 ms on the GUI thread while the longest job runs (the whole
//    chain of the default case, through the scene); a tick's latency is how late it came. p50, p99 and the worst.
// 2. Cancel latency: N mesh jobs, each cancelled once the meshing stage reports progress; the time from the cancel
//    request to the job's end. The bar: within 200 ms.
// Run with QT_QPA_PLATFORM=offscreen (no window is shown).
#include "hs/widgets/document/CaseDocument.h"
#include "hs/widgets/jobs/GenerationSession.h"
#include "hs/widgets/jobs/JobRunner.h"

#include <QApplication>
#include <QElapsedTimer>
#include <QEventLoop>
#include <QTimer>

#include <algorithm>
#include <cstdio>
#include <cstdlib>
#include <cstring>
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

} // namespace

int main(int argc, char** argv) {
    qputenv("QT_QPA_PLATFORM", qgetenv("QT_QPA_PLATFORM").isEmpty() ? "offscreen" : qgetenv("QT_QPA_PLATFORM"));
    QApplication app(argc, argv);
    int cancels = 10;
    int vertices = 30000;
    for (int i = 1; i + 1 < argc; ++i) {
        if (std::strcmp(argv[i], "--cancels") == 0)
            cancels = std::max(1, std::atoi(argv[++i]));
        else if (std::strcmp(argv[i], "--vertices") == 0)
            vertices = std::max(500, std::atoi(argv[++i]));
    }

    hs::widgets::CaseDocument document;
    document.edit("vertices", [vertices](hs::scene::CaseSpec& s) { s.meshing.targetVertices = vertices; });
    hs::widgets::GenerationSession session(document);
    session.setAutoUpdate(false);
    hs::widgets::JobRunner& runner = session.runner();

    // 1. GUI-thread latency during the whole chain.
    std::vector<double> lateMs;
    QElapsedTimer clock;
    constexpr int kTickMs = 5;
    QTimer ticker;
    ticker.setTimerType(Qt::PreciseTimer);
    ticker.setInterval(kTickMs);
    qint64 last = 0;
    QObject::connect(&ticker, &QTimer::timeout, [&] {
        const qint64 now = clock.nsecsElapsed();
        lateMs.push_back(std::max(0.0, double(now - last) / 1e6 - kTickMs));
        last = now;
    });
    bool ended = false;
    QObject::connect(&runner, &hs::widgets::JobRunner::idle, [&] { ended = true; });
    clock.start();
    last = clock.nsecsElapsed();
    ticker.start();
    session.runThrough(hs::generate::Stage::Scene);
    waitFor([&] { return ended; }, 600000);
    ticker.stop();
    const double jobSeconds = double(clock.nsecsElapsed()) / 1e9;
    if (!session.isCurrent(hs::generate::Stage::Scene)) {
        std::fprintf(stderr, "bench_jobs: the chain did not finish\n");
        return 1;
    }

    // 2. Cancel latency of the mesh job.
    std::vector<double> cancelMs;
    QString key;
    QObject::connect(&runner, &hs::widgets::JobRunner::progressChanged, [&](double, const QString& k) { key = k; });
    QObject::connect(&runner, &hs::widgets::JobRunner::cancelled,
                     [&](const QString&, double ms) { cancelMs.push_back(ms); });
    for (int i = 0; i < cancels; ++i) {
        // A new seed each time: the organ, pathologies and mesh all rerun.
        document.edit("seed", [i](hs::scene::CaseSpec& s) { s.seed = 1000 + std::uint64_t(i); });
        key.clear();
        ended = false;
        session.runThrough(hs::generate::Stage::Meshing);
        waitFor([&] { return key.startsWith("meshing") || ended; }, 300000);
        // Let the mesher get into its loops: cancel at a spread of points in the stage.
        QElapsedTimer pause;
        pause.start();
        waitFor([&] { return pause.elapsed() >= 100 * (i % 10); }, 2000);
        runner.cancel();
        waitFor([&] { return ended; }, 60000);
    }

    std::printf("GUI thread while the whole chain runs (%d target vertices, %.1f s, %zu ticks of %d ms)\n", vertices,
                jobSeconds, lateMs.size(), kTickMs);
    std::printf("%-28s %10s %10s %10s\n", "measure", "p50 ms", "p99 ms", "max ms");
    std::printf("%-28s %10.2f %10.2f %10.2f\n", "tick latency (GUI thread)", percentile(lateMs, 0.5),
                percentile(lateMs, 0.99), percentile(lateMs, 1.0));
    std::printf("%-28s %10.2f %10.2f %10.2f   (%zu of %d cancels in meshing; bar 200 ms)\n", "mesh job cancel",
                percentile(cancelMs, 0.5), percentile(cancelMs, 0.99), percentile(cancelMs, 1.0), cancelMs.size(),
                cancels);
    return 0;
}
