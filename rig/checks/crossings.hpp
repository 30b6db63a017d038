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
// With a modulus > 0 (a board's full-scale count, a shaft that keeps turning) the setpoint
// is on the circle: every setpoint + k * modulus is crossed. Returned in time order.
// With `held` (how long the position holds still from a time), the samples of a standstill are
// not taken one by one: they all equal the one before it, so no crossing lies between them, and
// the result is the same as without it.
[[nodiscard]] std::vector<Nanos> find_crossings(const PositionFn& position, double setpoint, Nanos from,
                                                Nanos to, Nanos step, Direction direction = Direction::Both,
                                                double modulus = 0.0, const HeldFn& held = {});

} // namespace hilrig::checks
