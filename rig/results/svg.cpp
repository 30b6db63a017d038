#include "rig/results/svg.hpp"

#include <algorithm>
#include <cmath>
#include <fmt/format.h>
#include <limits>
#include <utility>
#include <vector>

#include "rig/results/number_format.hpp"
#include "rig/results/svg_plot.hpp"
#include "rig/results/xml_escape.hpp"

namespace hilrig::rig {
namespace {

constexpr double kWidth = 600.0;
constexpr double kLeft = 70.0;   // room for y labels / row names
constexpr double kRight = 580.0; // plot's right edge
constexpr const char* kLimit = "#cf222e";
constexpr const char* kBand = "#d1f0d9";

std::string time_label(double ns) { return format_ns(ns); }
std::string number_label(double v) { return format_number(v); }

std::string vline(double x, double y0, double y1, const char* colour, bool dashed) {
  return fmt::format("<line x1=\"{0:.1f}\" y1=\"{1:.1f}\" x2=\"{0:.1f}\" y2=\"{2:.1f}\" stroke=\"{3}\"{4}/>",
                     x, y0, y1, colour, dashed ? " stroke-dasharray=\"4 3\"" : "");
}

std::string text(double x, double y, const std::string& s, const char* anchor,
                 const char* colour = "#1f2328") {
  return fmt::format(
      "<text x=\"{:.1f}\" y=\"{:.1f}\" font-size=\"9\" text-anchor=\"{}\" fill=\"{}\">{}</text>", x, y,
      anchor, colour, xml_escape(s));
}

// A label's anchor so it stays on the canvas near x.
const char* anchor_at(double x) { return x < kLeft + 60 ? "start" : x > kRight - 60 ? "end" : "middle"; }

} // namespace

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

namespace {

// The lane's value at t (its last change at or before t).
std::int64_t value_at(const TraceLane& lane, Nanos t) {
  std::int64_t v = lane.changes.empty() ? 0 : lane.changes.front().value;
  for (const auto& c : lane.changes) {
    if (c.time > t) break;
    v = c.value;
  }
  return v;
}

// A lane as a step line between y_of(value) levels across the plot.
std::string step_line(const TraceLane& lane, const svg::Scale& x, double span_end, auto y_of,
                      const char* colour) {
  std::string pts;
  std::int64_t v = lane.changes.front().value;
  pts += fmt::format("{:.1f},{:.1f}", kLeft, y_of(v));
  for (std::size_t i = 1; i < lane.changes.size(); ++i) {
    const double px = x(static_cast<double>(lane.changes[i].time.count()));
    pts += fmt::format(" {0:.1f},{1:.1f} {0:.1f},{2:.1f}", px, y_of(v), y_of(lane.changes[i].value));
    v = lane.changes[i].value;
  }
  pts += fmt::format(" {:.1f},{:.1f}", x(span_end), y_of(v));
  return fmt::format("<polyline points=\"{}\" fill=\"none\" stroke=\"{}\" stroke-width=\"1.5\"/>", pts,
                     colour);
}

const char* lane_colour(LaneRole r) {
  return r == LaneRole::Stimulus ? "#0969da"
         : r == LaneRole::Count  ? "#8250df"
         : r == LaneRole::Rate   ? "#bf3989"
                                 : "#1f2328";
}

// The limits as the reader states them: "limit 100 µs after the start", "expected 9.5 .. 10.5 counts".
std::string limit_words(const Measurement& m) {
  const auto v = [&](const std::optional<double>& l) { return format_value(*l, m.unit); };
  if (m.lower && m.upper) return fmt::format("expected {} .. {}", v(m.lower), v(m.upper));
  if (m.upper) return (is_time_from_start(m) ? "limit: start + " : "at most ") + v(m.upper);
  if (m.lower) return (is_time_from_start(m) ? "start + at least " : "at least ") + v(m.lower);
  return "expected window";
}

} // namespace

std::string timing_diagram_svg(const Measurement& m, Judgement shown, const WindowTrace* trace) {
  if (!m.window) return {};
  const TraceWindow span = trace ? trace->span : figure_span(m);
  const double s0 = static_cast<double>(span.begin.count()), s1 = static_cast<double>(span.end.count());
  const svg::Scale x(s0, s1, kLeft, kRight);
  const auto px = [&](Nanos t) { return std::clamp(x(static_cast<double>(t.count())), kLeft, kRight); };
  const char* edge_colour = outcome_colour(shown);
  constexpr double kTop = 24, kLogic = 22, kCount = 40;
  // The lanes: the trace's, or one output lane stepping at the captured edge.
  std::vector<TraceLane> fallback;
  if (!trace || trace->lanes.empty()) {
    TraceLane out{"edge", LaneRole::Output, {{span.begin, 0}}, 0};
    if (m.at) out.changes.push_back({*m.at, 1});
    fallback.push_back(std::move(out));
  }
  const std::vector<TraceLane>& lanes = fallback.empty() ? trace->lanes : fallback;
  double bottom = kTop;
  const auto levels = [](const TraceLane& l) {
    return l.role == LaneRole::Count || l.role == LaneRole::Rate;
  };
  for (const auto& l : lanes) bottom += levels(l) ? kCount : kLogic;
  std::string body;
  // The expected window behind every lane, its limits dashed; a time from an event marks the event.
  const std::optional<TraceWindow> want = expected_window(m);
  const bool from_start = is_time_from_start(m);
  const auto limit_line = [&](double at) {
    return fmt::format("<line class=\"limit\" x1=\"{0:.1f}\" y1=\"{1:.1f}\" x2=\"{0:.1f}\" y2=\"{2:.1f}\" "
                       "stroke=\"{3}\" stroke-dasharray=\"4 3\"/>",
                       at, kTop - 8, bottom, kLimit);
  };
  if (want) {
    const double w0 = px(want->begin), w1 = want->end == Nanos::max() ? kRight : px(want->end);
    body +=
        fmt::format("<rect class=\"expected\" x=\"{:.1f}\" y=\"{:.1f}\" width=\"{:.1f}\" height=\"{:.1f}\" "
                    "fill=\"{}\" stroke=\"#1a7f37\"/>",
                    w0, kTop - 4, std::max(1.0, w1 - w0), bottom - kTop + 4, kBand);
    if (!from_start || m.lower) body += limit_line(w0);
    if (want->end != Nanos::max()) body += limit_line(w1);
    body += text(from_start ? w1 : (w0 + w1) / 2, 10, limit_words(m),
                 anchor_at(from_start ? w1 : (w0 + w1) / 2), kLimit);
  } else {
    body += text(kRight, 10, "no limit: reported only", "end", "#57606a");
  }
  if (from_start) {
    const double at = px(m.window->begin);
    body += vline(at, kTop - 8, bottom, "#57606a", false);
    body += text(at, 20, "start " + format_time(m.window->begin), anchor_at(at), "#57606a");
  }
  double y = kTop;
  std::string notes;
  for (const auto& lane : lanes) {
    const bool count = levels(lane);
    const std::string unit = lane.role == LaneRole::Rate ? " steps/s" : "";
    const double h = count ? kCount : kLogic;
    body +=
        fmt::format("<g class=\"lane {}\" data-lane=\"{}\">", to_string(lane.role), xml_escape(lane.name));
    body += text(kLeft - 4, y + h / 2 + 3, lane.name, "end", lane_colour(lane.role));
    if (count) {
      std::int64_t lo = lane.changes.front().value, hi = lo;
      for (const auto& c : lane.changes) lo = std::min(lo, c.value), hi = std::max(hi, c.value);
      const svg::Scale yc(static_cast<double>(lo), static_cast<double>(hi), y + h - 6, y + 6);
      body += step_line(
          lane, x, s1, [&](std::int64_t v) { return yc(static_cast<double>(v)); }, lane_colour(lane.role));
      body +=
          text(kLeft + 2, y + 8, std::to_string(lane.changes.front().value), "start", lane_colour(lane.role));
      body +=
          text(kRight - 2, y + 8, std::to_string(lane.changes.back().value), "end", lane_colour(lane.role));
      if (m.at && *m.at >= span.begin && *m.at <= span.end)
        body += text(px(*m.at) + 3, y + h - 2, fmt::format("count {} at the edge", value_at(lane, *m.at)),
                     anchor_at(px(*m.at)), edge_colour);
    } else {
      body += step_line(
          lane, x, s1, [&](std::int64_t v) { return v != 0 ? y + 4 : y + h - 5; },
          lane.role == LaneRole::Output ? edge_colour : lane_colour(lane.role));
    }
    if (lane.thinned > 0) notes += fmt::format("{}: {} changes thinned to fit; ", lane.name, lane.thinned);
    body += "</g>";
    y += h;
  }
  if (m.at) {
    body += fmt::format("<line class=\"edge\" x1=\"{0:.1f}\" y1=\"{1:.1f}\" x2=\"{0:.1f}\" y2=\"{2:.1f}\" "
                        "stroke=\"{3}\" stroke-width=\"1.5\"/>",
                        px(*m.at), kTop - 4, bottom, edge_colour);
    body += text(px(*m.at), bottom + 32,
                 fmt::format("edge {}: {} {}", format_time(*m.at), m.name, format_value(m.value, m.unit)),
                 anchor_at(px(*m.at)), edge_colour);
  } else {
    body += text((kLeft + kRight) / 2, bottom + 32, "no edge captured", "middle", edge_colour);
  }
  body += svg::x_axis(x, bottom + 2, time_label, "run time");
  double height = bottom + 38;
  if (!notes.empty()) {
    body += text(kLeft, height + 6, notes.substr(0, notes.size() - 2), "start", "#57606a");
    height += 12;
  }
  return svg::open(kWidth, height, "timing of " + m.name) + body + svg::kClose;
}

std::string limits_svg(std::span<const ShownMeasurement> rows) {
  std::vector<ShownMeasurement> kept;
  for (const auto& r : rows)
    if (r.m->lower || r.m->upper) kept.push_back(r);
  if (kept.empty()) return {};
  constexpr double kRow = 26.0, kName = 200.0, kGaugeL = 210.0, kGaugeR = 520.0;
  const double height = kRow * static_cast<double>(kept.size()) + 8;
  std::string s = svg::open(kWidth, height, "measurements against their limits");
  double y = 4;
  for (const auto& [m, shown] : kept) {
    const double v = std::isfinite(m->value) ? m->value : 0.0;
    double lo = v, hi = v;
    for (const auto& l : {m->lower, m->upper})
      if (l) lo = std::min(lo, *l), hi = std::max(hi, *l);
    const svg::Scale x = svg::padded(lo, hi, 0.25, std::max(std::abs(hi) * 1e-3, 1e-6), kGaugeL, kGaugeR);
    const double mid = y + 11;
    s += text(kName, mid + 3, m->name, "end");
    s += fmt::format("<line x1=\"{}\" y1=\"{:.1f}\" x2=\"{}\" y2=\"{:.1f}\" stroke=\"#d0d7de\"/>", kGaugeL,
                     mid, kGaugeR, mid);
    const double b0 = m->lower ? x(*m->lower) : kGaugeL, b1 = m->upper ? x(*m->upper) : kGaugeR;
    s += fmt::format("<rect x=\"{:.1f}\" y=\"{:.1f}\" width=\"{:.1f}\" height=\"10\" fill=\"{}\"/>", b0,
                     mid - 5, std::max(1.0, b1 - b0), kBand);
    for (const auto& l : {m->lower, m->upper}) {
      if (!l) continue;
      s += vline(x(*l), mid - 8, mid + 8, kLimit, true);
      s += text(x(*l), mid + 15, format_value(*l, m->unit), "middle", kLimit);
    }
    if (std::isfinite(m->value)) {
      s += fmt::format("<circle cx=\"{:.1f}\" cy=\"{:.1f}\" r=\"4\" fill=\"{}\"/>", x(v), mid,
                       outcome_colour(shown));
    }
    s += text(kGaugeR + 6, mid + 3, format_value(m->value, m->unit), "start", outcome_colour(shown));
    y += kRow;
  }
  return s + svg::kClose;
}

std::string histogram_svg(std::span<const double> values, const std::string& unit,
                          std::span<const LimitLine> limits) {
  if (values.empty()) return {};
  const double vmin = *std::min_element(values.begin(), values.end());
  const double vmax = *std::max_element(values.begin(), values.end());
  double lo = vmin, hi = vmax;
  for (const auto& l : limits) lo = std::min(lo, l.value), hi = std::max(hi, l.value);
  const svg::Scale x = svg::padded(lo, hi, 0.05, 1e-3, kLeft, kRight);
  // Bins over the values' own range, so a far limit does not crush them into one bar.
  const auto bins = static_cast<std::size_t>(
      std::clamp(std::ceil(std::sqrt(static_cast<double>(values.size()))), 10.0, 50.0));
  const double width =
      vmax > vmin ? (vmax - vmin) / static_cast<double>(bins) : std::max(std::abs(vmax) * 1e-3, 1e-3);
  std::vector<std::size_t> counts(bins, 0);
  for (const double v : values) {
    const auto i = static_cast<std::size_t>(std::max(0.0, std::floor((v - vmin) / width)));
    ++counts[std::min(i, bins - 1)];
  }
  const double peak = static_cast<double>(*std::max_element(counts.begin(), counts.end()));
  const svg::Scale y(0.0, peak, 130.0, 24.0);
  std::string s = svg::open(kWidth, 168, fmt::format("histogram of {} values", values.size()));
  for (std::size_t i = 0; i < bins; ++i) {
    if (counts[i] == 0) continue;
    const double b0 = vmin + width * static_cast<double>(i);
    const double px0 = x(b0), px1 = std::max(x(b0 + width), px0 + 1.5);
    s += fmt::format(
        "<rect x=\"{:.1f}\" y=\"{:.1f}\" width=\"{:.1f}\" height=\"{:.1f}\" fill=\"#0969da\"><title>{} "
        "in [{}, {})</title></rect>",
        px0, y(static_cast<double>(counts[i])), std::max(px1 - px0 - 0.5, 1.0),
        130.0 - y(static_cast<double>(counts[i])), counts[i], format_value(b0, unit),
        format_value(b0 + width, unit));
  }
  double label_y = 12;
  for (const auto& l : limits) {
    s += vline(x(l.value), 8, 132, kLimit, true);
    s += text(x(l.value) - 3, label_y, l.name + " limit " + format_value(l.value, unit), "end", kLimit);
    label_y += 10;
  }
  s += svg::y_axis(y, kLeft, number_label, "count");
  s += svg::x_axis(x, 132, number_label, unit == "us" ? "µs" : unit);
  s += text(kLeft, 164,
            fmt::format("{} samples in {} bins of {}", values.size(), bins, format_value(width, unit)),
            "start", "#57606a");
  return s + svg::kClose;
}

std::string probes_svg(std::span<const Probe> probes, std::optional<double> band_lo_ns,
                       std::optional<double> band_hi_ns) {
  if (probes.empty()) return {};
  double lo = std::numeric_limits<double>::max(), hi = std::numeric_limits<double>::lowest();
  for (const auto& p : probes) {
    lo = std::min(lo, static_cast<double>(p.width.count()));
    hi = std::max(hi, static_cast<double>(p.width.count()));
  }
  for (const auto& b : {band_lo_ns, band_hi_ns})
    if (b) lo = std::min(lo, *b), hi = std::max(hi, *b);
  const svg::Scale x = svg::padded(lo, hi, 0.05, 1000.0, kLeft, kRight);
  std::string s = svg::open(kWidth, 110, "debounce probes against the filter band");
  if (band_lo_ns || band_hi_ns) {
    const double b0 = band_lo_ns ? x(*band_lo_ns) : kLeft, b1 = band_hi_ns ? x(*band_hi_ns) : kRight;
    s += fmt::format(
        "<rect x=\"{:.1f}\" y=\"14\" width=\"{:.1f}\" height=\"62\" fill=\"#fff8c5\" stroke=\"#9a6700\"/>",
        b0, std::max(1.0, b1 - b0));
    s += text((b0 + b1) / 2, 11, "filter band", "middle", "#9a6700");
  }
  s += text(kLeft - 4, 33, "accepted", "end", "#1a7f37") + text(kLeft - 4, 63, "rejected", "end", "#57606a");
  for (std::size_t i = 0; i < probes.size(); ++i) {
    const Probe& p = probes[i];
    const double px = x(static_cast<double>(p.width.count()));
    const double py = p.accepted ? 30 : 60;
    s += fmt::format(
        "<circle cx=\"{:.1f}\" cy=\"{}\" r=\"4\" fill=\"{}\" stroke=\"{}\"><title>probe {}: {} {}</title>"
        "</circle>",
        px, py, p.accepted ? "#1a7f37" : "#ffffff", p.accepted ? "#1a7f37" : "#57606a", i + 1,
        format_time(p.width), p.accepted ? "accepted" : "rejected");
    s += text(px, py - 6, std::to_string(i + 1), "middle", "#57606a");
  }
  s += svg::x_axis(x, 80, time_label, "pulse width");
  return s + svg::kClose;
}

std::string motion_svg(const MotionRecord& motion, std::span<const Marker> markers, std::optional<Nanos> from,
                       std::optional<Nanos> to) {
  if (motion.empty()) return {};
  const Nanos t0 = from.value_or(motion.points.front().time);
  const Nanos t1 = to.value_or(motion.points.back().time);
  // The points inside [t0, t1] and one either side, clipped to the plot: the line reaches the
  // edges even where the recorded knots are far apart.
  std::vector<MotionPoint> pts;
  const auto& all = motion.points;
  for (std::size_t i = 0; i < all.size(); ++i) {
    const bool next_inside = i + 1 < all.size() && all[i + 1].time >= t0;
    const bool prev_inside = i > 0 && all[i - 1].time <= t1;
    if ((all[i].time >= t0 && all[i].time <= t1) || (all[i].time < t0 && next_inside) ||
        (all[i].time > t1 && prev_inside))
      pts.push_back(all[i]);
  }
  if (pts.size() < 2) pts = all;
  double pmin = pts.front().position, pmax = pmin, vmin = pts.front().speed, vmax = vmin;
  for (const auto& p : pts) {
    pmin = std::min(pmin, p.position), pmax = std::max(pmax, p.position);
    vmin = std::min(vmin, p.speed), vmax = std::max(vmax, p.speed);
  }
  vmin = std::min(vmin, 0.0);
  const svg::Scale x(static_cast<double>(t0.count()), static_cast<double>(t1.count()), kLeft, kRight);
  const svg::Scale ys = svg::padded(vmin, vmax, 0.05, 1e-6, 110, 30);
  const svg::Scale yp = svg::padded(pmin, pmax, 0.05, 1e-6, 210, 130);
  std::string s = svg::open(kWidth, 260, "speed and position against time");
  const auto poly = [&](const svg::Scale& y, auto value, const char* colour) {
    std::string pts_attr;
    for (const auto& p : pts)
      pts_attr += fmt::format("{:.1f},{:.1f} ", x(static_cast<double>(p.time.count())), y(value(p)));
    return fmt::format("<polyline points=\"{}\" fill=\"none\" stroke=\"{}\" stroke-width=\"1.5\"/>", pts_attr,
                       colour);
  };
  // A nested viewport the width of the plot clips the lines at its edges.
  s += fmt::format("<svg x=\"{0}\" y=\"0\" width=\"{1}\" height=\"260\" viewBox=\"{0} 0 {1} 260\">", kLeft,
                   kRight - kLeft);
  s += poly(
      ys, [](const MotionPoint& p) { return p.speed; }, "#0969da");
  s += poly(
      yp, [](const MotionPoint& p) { return p.position; }, "#8250df");
  s += "</svg>";
  s += svg::y_axis(ys, kLeft, number_label, "speed (counts/s)");
  s += svg::y_axis(yp, kLeft, number_label, "position (counts)");
  double label_y = 248;
  const auto mark = [&](Nanos t, const std::string& label, const char* colour, bool dashed) {
    if (t < t0 || t > t1) return;
    const double px = x(static_cast<double>(t.count()));
    s += vline(px, 24, 212, colour, dashed);
    s += text(px, label_y, label + " " + format_time(t), anchor_at(px), colour);
    label_y += 10;
  };
  for (const auto& e : motion.events) mark(e.time, e.what, "#57606a", false);
  for (const auto& m : markers) mark(m.time, m.label, m.colour, true);
  s += svg::x_axis(x, 212, time_label, "run time");
  // The labels grew the figure downwards: resize it to fit them.
  const double height = std::max(260.0, label_y + 4);
  const std::string head = svg::open(kWidth, 260, "speed and position against time");
  return svg::open(kWidth, height, "speed and position against time") + s.substr(head.size()) + svg::kClose;
}

std::string trend_svg(std::span<const TrendPoint> nights, const std::string& unit,
                      std::optional<double> lower, std::optional<double> upper) {
  std::vector<double> shown;
  for (const TrendPoint& p : nights)
    if (p.value) shown.push_back(*p.value);
  if (shown.empty()) return {};
  // The limits are always on the canvas, however far the values are from them.
  if (lower) shown.push_back(*lower);
  if (upper) shown.push_back(*upper);
  const auto [lo, hi] = std::minmax_element(shown.begin(), shown.end());
  const svg::Scale y = svg::padded(*lo, *hi, 0.1, 1e-3, 120.0, 14.0);
  const double last = static_cast<double>(std::max<std::size_t>(nights.size(), 2) - 1);
  const svg::Scale x(0.0, last, kLeft + 10, kRight - 10);
  std::string s = svg::open(kWidth, 150, fmt::format("{} over {} night(s)", unit, nights.size()));
  s += svg::y_axis(y, kLeft, number_label, unit);
  for (const auto& [limit, word] : {std::pair{lower, "lower"}, std::pair{upper, "upper"}}) {
    if (!limit) continue;
    s += fmt::format("<line x1=\"{:.1f}\" y1=\"{:.1f}\" x2=\"{:.1f}\" y2=\"{:.1f}\" stroke=\"{}\" "
                     "stroke-dasharray=\"4 3\"/>",
                     kLeft, y(*limit), kRight, y(*limit), kLimit);
    s += text(kRight, y(*limit) - 2, fmt::format("{} limit {}", word, format_value(*limit, unit)), "end",
              kLimit);
  }
  std::string path;
  for (std::size_t i = 0; i < nights.size(); ++i)
    if (nights[i].value)
      path += fmt::format("{}{:.1f},{:.1f}", path.empty() ? "M" : " L", x(static_cast<double>(i)),
                          y(*nights[i].value));
  s += fmt::format("<path d=\"{}\" fill=\"none\" stroke=\"#0969da\"/>", path);
  for (std::size_t i = 0; i < nights.size(); ++i) {
    const TrendPoint& p = nights[i];
    if (!p.value) continue;
    const Judgement j = p.outcome == Outcome::Pass   ? Judgement::Pass
                        : p.outcome == Outcome::Fail ? Judgement::Fail
                                                     : Judgement::Error;
    s += fmt::format(
        "<circle cx=\"{:.1f}\" cy=\"{:.1f}\" r=\"3.5\" fill=\"{}\"><title>{}: {} ({})</title></circle>",
        x(static_cast<double>(i)), y(*p.value), outcome_colour(j), xml_escape(p.label),
        xml_escape(format_value(*p.value, unit)), to_string(p.outcome));
  }
  s += text(x(0.0), 140, nights.front().label, "start");
  if (nights.size() > 1) s += text(x(last), 140, nights.back().label, "end");
  s += svg::kClose;
  return s;
}

} // namespace hilrig::rig
