#include "Parallel.h"

#include <algorithm>
#include <thread>
#include <vector>

namespace hs::texture::detail {

int threadCount(int requested) {
    if (requested > 0)
        return requested;
    const unsigned hw = std::thread::hardware_concurrency();
    return hw == 0 ? 1 : static_cast<int>(std::min(hw, 64u));
}

void parallelRanges(int count, int threads, const std::function<void(int, int)>& body) {
    if (count <= 0)
        return;
    const int n = std::max(1, std::min(threads, count));
    if (n == 1) {
        body(0, count);
        return;
    }
    std::vector<std::thread> workers;
    workers.reserve(static_cast<std::size_t>(n - 1));
    for (int t = 1; t < n; ++t) {
        const int begin = static_cast<int>(static_cast<long long>(count) * t / n);
        const int end = static_cast<int>(static_cast<long long>(count) * (t + 1) / n);
        workers.emplace_back([&body, begin, end] { body(begin, end); });
    }
    body(0, static_cast<int>(static_cast<long long>(count) / n));
    for (auto& w : workers)
        w.join();
}

} // namespace hs::texture::detail
