#pragma once
/// Deterministic parallel loops: [0, n) is cut into chunks whose size the caller fixes, so per-chunk results
/// combined in chunk order give the same bits with 1 or N threads. Loops whose items are independent of each
/// other may size the chunks by the thread count (evenChunk).

#include <algorithm>
#include <atomic>
#include <cstddef>
#include <thread>
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
