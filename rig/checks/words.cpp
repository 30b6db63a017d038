#include "rig/checks/words.hpp"

#include <fmt/format.h>

namespace hilrig::checks {

const Observation* chosen_observation(std::span<const Observation> observations, const WordSpec& spec) {
  const Observation* chosen = nullptr;
  for (const auto& o : observations) {
    if (o.name != spec.observation) continue;
    if (spec.at && o.time > *spec.at) continue;
    if (!chosen || o.time >= chosen->time) chosen = &o;
  }
  return chosen;
}

rig::Measurement missing_word(const WordSpec& spec) {
  return failure(spec.name,
                 fmt::format("missing word: no observation named '{}'{}", spec.observation,
                             spec.at ? fmt::format(" by {} ns", spec.at->count()) : std::string()));
}

CheckResult check_word_within(std::span<const Observation> observations, const WordSpec& spec) {
  CheckResult r;
  r.kind = "word_within";
  const Observation* chosen = chosen_observation(observations, spec);
  if (!chosen) {
    r.measurements.push_back(missing_word(spec));
    return r;
  }
  r.measurements.push_back(measure(spec.name, chosen->value, chosen->unit, spec.lower, spec.upper,
                                   fmt::format("'{}' read at {} ns", spec.observation, chosen->time.count()),
                                   TraceWindow{chosen->time, chosen->time}, chosen->time));
  return r;
}

CheckResult check_word_equals(std::span<const Observation> observations, WordSpec spec, double expected) {
  spec.lower = expected;
  spec.upper = expected;
  CheckResult r = check_word_within(observations, spec);
  r.kind = "word_equals";
  return r;
}

} // namespace hilrig::checks
