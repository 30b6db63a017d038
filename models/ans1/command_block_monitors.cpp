// Command blocks 7..11: die protection, brake monitor, shift register, production cycle and
// production counters.
#include "models/ans1/command_block_fields.hpp"

namespace hilrig::models::ans1::command_fields {

namespace {
[[nodiscard]] int fsc_of(const DecodedBlock& out) { return out.setup.position.full_scale_count; }
} // namespace

ErrorCode decode_die_protection(const HostWords& w, DecodedBlock& out) {
  if (reserved_bits_set(w[0], bits({10, 9, 8, 6, 5}))) return ErrorCode::ReservedBits;
  const bool apply_output = has(w[0], 8);
  const bool apply_check = has(w[0], 9);
  const bool apply_action = has(w[0], 10);
  const bool needs_input = apply_output || apply_check || apply_action || has(w[0], 6);
  // w2 identifies the monitor for every Apply and for Delete (L2055, A20).
  if (needs_input && !in_range(w[2], 1, 16)) return ErrorCode::Parameter;
  if (apply_output && !in_range(w[1], 0, kOutputCount)) return ErrorCode::Parameter;
  const int fsc = fsc_of(out);
  if (apply_check) {
    if (!in_range(w[3], 0, 5)) return ErrorCode::Parameter;
    for (std::size_t i = 4; i <= 11; ++i) {
      if (!in_range(w[i], 0, fsc - 1)) return ErrorCode::Parameter;
    }
  }
  if (apply_action && !in_range(w[12], 0, 3)) return ErrorCode::Parameter;

  DieProtectionSetup& die = out.setup.monitors.die;
  if (has(w[0], 5)) die = DieProtectionSetup{}; // Delete All: every monitor [MODEL A20]
  if (!needs_input) return ErrorCode::None;
  DieMonitorSetup& m = die.monitors[static_cast<std::size_t>(w[2] - 1)];
  if (has(w[0], 6)) m = DieMonitorSetup{}; // the monitor's DP data; ANDing is left alone (L2070)
  if (apply_output) m.fault_output = static_cast<std::uint8_t>(w[1]);
  if (apply_check) {
    m.mode = static_cast<DieCheckMode>(w[3]);
    for (std::size_t k = 0; k < kDieWindows; ++k) m.windows[k] = DieWindow{w[4 + 2 * k], w[5 + 2 * k]};
  }
  if (apply_action) m.action = static_cast<DieActionMode>(w[12]);
  return ErrorCode::None;
}

ErrorCode decode_brake(const HostWords& w, DecodedBlock& out) {
  if (reserved_bits_set(w[0], bits({13, 12, 11, 10, 9, 8, 5}))) return ErrorCode::ReservedBits;
  if (has(w[0], 8) && !in_range(w[1], 0, 16)) return ErrorCode::Parameter;
  if (has(w[0], 9) && !in_range(w[2], 0, 255)) return ErrorCode::Parameter;
  if (has(w[0], 10) && !in_range(w[3], 0, 32767)) return ErrorCode::Parameter;
  if (has(w[0], 11) && !in_range(w[4], 0, kOutputCount)) return ErrorCode::Parameter;
  if (has(w[0], 12) && !in_range(w[5], 0, 32767)) return ErrorCode::Parameter;
  if (has(w[0], 13) && !in_range(w[6], 0, kOutputCount)) return ErrorCode::Parameter;
  BrakeSetup& b = out.setup.monitors.brake;
  if (has(w[0], 5)) b = BrakeSetup{};
  if (has(w[0], 8)) b.input = static_cast<std::uint8_t>(w[1]);
  if (has(w[0], 9)) b.complete_stop_count = static_cast<std::uint8_t>(w[2]);
  if (has(w[0], 10)) b.start_time_limit_ms = w[3];
  if (has(w[0], 11)) b.start_overrun_output = static_cast<std::uint8_t>(w[4]);
  if (has(w[0], 12)) b.stop_time_limit_ms = w[5];
  if (has(w[0], 13)) b.stop_overrun_output = static_cast<std::uint8_t>(w[6]);
  return ErrorCode::None;
}

ErrorCode decode_shift_register(const HostWords& w, DecodedBlock& out) {
  if (reserved_bits_set(w[0], bits({8, 5}))) return ErrorCode::ReservedBits;
  const int fsc = fsc_of(out);
  if (has(w[0], 8)) {
    if (!in_range(w[1], 0, 16)) return ErrorCode::Parameter;
    for (std::size_t i = 2; i <= 4; ++i) {
      if (!in_range(w[i], 0, fsc - 1)) return ErrorCode::Parameter;
    }
  }
  ShiftRegisterSetup& sr = out.setup.shift_register;
  if (has(w[0], 5)) sr = ShiftRegisterSetup{};
  if (has(w[0], 8)) sr = ShiftRegisterSetup{static_cast<std::uint8_t>(w[1]), w[2], w[3], w[4]};
  return ErrorCode::None;
}

ErrorCode decode_production_cycle(const HostWords& w, DecodedBlock& out) {
  if (reserved_bits_set(w[0], bits({9, 8}))) return ErrorCode::ReservedBits;
  if (has(w[0], 8) && !in_range(w[1], 0, fsc_of(out) - 1)) return ErrorCode::Parameter;
  if (has(w[0], 9) && (!in_range(w[2], 1, 32767) || !in_range(w[3], 1, 32767))) return ErrorCode::Parameter;
  ProductionSetup& p = out.setup.monitors.production;
  if (has(w[0], 8)) p.increment_position = w[1];
  if (has(w[0], 9)) {
    p.multiplier = w[2];
    p.divisor = w[3];
  }
  return ErrorCode::None;
}

ErrorCode decode_counters(const HostWords& w, DecodedBlock& out) {
  if (reserved_bits_set(w[0], bits({12, 11, 10, 9, 8, 5}))) return ErrorCode::ReservedBits;
  if (!in_range(w[1], 0, kCounterCount - 1)) return ErrorCode::Parameter;
  const auto id = static_cast<CounterId>(w[1]);
  const bool batch = id == CounterId::Batch1 || id == CounterId::Batch2 || id == CounterId::Batch3;
  const bool no_output = id == CounterId::Revolutions || id == CounterId::GoodPart;
  // Counters 4 and 5 have no output and no limit: bits 8 and 11 and words 2, 3, 5, 6 must be
  // 0 (L2187, L2208, L2217); an increment mode exists for batches only [MODEL].
  if (no_output && (has(w[0], 8) || has(w[0], 11) || w[2] != 0 || w[3] != 0 || w[5] != 0 || w[6] != 0)) {
    return ErrorCode::ParameterConflict;
  }
  if (has(w[0], 10) && !batch) return ErrorCode::ParameterConflict;
  if (has(w[0], 8) && !in_range(w[2], 0, kOutputCount)) return ErrorCode::Parameter;
  if (has(w[0], 9) && !in_range(w[3], 0, 2)) return ErrorCode::Parameter;
  if (has(w[0], 10) && !in_range(w[4], 0, 1)) return ErrorCode::Parameter;
  const std::uint32_t limit = join32(w[5], w[6]);
  const std::uint32_t preset = join32(w[7], w[8]);
  if (has(w[0], 11) && limit > kCounterMax) return ErrorCode::Parameter;
  if (has(w[0], 12) && preset > kCounterMax) return ErrorCode::Parameter;

  CounterSetup& c = out.setup.monitors.production.counters[static_cast<std::size_t>(w[1])];
  if (has(w[0], 5)) c = CounterSetup{};
  if (has(w[0], 8)) c.overflow_output = static_cast<std::uint8_t>(w[2]);
  if (has(w[0], 9)) c.overflow_mode = static_cast<OverflowMode>(w[3]);
  if (has(w[0], 10)) c.only_good_cycles = w[4] == 1;
  if (has(w[0], 11)) c.limit = limit;
  // Only an assigned output has requirements: mode 0 is "No Output" (L2212) and the output needs
  // a Counter Limit Value programmed (L2208; a limit of 0 is none [MODEL], it is never reached).
  // A mode or a limit (0 included, L2181) alone conflicts with nothing, in either order.
  if (c.overflow_output != 0 && (c.overflow_mode == OverflowMode::None || c.limit == 0)) {
    return ErrorCode::ParameterConflict;
  }
  if (has(w[0], 12)) out.actions.counter_preset = CounterPreset{id, preset};
  return ErrorCode::None;
}

} // namespace hilrig::models::ans1::command_fields
