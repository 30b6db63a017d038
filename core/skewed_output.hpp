#pragma once
// A board output whose turn-off takes a different time from its turn-on: an output driver
// (opto, transistor, solid-state relay) that switches slower one way, so every ON pulse
// reaches the pin stretched or shortened by the difference. `off_skew` > 0 delays each
// turn-off by off_skew; < 0 delays each turn-on by -off_skew; 0 passes every change through at
// once. A transition the other way that comes before a delayed one completes cancels it (the
// slow edge never finishes: a pulse or gap narrower than the skew does not reach the pin).

#include <vector>

#include "core/line.hpp"
#include "core/scheduler.hpp"

namespace hilrig {

class SkewedOutput final : public LineOutput {
public:
  // `pin`, `scheduler` outlive this; `on` is the pin's level while the output is on.
  SkewedOutput(Scheduler& scheduler, LineOutput& pin, Level on, Nanos off_skew);
  SkewedOutput(const SkewedOutput&) = delete;
  SkewedOutput& operator=(const SkewedOutput&) = delete;
  ~SkewedOutput() override;

  void set(Level level) override;
  // The level last set (what the board commands), not yet necessarily at the pin.
  [[nodiscard]] Level driven() const override { return commanded_; }

private:
  struct Pending {
    Nanos time;
    Level level;
    EventId id;
  };
  void complete();

  Scheduler& scheduler_;
  LineOutput& pin_;
  Level on_;
  Nanos off_skew_;
  Level commanded_;
  std::vector<Pending> pending_; // in time order
};

} // namespace hilrig
