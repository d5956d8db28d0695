#include "hs/core/Progress.h"

#include <algorithm>

namespace hs {

Progress& Progress::none() {
    static Progress instance{NoneTag{}};
    return instance;
}

void Progress::report(std::string_view stageKey, double fraction) {
    if (m_isNone)
        return;
    const double f = std::clamp(fraction, 0.0, 1.0);
    m_last.store(f, std::memory_order_relaxed);
    if (m_callback)
        m_callback(stageKey, f);
    if (m_parent)
        m_parent->report(stageKey, m_begin + (m_end - m_begin) * f);
}

void Progress::requestCancel() noexcept {
    if (!m_isNone)
        m_cancel.store(true, std::memory_order_relaxed);
}

bool Progress::cancelled() const noexcept {
    if (m_cancel.load(std::memory_order_relaxed))
        return true;
    return m_parent != nullptr && m_parent->cancelled();
}

Status Progress::check(std::string_view what, std::string_view during) const {
    if (!cancelled())
        return {};
    std::string detail = std::string(what) + " cancelled";
    if (!during.empty())
        detail += " while " + std::string(during);
    return fail(ErrorCode::Cancelled, std::move(detail));
}

} // namespace hs
