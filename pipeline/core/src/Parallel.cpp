#include "hs/core/Parallel.h"

#include <condition_variable>
#include <mutex>

namespace hs {

struct WorkerTeam::Shared {
    std::mutex mutex;
    std::condition_variable wake, done;
    std::atomic<std::uint64_t> generation{0}; ///< a new run, or (with stop) the end
    bool stop = false;
    // The run: its loop and the next chunk to take.
    std::size_t n = 0, chunk = 1, chunks = 0;
    void* fn = nullptr;
    Call call = nullptr;
    std::atomic<std::size_t> next{0};
    std::atomic<int> busy{0}; ///< helpers still in the run
};

namespace {
/// A helper spins this many rounds for the next run before it blocks (a physics step's passes follow each other
/// within microseconds; between steps it sleeps).
constexpr int kSpinRounds = 4000;
} // namespace

WorkerTeam::WorkerTeam(int threads) : m_shared(std::make_unique<Shared>()) {
    const int helpers = std::max(threads, 1) - 1;
    for (int i = 0; i < helpers; ++i)
        m_helpers.emplace_back([this] { helper(); });
}

WorkerTeam::~WorkerTeam() {
    {
        std::lock_guard<std::mutex> lock(m_shared->mutex);
        m_shared->stop = true;
        m_shared->generation.fetch_add(1, std::memory_order_release);
    }
    m_shared->wake.notify_all();
    for (auto& t : m_helpers)
        t.join();
}

void WorkerTeam::work() {
    Shared& s = *m_shared;
    for (;;) {
        const std::size_t c = s.next.fetch_add(1, std::memory_order_relaxed);
        if (c >= s.chunks)
            return;
        s.call(s.fn, c, c * s.chunk, std::min(s.n, (c + 1) * s.chunk));
    }
}

void WorkerTeam::helper() {
    Shared& s = *m_shared;
    std::uint64_t seen = 0;
    for (;;) {
        // Wait for a new generation: spin a little, then block.
        std::uint64_t g = s.generation.load(std::memory_order_acquire);
        for (int r = 0; g == seen && r < kSpinRounds; ++r) {
            std::this_thread::yield();
            g = s.generation.load(std::memory_order_acquire);
        }
        if (g == seen) {
            std::unique_lock<std::mutex> lock(s.mutex);
            s.wake.wait(lock, [&] { return s.generation.load(std::memory_order_acquire) != seen; });
            g = s.generation.load(std::memory_order_acquire);
        }
        seen = g;
        {
            std::lock_guard<std::mutex> lock(s.mutex);
            if (s.stop)
                return;
        }
        work();
        if (s.busy.fetch_sub(1, std::memory_order_acq_rel) == 1) {
            std::lock_guard<std::mutex> lock(s.mutex);
            s.done.notify_one();
        }
    }
}

void WorkerTeam::dispatch(std::size_t n, std::size_t chunk, void* fn, Call call) {
    Shared& s = *m_shared;
    {
        std::lock_guard<std::mutex> lock(s.mutex);
        s.n = n;
        s.chunk = chunk;
        s.chunks = chunkCount(n, chunk);
        s.fn = fn;
        s.call = call;
        s.next.store(0, std::memory_order_relaxed);
        s.busy.store(static_cast<int>(m_helpers.size()), std::memory_order_relaxed);
        s.generation.fetch_add(1, std::memory_order_release);
    }
    s.wake.notify_all();
    work();
    // The helpers finish their chunks (each takes part in every run, if only to find none left).
    for (int r = 0; s.busy.load(std::memory_order_acquire) != 0 && r < kSpinRounds; ++r)
        std::this_thread::yield();
    if (s.busy.load(std::memory_order_acquire) != 0) {
        std::unique_lock<std::mutex> lock(s.mutex);
        s.done.wait(lock, [&] { return s.busy.load(std::memory_order_acquire) == 0; });
    }
}

} // namespace hs
