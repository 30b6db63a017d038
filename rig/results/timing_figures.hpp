#pragma once
// Which judged windows get a timing diagram, and what each diagram spans: one rule for the
// executive (which cuts the trace around them) and the report (which draws them).

#include <cstddef>
#include <optional>
#include <vector>

#include "rig/results/measurement.hpp"

namespace hilrig::rig {

// Timing diagrams drawn per check; the rest of its windows are only in the table.
inline constexpr std::size_t kTimingFigures = 6;

// Whether the measurement gets a timing diagram: a window of some length with its captured
// edge, or a window whose edge the check did not capture (a missing edge, failed).
[[nodiscard]] bool has_timing(const Measurement& m);

// Whether the measurement is a time from its window's start (a latency in ns, us, ms or s).
[[nodiscard]] bool is_time_from_start(const Measurement& m);

// Where a correct board's edge falls: for a time from the window's start, [begin + lower (or
// begin), begin + upper (or open: Nanos::max())], none when it has no limit (a minimum or a
// median, reported only); otherwise the measurement's window itself (a position tolerance
// crossed in time, or the time a missing edge was waited for).
[[nodiscard]] std::optional<TraceWindow> expected_window(const Measurement& m);

// The measurement as its diagram shows it: its own limits, except a pulse_width check's pulse,
// which shows the one band [min, max] every pulse must lie in (the check judges its shortest
// pulse against min and its longest against max: each alone shows half the band).
[[nodiscard]] Measurement as_drawn(const CheckResult& c, const Measurement& m);

// The peak step rate band [lower, upper] (steps/s) a shaft_move check expects, from its
// peak_speed measurement's limits; none without one.
struct RateBand {
  std::optional<double> lower, upper;
};
[[nodiscard]] std::optional<RateBand> expected_rate(const CheckResult& c);

// The run time a diagram shows: the window, the expected window and the edge, with a fifth
// of their span (at least 1 us) either side; an open expected window shows at least 1 ms.
[[nodiscard]] TraceWindow figure_span(const Measurement& m);

// The measurements drawn: those with timing, not passing first, then those with an expected
// window (else in recorded order), one per distinct window and edge, at most kTimingFigures.
[[nodiscard]] std::vector<const Measurement*> timing_figures(const CheckResult& c);

// The trace cut for `m` (same window), or null.
[[nodiscard]] const WindowTrace* trace_for(const CheckResult& c, const Measurement& m);

} // namespace hilrig::rig
