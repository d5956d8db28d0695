#include "hs/widgets/jobs/JobRunner.h"

#include <QCoreApplication>
#include <QDeadlineTimer>
#include <QThread>

#include <algorithm>
#include <atomic>
#include <cmath>

namespace hs::widgets {

QString describeError(ErrorCode code) {
    switch (code) {
    case ErrorCode::InvalidInput:
        return JobRunner::tr("The case asks for something the pipeline cannot make: a value is outside its allowed "
                             "range or a pathology does not fit (see the details).");
    case ErrorCode::NotFound:
        return JobRunner::tr("A file the case names does not exist.");
    case ErrorCode::IoError:
        return JobRunner::tr("A file could not be read or written.");
    case ErrorCode::Unsupported:
        return JobRunner::tr("The case asks for something this version does not support.");
    case ErrorCode::LimitExceeded:
        return JobRunner::tr("The result would be larger than this program accepts.");
    case ErrorCode::Cancelled:
        return JobRunner::tr("The job was cancelled.");
    case ErrorCode::BackendFailure:
        return JobRunner::tr("A geometry or image library failed on this case.");
    case ErrorCode::Internal:
        break;
    }
    return JobRunner::tr("An internal error stopped the job.");
}

JobRunner::JobRunner(QObject* parent) : QObject(parent) {
    qRegisterMetaType<hs::Error>();
}

JobRunner::~JobRunner() {
    for (auto& job : m_jobs) {
        job->progress->requestCancel();
        job->watcher.disconnect(this);
        job->watcher.waitForFinished();
    }
}

QString JobRunner::title() const {
    return m_current ? m_current->title : QString();
}

void JobRunner::launch(std::unique_ptr<Job> job, std::function<void(Progress&)> body) {
    if (m_current) {
        m_current->progress->requestCancel(); // its result is dropped when it ends
        m_current->sinceCancel.start();
    }
    Job* raw = job.get();
    // The stage reports on worker threads; the promise carries the reports to the GUI thread, coalesced. The
    // Progress itself lives as long as the job, so cancel() can reach the stage that checks it.
    auto promiseSlot = std::make_shared<std::atomic<QPromise<void>*>>(nullptr);
    raw->progress = std::make_shared<Progress>([promiseSlot](std::string_view key, double fraction) {
        if (QPromise<void>* promise = promiseSlot->load())
            promise->setProgressValueAndText(static_cast<int>(std::lround(fraction * kProgressSteps)),
                                             QString::fromUtf8(key.data(), static_cast<qsizetype>(key.size())));
    });
    connect(&raw->watcher, &QFutureWatcher<void>::finished, this, [this, raw] { onJobFinished(raw); });
    connect(&raw->watcher, &QFutureWatcher<void>::progressTextChanged, this,
            [this, raw](const QString& key) { onJobProgress(raw, raw->watcher.progressValue(), key); });
    connect(&raw->watcher, &QFutureWatcher<void>::progressValueChanged, this,
            [this, raw](int value) { onJobProgress(raw, value, raw->watcher.progressText()); });
    m_current = raw;
    m_jobs.push_back(std::move(job));

    raw->watcher.setFuture(
        QtConcurrent::run([progress = raw->progress, promiseSlot, body = std::move(body)](QPromise<void>& promise) {
            promise.setProgressRange(0, kProgressSteps);
            promiseSlot->store(&promise);
            body(*progress);
            promiseSlot->store(nullptr);
        }));
    emit started(raw->title);
}

void JobRunner::onJobProgress(Job* job, int value, const QString& key) {
    if (job != m_current)
        return;
    emit progressChanged(double(value) / kProgressSteps, key);
}

void JobRunner::cancel() {
    if (!m_current || m_current->progress->cancelled())
        return;
    m_current->sinceCancel.start();
    m_current->progress->requestCancel();
}

bool JobRunner::waitForIdle(int timeoutMs) {
    QDeadlineTimer deadline(timeoutMs);
    while (!m_jobs.empty()) {
        if (deadline.hasExpired())
            return false;
        QCoreApplication::processEvents(QEventLoop::AllEvents, 10);
        QThread::msleep(1);
    }
    return true;
}

void JobRunner::onJobFinished(Job* job) {
    const auto it = std::find_if(m_jobs.begin(), m_jobs.end(), [job](const auto& j) { return j.get() == job; });
    if (it == m_jobs.end())
        return;
    std::unique_ptr<Job> done = std::move(*it);
    m_jobs.erase(it);
    const bool current = done.get() == m_current;
    if (current)
        m_current = nullptr;
    const QString title = done->title;
    if (!current) {
        // Replaced by a newer job: nothing of it reaches the document.
    } else if (done->progress->cancelled()) {
        emit cancelled(title, done->sinceCancel.isValid() ? double(done->sinceCancel.nsecsElapsed()) / 1e6 : 0.0);
    } else if (m_revision && m_revision() != done->revision) {
        emit discarded(title);
    } else if (auto error = done->deliver()) {
        if (error->code == ErrorCode::Cancelled)
            emit cancelled(title, 0.0);
        else
            emit failed(title, *error);
    } else {
        emit succeeded(title);
    }
    if (!m_current)
        emit idle();
}

} // namespace hs::widgets
