// Command blocks 3..6: one limit-switch output's setpoints, adjustments, timing and enabling.
#include "models/ans1/command_block_fields.hpp"
#include "models/ans1/setpoint.hpp"

namespace hilrig::models::ans1::command_fields {

namespace {
// Word 1 of CB3..CB6: the output 1..16.
[[nodiscard]] OutputSetup* output_of(const HostWords& w, DecodedBlock& out) {
  if (!in_range(w[1], 1, kOutputCount)) return nullptr;
  return &out.setup.output(w[1]);
}
[[nodiscard]] int fsc_of(const DecodedBlock& out) { return out.setup.position.full_scale_count; }

constexpr std::uint16_t kDeleteSetpointData = 6;
constexpr std::uint16_t kDeleteAll = 5;
} // namespace

ErrorCode decode_setpoints(const HostWords& w, DecodedBlock& out) {
  if (reserved_bits_set(w[0], bits({14, 13, 12, 11, 10, 9, 8, 6, 5}))) return ErrorCode::ReservedBits;
  const unsigned selector = (w[0] >> 8) & 3U;
  if (selector == 3) return ErrorCode::ParameterConflict; // L1869
  OutputSetup* o = output_of(w, out);
  if (o == nullptr) return ErrorCode::Parameter;
  const int fsc = fsc_of(out);
  if (selector == 1 && !in_range(as_signed(w[2]), -(fsc - 1), fsc - 1)) return ErrorCode::Parameter;
  if (selector == 2 && (!in_range(w[2], 0, 16) || !in_range(w[3], 0, fsc - 1))) return ErrorCode::Parameter;
  for (int k = 0; k < kPairsPerOutput; ++k) {
    if (!has(w[0], 10 + k)) continue;
    for (int i = 0; i < 4; ++i) {
      if (!in_range(w[static_cast<std::size_t>(4 * (k + 1) + i)], 0, fsc - 1)) return ErrorCode::Parameter;
    }
  }
  // Delete first, then apply what the block carries.
  if (has(w[0], kDeleteAll)) *o = OutputSetup{};
  if (has(w[0], kDeleteSetpointData)) o->pairs = {};
  if (selector == 1) o->ls_offset = as_signed(w[2]);
  if (selector == 2) {
    o->ls_preset_input = static_cast<std::uint8_t>(w[2]);
    o->ls_preset_value = w[3];
  }
  for (int k = 0; k < kPairsPerOutput; ++k) {
    if (!has(w[0], 10 + k)) continue;
    const auto base = static_cast<std::size_t>(4 * (k + 1));
    o->pairs[static_cast<std::size_t>(k)] = SetpointPair{w[base], w[base + 1], w[base + 2], w[base + 3]};
  }
  const auto fsc16 = static_cast<std::uint16_t>(fsc);
  for (const SetpointPair& pair : o->pairs) {
    if (pair.used() && !stitch_fits(pair, fsc16)) return ErrorCode::ParameterConflict; // L868 [MODEL code]
  }
  if (pairs_overlap(o->pairs, fsc16)) return ErrorCode::SetpointOverlap; // L1898
  if (has(w[0], 14)) out.actions.ls_preset_output = w[1];
  return ErrorCode::None;
}

ErrorCode decode_adjust(const HostWords& w, DecodedBlock& out) {
  if (reserved_bits_set(w[0], bits({14, 13, 12, 11, 10, 9, 8, 7, 6}))) return ErrorCode::ReservedBits;
  OutputSetup* o = output_of(w, out);
  if (o == nullptr) return ErrorCode::Parameter;
  const bool any_selected = (w[0] & 0x3FC0U) != 0;
  if (!any_selected) return ErrorCode::None;
  for (const SetpointPair& pair : o->pairs) {
    if (pair.stitched()) return ErrorCode::ParameterConflict; // L1905 (code not stated) [MODEL]
  }
  const int fsc = fsc_of(out);
  const int step = has(w[0], 14) ? 1 : fsc - 1; // bit 14: 1 = +1, 0 = -1 [A18]; wraps mod FSC [MODEL]
  for (int k = 0; k < kPairsPerOutput; ++k) {
    SetpointPair& pair = o->pairs[static_cast<std::size_t>(k)];
    if (has(w[0], 6 + 2 * k)) pair.from = static_cast<std::uint16_t>((pair.from + step) % fsc);
    if (has(w[0], 7 + 2 * k)) pair.to = static_cast<std::uint16_t>((pair.to + step) % fsc);
  }
  if (pairs_overlap(o->pairs, static_cast<std::uint16_t>(fsc))) return ErrorCode::SetpointOverlap; // L1907
  return ErrorCode::None;
}

ErrorCode decode_timing(const HostWords& w, DecodedBlock& out) {
  if (reserved_bits_set(w[0], bits({11, 10, 9, 8, 6, 5}))) return ErrorCode::ReservedBits;
  const unsigned advance = (w[0] >> 8) & 3U;
  const unsigned timer = (w[0] >> 10) & 3U;
  if (advance == 3) return ErrorCode::ParameterConflict; // L1951
  OutputSetup* o = output_of(w, out);
  if (o == nullptr) return ErrorCode::Parameter;
  if (advance != 0 && !in_range(w[2], 0, 32767)) return ErrorCode::Parameter;
  if (advance == 1 && !in_range(w[3], 0, 32767)) return ErrorCode::Parameter;
  if (advance == 2 && !in_range(w[3], 0, 9999)) return ErrorCode::Parameter;
  if (timer != 0 && !in_range(w[4], 0, 32767)) return ErrorCode::Parameter;
  if (has(w[0], kDeleteAll)) *o = OutputSetup{};
  if (has(w[0], kDeleteSetpointData)) { // "Delete timing data": advances and timer
    o->advance_mode = AdvanceMode::None;
    o->lead_ms = o->trail_ms = o->variable_us_per_rpm = 0;
    o->timer_type = TimerType::TimeOrPosition;
    o->timer_ms = 0;
  }
  if (advance == 1) {
    o->advance_mode = AdvanceMode::Fixed;
    o->lead_ms = w[2];
    o->trail_ms = w[3];
    o->variable_us_per_rpm = 0;
  } else if (advance == 2) {
    o->advance_mode = AdvanceMode::Variable;
    o->lead_ms = w[2];
    o->trail_ms = 0;
    o->variable_us_per_rpm = w[3];
  }
  if (timer != 0) {
    o->timer_type = timer == 1 ? TimerType::TimeOrPosition : TimerType::TimeOnly;
    o->timer_ms = w[4];
  }
  return ErrorCode::None;
}

ErrorCode decode_enabling(const HostWords& w, DecodedBlock& out) {
  if (reserved_bits_set(w[0], bits({10, 9, 8, 6, 5}))) return ErrorCode::ReservedBits;
  const bool anding = has(w[0], 8);
  const bool rpm = has(w[0], 9);
  const bool sr = has(w[0], 10);
  if (anding && (rpm || sr)) return ErrorCode::ParameterConflict; // L2028, L2042
  OutputSetup* o = output_of(w, out);
  if (o == nullptr) return ErrorCode::Parameter;
  const int fsc = fsc_of(out);
  if (anding) {
    int windows = 0;
    for (std::size_t i = 2; i <= 17; ++i) {
      if (!in_range(w[i], 0, 3)) return ErrorCode::Parameter;
      if (w[i] == 3) ++windows;
    }
    if (!in_range(w[18], 0, fsc - 1) || !in_range(w[19], 0, fsc - 1)) return ErrorCode::Parameter;
    if (windows > 1) return ErrorCode::ParameterConflict; // one window input per output (L983)
  }
  if (rpm && (as_signed(w[2]) < -32767 || as_signed(w[3]) < -32767)) return ErrorCode::Parameter;
  if (sr && !in_range(w[4], 0, kShiftRegisterBits)) return ErrorCode::Parameter;
  if (has(w[0], kDeleteAll)) *o = OutputSetup{};
  if (has(w[0], kDeleteSetpointData)) { // "Delete enabling data"
    o->rpm_low = o->rpm_high = 0;
    o->anding = {};
    o->window_low = o->window_high = 0;
    o->sr_bit = 0;
  }
  if (anding) {
    for (std::size_t i = 0; i < kInputCount; ++i) o->anding[i] = static_cast<AndingMode>(w[i + 2]);
    o->window_low = w[18];
    o->window_high = w[19];
  }
  if (rpm) {
    o->rpm_low = as_signed(w[2]);
    o->rpm_high = as_signed(w[3]);
  }
  if (sr) o->sr_bit = w[4];
  return ErrorCode::None;
}

} // namespace hilrig::models::ans1::command_fields
