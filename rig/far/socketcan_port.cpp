#include "rig/far/socketcan_port.hpp"

#include <time.h>

#include <algorithm>

#include "core/clock.hpp"

namespace hilrig::far {

namespace {

// CLOCK_REALTIME, the clock SocketCAN stamps received frames with (SO_TIMESTAMPING, software).
Nanos realtime_now() {
  timespec ts{};
  ::clock_gettime(CLOCK_REALTIME, &ts);
  return Nanos{static_cast<std::int64_t>(ts.tv_sec) * 1'000'000'000 + ts.tv_nsec};
}

} // namespace

SocketCanPort::SocketCanPort(Scheduler& scheduler, const std::string& interface)
    : scheduler_(scheduler), socket_(interface) {}

void SocketCanPort::send(const CanFrame& frame) {
  // The far side never blocks on a full transmit queue: a frame that cannot go now is lost.
  if (socket_.send(frame, MonotonicClock{}.now()) != socketcan::SendStatus::Sent) ++send_failures_;
}

std::size_t SocketCanPort::poll(Nanos t) {
  std::size_t n = 0;
  const Nanos now_realtime = realtime_now();
  while (const auto r = socket_.receive()) {
    if (r->is_error) {
      ++error_frames_;
      tracker_.apply(r->error);
      continue;
    }
    ++frames_;
    ++n;
    const Nanos age = std::max(Nanos{0}, now_realtime - r->timestamp);
    const Nanos at = std::clamp(t - age, scheduler_.now(), std::max(t, scheduler_.now()));
    scheduler_.at(at, [this, frame = r->frame, at] { deliver(frame, at); });
  }
  return n;
}

void SocketCanPort::deliver(const CanFrame& frame, Nanos at) const {
  for (const CanReceiveHandler& h : handlers_) h(frame, at);
}

} // namespace hilrig::far
