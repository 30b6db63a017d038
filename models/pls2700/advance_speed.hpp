#pragma once
// The speed that drives the advances of one channel (pls2700.md R-ADV-5 [X], model [I]).
// The manual (L409-L415) wants an output to act at the programmed position at any speed; the
// motion of a single update is quantised to whole 8192-count steps and alternates between
// adjacent counts (e.g. 8 and 9 at 300 rpm and 200 us), which moves an advanced edge by
// a_on x 1 step / T_upd per update and makes the output chatter. The model therefore sums
// the motion over a moving window of the last `window` (default 200 ms, twice the largest
// advance of 99 ms, L1393) and keeps the speed it uses until the window's count differs from
// it by two steps or more: at constant speed the used speed never changes (one ON pulse per
// pass) and is within 2 steps / window of the true speed, i.e. a 99 ms advance within one
// 8192-count step (half a count of a 4096 Scale Factor).
#include <cstdint>
#include <vector>

#include "core/time.hpp"

namespace hilrig::models::pls2700 {

class AdvanceSpeed {
public:
  // `updates` = the window in update periods (at least 1); `period` = the update period.
  AdvanceSpeed(int updates, Nanos period);
  // One update's motion in 8192-count steps.
  void add(int step);
  // No motion known (transducer fault): the window starts again.
  void reset();
  // The speed the advances use, in 8192-count steps per ms (signed).
  [[nodiscard]] double steps_per_ms() const { return used_; }

private:
  std::vector<int> steps_; // ring of the last `updates` steps
  std::size_t head_ = 0;
  std::size_t count_ = 0;
  std::int64_t sum_ = 0;
  double period_ms_;
  double used_ = 0.0;
};

// The window in updates for a window time and an update period (rounded up, at least 1).
[[nodiscard]] int advance_window_updates(Nanos window, Nanos period);

} // namespace hilrig::models::pls2700
