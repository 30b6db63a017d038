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

namespace {

// A read of spec.observation due at or before spec.at that the rig made after it.
const Observation* read_late(std::span<const Observation> observations, const WordSpec& spec) {
  if (!spec.at) return nullptr;
  for (const auto& o : observations)
    if (o.name == spec.observation && o.due && *o.due <= *spec.at && o.time > *spec.at) return &o;
  return nullptr;
}

} // namespace

rig::Measurement missing_word(std::span<const Observation> observations, const WordSpec& spec) {
  if (const Observation* late = read_late(observations, spec))
    return error(
        spec.name,
        fmt::format("not judged: the rig made read '{}' at {} ns, after at_ms {} ns: due at {} ns, it "
                    "waited for the handshake before it (docs/campaigns.md, [[host]])",
                    spec.observation, late->time.count(), spec.at->count(), late->due->count()));
  return failure(spec.name,
                 fmt::format("missing word: no observation named '{}'{}", spec.observation,
                             spec.at ? fmt::format(" by {} ns", spec.at->count()) : std::string()));
}

CheckResult check_word_within(std::span<const Observation> observations, const WordSpec& spec) {
  CheckResult r;
  r.kind = "word_within";
  const Observation* chosen = chosen_observation(observations, spec);
  if (!chosen) {
    r.measurements.push_back(missing_word(observations, spec));
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
