#pragma once
// Small helpers every check shares: unit conversion, nearest-rank percentiles, edge search
// (measurements are built by measure.hpp). Pure functions, no state.

#include <cstddef>
#include <functional>
#include <optional>
#include <span>
#include <string>
#include <vector>

#include "core/line.hpp"
#include "core/time.hpp"
#include "rig/checks/measure.hpp"
#include "rig/results/measurement.hpp"

namespace hilrig::checks {

using rig::CheckResult;

// Position of the stimulus (counts) as a function of time, e.g. MotionProfile::position.
using PositionFn = std::function<double(Nanos)>;
// The last instant through which a PositionFn stays exactly what it is at t (t itself when it
// moves), e.g. MotionProfile::held_until.
using HeldFn = std::function<Nanos(Nanos)>;

// Nearest-rank percentile (p in (0, 100]) of sorted values: the smallest sample with at least
// p% of the samples at or below it. Always an observed value, so its trace window exists.
[[nodiscard]] std::size_t nearest_rank_index(std::size_t n, double p);

// The first edge at or after `from` (and before `until`) whose level is `level`.
[[nodiscard]] std::optional<Edge> next_edge(std::span<const Edge> edges, Nanos from, Nanos until,
                                            Level level);

// A line's level at t, from its edges (times ascending) and its level before the first: an edge
// at exactly t has happened.
[[nodiscard]] Level level_at(std::span<const Edge> edges, Nanos t, Level before);

[[nodiscard]] const char* level_name(Level l);

} // namespace hilrig::checks
