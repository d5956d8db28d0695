#pragma once
/// The bridge between the GUI thread and the pipeline: every stage run is a job on a worker thread (QtConcurrent with
/// a QPromise), whose hs::Progress reports become the future's progress and whose Cancel asks the stage to stop
/// through Progress::requestCancel. A job carries the revision of the document it was computed from: a result that
/// arrives after the document changed is discarded, never applied. Errors come back as hs::Error; show them with
/// describeError(), which translates the code and never shows the English detail.
///
/// The GUI thread never runs a stage: start() returns at once, and `apply` runs on the GUI thread when the job is
/// done (MITK's QtConcurrent + QFutureWatcher pattern; exceptions are caught on the worker and come back as errors).

#include "hs/core/Error.h"
#include "hs/core/Progress.h"
#include "hs/core/Result.h"

#include <QElapsedTimer>
#include <QFutureWatcher>
#include <QObject>
#include <QPromise>
#include <QString>
#include <QtConcurrent/QtConcurrentRun>

#include <cstdint>
#include <exception>
#include <functional>
#include <memory>
#include <optional>
#include <string>
#include <utility>

namespace hs::widgets {

/// The translated sentence for what went wrong in a job, by error code only (the detail is for logs).
QString describeError(ErrorCode code);

class JobRunner : public QObject {
    Q_OBJECT

public:
    /// Progress values of the job's future run from 0 to kProgressSteps.
    static constexpr int kProgressSteps = 1000;

    explicit JobRunner(QObject* parent = nullptr);
    /// Cancels a running job and waits for its worker (a stage stops within about 100 ms of a cancel).
    ~JobRunner() override;

    /// The document revision that results must belong to; a job whose revision differs when it ends is discarded.
    void setRevisionSource(std::function<std::uint64_t()> source) { m_revision = std::move(source); }

    /// Starts `work` on a worker thread; `apply` gets its value on the GUI thread if the job succeeded and its
    /// `revision` is still current. A job already running is cancelled and its result dropped.
    template <class T>
    void start(const QString& title, std::uint64_t revision, std::function<Result<T>(Progress&)> work,
               std::function<void(T&&)> apply);

    bool isRunning() const { return m_current != nullptr; }
    /// The running job's title; empty when idle.
    QString title() const;
    /// Asks the running job to stop; cancelled() follows once its stage has returned.
    void cancel();
    /// Waits (processing no events) until no job runs; false after `timeoutMs`.
    bool waitForIdle(int timeoutMs);

signals:
    void started(const QString& title);
    /// `fraction` in [0, 1] of the whole job; `stageKey` is the pipeline's dotted step ("meshing.relax").
    void progressChanged(double fraction, const QString& stageKey);
    void succeeded(const QString& title);
    void failed(const QString& title, const hs::Error& error);
    /// The job stopped on a cancel; `latencyMs` from the cancel request to the stage's return.
    void cancelled(const QString& title, double latencyMs);
    /// The job ended after the document changed: its result was dropped.
    void discarded(const QString& title);
    /// After any of the four outcomes above, when no other job runs.
    void idle();

private:
    struct Job {
        QString title;
        std::uint64_t revision = 0;
        std::shared_ptr<Progress> progress;
        QFutureWatcher<void> watcher;
        std::function<std::optional<Error>()> deliver; ///< GUI thread: applies the value, or returns the error
        QElapsedTimer sinceCancel;
    };

    void launch(std::unique_ptr<Job> job, std::function<void(Progress&)> body);
    void onJobFinished(Job* job);
    void onJobProgress(Job* job, int value, const QString& key);

    std::function<std::uint64_t()> m_revision;
    Job* m_current = nullptr;
    std::vector<std::unique_ptr<Job>> m_jobs; ///< the current one and cancelled ones still winding down
};

template <class T>
void JobRunner::start(const QString& title, std::uint64_t revision, std::function<Result<T>(Progress&)> work,
                      std::function<void(T&&)> apply) {
    auto job = std::make_unique<Job>();
    job->title = title;
    job->revision = revision;
    auto slot = std::make_shared<std::optional<Result<T>>>();
    job->deliver = [slot, apply = std::move(apply)]() -> std::optional<Error> {
        if (!*slot)
            return Error{ErrorCode::Internal, "the job ended without a result"};
        if (!**slot)
            return (*slot)->error();
        apply(std::move(**slot).value());
        return std::nullopt;
    };
    launch(std::move(job), [slot, work = std::move(work)](Progress& progress) {
        try {
            slot->emplace(work(progress));
        } catch (const std::exception& e) {
            slot->emplace(Error{ErrorCode::Internal, e.what()});
        } catch (...) {
            slot->emplace(Error{ErrorCode::Internal, "unknown exception in a job"});
        }
    });
}

} // namespace hs::widgets

Q_DECLARE_METATYPE(hs::Error)
