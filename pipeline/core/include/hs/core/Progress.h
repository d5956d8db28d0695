#pragma once
/// Progress reporting and cooperative cancellation for long stages.

#include "hs/core/Result.h"

#include <atomic>
#include <functional>
#include <string>
#include <string_view>

namespace hs {

/// A stage reports `report("meshing.relax", 0.4)` and checks `cancelled()` in its loops (often enough that a
/// cancel takes effect within 100 ms). Thread-safe: report() and cancelled() may be called from worker threads;
/// the callback runs on the calling thread and must be cheap (the GUI posts it to its own thread).
class Progress {
public:
    /// stageKey: dotted, stable key of the step ("meshing.relax"); fraction in [0, 1] of the whole task.
    using Callback = std::function<void(std::string_view stageKey, double fraction)>;

    Progress() = default;
    explicit Progress(Callback callback) : m_callback(std::move(callback)) {}
    Progress(const Progress&) = delete;
    Progress& operator=(const Progress&) = delete;

    /// A shared no-op instance: reports go nowhere and it is never cancelled.
    static Progress& none();

    /// Reports `fraction` (clamped to [0, 1]) of the current range, mapped into the parent's range.
    void report(std::string_view stageKey, double fraction);

    /// Asks the running stage to stop; it returns ErrorCode::Cancelled at its next check.
    void requestCancel() noexcept;
    bool cancelled() const noexcept;
    /// Ok, or ErrorCode::Cancelled with "<what> cancelled" (+ " while <during>" when given) once cancelled:
    /// `HS_TRY(progress.check("meshing", "relaxing particles"));`.
    [[nodiscard]] Status check(std::string_view what, std::string_view during = {}) const;

    /// The last fraction reported (in this object's own [0, 1] scale).
    double fraction() const noexcept { return m_last.load(std::memory_order_relaxed); }

    /// A child whose [0, 1] maps onto [begin, end] of this one; cancelling either cancels the child's checks.
    /// `observer`, when given, also gets the child's reports on the child's own scale (before the parent does).
    class Sub;
    Sub sub(double begin, double end, Callback observer = {});

private:
    friend class Sub;
    struct NoneTag {};
    explicit Progress(NoneTag) : m_isNone(true) {}

    Callback m_callback;
    Progress* m_parent = nullptr;
    double m_begin = 0.0;
    double m_end = 1.0;
    bool m_isNone = false;
    std::atomic<bool> m_cancel{false};
    std::atomic<double> m_last{0.0};
};

class Progress::Sub : public Progress {
public:
    Sub(Progress& parent, double begin, double end, Callback observer = {}) {
        m_parent = &parent;
        m_begin = begin;
        m_end = end;
        m_callback = std::move(observer);
    }
};

inline Progress::Sub Progress::sub(double begin, double end, Callback observer) {
    return Sub(*this, begin, end, std::move(observer));
}

} // namespace hs
