#include "models/ans1/monitors.hpp"

#include <algorithm>
#include <optional>

namespace hilrig::models::ans1 {

namespace {
[[nodiscard]] std::uint16_t bit(int point) { return static_cast<std::uint16_t>(1U << (point - 1)); }
} // namespace

Monitors::Monitors(MonitorFaults faults, Nanos brake_sample_start)
    : brake_(faults.brake_never_faults, brake_sample_start), die_(faults.die_check_never_counts) {}

void Monitors::configure(const MonitorSetup& setup, std::uint16_t full_scale_count) {
  setup_ = setup;
  if (!(setup.brake == brake_.setup())) {
    // The brake input's level as the last scan read it, once a scan has read the inputs.
    std::optional<bool> released_now;
    if (started_ && setup.brake.input != 0) released_now = (inputs_ & bit(setup.brake.input)) != 0;
    brake_.configure(setup.brake, released_now);
  }
  die_.configure(setup.die, full_scale_count);
  counters_.configure(setup.production, full_scale_count);
}

bool Monitors::brake_ticks_idle() const {
  const int input = brake_.setup().input;
  return started_ && brake_.tick_records_only(input != 0 && (inputs_ & bit(input)) != 0);
}

void Monitors::scan(Nanos now, const MonitorInputs& in) {
  if (started_) {
    const auto changed = static_cast<std::uint16_t>(in.inputs ^ inputs_);
    for (int input = 1; input <= 16; ++input) {
      if ((changed & bit(input)) == 0) continue;
      ((in.inputs & bit(input)) != 0 ? rising_ : falling_)[static_cast<std::size_t>(input - 1)] = in.gmp;
    }
  }
  inputs_ = in.inputs;
  gmp_ = in.gmp;

  die_.update(now, in.gmp, in.inputs);
  // The part-cycle event closes the production cycle: its DP faults decide Good Part and
  // mode-1 batch counting, then a new DP cycle begins.
  if (counters_.update(in.gmp, die_.fault_in_cycle())) die_.begin_production_cycle();

  // Brake monitor on the 1 ms timer tick (spec §4.0).
  if (!started_) next_tick_ = Nanos{((now.count() + 999'999) / 1'000'000) * 1'000'000};
  started_ = true;
  const int brake_input = brake_.setup().input;
  const bool released = brake_input != 0 && (in.inputs & bit(brake_input)) != 0;
  // Ticks and debounce samples in time order: a sample start off the whole ms puts the samples
  // between ticks (a tick takes a sample due at its own time).
  while (true) {
    const Nanos sample = brake_.next_sample();
    if (sample < next_tick_ && sample <= now) {
      brake_.sample(sample, released, in.gmp);
      continue;
    }
    if (next_tick_ > now) break;
    brake_.tick(next_tick_, released, in.pos4096, in.gmp);
    next_tick_ += BrakeMonitor::kTick;
  }
}

Nanos Monitors::next_change(bool idle_ticks_recorded) const {
  const bool deadlines = brake_.setup().input != 0 && !(idle_ticks_recorded && brake_ticks_idle());
  const Nanos brake = deadlines ? std::min(next_tick_, brake_.next_sample()) : Nanos::max();
  return std::min(brake, die_.next_change());
}

OutputClaims Monitors::claims() const {
  const BrakeSetup& b = brake_.setup();
  std::uint16_t brake_mask = 0;
  std::uint16_t brake_levels = 0;
  // Overrun outputs are ON while healthy and OFF on a fault [MODEL A5, chapter 3].
  if (b.input != 0 && b.start_overrun_output != 0) {
    brake_mask = static_cast<std::uint16_t>(brake_mask | bit(b.start_overrun_output));
    if (!brake_.start_fault())
      brake_levels = static_cast<std::uint16_t>(brake_levels | bit(b.start_overrun_output));
  }
  if (b.input != 0 && b.stop_overrun_output != 0) {
    brake_mask = static_cast<std::uint16_t>(brake_mask | bit(b.stop_overrun_output));
    if (!brake_.stop_fault()) {
      if (b.stop_overrun_output != b.start_overrun_output || !brake_.start_fault())
        brake_levels = static_cast<std::uint16_t>(brake_levels | bit(b.stop_overrun_output));
    } else {
      brake_levels = static_cast<std::uint16_t>(brake_levels & ~bit(b.stop_overrun_output));
    }
  }
  return make_claims(die_.fault_output_mask(), die_.fault_output_levels(), brake_mask, brake_levels,
                     counters_.overflow_output_mask(), counters_.overflow_output_levels());
}

} // namespace hilrig::models::ans1
