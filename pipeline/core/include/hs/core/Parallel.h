#pragma once
/// Deterministic parallel loops: [0, n) is cut into chunks whose size the caller fixes, so per-chunk results
/// combined in chunk order give the same bits with 1 or N threads. Loops whose items are independent of each
/// other may size the chunks by the thread count (evenChunk).

#include <algorithm>
#include <atomic>
#include <cstddef>
#include <memory>
#include <thread>
#include <type_traits>
#include <vector>

namespace hs {

/// Worker threads for `requested` (<= 0: hardware concurrency), 1..256.
inline int resolveThreads(int requested) {
    if (requested > 0)
        return std::min(requested, 256);
    const unsigned hw = std::thread::hardware_concurrency();
    return hw == 0 ? 1 : static_cast<int>(std::min(hw, 256u));
}

inline std::size_t chunkCount(std::size_t n, std::size_t chunk) {
    return (n + chunk - 1) / chunk;
}

/// The chunk size that cuts [0, n) into at most `threads` near-equal chunks (for loops whose items are independent,
/// so the cut does not change the result; each chunk then costs one pass of any per-chunk setup).
inline std::size_t evenChunk(std::size_t n, int threads) {
    const auto t = static_cast<std::size_t>(std::max(threads, 1));
    return std::max<std::size_t>(1, (n + t - 1) / t);
}

/// Calls fn(chunkIndex, begin, end) for every chunk of [0, n), on up to `threads` threads; returns when all are
/// done. Exceptions must not escape `fn`.
template <class Fn>
void parallelChunks(std::size_t n, std::size_t chunk, int threads, Fn&& fn) {
    const std::size_t chunks = chunkCount(n, chunk);
    const std::size_t workers = std::min<std::size_t>(static_cast<std::size_t>(std::max(threads, 1)), chunks);
    if (workers <= 1) {
        for (std::size_t c = 0; c < chunks; ++c)
            fn(c, c * chunk, std::min(n, (c + 1) * chunk));
        return;
    }
    std::atomic<std::size_t> next{0};
    auto work = [&] {
        for (;;) {
            const std::size_t c = next.fetch_add(1, std::memory_order_relaxed);
            if (c >= chunks)
                return;
            fn(c, c * chunk, std::min(n, (c + 1) * chunk));
        }
    };
    std::vector<std::thread> pool;
    pool.reserve(workers - 1);
    for (std::size_t t = 1; t < workers; ++t)
        pool.emplace_back(work);
    work();
    for (auto& th : pool)
        th.join();
}

} // namespace hs

namespace hs {

/// Threads kept for a loop run many times a second (a physics step's passes): parallelChunks starts and joins its
/// threads on every call, which costs tens of microseconds a pass. The team's helpers wait between runs (briefly
/// spinning, then blocked), and the calling thread takes chunks too. The chunks are the caller's, so the result is
/// the same bits with any team size. One run at a time; not for use from several threads at once.
class WorkerTeam {
public:
    /// A team of `threads` (the caller included; 1: no helper, every run is serial).
    explicit WorkerTeam(int threads);
    ~WorkerTeam();
    WorkerTeam(const WorkerTeam&) = delete;
    WorkerTeam& operator=(const WorkerTeam&) = delete;

    int size() const { return static_cast<int>(m_helpers.size()) + 1; }

    /// Calls fn(chunkIndex, begin, end) for every chunk of [0, n); returns when all are done. Exceptions must not
    /// escape `fn`.
    template <class Fn>
    void run(std::size_t n, std::size_t chunk, Fn&& fn) {
        const std::size_t chunks = chunkCount(n, chunk);
        if (m_helpers.empty() || chunks <= 1) {
            for (std::size_t c = 0; c < chunks; ++c)
                fn(c, c * chunk, std::min(n, (c + 1) * chunk));
            return;
        }
        using F = std::remove_reference_t<Fn>;
        dispatch(n, chunk, const_cast<void*>(static_cast<const void*>(&fn)),
                 [](void* f, std::size_t c, std::size_t b, std::size_t e) { (*static_cast<F*>(f))(c, b, e); });
    }

private:
    using Call = void (*)(void*, std::size_t, std::size_t, std::size_t);
    void dispatch(std::size_t n, std::size_t chunk, void* fn, Call call);
    void helper();
    void work();

    struct Shared;
    std::unique_ptr<Shared> m_shared;
    std::vector<std::thread> m_helpers;
};

} // namespace hs
