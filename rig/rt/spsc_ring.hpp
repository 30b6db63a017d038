#pragma once
// Lock-free single-producer/single-consumer ring: how the RT loop hands samples to the
// non-RT side without a lock or an allocation. Capacity is fixed at construction (a
// power of two); push() fails rather than blocks when the consumer falls behind.

#include <atomic>
#include <cstddef>
#include <memory>
#include <new>
#include <stdexcept>

namespace hilrig::rig {

template <typename T> class SpscRing {
public:
  explicit SpscRing(std::size_t capacity) : mask_(capacity - 1), slots_(std::make_unique<T[]>(capacity)) {
    if (capacity < 2 || (capacity & (capacity - 1)) != 0) {
      throw std::invalid_argument("SpscRing: capacity must be a power of two >= 2");
    }
  }

  // Producer side only. False when full (the caller counts the loss).
  bool push(const T& item) noexcept {
    const std::size_t head = head_.load(std::memory_order_relaxed);
    if (head - tail_cache_ > mask_) {
      tail_cache_ = tail_.load(std::memory_order_acquire);
      if (head - tail_cache_ > mask_) return false;
    }
    slots_[head & mask_] = item;
    head_.store(head + 1, std::memory_order_release);
    return true;
  }

  // Consumer side only. False when empty.
  bool pop(T& out) noexcept {
    const std::size_t tail = tail_.load(std::memory_order_relaxed);
    if (tail == head_cache_) {
      head_cache_ = head_.load(std::memory_order_acquire);
      if (tail == head_cache_) return false;
    }
    out = slots_[tail & mask_];
    tail_.store(tail + 1, std::memory_order_release);
    return true;
  }

  [[nodiscard]] std::size_t capacity() const noexcept { return mask_ + 1; }

private:
  // Producer and consumer indices on separate cache lines so they do not false-share.
  static constexpr std::size_t kLine = 64;
  const std::size_t mask_;
  std::unique_ptr<T[]> slots_;
  alignas(kLine) std::atomic<std::size_t> head_{0};
  std::size_t tail_cache_ = 0; // producer's view of tail_
  alignas(kLine) std::atomic<std::size_t> tail_{0};
  std::size_t head_cache_ = 0; // consumer's view of head_
};

} // namespace hilrig::rig
