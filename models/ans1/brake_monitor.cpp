#include "models/ans1/brake_monitor.hpp"

#include <cstdlib>

namespace hilrig::models::ans1 {

namespace {
[[nodiscard]] std::int64_t whole_ms(Nanos d) { return d / milliseconds(1); }
// A time at its limit is within it; a limit of 0 disables the check [MODEL A44].
[[nodiscard]] bool over_limit(std::int64_t time_ms, std::uint16_t limit_ms) {
  return limit_ms != 0 && time_ms > limit_ms;
}
} // namespace

void BrakeMonitor::configure(const BrakeSetup& setup, std::optional<bool> released_now) {
  const bool same_input = primed_ && setup.input == setup_.input;
  setup_ = setup;
  phase_ = Phase::Idle;
  if (setup.input == 0) {
    primed_ = false;
    status_ = BrakeStatus{};
    start_fault_ = false;
    stop_fault_ = false;
    return;
  }
  if (same_input) return; // the ticks go on sampling the same input
  // An inactive->active transition after the monitor is programmed is a release (L1054,
  // L2614): compare the first tick with the level now, not with the first tick's own.
  primed_ = released_now.has_value();
  if (released_now) released_ = *released_now;
}

void BrakeMonitor::clear_errors() {
  start_fault_ = false;
  stop_fault_ = false;
}

std::int64_t BrakeMonitor::position_ms_ago(std::int64_t ms) const {
  // history_ holds one position per tick; the newest is at index (ticks_ - 1).
  const auto index = (ticks_ - 1 - static_cast<std::uint64_t>(ms)) % kHistory;
  return history_[static_cast<std::size_t>(index)];
}

void BrakeMonitor::tick(Nanos now, bool released, std::int64_t pos4096, std::uint16_t gmp) {
  history_[static_cast<std::size_t>(ticks_ % kHistory)] = pos4096;
  ++ticks_;
  if (setup_.input == 0) return;
  if (!primed_) {
    primed_ = true;
    released_ = released;
    return;
  }
  const bool was_released = released_;
  released_ = released;
  const bool release_edge = !was_released && released;
  const bool apply_edge = was_released && !released;

  switch (phase_) {
  case Phase::Idle:
    if (release_edge) {
      phase_ = Phase::Starting;
      t0_ = now;
      overrun_tripped_ = false;
      start_pos_ = pos4096;
      status_.released_position = gmp;
    } else if (apply_edge) {
      begin_debounce(now, gmp);
    }
    break;
  case Phase::Starting:
    if (apply_edge) {
      // Applied again before the press moved: that start is abandoned [MODEL].
      begin_debounce(now, gmp);
    } else if (std::llabs(pos4096 - start_pos_) > 2 * static_cast<std::int64_t>(setup_.complete_stop_count)) {
      finish_start(whole_ms(now - t0_));
    } else {
      still_starting(whole_ms(now - t0_));
    }
    break;
  case Phase::Debouncing:
    sample(now, released, gmp);
    break;
  case Phase::Stopping: {
    // The input is ignored until the cycle ends (L1041). Sliding 125 ms window, evaluated
    // every tick once a whole window lies after the application [MODEL A10].
    const std::int64_t elapsed = whole_ms(now - t0_);
    if (elapsed >= kStopWindowMs &&
        std::llabs(pos4096 - position_ms_ago(kStopWindowMs)) < setup_.complete_stop_count) {
      finish_stop(elapsed);
    } else {
      still_stopping(elapsed);
    }
    break;
  }
  }
}

void BrakeMonitor::begin_debounce(Nanos now, std::uint16_t gmp) {
  phase_ = Phase::Debouncing;
  t0_ = now;
  overrun_tripped_ = false;
  pending_applied_position_ = gmp;
  next_sample_ = now + sample_start_;
  samples_taken_ = 0;
  active_samples_ = 0;
  inactive_samples_ = 0;
}

void BrakeMonitor::sample(Nanos now, bool released, std::uint16_t gmp) {
  while (phase_ == Phase::Debouncing && next_sample_ <= now) debounce(next_sample_, released, gmp);
}

void BrakeMonitor::debounce(Nanos at, bool released, std::uint16_t gmp) {
  bool noise = false;
  // 16 samples 1 ms apart from sample_start_ after the edge (16..31 ms, L1039), the decision
  // 1 ms after the last (32 ms, L1040); "8 of 16" counted cumulatively [MODEL A9].
  if (samples_taken_ < kSamples) {
    ++samples_taken_;
    next_sample_ = at + kTick;
    if (released) {
      noise = ++active_samples_ >= kNoiseActiveSamples;
    } else {
      ++inactive_samples_;
    }
  } else {
    if (inactive_samples_ >= kQualifyInactiveSamples) {
      phase_ = Phase::Stopping;
      return;
    }
    noise = true;
  }
  if (!noise) return;
  ++status_.noise_rejections;
  if (!released) {
    begin_debounce(at, gmp); // still applied: restart at once, re-timing t0 [MODEL A9]
  } else {
    phase_ = Phase::Idle; // wait for the next 1->0 edge
  }
}

void BrakeMonitor::still_starting(std::int64_t elapsed_ms) {
  // No motion yet: the start time is already longer than elapsed_ms, so an overrun is certain
  // now, not only when the press finally moves (a press that never moves must still trip).
  // Tripped once per cycle, so Clear Errors holds until the cycle ends and is judged again.
  if (!overrun_tripped_ && over_limit(elapsed_ms, setup_.start_time_limit_ms)) {
    overrun_tripped_ = true;
    start_fault_ = !never_faults_;
  }
  // L2616 [A8]: a start time over 32,767 ms is recorded as 32,768 once it is that long.
  if (elapsed_ms > 32767) status_.start_time_ms = kStartTimeOverflow;
}

void BrakeMonitor::still_stopping(std::int64_t elapsed_ms) {
  // No standstill at elapsed_ms: the earliest standstill is one tick later, whose net stop time
  // (L1052) is elapsed_ms + 1 - 125. Once that is over the limit the overrun is certain, so a
  // brake that fails to stop a turning press trips here instead of waiting for standstill.
  if (!overrun_tripped_ && over_limit(elapsed_ms + 1 - kStopWindowMs, setup_.stop_time_limit_ms)) {
    overrun_tripped_ = true;
    stop_fault_ = !never_faults_;
  }
}

void BrakeMonitor::finish_start(std::int64_t elapsed_ms) {
  phase_ = Phase::Idle;
  status_.start_time_ms = elapsed_ms > 32767 ? kStartTimeOverflow : static_cast<std::uint16_t>(elapsed_ms);
  ++status_.completed_starts;
  // A limit of 0 disables the check [MODEL A44]; a start within limit clears the fault [MODEL A44].
  start_fault_ = over_limit(elapsed_ms, setup_.start_time_limit_ms) && !never_faults_;
}

void BrakeMonitor::finish_stop(std::int64_t elapsed_ms) {
  phase_ = Phase::Idle;
  const std::int64_t net = elapsed_ms - kStopWindowMs; // L1052; limit compared with net [MODEL A44]
  status_.stop_time_ms = net > 32767 ? kStartTimeOverflow : static_cast<std::uint16_t>(net);
  status_.applied_position = pending_applied_position_;
  ++status_.completed_stops;
  stop_fault_ = over_limit(net, setup_.stop_time_limit_ms) && !never_faults_;
}

} // namespace hilrig::models::ans1
