#include "models/ssi7361/programming.hpp"

#include <array>

#include "models/ssi7361/data_path.hpp"

namespace hilrig::models::ssi7361 {
namespace {

constexpr std::uint16_t kMaxScalar = 32'767;

bool scalars_valid(std::uint16_t mul, std::uint16_t div, const Params& params) {
  if (mul < 1 || mul > kMaxScalar || div < 1 || div > kMaxScalar) return false;
  return params.multiplier_may_equal_divisor ? mul <= div : mul < div;
}

bool preset_valid(std::int32_t preset, const Params& params) {
  const std::int64_t p = preset;
  return p >= -static_cast<std::int64_t>(params.preset_limit) && p <= params.preset_limit;
}

bool rut_valid(std::uint16_t rut) { return rut >= 1 && rut <= 1000; }

// The parameter checks in the manual's order (L1950-1956): the command bit that programs
// the parameter, and the error bit it raises.
struct Check {
  std::uint16_t command;
  std::uint16_t error;
};
constexpr std::array<Check, 4> kOrder{{
    {qbit::kFormat, ibit::kFormatError},
    {qbit::kScalars, ibit::kScalarError},
    {qbit::kPresetValue, ibit::kPresetError},
    {qbit::kRut, ibit::kRutError},
}};

bool check_passes(const Check& c, const Setup& next, const Params& params) {
  switch (c.error) {
  case ibit::kFormatError:
    return format_valid(next.ssi);
  case ibit::kScalarError:
    return scalars_valid(next.multiplier, next.divisor, params);
  case ibit::kPresetError:
    return preset_valid(next.preset, params);
  default:
    return rut_valid(next.rut_ms);
  }
}

// The first failing check's error bit, or 0.
std::uint16_t first_error(std::uint16_t q, const Setup& next, const Params& params) {
  const bool reversed = params.variant == Variant::ErrorOrderReversed;
  for (std::size_t i = 0; i < kOrder.size(); ++i) {
    const Check& c = kOrder[reversed ? kOrder.size() - 1 - i : i];
    if ((q & c.command) != 0 && !check_passes(c, next, params)) return c.error;
  }
  return 0;
}

// The command bits that reprogram each pending parameter error.
std::uint16_t commands_fixing(std::uint16_t pending) {
  std::uint16_t out = 0;
  for (const Check& c : kOrder) {
    if ((pending & c.error) != 0) out = static_cast<std::uint16_t>(out | c.command);
  }
  return out;
}

Setup proposed(const Setup& current, std::uint16_t q, const CommandWords& w) {
  Setup next = current;
  if ((q & qbit::kFormat) != 0) next.ssi = decode_format(w[cmd::kFormat]);
  if ((q & qbit::kScalars) != 0) {
    next.multiplier = w[cmd::kMultiplier];
    next.divisor = w[cmd::kDivisor];
  }
  if ((q & qbit::kPresetValue) != 0) next.preset = join_words(w[cmd::kPresetLow], w[cmd::kPresetHigh]);
  if ((q & qbit::kRut) != 0) next.rut_ms = w[cmd::kRut];
  if ((q & qbit::kProgramDirection) != 0) next.count_negative = (q & qbit::kCountDirection) != 0;
  return next;
}

void fail(ProgramState& state, std::uint16_t bit) {
  // Pending parameter errors stay (they still need reprogramming); CMDErr and MsgIgn are
  // this cycle's own verdict.
  state.errors =
      static_cast<std::uint16_t>((state.errors & (ibit::kParameterErrors | ibit::kEepromError)) | bit);
}

} // namespace

CycleOutcome run_cycle(ProgramState& state, const CommandWords& words, std::uint32_t latest_raw,
                       const Params& params) {
  CycleOutcome out;
  const std::uint16_t q = words[cmd::kQ];
  const bool e2clr = (q & qbit::kE2Clear) != 0;

  if ((q & qbit::kReserved) != 0 || (words[cmd::kFormat] & fbit::kReserved) != 0 ||
      ((q & qbit::kCountDirection) != 0 && (q & qbit::kProgramDirection) == 0)) {
    fail(state, ibit::kCommandError);
    return out;
  }
  if ((state.errors & ibit::kEepromError) != 0) {
    if (!e2clr) {
      fail(state, ibit::kCommandError);
      return out;
    }
    // E2CLR: factory defaults, LO 0, every error cleared (L2119-2121, A18).
    state.setup = Setup{};
    state.offset = 0;
    state.errors = 0;
    ++state.eeprom_writes;
    out.defaults_loaded = true;
    if ((q & qbit::kCommands) == 0) {
      out.accepted = true;
      return out;
    }
  }
  // Without an EEPROM error E2CLR "will have no effect" (L2120-2121): a cycle with no command
  // bit 07-01 besides it is CMDErr condition 2 (L2031), and a pending CMDErr stays.
  if ((q & qbit::kCommands) == 0) {
    fail(state, ibit::kCommandError);
    return out;
  }
  const std::uint16_t pending = state.errors & ibit::kParameterErrors;
  if (pending != 0 && (q & commands_fixing(pending)) != commands_fixing(pending)) {
    fail(state, ibit::kMessageIgnored);
    return out;
  }

  const Setup next = proposed(state.setup, q, words);
  if (const std::uint16_t error = first_error(q, next, params); error != 0) {
    state.errors = static_cast<std::uint16_t>((state.errors & ibit::kEepromError) | error);
    return out;
  }

  // Commit everything at once.
  const bool format_changes = next.ssi != state.setup.ssi;
  const bool programs = (q & (qbit::kCommands & ~qbit::kApplyPreset)) != 0;
  state.setup = next;
  state.errors &= ibit::kEepromError;
  if ((q & qbit::kFormat) != 0 &&
      (format_changes || params.format_clears_offset == FormatClearsOffset::Always))
    state.offset = 0;
  if (programs) ++state.eeprom_writes;
  out.accepted = true;
  out.rut_programmed = (q & qbit::kRut) != 0;
  if ((q & qbit::kApplyPreset) != 0) {
    state.offset = preset_offset(latest_raw, state.setup, params);
    ++state.eeprom_writes;
    out.preset_applied = true;
  }
  return out;
}

} // namespace hilrig::models::ssi7361
