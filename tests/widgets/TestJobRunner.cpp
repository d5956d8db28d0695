// Qt Test for hs::widgets::JobRunner and GenerationSession: results applied on the GUI thread, errors by code,
// a cancel that stops a running stage, results of an older document dropped, the organ rebuilt after an edit, a
// running mesh job cancelled.
#include "hs/widgets/document/CaseDocument.h"
#include "hs/widgets/jobs/GenerationSession.h"
#include "hs/widgets/jobs/JobRunner.h"
#include "hs/widgets/jobs/JobStatusWidget.h"

#include <QElapsedTimer>
#include <QSignalSpy>
#include <QTemporaryDir>
#include <QTest>
#include <QThread>

#include <atomic>

using hs::ErrorCode;
using hs::Progress;
using hs::Result;
using hs::widgets::JobRunner;

namespace {

/// A job that works until it is cancelled, checking every millisecond like a stage's inner loop.
Result<int> untilCancelled(Progress& progress, std::atomic<bool>& running) {
    running = true;
    for (int i = 0; i < 60000; ++i) {
        progress.report("test.loop", double(i % 1000) / 1000.0);
        HS_TRY(progress.check("test"));
        QThread::msleep(1);
    }
    return 1;
}

} // namespace

class TestJobRunner : public QObject {
    Q_OBJECT

private slots:
    void appliesTheValueOnTheGuiThread();
    void reportsAFailureByItsCode();
    void cancelStopsTheJob();
    void dropsAResultOfAnOlderRevision();
    void aNewJobReplacesTheRunningOne();
    void sessionRebuildsTheOrganAfterAnEdit();
    void sessionCancelsARunningMeshJob();
    void theStatusNamesEachPipelineStepInWords();
};

void TestJobRunner::appliesTheValueOnTheGuiThread() {
    JobRunner runner;
    QSignalSpy succeeded(&runner, &JobRunner::succeeded);
    QThread* applyThread = nullptr;
    QThread* workThread = nullptr;
    int value = 0;
    runner.start<int>(
        "answer", 0,
        [&](Progress& progress) -> Result<int> {
            workThread = QThread::currentThread();
            progress.report("test.half", 0.5);
            return 42;
        },
        [&](int&& v) {
            applyThread = QThread::currentThread();
            value = v;
        });
    QVERIFY(runner.isRunning());
    QCOMPARE(runner.title(), QString("answer"));
    QVERIFY(succeeded.wait(5000));
    QCOMPARE(value, 42);
    QCOMPARE(applyThread, QThread::currentThread());
    QVERIFY(workThread != QThread::currentThread());
    QVERIFY(!runner.isRunning());
}

void TestJobRunner::reportsAFailureByItsCode() {
    JobRunner runner;
    QSignalSpy failed(&runner, &JobRunner::failed);
    bool applied = false;
    runner.start<int>(
        "fails", 0,
        [](Progress&) -> Result<int> { return hs::fail(ErrorCode::InvalidInput, "/patient/ageYears: 130 is outside"); },
        [&](int&&) { applied = true; });
    QVERIFY(failed.wait(5000));
    QVERIFY(!applied);
    const auto error = failed.at(0).at(1).value<hs::Error>();
    QCOMPARE(error.code, ErrorCode::InvalidInput);
    // The sentence shown to the user comes from the code, never from the English detail.
    QVERIFY(!hs::widgets::describeError(error.code).contains("ageYears"));
    QVERIFY(!hs::widgets::describeError(error.code).isEmpty());
    QVERIFY(hs::widgets::describeError(ErrorCode::Cancelled) != hs::widgets::describeError(ErrorCode::IoError));
}

void TestJobRunner::cancelStopsTheJob() {
    JobRunner runner;
    QSignalSpy cancelled(&runner, &JobRunner::cancelled);
    QSignalSpy idle(&runner, &JobRunner::idle);
    std::atomic<bool> running{false};
    bool applied = false;
    runner.start<int>(
        "loop", 0, [&](Progress& p) { return untilCancelled(p, running); }, [&](int&&) { applied = true; });
    QTRY_VERIFY_WITH_TIMEOUT(running.load(), 5000);
    runner.cancel();
    QVERIFY(cancelled.wait(5000));
    QVERIFY(!applied);
    QCOMPARE(idle.count(), 1);
    const double latencyMs = cancelled.at(0).at(1).toDouble();
    QVERIFY2(latencyMs >= 0.0 && latencyMs < 2000.0, qPrintable(QString::number(latencyMs)));
}

void TestJobRunner::dropsAResultOfAnOlderRevision() {
    JobRunner runner;
    std::uint64_t revision = 1;
    runner.setRevisionSource([&] { return revision; });
    QSignalSpy discarded(&runner, &JobRunner::discarded);
    std::atomic<bool> release{false};
    bool applied = false;
    runner.start<int>(
        "stale", 1,
        [&](Progress&) -> Result<int> {
            while (!release)
                QThread::msleep(1);
            return 7;
        },
        [&](int&&) { applied = true; });
    revision = 2; // the document changed while the job ran
    release = true;
    QVERIFY(discarded.wait(5000));
    QVERIFY(!applied);
}

void TestJobRunner::aNewJobReplacesTheRunningOne() {
    JobRunner runner;
    QSignalSpy succeeded(&runner, &JobRunner::succeeded);
    QSignalSpy cancelled(&runner, &JobRunner::cancelled);
    std::atomic<bool> running{false};
    int applied = 0;
    runner.start<int>(
        "first", 0, [&](Progress& p) { return untilCancelled(p, running); }, [&](int&&) { applied += 1; });
    QTRY_VERIFY_WITH_TIMEOUT(running.load(), 5000);
    runner.start<int>(
        "second", 0, [](Progress&) -> Result<int> { return 2; }, [&](int&& v) { applied += 10 * v; });
    QVERIFY(runner.waitForIdle(5000));
    QCOMPARE(applied, 20);
    QCOMPARE(succeeded.count(), 1);
    QCOMPARE(cancelled.count(), 0); // the first one was replaced, not cancelled by the user
}

void TestJobRunner::sessionRebuildsTheOrganAfterAnEdit() {
    hs::widgets::CaseDocument document;
    hs::widgets::GenerationSession session(document);
    QSignalSpy changed(&session, &hs::widgets::GenerationSession::resultsChanged);
    session.runThrough(hs::generate::Stage::Organ);
    QVERIFY(changed.wait(30000));
    QVERIFY(session.isCurrent(hs::generate::Stage::Organ));
    QVERIFY(!session.isCurrent(hs::generate::Stage::Pathology));
    const auto firstOrgan = session.results()->organ->mesh.points;

    document.edit("Age", [](hs::scene::CaseSpec& s) { s.patient.ageYears = 55.0; });
    QVERIFY(!session.isCurrent(hs::generate::Stage::Organ));
    QVERIFY(changed.wait(30000)); // rebuilt on its own after the pause
    QVERIFY(session.isCurrent(hs::generate::Stage::Organ));
    QVERIFY(session.results()->organ->mesh.points != firstOrgan);
}

void TestJobRunner::sessionCancelsARunningMeshJob() {
    hs::widgets::CaseDocument document;
    hs::widgets::GenerationSession session(document);
    session.setAutoUpdate(false);
    JobRunner& runner = session.runner();
    QSignalSpy cancelled(&runner, &JobRunner::cancelled);
    QString lastKey;
    connect(&runner, &JobRunner::progressChanged, this, [&](double, const QString& key) { lastKey = key; });
    session.runThrough(hs::generate::Stage::Meshing);
    QTRY_VERIFY_WITH_TIMEOUT(lastKey.startsWith("meshing"), 60000);
    runner.cancel();
    QVERIFY(cancelled.wait(10000));
    QVERIFY(!session.isCurrent(hs::generate::Stage::Meshing));
    const double latencyMs = cancelled.at(0).at(1).toDouble();
    qInfo("mesh job cancel latency: %.1f ms", latencyMs);
    QVERIFY2(latencyMs < 2000.0, qPrintable(QString::number(latencyMs)));
}

void TestJobRunner::theStatusNamesEachPipelineStepInWords() {
    using hs::widgets::JobStatusWidget;
    QCOMPARE(JobStatusWidget::stepName("meshing.relax"), QString("relaxing the particles"));
    QCOMPARE(JobStatusWidget::stepName("meshing.relax.sweep"), QString("relaxing the particles")); // its step's
    QCOMPARE(JobStatusWidget::stepName("texture"), QString("texturing"));
    QCOMPARE(JobStatusWidget::stepName("meshing.unknownStep"), QString("meshing the body")); // its stage's
    QCOMPARE(JobStatusWidget::stepName("elsewhere.step"), QString("elsewhere.step"));
    // Every step the pipeline reports while generating has a name (none falls back to its key).
    QStringList unnamed;
    hs::Progress progress([&](std::string_view key, double) {
        const QString k = QString::fromUtf8(key.data(), int(key.size()));
        if (JobStatusWidget::stepName(k) == k && !unnamed.contains(k))
            unnamed.append(k);
    });
    hs::scene::CaseSpec spec = hs::scene::defaultCase();
    spec.meshing.targetVertices = 3000;
    spec.texture.sizePx = 128;
    QVERIFY(hs::generate::generateScene(spec, {}, progress).ok());
    QVERIFY2(unnamed.isEmpty(), qPrintable(unnamed.join(", ")));
}

QTEST_MAIN(TestJobRunner)
#include "TestJobRunner.moc"
