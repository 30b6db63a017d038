#include "models/ans1/command_block.hpp"

#include "models/ans1/command_block_fields.hpp"
#include "models/ans1/positions_fit.hpp"

namespace hilrig::models::ans1 {

using namespace command_fields;

DecodedBlock decode_command_block(const HostWords& w, const Ans1Setup& current, const HostContext& context) {
  DecodedBlock out;
  out.block = w[0] & kBlockNumberMask;
  out.setup = current;
  const bool clear = has(w[0], 4);
  ErrorCode error = ErrorCode::None;
  switch (out.block) {
  case 0:
    break; // CB0: bits 14..5 and words 1..19 are ignored (L1713-L1721)
  case 1:
    error = decode_return_data(w, out);
    break;
  case 2:
    error = decode_global(w, out);
    break;
  case 3:
    error = decode_setpoints(w, out);
    break;
  case 4:
    error = decode_adjust(w, out);
    break;
  case 5:
    error = decode_timing(w, out);
    break;
  case 6:
    error = decode_enabling(w, out);
    break;
  case 7:
    error = decode_die_protection(w, out);
    break;
  case 8:
    error = decode_brake(w, out);
    break;
  case 9:
    error = decode_shift_register(w, out);
    break;
  case 10:
    error = decode_production_cycle(w, out);
    break;
  case 11:
    error = decode_counters(w, out);
    break;
  case 15:
    error = decode_save_restore(w, context, out);
    break;
  default:
    error = ErrorCode::CommandWord;
    break; // 12..14 undefined [MODEL A43]
  }
  if (error != ErrorCode::None) {
    out.setup = current;
    out.actions = BlockActions{};
  }
  out.error = error;
  out.actions.clear_errors = clear; // Clear Errors works even in a rejected block
  return out;
}

namespace command_fields {

ErrorCode decode_return_data(const HostWords& w, DecodedBlock& out) {
  if (reserved_bits_set(w[0], bits({10, 9, 8}))) return ErrorCode::ReservedBits;
  if (has(w[0], 8)) {
    // w2 must name an output for the output blocks, w3 an input for the input blocks, as
    // Tables 5.1/6.1 list them (L1755-L1766, L2268-L2279; DA19 takes both, L1766, L2279); the
    // other word is ignored [MODEL; A48: DA5 has no input].
    const unsigned attribute = w[1];
    if (!is_data_attribute(attribute)) return ErrorCode::Parameter;
    const bool uses_output =
        attribute == 1 || attribute == 2 || attribute == 3 || attribute == 16 || attribute == 19;
    const bool uses_input = attribute == 4 || attribute == 16 || attribute == 18 || attribute == 19;
    if (uses_output && !in_range(w[2], 1, 16)) return ErrorCode::Parameter;
    if (uses_input && !in_range(w[3], 1, 16)) return ErrorCode::Parameter;
    DataSelection sel;
    sel.attribute = static_cast<std::uint8_t>(attribute);
    sel.output = static_cast<std::uint8_t>(uses_output ? w[2] : 1);
    sel.input = static_cast<std::uint8_t>(uses_input ? w[3] : 1);
    out.actions.selection = sel;
  }
  if (has(w[0], 9)) out.actions.output_forces = Forces{w[4], w[5]};
  if (has(w[0], 10)) out.actions.input_forces = Forces{w[6], w[7]};
  return ErrorCode::None;
}

ErrorCode decode_global(const HostWords& w, DecodedBlock& out) {
  if (reserved_bits_set(w[0], bits({14, 13, 12, 11, 10, 9, 8, 7, 5}))) return ErrorCode::ReservedBits;
  const bool any_apply = (w[0] & bits({14, 13, 12, 11, 10, 9, 8, 7})) != 0;
  if (has(w[0], 5)) {
    // Restore Factory Defaults replaces everything, so it cannot go with Apply bits [MODEL].
    if (any_apply) return ErrorCode::ParameterConflict;
    out.actions.factory_defaults = true;
    out.setup = Ans1Setup{};
    return ErrorCode::None;
  }
  PositionSetup& p = out.setup.position;
  if (has(w[0], 7) && (w[1] & 0xFFE0U) != 0) return ErrorCode::ReservedBits; // w1 bits 15..5
  const int cpc = has(w[0], 8) ? w[2] : p.counts_per_cycle;
  if (!in_range(cpc, 2, 4096)) return ErrorCode::Parameter;
  const int fsc = has(w[0], 9) ? w[3] : p.full_scale_count;
  if (has(w[0], 9) && !in_range(fsc, 1, cpc)) return ErrorCode::Parameter;
  const int smo = has(w[0], 10) ? as_signed(w[4]) : p.scaled_offset;
  if (has(w[0], 10) && !in_range(smo, -(fsc - 1), fsc - 1)) return ErrorCode::Parameter;
  const int mpv = has(w[0], 11) ? w[5] : p.preset_value;
  if (has(w[0], 11) && (!in_range(mpv, 0, fsc - 1) || !in_range(w[6], 0, 16))) return ErrorCode::Parameter;
  // A new CPC or FSC that the kept values no longer fit is a conflict [MODEL]: SMO, MPV and
  // every programmed position of the outputs and monitors (positions_fit.hpp).
  if (fsc > cpc || !in_range(smo, -(fsc - 1), fsc - 1) || mpv > fsc - 1) return ErrorCode::ParameterConflict;
  if (fsc < p.full_scale_count && !positions_fit(out.setup, static_cast<std::uint16_t>(fsc))) {
    return ErrorCode::ParameterConflict;
  }

  if (has(w[0], 7)) set_bit_parameters(p, w[1]);
  p.counts_per_cycle = static_cast<std::uint16_t>(cpc);
  p.full_scale_count = static_cast<std::uint16_t>(fsc);
  p.scaled_offset = smo;
  if (has(w[0], 11)) {
    p.preset_value = w[5];
    p.preset_input = static_cast<std::uint8_t>(w[6]);
  }
  if (has(w[0], 12)) p.rpm_filter = w[7];
  if (has(w[0], 13)) p.input_active_state = w[8];
  out.actions.machine_preset = has(w[0], 14);
  return ErrorCode::None;
}

ErrorCode decode_save_restore(const HostWords& w, const HostContext& ctx, DecodedBlock& out) {
  if (reserved_bits_set(w[0], bits({10, 9, 8, 5}))) return ErrorCode::ReservedBits;
  ProgramCommand cmd;
  cmd.save_global = has(w[0], 10);
  cmd.save_program = has(w[0], 9);
  cmd.load_program = has(w[0], 8);
  cmd.delete_stored = has(w[0], 5);
  if (cmd.save_program && cmd.load_program) return ErrorCode::ParameterConflict; // L2237
  if (cmd.save_program || cmd.load_program) {
    if (!in_range(w[1], 0, kFactoryProgram)) return ErrorCode::Parameter;
    cmd.slot = static_cast<std::uint8_t>(w[1]);
  }
  if (cmd.save_program) {
    const int slot = cmd.slot == 0 ? ctx.active_program : cmd.slot;
    // Factory defaults are load-only (L2245); "save to the active program" needs one [MODEL].
    if (slot == kFactoryProgram || slot == 0) return ErrorCode::ParameterConflict;
  }
  if (cmd.load_program && cmd.slot >= 1 && cmd.slot <= kProgramSlots) {
    const Ans1Setup* stored = ctx.stored[cmd.slot];
    if (stored == nullptr) return ErrorCode::Parameter; // nothing stored there [MODEL]
    // Its positions must fit the FSC in force, which a program does not carry [MODEL].
    if (!positions_fit(*stored, out.setup.position.full_scale_count)) return ErrorCode::ParameterConflict;
  }
  out.actions.program = cmd;
  return ErrorCode::None;
}

} // namespace command_fields
} // namespace hilrig::models::ans1
