#pragma once
// The smallest deviation at which a monotone predicate ("the check fails") turns true: an
// exponential search outward from the nominal value brackets the flip, then bisection narrows
// the bracket to the resolution. Deterministic and bounded: at most one probe per doubling
// of the range plus one per halving down to the resolution.

#include <cstddef>
#include <functional>
#include <optional>
#include <string>

namespace hilrig::power {

// What one probe found at a deviation: the check passed, failed, or could not be judged.
enum class Probe { Pass, Fail, Error };

struct BisectSpec {
  double max_deviation = 0.0; // > 0: the farthest the knob may go from its nominal value
  double resolution = 0.0;    // > 0: stop when the bracket is this narrow
  double first_step = 0.0;    // > 0: the first deviation tried (then doubled)
  bool integer = false;       // probe whole numbers only (a knob in ns)
  std::size_t max_probes = 64;
};

struct BisectResult {
  // The smallest failing deviation found (within resolution of the largest passing one).
  std::optional<double> threshold;
  double last_pass = 0.0; // the largest deviation seen to pass
  std::size_t probes = 0; // how many times the predicate was asked
  std::string reason;     // why there is no threshold ("" when there is one)
};

// probe(deviation) for deviations in [0, max_deviation]; the nominal (0) must pass.
[[nodiscard]] BisectResult bisect_threshold(const BisectSpec& spec,
                                            const std::function<Probe(double)>& probe);

} // namespace hilrig::power
