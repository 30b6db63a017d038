#pragma once
// Where output edges fired, in counts: advance counts (speed-compensated edges) and the
// generic "edge at position" check.

#include <cstddef>
#include <functional>
#include <optional>
#include <span>
#include <string>

#include "core/line.hpp"
#include "rig/checks/support.hpp"

namespace hilrig::checks {

// How many times the stimulus brought the shaft to the position an edge is expected at, in the
// span judged (a crossing scan of the motion). Asked only when fewer edges than min_edges were
// found: with fewer of those too, the shortfall is the stimulus's (an error, not the board's
// fail). Empty: not known, every shortfall is the board's.
struct Reaches {
  std::size_t complete = 0; // reaches the shaft had left the tolerance band of by the span's end
  // One more reach whose band the shaft was still in when the span ended: a board within the
  // tolerance may fire after it, so its missing edge is not the board's.
  bool open_at_end = false;
};
using ReachedFn = std::function<Reaches()>;

struct AdvanceSpec {
  std::string name = "advance";
  Level level = Level::High;              // which edges: High = the output turning on (the "from" setpoint)
  double setpoint = 0.0;                  // counts
  Nanos advance{0};                       // advance time T: the edge is expected at setpoint - S*T
  std::optional<double> advance_counts{}; // when set, used instead of S*T (e.g. the board's reported advance)
  double tolerance = 1.0;                 // counts, either side
  double modulus = 0.0;                   // full-scale count (positions wrap); 0 = absolute positions
  std::size_t min_edges = 1;              // fewer edges of `level` than this fails "<name>.edges"
};

// For each edge of spec.level: "<name>.edge<i>" = position(edge.time) in counts against
// expected ± tolerance, where expected = setpoint - speed(edge.time) * advance (speed in
// counts/s, signed, so reverse motion advances the other way). The window is the time span in
// which the position lies inside the tolerance (linear at the edge's speed), `at` the edge.
// Plus "<name>.edges" (count, lower min_edges; an error when `reached` is fewer too).
[[nodiscard]] CheckResult check_advance(std::span<const Edge> output, const PositionFn& position,
                                        const PositionFn& speed, const AdvanceSpec& spec,
                                        const ReachedFn& reached = {});

struct EdgeAtPositionSpec {
  std::string name = "edge";
  Level level = Level::High;
  double position = 0.0; // counts
  double tolerance = 1.0;
  double modulus = 0.0;
  std::size_t min_edges = 1;
  std::optional<Nanos> from{}; // judge only the edges at or after this time (default: all)
  std::optional<Nanos> to{};   // judge only the edges at or before this time (default: all)
};

// Every edge of spec.level in [from, to] fired within position ± tolerance. `speed` may be
// empty; it only gives the expected window in time for the report. `reached`: as for
// check_advance, the times the shaft reached spec.position in [from, to].
[[nodiscard]] CheckResult check_edge_at_position(std::span<const Edge> output, const PositionFn& position,
                                                 const PositionFn& speed, const EdgeAtPositionSpec& spec,
                                                 const ReachedFn& reached = {});

} // namespace hilrig::checks
