#include "core/clock.hpp"

#include <ctime>
#include <stdexcept>

namespace hilrig {

void VirtualClock::advance_to(Nanos t) {
  if (t < now_) {
    throw std::logic_error("VirtualClock: time cannot go backwards");
  }
  now_ = t;
}

Nanos MonotonicClock::now() const {
  timespec ts{};
  clock_gettime(CLOCK_MONOTONIC, &ts);
  return Nanos{static_cast<std::int64_t>(ts.tv_sec) * 1'000'000'000 + ts.tv_nsec};
}

} // namespace hilrig
