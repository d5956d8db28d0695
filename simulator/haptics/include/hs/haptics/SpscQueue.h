#pragma once
/// A bounded lock-free queue for one producer thread and one consumer thread (a ring of atomic indices;
/// Lamport's single-producer single-consumer buffer). The haptics loop pushes device samples, the physics pops them.

#include <atomic>
#include <cstddef>
#include <vector>

namespace hs::haptics {

template <class T>
class SpscQueue {
public:
    /// Holds up to `capacity` items (rounded up to a power of two, at least 2).
    explicit SpscQueue(std::size_t capacity) {
        std::size_t n = 2;
        while (n < capacity)
            n *= 2;
        m_items.resize(n);
        m_mask = n - 1;
    }
    SpscQueue(const SpscQueue&) = delete;
    SpscQueue& operator=(const SpscQueue&) = delete;

    std::size_t capacity() const { return m_items.size(); }

    /// Producer: false (the item dropped) when full.
    bool push(const T& item) {
        const std::size_t tail = m_tail.load(std::memory_order_relaxed);
        if (tail - m_head.load(std::memory_order_acquire) == m_items.size())
            return false;
        m_items[tail & m_mask] = item;
        m_tail.store(tail + 1, std::memory_order_release);
        return true;
    }

    /// Consumer: false when empty.
    bool pop(T& out) {
        const std::size_t head = m_head.load(std::memory_order_relaxed);
        if (head == m_tail.load(std::memory_order_acquire))
            return false;
        out = m_items[head & m_mask];
        m_head.store(head + 1, std::memory_order_release);
        return true;
    }

    /// Either side: items waiting (a snapshot).
    std::size_t size() const { return m_tail.load(std::memory_order_acquire) - m_head.load(std::memory_order_acquire); }

private:
    static constexpr std::size_t kLine = 64; // keep the two indices on separate cache lines
    std::vector<T> m_items;
    std::size_t m_mask = 0;
    alignas(kLine) std::atomic<std::size_t> m_head{0};
    alignas(kLine) std::atomic<std::size_t> m_tail{0};
};

} // namespace hs::haptics
