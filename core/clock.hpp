#pragma once
// One clock interface, two clocks: virtual (owned by the Scheduler, deterministic) and
// monotonic (CLOCK_MONOTONIC, on a rig).

#include "core/time.hpp"

namespace hilrig {

class Clock {
public:
  virtual ~Clock() = default;
  [[nodiscard]] virtual Nanos now() const = 0;
};

// Advanced only by its owner (the Scheduler); never goes backwards.
class VirtualClock final : public Clock {
public:
  explicit VirtualClock(Nanos start = Nanos{0}) : now_(start) {}
  [[nodiscard]] Nanos now() const override { return now_; }
  void advance_to(Nanos t);

private:
  Nanos now_;
};

class MonotonicClock final : public Clock {
public:
  [[nodiscard]] Nanos now() const override;
};

} // namespace hilrig
