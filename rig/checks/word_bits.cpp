#include "rig/checks/word_bits.hpp"

#include <cmath>

#include <fmt/format.h>

namespace hilrig::checks {

CheckResult check_word_bits(std::span<const Observation> observations, const WordSpec& spec,
                            std::uint16_t mask, std::uint16_t value) {
  CheckResult r;
  r.kind = "word_bits";
  if (mask == 0) {
    r.measurements.push_back(error(spec.name, "nothing judged: mask 0 selects no bit"));
    return r;
  }
  const Observation* chosen = chosen_observation(observations, spec);
  if (!chosen) {
    r.measurements.push_back(missing_word(observations, spec));
    return r;
  }
  // A signed read of a word keeps its 16 bits: take them back as two's complement.
  const auto word =
      static_cast<std::uint16_t>(static_cast<std::int64_t>(std::llround(chosen->value)) & 0xFFFF);
  const auto masked = static_cast<std::uint16_t>(word & mask);
  r.measurements.push_back(measure(spec.name, masked, "", value, value,
                                   fmt::format("'{}' = 0x{:04X} read at {} ns; mask 0x{:04X}, want 0x{:04X}",
                                               spec.observation, word, chosen->time.count(), mask, value),
                                   TraceWindow{chosen->time, chosen->time}, chosen->time));
  return r;
}

} // namespace hilrig::checks
