#pragma once
// Small helpers every check shares: unit conversion, nearest-rank percentiles, edge search
// and measurement building. Pure functions, no state.

#include <cstddef>
#include <functional>
#include <optional>
#include <span>
#include <string>
#include <vector>

#include "core/line.hpp"
#include "core/time.hpp"
#include "rig/results/measurement.hpp"

namespace hilrig::checks {

using rig::CheckResult;
using rig::Measurement;
using rig::Outcome;
using rig::TraceWindow;

// Position of the stimulus (counts) as a function of time, e.g. MotionProfile::position.
using PositionFn = std::function<double(Nanos)>;

// Exact decimal conversions: an integer count of ns divided once, so 20'000 ns is exactly 20.0 us.
[[nodiscard]] constexpr double to_us(Nanos t) { return static_cast<double>(t.count()) / 1e3; }
[[nodiscard]] constexpr double to_ms(Nanos t) { return static_cast<double>(t.count()) / 1e6; }

// Nearest-rank percentile (p in (0, 100]) of sorted values: the smallest sample with at least
// p% of the samples at or below it. Always an observed value, so its trace window exists.
[[nodiscard]] std::size_t nearest_rank_index(std::size_t n, double p);

// The first edge at or after `from` (and before `until`) whose level is `level`.
[[nodiscard]] std::optional<Edge> next_edge(std::span<const Edge> edges, Nanos from, Nanos until,
                                            Level level);

// A measurement judged against its limits.
[[nodiscard]] Measurement measure(std::string name, double value, std::string unit,
                                  std::optional<double> lower, std::optional<double> upper,
                                  std::string detail, std::optional<TraceWindow> window = std::nullopt,
                                  std::optional<Nanos> at = std::nullopt);

// A measurement that is a failure for a named reason (a missing edge, a missing word).
[[nodiscard]] Measurement failure(std::string name, std::string reason,
                                  std::optional<TraceWindow> window = {});
// A measurement that could not be taken (bad parameters, no such signal): outcome Error.
[[nodiscard]] Measurement error(std::string name, std::string reason);

[[nodiscard]] const char* level_name(Level l);

} // namespace hilrig::checks
