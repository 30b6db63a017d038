#include "models/ans1/die_protection.hpp"

#include <algorithm>

namespace hilrig::models::ans1 {

namespace {
[[nodiscard]] std::uint16_t bit(int point) { return static_cast<std::uint16_t>(1U << (point - 1)); }

// Half-open window [leading, trailing), wrapping through zero when leading > trailing, the same
// boundary rule as a setpoint pair [MODEL A17].
[[nodiscard]] bool in_window(std::uint16_t p, const DieWindow& w) {
  if (!w.used()) return false;
  if (w.leading < w.trailing) return p >= w.leading && p < w.trailing;
  return p >= w.leading || p < w.trailing;
}
} // namespace

void DieProtection::configure(const DieProtectionSetup& setup, std::uint16_t full_scale_count) {
  for (std::size_t i = 0; i < state_.size(); ++i) {
    if (!(setup.monitors[i] == setup_.monitors[i]) || full_scale_count != fsc_) state_[i] = MonitorState{};
  }
  setup_ = setup;
  fsc_ = full_scale_count;
}

bool DieProtection::inside(const DieMonitorSetup& m, std::uint16_t gmp) const {
  return std::any_of(m.windows.begin(), m.windows.end(),
                     [gmp](const DieWindow& w) { return in_window(gmp, w); });
}

void DieProtection::keep_quiet(QuietInterval& quiet, std::uint16_t gmp) const {
  for (const DieMonitorSetup& m : setup_.monitors) {
    if (m.mode == DieCheckMode::Off) continue;
    for (const DieWindow& w : m.windows) {
      if (w.used())
        quiet.keep_arc(gmp, w.leading, wrap(static_cast<std::int64_t>(w.trailing) - w.leading, fsc_), fsc_);
    }
  }
}

Nanos DieProtection::next_change() const {
  Nanos next = Nanos::max();
  for (int input = 1; input <= 16; ++input) {
    if (setup_.monitors[index(input)].mode == DieCheckMode::Off) continue;
    const MonitorState& s = state_[index(input)];
    const bool waits =
        s.primed && ((s.inside && s.level && !s.high_ok) || (!s.inside && !s.level && !s.low_ok));
    if (waits) next = std::min(next, std::max(s.level_since, s.inside_since) + kQualifyTime);
  }
  return next;
}

void DieProtection::update(Nanos now, std::uint16_t gmp, std::uint16_t inputs) {
  for (int input = 1; input <= 16; ++input) {
    const DieMonitorSetup& m = setup_.monitors[index(input)];
    if (m.mode == DieCheckMode::Off) continue;
    update_one(input, now, (inputs & bit(input)) != 0, inside(m, gmp));
  }
}

void DieProtection::update_one(int input, Nanos now, bool level, bool in_window_now) {
  MonitorState& s = state_[index(input)];
  if (!s.primed) {
    s = MonitorState{};
    s.primed = true;
    s.level = level;
    s.level_since = now;
    s.inside = in_window_now;
    s.inside_since = now;
    return;
  }
  // 1. The levels held since the previous call: did one of them last 500 us?
  const Nanos held = now - std::max(s.level_since, s.inside_since);
  if (held >= kQualifyTime) {
    if (s.inside && s.level) s.high_ok = true;
    if (!s.inside && !s.level) s.low_ok = true;
  }
  // 2. An input edge at this instant (checked against the window state before any window
  //    edge at the same instant: the input moved while the position had not yet left).
  if (level != s.level) {
    s.level = level;
    s.level_since = now;
    input_edge(input, level);
  }
  // 3. A window edge at this instant.
  if (in_window_now != s.inside) {
    s.inside = in_window_now;
    s.inside_since = now;
    if (in_window_now) {
      leading_edge(input);
    } else {
      trailing_edge(input);
    }
  }
}

void DieProtection::input_edge(int input, bool level) {
  const DieMonitorSetup& m = setup_.monitors[index(input)];
  MonitorState& s = state_[index(input)];
  switch (m.mode) {
  case DieCheckMode::NormallyTrue: // L1077: the fault is the loss of the signal
    if (!level) {
      fault(input);
    } else if (self_resets(m.action)) {
      s.counter = 0;
    }
    break;
  case DieCheckMode::NormallyFalse: // L1081
    if (level) {
      fault(input);
    } else if (self_resets(m.action)) {
      s.counter = 0;
    }
    break;
  case DieCheckMode::Constant: // L1121: any low inside faults at once
    if (!level && s.inside) fault_once_per_period(input);
    break;
  case DieCheckMode::Quick: // L1157: any high outside faults at once
    if (level && !s.inside) fault_once_per_period(input);
    break;
  case DieCheckMode::Cyclic:
  case DieCheckMode::Off:
    break;
  }
}

void DieProtection::leading_edge(int input) {
  const DieMonitorSetup& m = setup_.monitors[index(input)];
  MonitorState& s = state_[index(input)];
  switch (m.mode) {
  case DieCheckMode::Cyclic:     // L1087: low >= 500 us since the previous trailing edge
    if (!s.low_ok) fault(input); // not limited to once per period [MODEL A50]
    break;
  case DieCheckMode::Constant: // L1121-L1149
    if (!s.low_ok) fault_once_per_period(input);
    if (!s.level) fault_once_per_period(input);
    break;
  default:
    break;
  }
  s.high_ok = false;
}

void DieProtection::trailing_edge(int input) {
  const DieMonitorSetup& m = setup_.monitors[index(input)];
  MonitorState& s = state_[index(input)];
  switch (m.mode) {
  case DieCheckMode::Cyclic: // L1087: high >= 500 us inside the window
    if (!s.high_ok) fault(input);
    break;
  case DieCheckMode::Quick: // L1157-L1183: never high enough inside, or still high now
    if (!s.high_ok || s.level) fault_once_per_period(input);
    break;
  default:
    break;
  }
  if (m.mode == DieCheckMode::Cyclic || m.mode == DieCheckMode::Constant || m.mode == DieCheckMode::Quick) {
    // The period ends here (a fault raised at this edge belongs to it, L1167, L1180).
    if (self_resets(m.action) && !s.period_fault) s.counter = 0; // L1112, L1149, L1183
    s.period_fault = false;
  }
  s.low_ok = false;
}

void DieProtection::fault_once_per_period(int input) {
  if (state_[index(input)].period_fault) return;
  fault(input);
}

void DieProtection::fault(int input) {
  MonitorState& s = state_[index(input)];
  s.period_fault = true;
  if (faulted_in_cycle_ == 0) first_to_fault_ = bit(input);
  faulted_in_cycle_ = static_cast<std::uint16_t>(faulted_in_cycle_ | bit(input));
  if (!never_counts_) s.counter = static_cast<std::uint8_t>(s.counter + 1U); // 255 + 1 -> 0 (L1067)
}

void DieProtection::begin_production_cycle() {
  first_to_fault_ = 0;
  faulted_in_cycle_ = 0;
}

std::uint16_t DieProtection::monitored_inputs() const {
  std::uint16_t mask = 0;
  for (int input = 1; input <= 16; ++input) {
    if (setup_.monitors[index(input)].mode != DieCheckMode::Off)
      mask = static_cast<std::uint16_t>(mask | bit(input));
  }
  return mask;
}

std::uint16_t DieProtection::fault_output_mask() const {
  std::uint16_t mask = 0;
  for (const DieMonitorSetup& m : setup_.monitors) {
    if (m.mode != DieCheckMode::Off && m.fault_output != 0)
      mask = static_cast<std::uint16_t>(mask | bit(m.fault_output));
  }
  return mask;
}

std::uint16_t DieProtection::fault_output_levels() const {
  // Several monitors may share one fault output: it is ON only while all of them are healthy.
  std::uint16_t on = fault_output_mask();
  for (int input = 1; input <= 16; ++input) {
    const DieMonitorSetup& m = setup_.monitors[index(input)];
    if (m.mode == DieCheckMode::Off || m.fault_output == 0) continue;
    const bool healthy =
        !output_follows_counter(m.action) || state_[index(input)].counter == 0; // L1072-L1073
    if (!healthy) on = static_cast<std::uint16_t>(on & ~bit(m.fault_output));
  }
  return on;
}

} // namespace hilrig::models::ans1
