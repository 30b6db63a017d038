#include "models/ans1/data_block.hpp"

#include <algorithm>

#include "models/ans1/ans1.hpp"
#include "models/ans1/monitors.hpp"
#include "models/ans1/speed.hpp"

namespace hilrig::models::ans1 {

namespace {
[[nodiscard]] std::uint16_t u16(std::int32_t v) { return static_cast<std::uint16_t>(v); }
[[nodiscard]] std::uint16_t bit(int point) { return static_cast<std::uint16_t>(1U << (point - 1)); }
[[nodiscard]] std::uint16_t high(std::uint32_t v) { return static_cast<std::uint16_t>(v >> 16); }
[[nodiscard]] std::uint16_t low(std::uint32_t v) { return static_cast<std::uint16_t>(v & 0xFFFFU); }

void global_setup(const Ans1& d, std::uint8_t active_program, HostWords& w) { // DA0
  const std::uint16_t out_on = static_cast<std::uint16_t>(d.output_force_enable() & d.output_force_state());
  const std::uint16_t out_off = static_cast<std::uint16_t>(d.output_force_enable() & ~d.output_force_state());
  const std::uint16_t in_on = static_cast<std::uint16_t>(d.input_force_enable() & d.input_force_state());
  const std::uint16_t in_off = static_cast<std::uint16_t>(d.input_force_enable() & ~d.input_force_state());
  const PositionSetup& p = d.position_setup();
  w[1] = out_on;
  w[2] = static_cast<std::uint16_t>(~out_off); // inverted: 0 = forced off (L2321)
  w[3] = in_on;
  w[4] = static_cast<std::uint16_t>(~in_off);
  w[5] = bit_parameters(p);
  w[6] = p.counts_per_cycle;
  w[7] = p.full_scale_count;
  w[8] = u16(p.scaled_offset); // in use: programmed or computed by a preset (L2329)
  w[9] = p.preset_value;
  w[10] = p.preset_input;
  w[11] = p.rpm_filter;
  w[12] = p.input_active_state;
  w[13] = kModuleId;
  w[14] = kProductCode;
  w[15] = kMajorRevision;
  w[16] = kMinorRevision;
  w[17] = active_program;
}

void output_setpoints(const Ans1& d, int n, HostWords& w) { // DA1
  const OutputSetup& o = d.output_setup(n);
  w[1] = static_cast<std::uint16_t>(n);
  for (std::size_t k = 0; k < kPairsPerOutput; ++k) {
    w[2 + 4 * k] = o.pairs[k].from;
    w[3 + 4 * k] = o.pairs[k].to;
    w[4 + 4 * k] = o.pairs[k].on_stitch;
    w[5 + 4 * k] = o.pairs[k].off_stitch;
  }
}

void output_adjustments(const Ans1& d, int n, HostWords& w) { // DA2
  const OutputSetup& o = d.output_setup(n);
  w[1] = static_cast<std::uint16_t>(n);
  w[2] = u16(o.ls_offset);
  w[3] = o.ls_preset_input;
  w[4] = o.ls_preset_value;
  w[5] = o.lead_ms;
  w[6] = o.variable_us_per_rpm;
  w[7] = o.trail_ms;
  w[8] = o.timer_ms;
  w[9] = o.timer_type == TimerType::TimeOnly ? 1 : 0;
  w[10] = u16(o.rpm_low);
  w[11] = u16(o.rpm_high);
  w[12] = o.sr_bit;
}

void output_enabling(const Ans1& d, int n, HostWords& w) { // DA3
  const OutputSetup& o = d.output_setup(n);
  w[1] = static_cast<std::uint16_t>(n);
  for (std::size_t i = 0; i < kInputCount; ++i) w[2 + i] = static_cast<std::uint16_t>(o.anding[i]);
  w[18] = o.window_low;
  w[19] = o.window_high;
}

void die_setup(const Monitors& m, int input, HostWords& w) { // DA4
  const DieMonitorSetup& s = m.setup().die.monitors[static_cast<std::size_t>(input - 1)];
  w[1] = s.fault_output;
  w[2] = static_cast<std::uint16_t>(input);
  w[3] = static_cast<std::uint16_t>(s.mode);
  for (std::size_t k = 0; k < kDieWindows; ++k) {
    w[4 + 2 * k] = s.windows[k].leading;
    w[5 + 2 * k] = s.windows[k].trailing;
  }
  w[12] = static_cast<std::uint16_t>(s.action);
}

void brake_setup(const Monitors& m, HostWords& w) { // DA5
  const BrakeSetup& b = m.setup().brake;
  w[1] = b.input;
  w[2] = b.complete_stop_count;
  w[3] = b.start_time_limit_ms;
  w[4] = b.start_overrun_output;
  w[5] = b.stop_time_limit_ms;
  w[6] = b.stop_overrun_output;
}

void counter_setup(const Monitors& m, HostWords& w) { // DA8
  const auto& c = m.setup().production.counters;
  w[1] = c[0].overflow_output;
  w[2] = high(c[0].limit);
  w[3] = low(c[0].limit);
  for (std::size_t b = 1; b <= 3; ++b) {
    const std::size_t base = 4 + 5 * (b - 1);
    w[base] = c[b].overflow_output;
    w[base + 1] = static_cast<std::uint16_t>(c[b].overflow_mode);
    w[base + 2] = c[b].only_good_cycles ? 1 : 0;
    w[base + 3] = high(c[b].limit);
    w[base + 4] = low(c[b].limit);
  }
}

void machine_status(const DataSelection& sel, const Ans1& d, const Monitors& m, HostWords& w) { // DA16
  const ProductionSetup& p = m.setup().production;
  const std::int32_t rate =
      static_cast<std::int32_t>(d.speed_rpm()) * p.multiplier / std::max<int>(p.divisor, 1);
  const OutputStatusMasks& masks = d.status_masks();
  w[1] = d.gmp();
  w[2] = u16(d.speed_rpm());
  w[3] = u16(saturated_speed_word(rate)); // S x Multiplier / Divisor (L2536), truncated [MODEL]
  w[4] = d.time_of_rotation();
  w[5] = d.input_states();
  w[6] = sel.input;
  w[7] = m.rising_position(sel.input);
  w[8] = m.falling_position(sel.input);
  w[9] = d.output_states();
  w[10] = masks.calc;
  w[11] = masks.simple;
  w[12] = masks.pulse;
  w[13] = masks.window;
  w[14] = masks.shift_register;
  w[15] = masks.rpm;
  w[16] = masks.timer;
  w[17] = d.user_defined_enabled();
  w[18] = sel.output;
  w[19] = d.ls_position(sel.output);
}

void counter_values(const Ans1& d, const Monitors& m, HostWords& w) { // DA17
  const ProductionCounters& c = m.counters();
  w[1] = d.gmp();
  for (std::size_t i = 0; i < kCounterCount; ++i) {
    const std::uint32_t v = c.value(static_cast<CounterId>(i));
    w[2 + 2 * i] = high(v);
    w[3 + 2 * i] = low(v);
  }
  w[14] = c.overflow_output_mask();
  for (std::size_t i = 0; i <= 3; ++i) w[15 + i] = c.overflow_state_mask(static_cast<CounterId>(i));
}

void die_status(const DataSelection& sel, const Ans1& d, const Monitors& m, HostWords& w) { // DA18
  const DieProtection& die = m.die();
  w[1] = d.gmp();
  w[2] = die.fault_output_levels();
  w[3] = static_cast<std::uint16_t>(d.input_states() & die.monitored_inputs());
  w[4] = die.first_to_fault();
  w[5] = die.faulted_in_cycle();
  w[6] = sel.input;
  w[7] = die.fault_count(sel.input);
  w[8] = m.rising_position(sel.input);
  w[9] = m.falling_position(sel.input);
}

void brake_status(const DataSelection& sel, const Ans1& d, const Monitors& m, HostWords& w) { // DA19
  const BrakeMonitor& b = m.brake();
  const int input = b.setup().input;
  w[1] = d.gmp();
  w[2] = input != 0 ? static_cast<std::uint16_t>(d.input_states() & bit(input)) : 0;
  w[3] = b.status().released_position;
  w[4] = b.status().start_time_ms;
  w[5] = b.status().applied_position;
  w[6] = b.status().stop_time_ms;
  w[7] = d.output_states();
  w[8] = sel.output;
  const AdvanceCounts& a = d.advances(sel.output);
  w[9] = u16(a.lead);
  w[10] = u16(a.trail);
}

void shift_register_status(const Ans1& d, HostWords& w) { // DA20
  const int input = d.shift_register_setup().input;
  w[1] = d.gmp();
  w[2] = input != 0 ? static_cast<std::uint16_t>(d.input_states() & bit(input)) : 0;
  w[3] = d.output_states();
  const auto words = d.shift_register().words();
  std::copy(words.begin(), words.end(), w.begin() + 4);
}
} // namespace

void compose_data_block(const DataSelection& sel, const Ans1& device, std::uint8_t active_program,
                        HostWords& w) {
  const Monitors& monitors = device.monitors();
  std::fill(w.begin() + 1, w.end(), std::uint16_t{0});
  switch (sel.attribute) {
  case 0:
    global_setup(device, active_program, w);
    break;
  case 1:
    output_setpoints(device, sel.output, w);
    break;
  case 2:
    output_adjustments(device, sel.output, w);
    break;
  case 3:
    output_enabling(device, sel.output, w);
    break;
  case 4:
    die_setup(monitors, sel.input, w);
    break;
  case 5:
    brake_setup(monitors, w);
    break;
  case 6: {
    const ShiftRegisterSetup& sr = device.shift_register_setup();
    w[1] = sr.input;
    w[2] = sr.window_from;
    w[3] = sr.window_to;
    w[4] = sr.shift_position;
    break;
  }
  case 7: {
    const ProductionSetup& p = monitors.setup().production;
    w[1] = p.increment_position;
    w[2] = p.multiplier;
    w[3] = p.divisor;
    break;
  }
  case 8:
    counter_setup(monitors, w);
    break;
  case 16:
    machine_status(sel, device, monitors, w);
    break;
  case 17:
    counter_values(device, monitors, w);
    break;
  case 18:
    die_status(sel, device, monitors, w);
    break;
  case 19:
    brake_status(sel, device, monitors, w);
    break;
  case 20:
    shift_register_status(device, w);
    break;
  default:
    break;
  }
}

} // namespace hilrig::models::ans1
