#pragma once
// Inline SVG figures for report.html, drawn from what the results recorded (never
// recomputed): a timing diagram around a judged window, a measurement against its limits, a
// latency histogram against its limits, a debounce check's probes against the filter band,
// and a run's speed and position against time with its events. Self-contained markup.

#include <optional>
#include <span>
#include <string>
#include <vector>

#include "rig/results/measurement.hpp"
#include "rig/results/motion_record.hpp"
#include "rig/results/timing_figures.hpp"

namespace hilrig::rig {

// The colour of an outcome word.
[[nodiscard]] const char* outcome_colour(Judgement j);

// A timing diagram around the measurement's window: the expected window (expected_window())
// shaded over every lane with its limits marked, and the captured edge `at` (in the colour of
// `shown`) or "no edge captured". With `trace`, the lanes are what the run captured over
// its span: the stimulus (encoder A/B or the driven line), the shaft's count (a step line
// with its values) and the output; without, one output lane stepping at `at`. Empty without
// a window.
[[nodiscard]] std::string timing_diagram_svg(const Measurement& m, Judgement shown,
                                             const WindowTrace* trace = nullptr);

// One row per measurement: its value (a dot in the colour of its word) against its limits
// (the passing band shaded, each limit marked). Empty when no measurement has a limit.
struct ShownMeasurement {
  const Measurement* m;
  Judgement shown;
};
[[nodiscard]] std::string limits_svg(std::span<const ShownMeasurement> rows);

// A named limit line on a histogram or a probe axis.
struct LimitLine {
  std::string name;
  double value;
};
// Histogram of values (bins over the values' range) on an axis that always holds every limit;
// counts on the y axis. Empty when there are no values.
[[nodiscard]] std::string histogram_svg(std::span<const double> values, const std::string& unit,
                                        std::span<const LimitLine> limits);

// A debounce check's probes by width (accepted above, rejected below, numbered in the order
// they ran) against the filter band [band_lo, band_hi] (ns) when known. Empty without probes.
[[nodiscard]] std::string probes_svg(std::span<const Probe> probes, std::optional<double> band_lo_ns,
                                     std::optional<double> band_hi_ns);

// An instant marked on a motion plot.
struct Marker {
  Nanos time;
  std::string label;
  const char* colour;
};
// Speed and position against time over [from, to] (the whole record when not given), with
// the record's events (grey) and `markers` as vertical lines. Empty when the record is.
[[nodiscard]] std::string motion_svg(const MotionRecord& motion, std::span<const Marker> markers,
                                     std::optional<Nanos> from = std::nullopt,
                                     std::optional<Nanos> to = std::nullopt);

} // namespace hilrig::rig

namespace hilrig::rig {

// One night of a measurement's trend: its value (none when that night did not measure it)
// and outcome; label names the night (its start time or file).
struct TrendPoint {
  std::string label;
  std::optional<double> value;
  Outcome outcome = Outcome::Error;
};

// A measurement over the nights: each night's value as a point in its outcome's colour,
// joined in order, with the limits as dashed lines always on the canvas. Empty when no
// night has a value.
[[nodiscard]] std::string trend_svg(std::span<const TrendPoint> nights, const std::string& unit,
                                    std::optional<double> lower, std::optional<double> upper);

} // namespace hilrig::rig
