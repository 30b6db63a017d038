#pragma once
// Timed limit switches (spec §4.7). The timer starts on the advanced From edge (the rising
// edge of the pair state). Time-or-Position turns off at the first of expiry and To;
// Time-Only ignores To and turns off at expiry. A Time-Only From edge that comes again
// before expiry turns the output off for one count, then on again with the timer restarted
// ([MODEL], A39). Expiry is evaluated at each scan against the exact start time.
#include <cstdint>

#include "core/time.hpp"
#include "models/ans1/output_setup.hpp"

namespace hilrig::models::ans1 {

class TimedLimit {
public:
  // The output for this scan, given the pair state `calc` at limit-switch position p.
  // The timer expires timer_ms + timer_error after its start (timer_error: a detection-power
  // knob, params.hpp).
  bool step(bool calc, std::uint16_t p, Nanos now, TimerType type, std::uint16_t timer_ms,
            bool retrigger_restarts = true, Nanos timer_error = Nanos{0});
  // True while the output is held off because its timer expired (DA16 w16 bit reads 0).
  [[nodiscard]] bool expired() const { return expired_; }
  // A Time-Only re-trigger holds the output off at one position: any count change matters.
  [[nodiscard]] bool holding() const { return hold_; }
  void reset() { *this = TimedLimit{}; }
  // When a running timer expires (the first step at or after it changes the state); max when
  // none runs. What scan skipping wakes for: the limit the last step judged against, so the
  // deadline and the expiry are one computation (a reprogrammed timer wakes the scan anyway).
  [[nodiscard]] Nanos expiry() const { return running_ ? start_ + limit_ : Nanos::max(); }

private:
  Nanos start_{};
  Nanos limit_{}; // timer_ms + timer_error at the last step
  bool previous_calc_ = false;
  bool running_ = false;
  bool expired_ = false;
  bool hold_ = false; // Time-Only re-trigger: off until the position moves one count
  std::uint16_t hold_position_ = 0;
  friend bool operator==(const TimedLimit&, const TimedLimit&) = default;
};

} // namespace hilrig::models::ans1
