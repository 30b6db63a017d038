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

// "<name>" = the chosen observation's value against [lower, upper]. No such observation is a
// failure ("missing word").
[[nodiscard]] CheckResult check_word_within(std::span<const Observation> observations, const WordSpec& spec);
// The same with lower = upper = expected.
[[nodiscard]] CheckResult check_word_equals(std::span<const Observation> observations, WordSpec spec,
                                            double expected);

} // namespace hilrig::checks
