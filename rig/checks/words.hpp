#pragma once
// Word checks on observations: a status or data word read from the board equals a value, or
// lies within limits.

#include <optional>
#include <span>
#include <string>

#include "rig/checks/support.hpp"

namespace hilrig::checks {

using rig::Observation;

struct WordSpec {
  std::string name = "word";
  std::string observation{}; // the observation's name, e.g. "dut.da19.w6"
  std::optional<double> lower{};
  std::optional<double> upper{};
  std::optional<Nanos> at{}; // judge the latest observation at or before this; default: the last
};

// The observation a word check judges: the latest named spec.observation at or before spec.at
// (any time without it); nullptr when there is none.
[[nodiscard]] const Observation* chosen_observation(std::span<const Observation> observations,
                                                    const WordSpec& spec);
// A word check's measurement when there is none. A read due by spec.at that the rig made only
// after it (a host action waits for the handshake before it) is the rig's lateness, not the
// board's: an error, nothing judged. Otherwise a failure: "missing word: no observation named
// 'x' by T ns" (the board did not answer, or the campaign never read it).
[[nodiscard]] rig::Measurement missing_word(std::span<const Observation> observations, const WordSpec& spec);

// "<name>" = the chosen observation's value against [lower, upper]. No such observation:
// missing_word().
[[nodiscard]] CheckResult check_word_within(std::span<const Observation> observations, const WordSpec& spec);
// The same with lower = upper = expected.
[[nodiscard]] CheckResult check_word_equals(std::span<const Observation> observations, WordSpec spec,
                                            double expected);

} // namespace hilrig::checks
