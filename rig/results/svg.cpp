#include "rig/results/svg.hpp"

#include <algorithm>
#include <cmath>
#include <fmt/format.h>
#include <vector>

#include "rig/results/xml_escape.hpp"

namespace hilrig::rig {
namespace {

constexpr double kWidth = 520.0;
constexpr double kLeft = 10.0;
constexpr double kPlot = 500.0;

const char* outcome_colour(Judgement j) {
  switch (j) {
  case Judgement::Pass:
    return "#1a7f37";
  case Judgement::Fail:
    return "#cf222e";
  case Judgement::Caught:
    return "#0969da";
  case Judgement::NotJudged:
    return "#57606a";
  case Judgement::Error:
    return "#9a6700";
  }
  return "#9a6700";
}

} // namespace

std::string timing_diagram_svg(const Measurement& m, Judgement shown) {
  if (!m.window || !m.at) return {};
  const double t0 = static_cast<double>(m.window->begin.count());
  const double w0 = 0.0;
  const double w1 = static_cast<double>(m.window->end.count()) - t0;
  const double e = static_cast<double>(m.at->count()) - t0;
  double lo = std::min({w0, w1, e});
  double hi = std::max({w0, w1, e});
  const double margin = std::max((hi - lo) * 0.25, 1000.0); // at least 1 us either side
  lo -= margin;
  hi += margin;
  const auto x = [&](double t) { return kLeft + (t - lo) / (hi - lo) * kPlot; };
  std::string s = fmt::format("<svg xmlns=\"http://www.w3.org/2000/svg\" width=\"{}\" height=\"70\" "
                              "viewBox=\"0 0 {} 70\" role=\"img\"><title>{}</title>",
                              kWidth, kWidth, xml_escape(m.name));
  s += fmt::format(
      "<rect x=\"{:.1f}\" y=\"12\" width=\"{:.1f}\" height=\"30\" fill=\"#d1f0d9\" stroke=\"#1a7f37\"/>",
      x(w0), std::max(1.0, x(w1) - x(w0)));
  s +=
      fmt::format("<line x1=\"{}\" y1=\"42\" x2=\"{}\" y2=\"42\" stroke=\"#57606a\"/>", kLeft, kLeft + kPlot);
  s += fmt::format(
      "<line x1=\"{0:.1f}\" y1=\"6\" x2=\"{0:.1f}\" y2=\"46\" stroke=\"{1}\" stroke-width=\"2\"/>", x(e),
      outcome_colour(shown));
  s += fmt::format(
      "<text x=\"{:.1f}\" y=\"58\" font-size=\"10\" text-anchor=\"middle\">window {:.3f}..{:.3f} us</text>",
      (x(w0) + x(w1)) / 2.0, w0 / 1e3, w1 / 1e3);
  s += fmt::format(
      "<text x=\"{:.1f}\" y=\"68\" font-size=\"10\" text-anchor=\"middle\" fill=\"{}\">edge {:.3f} us</text>",
      x(e), outcome_colour(shown), e / 1e3);
  s += "</svg>";
  return s;
}

std::string histogram_svg(std::span<const double> values, const std::string& unit,
                          std::optional<double> limit) {
  if (values.empty()) return {};
  double lo = *std::min_element(values.begin(), values.end());
  double hi = *std::max_element(values.begin(), values.end());
  if (limit) hi = std::max(hi, *limit);
  if (hi <= lo) hi = lo + 1.0;
  const auto bins = static_cast<std::size_t>(
      std::clamp(std::ceil(std::sqrt(static_cast<double>(values.size()))), 1.0, 40.0));
  std::vector<std::size_t> counts(bins, 0);
  for (const double v : values) {
    const auto b = static_cast<std::size_t>((v - lo) / (hi - lo) * static_cast<double>(bins));
    ++counts[std::min(b, bins - 1)];
  }
  const std::size_t peak = *std::max_element(counts.begin(), counts.end());
  const double plot_h = 100.0;
  const double bar_w = kPlot / static_cast<double>(bins);
  std::string s = fmt::format("<svg xmlns=\"http://www.w3.org/2000/svg\" width=\"{}\" height=\"140\" "
                              "viewBox=\"0 0 {} 140\" role=\"img\"><title>histogram of {} values</title>",
                              kWidth, kWidth, values.size());
  for (std::size_t i = 0; i < bins; ++i) {
    const double h = plot_h * static_cast<double>(counts[i]) / static_cast<double>(peak);
    s += fmt::format("<rect x=\"{:.1f}\" y=\"{:.1f}\" width=\"{:.1f}\" height=\"{:.1f}\" fill=\"#0969da\">"
                     "<title>{}</title></rect>",
                     kLeft + bar_w * static_cast<double>(i), 10.0 + plot_h - h, std::max(bar_w - 1.0, 0.5), h,
                     counts[i]);
  }
  s += fmt::format("<line x1=\"{}\" y1=\"110\" x2=\"{}\" y2=\"110\" stroke=\"#57606a\"/>", kLeft,
                   kLeft + kPlot);
  if (limit) {
    const double lx = kLeft + (*limit - lo) / (hi - lo) * kPlot;
    s += fmt::format(
        "<line x1=\"{0:.1f}\" y1=\"6\" x2=\"{0:.1f}\" y2=\"112\" stroke=\"#cf222e\" "
        "stroke-dasharray=\"4 3\"/><text x=\"{0:.1f}\" y=\"8\" font-size=\"10\" text-anchor=\"end\" "
        "fill=\"#cf222e\">limit {1} {2}</text>",
        lx, *limit, xml_escape(unit));
  }
  s += fmt::format("<text x=\"{}\" y=\"126\" font-size=\"10\">{} {}</text>", kLeft, lo, xml_escape(unit));
  s += fmt::format("<text x=\"{}\" y=\"126\" font-size=\"10\" text-anchor=\"end\">{} {}</text>",
                   kLeft + kPlot, hi, xml_escape(unit));
  s += fmt::format(
      "<text x=\"{}\" y=\"138\" font-size=\"10\" text-anchor=\"middle\">{} samples, peak bin {}</text>",
      kLeft + kPlot / 2.0, values.size(), peak);
  s += "</svg>";
  return s;
}

} // namespace hilrig::rig
