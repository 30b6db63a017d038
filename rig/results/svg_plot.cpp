#include "rig/results/svg_plot.hpp"

#include <cmath>
#include <fmt/format.h>

#include "rig/results/xml_escape.hpp"

namespace hilrig::rig::svg {

Scale::Scale(double lo_, double hi_, double px0_, double px1_) : lo(lo_), hi(hi_), px0(px0_), px1(px1_) {
  if (!(hi > lo)) {
    const double d = std::max(std::abs(lo) * 0.1, 1.0);
    lo -= d;
    hi += d;
  }
}

Scale padded(double lo, double hi, double fraction, double floor, double px0, double px1) {
  const double pad = std::max((hi - lo) * fraction, floor);
  return Scale(lo - pad, hi + pad, px0, px1);
}

std::vector<double> nice_ticks(double lo, double hi, int count) {
  std::vector<double> out;
  if (!(hi > lo) || count < 1) return out;
  const double raw = (hi - lo) / count;
  const double mag = std::pow(10.0, std::floor(std::log10(raw)));
  const double f = raw / mag;
  const double step = (f < 1.5 ? 1.0 : f < 3.5 ? 2.0 : f < 7.5 ? 5.0 : 10.0) * mag;
  for (double v = std::ceil(lo / step) * step; v <= hi + step * 1e-9; v += step)
    out.push_back(std::abs(v) < step * 1e-9 ? 0.0 : v);
  return out;
}

std::string x_axis(const Scale& x, double y, Label label, const std::string& title) {
  std::string s =
      fmt::format("<g class=\"axis\"><line x1=\"{:.1f}\" y1=\"{:.1f}\" x2=\"{:.1f}\" y2=\"{:.1f}\" "
                  "stroke=\"#57606a\"/>",
                  x.px0, y, x.px1, y);
  for (const double v : nice_ticks(x.lo, x.hi, 6)) {
    s += fmt::format("<line x1=\"{0:.1f}\" y1=\"{1:.1f}\" x2=\"{0:.1f}\" y2=\"{2:.1f}\" stroke=\"#57606a\"/>"
                     "<text x=\"{0:.1f}\" y=\"{3:.1f}\" font-size=\"9\" text-anchor=\"middle\">{4}</text>",
                     x(v), y, y + 3, y + 12, xml_escape(label(v)));
  }
  s += fmt::format(
      "<text x=\"{:.1f}\" y=\"{:.1f}\" font-size=\"9\" text-anchor=\"end\" fill=\"#57606a\">{}</text>", x.px1,
      y + 22, xml_escape(title));
  return s + "</g>";
}

std::string y_axis(const Scale& y, double x, Label label, const std::string& title) {
  std::string s =
      fmt::format("<g class=\"axis\"><line x1=\"{0:.1f}\" y1=\"{1:.1f}\" x2=\"{0:.1f}\" y2=\"{2:.1f}\" "
                  "stroke=\"#57606a\"/>",
                  x, y.px0, y.px1);
  for (const double v : nice_ticks(std::min(y.lo, y.hi), std::max(y.lo, y.hi), 4)) {
    s += fmt::format("<line x1=\"{0:.1f}\" y1=\"{1:.1f}\" x2=\"{2:.1f}\" y2=\"{1:.1f}\" stroke=\"#57606a\"/>"
                     "<text x=\"{3:.1f}\" y=\"{4:.1f}\" font-size=\"9\" text-anchor=\"end\">{5}</text>",
                     x - 3, y(v), x, x - 5, y(v) + 3, xml_escape(label(v)));
  }
  s += fmt::format("<text x=\"{:.1f}\" y=\"{:.1f}\" font-size=\"9\" fill=\"#57606a\">{}</text>", x + 4,
                   std::min(y.px0, y.px1) - 4, xml_escape(title));
  return s + "</g>";
}

std::string open(double width, double height, const std::string& title) {
  return fmt::format(
      "<svg xmlns=\"http://www.w3.org/2000/svg\" width=\"{0}\" height=\"{1}\" viewBox=\"0 0 {0} {1}\" "
      "role=\"img\"><title>{2}</title>",
      width, height, xml_escape(title));
}

} // namespace hilrig::rig::svg
