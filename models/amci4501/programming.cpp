#include "models/amci4501/programming.hpp"

#include <bit>

namespace hilrig::models::amci4501 {

ProgramResult validate_program(const OutputWords& words, const Params& params) {
  ProgramResult r;
  const std::uint16_t control_word = words[0];
  const auto mode_bits = static_cast<std::uint16_t>(control_word & control::kModeBits);
  if ((control_word & control::kReserved) != 0 || std::popcount(mode_bits) > 1) {
    r.command_error = true;
    return r;
  }
  Config c;
  c.mode = mode_bits == 0 ? 1 : std::countr_zero(mode_bits); // bit n selects mode n
  if (c.mode <= 4) {
    c.timeout_word = words[1];
    if (c.timeout_word > 32767) r.parameter_error = true;
  }
  if (c.mode == 2) {
    const auto lower_bad = [&](std::uint16_t lower) {
      return params.lower_word_over_999_is_error && lower > 999;
    };
    const std::uint64_t on = join_thousands(words[2], words[3]);
    const std::uint64_t off = join_thousands(words[4], words[5]);
    if (lower_bad(words[3]) || lower_bad(words[5]) || on > 65535 || off > 65535 || on >= off)
      r.parameter_error = true;
    c.on_setpoint = static_cast<std::uint32_t>(on);
    c.off_setpoint = static_cast<std::uint32_t>(off);
  }
  if (!r.parameter_error) r.config = c;
  return r;
}

Nanos timeout_of(const Config& config, const Params& params) {
  return config.timeout_word == 0 ? params.default_timeout : milliseconds(config.timeout_word);
}

} // namespace hilrig::models::amci4501
