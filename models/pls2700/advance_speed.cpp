#include "models/pls2700/advance_speed.hpp"

#include <algorithm>
#include <cmath>

namespace hilrig::models::pls2700 {

AdvanceSpeed::AdvanceSpeed(int updates, Nanos period)
    : steps_(static_cast<std::size_t>(std::max(updates, 1)), 0),
      period_ms_(static_cast<double>(period.count()) / 1e6) {}

void AdvanceSpeed::add(int step) {
  if (count_ == steps_.size()) {
    sum_ -= steps_[head_];
  } else {
    ++count_;
  }
  steps_[head_] = step;
  sum_ += step;
  head_ = (head_ + 1) % steps_.size();
  // The window's count against the used speed over the same time: a difference below two
  // steps is the count's own quantisation (floor or ceil of the true motion), not a change.
  // A window without motion is standstill.
  const double window_ms = static_cast<double>(count_) * period_ms_;
  if (sum_ == 0 || count_ == 1 || std::abs(static_cast<double>(sum_) - used_ * window_ms) >= 2.0) {
    used_ = static_cast<double>(sum_) / window_ms;
  }
}

void AdvanceSpeed::reset() {
  // The ring is not cleared: add() reads a slot only once the window is full, and by then it
  // has written every slot since this reset. Clearing 1,000 of them at every update of a
  // faulted transducer was a tenth of a faulted run's time.
  head_ = 0;
  count_ = 0;
  sum_ = 0;
  used_ = 0.0;
}

int advance_window_updates(Nanos window, Nanos period) {
  const auto n = (window.count() + period.count() - 1) / period.count();
  return static_cast<int>(std::max<std::int64_t>(n, 1));
}

} // namespace hilrig::models::pls2700
