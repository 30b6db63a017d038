// The six modes' rules (digest §3.1-3.6), driven by the input edges at the instant they
// arrive; what the host and the Cycle Output see follows one throughput later (defer()).
#include <algorithm>

#include "models/amci4501/amci4501.hpp"

namespace hilrig::models::amci4501 {

namespace {
std::array<std::uint16_t, 2> split(std::uint64_t value) {
  const SplitWords s = split_thousands(value);
  return {s.upper, s.lower};
}
} // namespace

void Amci4501::start_edge(bool now_active, Nanos t) {
  switch (config_.mode) {
  case 1: // §3.1: Start's active edge starts a registration cycle (L7, L225)
  case 3: // §3.3: ... or a timing (L26)
    if (!now_active || phase_ != Phase::Idle || timeout_error_) return;
    phase_ = Phase::Running;
    p_start_ = decoder_.count();
    t_start_ = tick(t);
    arm_timeout(t);
    if (config_.mode == 1) defer(t, Op::CycleOutput, true); // on while counting (L7)
    return;
  case 4:
    if (now_active) mode4_start(t);
    return;
  case 5:
  case 6:
    break;
  default:
    return;
  }
  // Modes 5 and 6 (§3.5, §3.6): Start's active interval -> words 1-2 (mode 5) / word 1 (6).
  if (now_active) {
    seen_active_[0] = true;
    on_tick_[0] = tick(t);
    on_position_[0] = decoder_.count();
    return;
  }
  if (!seen_active_[0]) return; // active before the mode began: no measurement
  seen_active_[0] = false;
  if (config_.mode == 5) {
    defer(t, Op::Write, false, 1, split(time_value(on_tick_[0], tick(t))));
  } else {
    const std::array<std::uint16_t, 1> w{mode6_count(decoder_.count() - on_position_[0])};
    defer(t, Op::Write, false, 1, w);
  }
}

void Amci4501::latch_edge(bool now_active, Nanos t) {
  switch (config_.mode) {
  case 1:
  case 3: {
    if (!now_active || phase_ != Phase::Running) return; // Latch outside a cycle: ignored
    phase_ = Phase::Idle;
    cancel_timeout();
    if (config_.mode == 1) {
      // Net signed count (A11); the word holds it modulo 2^16, 0..65,535 (L7).
      const std::int64_t counts = decoder_.count() - p_start_;
      if (counts < 0 || counts > 65535) ++overflows_;
      defer(t, Op::CycleOutput, false);
      const std::array<std::uint16_t, 1> w{static_cast<std::uint16_t>(counts)};
      defer(t, Op::Publish, false, 1, w);
    } else {
      defer(t, Op::Publish, false, 1, split(time_value(t_start_, tick(t))));
    }
    return;
  }
  case 2:
    if (!window_) return;
    if (now_active && pulses_ < 2 && !in_pulse_) { // leading edge: L1 / L3
      in_pulse_ = true;
      l_values_[static_cast<std::size_t>(2 * pulses_)] = latch_count();
      defer(t, Op::CycleOutput, true);     // the output copies the first two pulses (L12)
    } else if (!now_active && in_pulse_) { // trailing edge: L2 / L4
      in_pulse_ = false;
      l_values_[static_cast<std::size_t>(2 * pulses_ + 1)] = latch_count();
      ++pulses_;
      defer(t, Op::CycleOutput, false);
    }
    return;
  case 4:
    if (now_active) mode4_latch(t);
    return;
  case 5:
  case 6:
    break;
  default:
    return;
  }
  // Modes 5 and 6: Latch's active interval -> words 3-4 (mode 5) / word 2 (mode 6) (A22).
  if (now_active) {
    seen_active_[1] = true;
    on_tick_[1] = tick(t);
    on_position_[1] = decoder_.count();
    return;
  }
  if (!seen_active_[1]) return;
  seen_active_[1] = false;
  if (config_.mode == 5) {
    defer(t, Op::Write, false, 3, split(time_value(on_tick_[1], tick(t))));
  } else {
    const std::array<std::uint16_t, 1> w{mode6_count(decoder_.count() - on_position_[1])};
    defer(t, Op::Write, false, 2, w);
  }
}

// A mode 6 count in its word: "a maximum value of 32,767" (L117), so a longer forward count
// reads 32,767, not a negative number against its direction (L55); a reverse one stops at
// -32,768, the word's least (the negative limit is not stated, A24) [MODEL]. Either counts as
// an overflow.
std::uint16_t Amci4501::mode6_count(std::int64_t c) {
  if (c < -32768 || c > 32767) ++overflows_;
  return static_cast<std::uint16_t>(std::clamp<std::int64_t>(c, -32768, 32767));
}

// Lx = P(edge) - Son, counted from the window opening (L12); one register each, at most
// 32,767 (L115).
std::uint16_t Amci4501::latch_count() {
  const std::int64_t c = decoder_.count() - static_cast<std::int64_t>(config_.on_setpoint);
  if (c < 0 || c > 32767) ++overflows_; // A12: not representable
  if (params_.saturate_latch_counts) return static_cast<std::uint16_t>(std::clamp<std::int64_t>(c, 0, 32767));
  return static_cast<std::uint16_t>(c);
}

// Mode 2 window (§3.2, [I] A14): opens when a count-up step makes P == Son, closes when a
// count-up step makes P == Soff; membership Son <= P < Soff.
void Amci4501::mode2_position(int delta, Nanos t) {
  if (delta <= 0) return;
  const std::int64_t p = decoder_.count();
  if (!window_ && p == static_cast<std::int64_t>(config_.on_setpoint)) {
    open_window(t);
  } else if (window_ && p == static_cast<std::int64_t>(config_.off_setpoint)) {
    close_window(t);
  }
}

void Amci4501::open_window(Nanos t) {
  if (timeout_error_) return; // no new cycle while Time Out is set (L119)
  window_ = true;
  in_pulse_ = false; // a pulse already active when the window opens is not counted (A14)
  pulses_ = 0;
  l_values_ = {};
  arm_timeout(t);
}

void Amci4501::close_window(Nanos t) {
  window_ = false;
  cancel_timeout();
  if (in_pulse_) { // forced off at window end (L12, L330); its trailing value stays 0
    in_pulse_ = false;
    defer(t, Op::CycleOutput, false);
  }
  defer(t, Op::Publish, false, 1, l_values_);
}

// Mode 4 (§3.4): S1 -> L1 gives TM1, L2 -> S2 gives TM2; published at S2 only (L32, L228).
void Amci4501::mode4_start(Nanos t) {
  const std::int64_t now = tick(t);
  const bool filters = params_.fw_version >= 2 && params_.variant != Variant::Mode4FilterIgnored;
  switch (phase_) {
  case Phase::Idle: {
    if (timeout_error_) return;
    if (filters && have_s2_) {
      // Filter 2 (L42, [I] A18): the next S1 only max(TM2, 5 ms) after S2.
      const std::int64_t hold = std::max(tm2_ticks_, milliseconds(5) / params_.timer_resolution);
      if (now - t_s2_ < hold) return;
    }
    phase_ = Phase::WaitL1;
    t_start_ = now;
    arm_timeout(t);
    return;
  }
  case Phase::WaitS2: {
    phase_ = Phase::Idle;
    cancel_timeout();
    have_s2_ = true;
    t_s2_ = now;
    tm2_ticks_ = now - t_l2_;
    const auto tm1 = split(time_value(t_start_, t_l1_));
    const auto tm2 = split(time_value(t_l2_, now));
    const std::array<std::uint16_t, 4> w{tm1[0], tm1[1], tm2[0], tm2[1]};
    defer(t, Op::Publish, false, 1, w);
    return;
  }
  default: // a Start between S1 and L1, or before L2: ignored (A25)
    return;
  }
}

void Amci4501::mode4_latch(Nanos t) {
  const std::int64_t now = tick(t);
  const bool filters = params_.fw_version >= 2 && params_.variant != Variant::Mode4FilterIgnored;
  if (phase_ == Phase::WaitL1) {
    t_l1_ = now;
    tm1_ticks_ = now - t_start_;
    phase_ = Phase::WaitL2;
  } else if (phase_ == Phase::WaitL2) {
    // Filter 1 (L40, [I] A18): L2 only TM1/4 after L1 (4·dt >= TM1: exact in ticks).
    if (filters && 4 * (now - t_l1_) < tm1_ticks_) return;
    t_l2_ = now;
    phase_ = Phase::WaitS2;
  }
}

// A cycle that does not finish within the timeout (L93): Time Out set, the cycle
// abandoned, no new cycle until control bit 1 (L119). Acts at the timeout instant.
void Amci4501::on_timeout() {
  timeout_event_ = {};
  timeout_error_ = true;
  const Phase was = phase_;
  phase_ = Phase::Idle;
  end_cycle_output(); // modes 1 and 2; in the others the output is never on (L277)
  window_ = false;
  in_pulse_ = false;
  if (config_.mode == 4 && params_.fw_version >= 3) {
    // L97-102: only S1 -> 0 / 0; S1 and L1 (with or without L2) -> TM1 / 0.
    const auto tm1 = was == Phase::WaitL1 ? split(0) : split(time_value(t_start_, t_l1_));
    inputs_[1] = tm1[0];
    inputs_[2] = tm1[1];
    inputs_[3] = 0;
    inputs_[4] = 0;
    if (params_.mode4_timeout_sets_new) new_value_ = true;
  }
}

} // namespace hilrig::models::amci4501
