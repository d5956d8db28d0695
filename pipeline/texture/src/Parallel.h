#pragma once
/// Deterministic parallel loops: work is split into fixed contiguous ranges, and callers make each item a pure
/// function of its inputs, so results never depend on the number of threads.

#include <functional>

namespace hs::texture::detail {

/// Number of worker threads for `requested` (<= 0: hardware concurrency), at least 1.
int threadCount(int requested);

/// Calls body(begin, end) on disjoint ranges covering [0, count) from up to `threads` threads; returns when all are
/// done. Exceptions must not escape `body`.
void parallelRanges(int count, int threads, const std::function<void(int begin, int end)>& body);

} // namespace hs::texture::detail
