#pragma once
// Throughput: the latency from each stimulus crossing of a setpoint to the next output edge
// of the expected level, as a distribution over many crossings.

#include <cstddef>
#include <optional>
#include <span>
#include <string>

#include "core/line.hpp"
#include "rig/checks/support.hpp"

namespace hilrig::checks {

struct ThroughputSpec {
  std::string name = "throughput";  // measurement names are "<name>.count", "<name>.max", ...
  Level expected = Level::High;     // the output level the crossing must produce
  Nanos limit{0};                   // upper limit on the max latency: every crossing must meet it
  std::optional<Nanos> p99_limit{}; // upper limit on p99; defaults to limit
  // Lower limit on the min latency: the fastest answer a manual states (the ANS1's "10 to 20
  // us", L572): a board answering before it does not behave as its manual says.
  std::optional<Nanos> min_limit{};
  // An edge is looked for from the crossing until the next crossing, and never longer than
  // this: a crossing with no edge in time is a missing edge, a failure.
  Nanos timeout = Nanos::max();
  std::size_t min_count = 1; // fewer measured latencies than this fails "<name>.count"
};

// Measurements (unit us, windows from crossing to edge of the sample that set the value):
// count (lower min_count), min (lower min_limit), median (nearest rank, no limits), p99 (upper p99_limit),
// max (upper limit), missing (number of crossings with no edge; upper 0). Series "latency".
[[nodiscard]] CheckResult check_throughput(std::span<const Nanos> crossings, std::span<const Edge> output,
                                           const ThroughputSpec& spec);

} // namespace hilrig::checks
