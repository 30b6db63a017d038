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
  // Only the first edge of a burst answers: an edge after the line held the other level for at
  // least this long (an SSI frame's first falling clock edge after the idle gap, ssi7361
  // L1085, L1091-1092). Without it an edge inside a burst that started early, a whole number of
  // clock periods early, can land on the crossing and read as on time.
  std::optional<Nanos> quiet{};
  // An edge up to this long before the crossing is in time too (a negative latency, judged by
  // "<name>.min" against -early): a start that may come as early as late. Each crossing is then
  // answered by the first edge from halfway back to the previous crossing (at least `early`
  // back) to halfway on to the next, so an edge too early is measured, not lost. Not with
  // min_limit.
  std::optional<Nanos> early{};
  // Fewer measured latencies than this fails "<name>.count"; fewer crossings than this is an
  // error there (the stimulus fell short, not the board).
  std::size_t min_count = 1;
};

// Measurements (unit us, windows from crossing to edge of the sample that set the value):
// count (lower min_count), min (lower min_limit), median (nearest rank, no limits), p99 (upper p99_limit),
// max (upper limit), missing (number of crossings with no edge; upper 0). Series "latency".
// With `early`, min's lower limit is -early and a latency may be negative.
// `seen_until` is the capture's end: a crossing with no edge whose limit_us reaches past it is
// not judged (a board within the limit may answer after the run), and is named in count's detail.
[[nodiscard]] CheckResult check_throughput(std::span<const Nanos> crossings, std::span<const Edge> output,
                                           const ThroughputSpec& spec, Nanos seen_until = Nanos::max());

} // namespace hilrig::checks
