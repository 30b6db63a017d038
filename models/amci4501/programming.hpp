#pragma once
// The programming cycle's validation (L151-177, digest §5.3-5.4): which mode the control
// word selects, and whether the words that mode uses are in range. Pure: the module
// applies the result.

#include <cstdint>

#include "core/time.hpp"
#include "models/amci4501/host_words.hpp"
#include "models/amci4501/params.hpp"

namespace hilrig::models::amci4501 {

struct Config {
  int mode = 1;                   // power-up mode (L176)
  std::uint16_t timeout_word = 0; // ms, 0 = Params::default_timeout (L169); modes 1-4
  std::uint32_t on_setpoint = 0;  // mode 2, counts
  std::uint32_t off_setpoint = 0; // mode 2, counts
  friend bool operator==(const Config&, const Config&) = default;
};

struct ProgramResult {
  bool command_error = false;   // status bit 4
  bool parameter_error = false; // status bit 5
  Config config;                // valid only when neither error is set
  [[nodiscard]] bool valid() const { return !command_error && !parameter_error; }
};

// Command Error: a reserved bit (7-14) or more than one mode bit. Parameter Error: a word
// the selected mode uses is out of range (A29: don't-care words are never checked) —
// timeout > 32,767 (modes 1-4); a setpoint above 65,535, a lower word above 999 (when
// Params::lower_word_over_999_is_error) or on >= off (mode 2).
[[nodiscard]] ProgramResult validate_program(const OutputWords& words, const Params& params);

// The timeout a configuration runs with.
[[nodiscard]] Nanos timeout_of(const Config& config, const Params& params);

} // namespace hilrig::models::amci4501
