#pragma once
// What each report figure shows, as the JSON report-web/figures.js draws with uPlot: drawn
// from what the results recorded (never recomputed). A figure is {kind, title, charts, notes};
// a chart is its series ("data": x then one array per series), its scales, and its marks:
// "bands" (x ranges shaded), "vlines" (instants or limits on x), "hlines" (limits on y). Times
// are nanoseconds from the figure's origin (x.origin says which instant), so the axes read
// "time from the window start" in the unit that fits.

#include <nlohmann/json.hpp>
#include <optional>
#include <span>
#include <string>

#include "rig/results/measurement.hpp"
#include "rig/results/motion_record.hpp"
#include "rig/results/timing_figures.hpp"

namespace hilrig::rig {

// The colour of an outcome word.
[[nodiscard]] const char* outcome_colour(Judgement j);

// A timing diagram around the measurement's window, time from the window's start: the
// expected window (expected_window()) shaded over every lane with its limits marked, and the
// captured edge `at` (in the colour of `shown`) or "no edge captured". With `trace`, one chart
// per lane the run captured over its span (stimulus and output as logic levels, the shaft's
// count and a step rate as values), all stepped; without, one output lane stepping at `at`.
// Null without a window.
// A rate lane shows `rate`, the step rate band expected at the move's peak, shaded, and
// `profile`, the step rate the move's profile expects (CheckResult::expected_rate), as a
// dashed line through its knots over the measured rate.
[[nodiscard]] nlohmann::json timing_figure(const Measurement& m, Judgement shown,
                                           const WindowTrace* trace = nullptr,
                                           std::optional<RateBand> rate = std::nullopt,
                                           std::span<const RatePoint> profile = {});

// One chart per measurement with a limit: its value (a point in the colour of its word) on
// an axis in its unit holding every limit, the passing band shaded. Null when none has one.
struct ShownMeasurement {
  const Measurement* m;
  Judgement shown;
};
[[nodiscard]] nlohmann::json limits_figure(std::span<const ShownMeasurement> rows);

// A named limit line on a histogram.
struct LimitLine {
  std::string name;
  double value;
};
// Histogram of values (bins over the values' range) on an axis that always holds every limit;
// counts on the y axis. Null when there are no values.
[[nodiscard]] nlohmann::json histogram_figure(std::span<const double> values, const std::string& unit,
                                              std::span<const LimitLine> limits);

// A debounce check's probes by width (accepted above, rejected below, numbered in the order
// they ran) against the filter band [band_lo, band_hi] (ns) when known. Null without probes.
[[nodiscard]] nlohmann::json probes_figure(std::span<const Probe> probes, std::optional<double> band_lo_ns,
                                           std::optional<double> band_hi_ns);

// An instant marked on a motion plot.
struct Marker {
  Nanos time;
  std::string label;
  const char* colour;
  const char* cls; // "limit" for a limit, else "event"
};
// Speed and position against time over [from, to] (the whole record when not given), time
// from `origin` (the record's start when not given), with the record's events (grey) and
// `markers` as vertical lines. Null when the record is empty.
[[nodiscard]] nlohmann::json motion_figure(const MotionRecord& motion, std::span<const Marker> markers,
                                           std::optional<Nanos> from = std::nullopt,
                                           std::optional<Nanos> to = std::nullopt,
                                           std::optional<Nanos> origin = std::nullopt);

// One night of a measurement's trend: its value (none when that night did not measure it)
// and the word it read that night (measurement_judgement(): a fault's evidence is "caught",
// not "fail"); label names the night (its start time or file).
struct TrendPoint {
  std::string label;
  std::optional<double> value;
  Judgement word = Judgement::Error;
};
// A measurement over the nights: each night's value as a point in its word's colour,
// joined in order, with the limits as lines always on the canvas. Null when no night has a
// value.
[[nodiscard]] nlohmann::json trend_figure(std::span<const TrendPoint> nights, const std::string& unit,
                                          std::optional<double> lower, std::optional<double> upper);

} // namespace hilrig::rig
