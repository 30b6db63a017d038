#pragma once
// Inline SVG figures for report.html: a timing diagram (expected window against captured
// edge) and a histogram (latency distribution against its limit). Self-contained markup.

#include <optional>
#include <span>
#include <string>

#include "rig/results/measurement.hpp"

namespace hilrig::rig {

// The measurement's window drawn as the expected band and `at` as the captured edge; the
// axis is in us relative to the window's start. Empty when the measurement has no window or at.
// The edge is drawn in the colour of `shown`, the word the report gives the measurement.
[[nodiscard]] std::string timing_diagram_svg(const Measurement& m, Judgement shown);

// Histogram of values with a dashed line at `limit` (if any). Empty when there are no values.
[[nodiscard]] std::string histogram_svg(std::span<const double> values, const std::string& unit,
                                        std::optional<double> limit);

} // namespace hilrig::rig
