#pragma once
// Setpoint crossings of a position function: the stimulus instants of throughput checks.

#include <vector>

#include "core/time.hpp"
#include "rig/checks/support.hpp"

namespace hilrig::checks {

enum class Direction { Rising, Falling, Both };

// Every instant in (from, to] at which position crosses setpoint, to the nanosecond:
// rising = the first ns at which position >= setpoint after being below it; falling = the
// first ns at which position <= setpoint after being above it. The function is scanned every
// `step` and each sign change refined by bisection, so two crossings closer than `step` can
// be missed: choose step shorter than the shortest dwell on either side of the setpoint.
[[nodiscard]] std::vector<Nanos> find_crossings(const PositionFn& position, double setpoint, Nanos from,
                                                Nanos to, Nanos step, Direction direction = Direction::Both);

} // namespace hilrig::checks
