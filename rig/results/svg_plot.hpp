#pragma once
// The pieces every report figure is drawn with: a linear scale from data to pixels, "nice"
// axis ticks (1, 2, 5 × 10^k) and an axis with its labels, as inline SVG markup.

#include <string>
#include <vector>

namespace hilrig::rig::svg {

// [lo, hi] in data units onto [px0, px1] in pixels; a degenerate range is widened.
struct Scale {
  double lo, hi, px0, px1;
  Scale(double lo_, double hi_, double px0_, double px1_);
  [[nodiscard]] double operator()(double v) const { return px0 + (v - lo) / (hi - lo) * (px1 - px0); }
};

// [lo, hi] grown by `fraction` of its span on each side (and by `floor` at least).
[[nodiscard]] Scale padded(double lo, double hi, double fraction, double floor, double px0, double px1);
// About `count` round tick values inside [lo, hi].
[[nodiscard]] std::vector<double> nice_ticks(double lo, double hi, int count);

// Tick labels are `label(value)`.
using Label = std::string (*)(double);
// A horizontal axis at y with ticks and labels below it, and its title right-aligned.
[[nodiscard]] std::string x_axis(const Scale& x, double y, Label label, const std::string& title);
// A vertical axis at x with ticks and labels to its left, and its title above it.
[[nodiscard]] std::string y_axis(const Scale& y, double x, Label label, const std::string& title);

// The opening tag (with a <title> for screen readers) and the closing one.
[[nodiscard]] std::string open(double width, double height, const std::string& title);
inline constexpr const char* kClose = "</svg>";

} // namespace hilrig::rig::svg
