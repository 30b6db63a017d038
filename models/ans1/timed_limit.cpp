#include "models/ans1/timed_limit.hpp"

namespace hilrig::models::ans1 {

bool TimedLimit::step(bool calc, std::uint16_t p, Nanos now, TimerType type, std::uint16_t timer_ms,
                      bool retrigger_restarts, Nanos timer_error) {
  if (timer_ms == 0) {
    reset();
    previous_calc_ = calc;
    return calc;
  }
  const bool rising = calc && !previous_calc_;
  previous_calc_ = calc;
  const Nanos limit = milliseconds(timer_ms) + timer_error;
  limit_ = limit;

  if (type == TimerType::TimeOrPosition) {
    if (rising) {
      running_ = true;
      expired_ = false;
      start_ = now;
    }
    if (running_ && now - start_ >= limit) {
      running_ = false;
      expired_ = true;
    }
    if (!calc) { // To reached: the output is off by position, not by time
      running_ = false;
      expired_ = false;
    }
    return calc && !expired_;
  }

  // Time-Only
  if (rising) {
    if (running_) {
      hold_ = true;
      hold_position_ = p;
      if (retrigger_restarts) {
        start_ = now;
      }
    } else {
      running_ = true;
      expired_ = false;
      start_ = now;
    }
  }
  if (hold_ && p != hold_position_) {
    hold_ = false;
  }
  if (running_ && now - start_ >= limit) {
    running_ = false;
    expired_ = true;
    hold_ = false;
  }
  return running_ && !hold_;
}

} // namespace hilrig::models::ans1
