#pragma once
// Sending a run of frames with as few syscalls as the transmit queue allows: sendmmsg(2)
// queues up to a batch at a time and may queue only part of it; a full queue (EAGAIN,
// ENOBUFS) is waited out until the deadline, and the frames not yet queued are retried from
// the first one the kernel did not take, so the frames go out once each and in order.
// The syscalls are the caller's (two callables), which is what lets this logic be tested
// without a kernel. No allocation, no clock read of its own.

#include <algorithm>
#include <cerrno>
#include <cstddef>
#include <cstdint>

namespace hilrig::socketcan {

enum class SendStatus : std::uint8_t { Sent, DeadlineMissed, BusOff, Failed };

struct BatchSent {
  std::size_t sent = 0;                 // frames [0, sent) were queued, in order
  SendStatus status = SendStatus::Sent; // Sent when every frame was; else why the rest were not
  int error = 0;                        // the errno that stopped it (0 when all were sent)
};

// `send_many(first, count)` queues frames [first, first + count) and returns how many it
// queued (1..count) or -errno when it queued none; `wait_for_room()` waits until the queue
// may take a frame and returns false once the deadline has passed.
template <typename SendMany, typename WaitForRoom>
BatchSent send_in_batches(std::size_t total, std::size_t batch, SendMany&& send_many,
                          WaitForRoom&& wait_for_room) noexcept {
  BatchSent r;
  while (r.sent < total) {
    const std::size_t count = std::min(batch, total - r.sent);
    const long n = send_many(r.sent, count);
    if (n > 0) {
      r.error = 0;
      r.sent += static_cast<std::size_t>(std::min<long>(n, static_cast<long>(count)));
      continue;
    }
    const int err = n == 0 ? EAGAIN : static_cast<int>(-n); // none queued and no error: the queue is full
    if (err == EINTR) continue;
    r.error = err;
    if (err == ENETDOWN) { // the controller took itself off the bus
      r.status = SendStatus::BusOff;
      return r;
    }
    if (err != EAGAIN && err != ENOBUFS) {
      r.status = SendStatus::Failed;
      return r;
    }
    if (!wait_for_room()) {
      r.status = SendStatus::DeadlineMissed;
      return r;
    }
  }
  return r;
}

} // namespace hilrig::socketcan
