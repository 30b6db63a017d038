#include "rig/results/figure_data.hpp"

#include <algorithm>
#include <cmath>
#include <fmt/format.h>
#include <utility>
#include <vector>

#include "rig/results/number_format.hpp"
#include "rig/results/timing_figures.hpp"

namespace hilrig::rig {

using nlohmann::json;

namespace {

constexpr const char* kLimit = "#cf222e";
constexpr const char* kBand = "rgba(26,127,55,0.18)";
constexpr const char* kGrey = "#57606a";

double rel(Nanos t, Nanos origin) { return static_cast<double>((t - origin).count()); }

json vline(double at, const char* colour, const std::string& label, const char* cls, bool dashed) {
  return {{"at", at}, {"colour", colour}, {"label", label}, {"cls", cls}, {"dashed", dashed}};
}

json time_axis(const char* label, double min, double max) {
  return {{"label", label}, {"time", true}, {"min", min}, {"max", max}};
}

// [lo, hi] grown by `fraction` of its span on each side (by `floor` at least).
std::pair<double, double> padded(double lo, double hi, double fraction, double floor) {
  const double pad = std::max((hi - lo) * fraction, floor);
  return {lo - pad, hi + pad};
}

const char* lane_colour(LaneRole r) {
  return r == LaneRole::Stimulus ? "#0969da"
         : r == LaneRole::Count  ? "#8250df"
         : r == LaneRole::Rate   ? "#bf3989"
                                 : "#1f2328";
}

// The limits as the reader states them: "limit: start + 100 µs", "expected 9.5 .. 10.5".
std::string limit_words(const Measurement& m) {
  const auto v = [&](const std::optional<double>& l) { return format_value(*l, m.unit); };
  if (m.lower && m.upper)
    return (is_time_from_start(m) ? "expected start + " : "expected ") + v(m.lower) + " .. " + v(m.upper);
  if (m.upper) return (is_time_from_start(m) ? "limit: start + " : "at most ") + v(m.upper);
  if (m.lower) return (is_time_from_start(m) ? "start + at least " : "at least ") + v(m.lower);
  return "expected window";
}

// The lane's value at t (its last change at or before t).
std::int64_t value_at(const TraceLane& lane, Nanos t) {
  std::int64_t v = lane.changes.front().value;
  for (const auto& c : lane.changes) {
    if (c.time > t) break;
    v = c.value;
  }
  return v;
}

// One lane as a stepped series over [span.begin, span.end], time from origin.
json lane_chart(const TraceLane& lane, const TraceWindow& span, Nanos origin, const char* colour) {
  json xs = json::array(), ys = json::array();
  for (const auto& c : lane.changes) {
    // An analog lane's sample before the span (it has none inside) stays at its own time.
    xs.push_back(rel(lane.real ? c.time : std::max(c.time, span.begin), origin));
    if (lane.real)
      ys.push_back(c.real);
    else
      ys.push_back(c.value);
  }
  if (lane.real) // an analog lane: a line through its samples, ending at its last
    return {{"lane", lane.name},
            {"role", to_string(lane.role)},
            {"height", 70},
            {"y", {{"label", "V"}}},
            {"data", {std::move(xs), std::move(ys)}},
            {"series", {{{"label", lane.name}, {"colour", colour}, {"draw", "line"}}}}};
  xs.push_back(rel(span.end, origin));
  ys.push_back(lane.changes.back().value);
  const bool level = lane.role == LaneRole::Count || lane.role == LaneRole::Rate;
  json y = {{"label", lane.role == LaneRole::Rate ? "steps/s" : level ? "counts" : ""}};
  y[level ? "integer" : "logic"] = true;
  return {{"lane", lane.name},
          {"role", to_string(lane.role)},
          {"height", level ? 90 : 44},
          {"y", std::move(y)},
          {"data", {std::move(xs), std::move(ys)}},
          {"series", {{{"label", lane.name}, {"colour", colour}, {"draw", "step"}}}}};
}

// The expected profile as a second series of a rate lane's chart: uPlot gives both one x
// array, so the lane's points and the profile's knots are merged in time. At a knot the lane
// holds its level (a stepped series drawn the same); at a lane point the profile is its line
// between the knots around (the same line), and nothing outside its knots.
void add_profile(json& chart, std::span<const RatePoint> profile, Nanos origin) {
  const json lane_x = chart["data"][0], lane_y = chart["data"][1];
  std::vector<double> kx, ky;
  for (const auto& k : profile) kx.push_back(rel(k.time, origin)), ky.push_back(k.rate);
  const auto on_profile = [&](double x) -> json {
    if (x < kx.front() || x > kx.back()) return nullptr;
    const auto hi = static_cast<std::size_t>(std::upper_bound(kx.begin(), kx.end(), x) - kx.begin());
    if (hi == kx.size()) return ky.back();
    const std::size_t lo = hi - 1;
    return ky[lo] + (ky[hi] - ky[lo]) * (x - kx[lo]) / (kx[hi] - kx[lo]);
  };
  json xs = json::array(), ys = json::array(), expected = json::array();
  std::size_t i = 0, k = 0;
  while (i < lane_x.size() || k < kx.size()) {
    if (k < kx.size() && (i == lane_x.size() || kx[k] < lane_x[i].get<double>())) {
      xs.push_back(kx[k]);
      ys.push_back(i > 0 ? lane_y[i - 1] : json(nullptr));
      expected.push_back(ky[k++]);
    } else {
      xs.push_back(lane_x[i]);
      ys.push_back(lane_y[i]);
      expected.push_back(on_profile(lane_x[i++].get<double>()));
    }
  }
  chart["data"] = {xs, ys, expected};
  chart["series"].push_back({{"label", "expected profile"},
                             {"colour", "#1a7f37"},
                             {"draw", "line"},
                             {"dashed", true},
                             {"cls", "expected"}});
}

// The words for a profile: its start, peak and end.
std::string profile_words(std::span<const RatePoint> profile) {
  double peak = 0.0;
  for (const auto& k : profile) peak = std::max(peak, k.rate);
  return fmt::format("expected profile: {} steps/s from {}, peak {} steps/s, back to {} steps/s at {}",
                     format_number(profile.front().rate), format_time(profile.front().time),
                     format_number(peak), format_number(profile.back().rate),
                     format_time(profile.back().time));
}

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

json timing_figure(const Measurement& m, Judgement shown, const WindowTrace* trace,
                   std::optional<RateBand> rate, std::span<const RatePoint> profile) {
  if (!m.window) return nullptr;
  const TraceWindow span = trace ? trace->span : figure_span(m);
  const Nanos origin = m.window->begin;
  const char* edge_colour = outcome_colour(shown);
  // The lanes: the trace's, or one output lane stepping at the captured edge.
  std::vector<TraceLane> fallback;
  if (!trace || trace->lanes.empty()) {
    TraceLane out{"edge", LaneRole::Output, {{span.begin, 0}}, 0};
    if (m.at) out.changes.push_back({*m.at, 1});
    fallback.push_back(std::move(out));
  }
  const std::vector<TraceLane>& lanes = fallback.empty() ? trace->lanes : fallback;
  // The marks every lane carries: the expected window and its limits, the start, the edge.
  json bands = json::array(), vlines = json::array();
  const std::optional<TraceWindow> want = expected_window(m);
  const bool from_start = is_time_from_start(m);
  const double x_max = rel(span.end, origin);
  if (want) {
    const double w0 = rel(want->begin, origin);
    const double w1 = want->end == Nanos::max() ? x_max : rel(want->end, origin);
    bands.push_back(
        {{"from", w0}, {"to", w1}, {"colour", kBand}, {"label", limit_words(m)}, {"cls", "expected"}});
    if (!from_start || m.lower) vlines.push_back(vline(w0, kLimit, "", "limit", true));
    if (want->end != Nanos::max()) vlines.push_back(vline(w1, kLimit, "", "limit", true));
  }
  if (from_start) vlines.push_back(vline(0.0, kGrey, "start " + format_time(origin), "start", false));
  if (m.at)
    vlines.push_back(
        vline(rel(*m.at, origin), edge_colour,
              fmt::format("edge: {} {}", m.name,
                          format_value(m.value, m.unit, limit_beyond(m.value, m.lower, m.upper))),
              "edge", false));
  json charts = json::array();
  std::string notes;
  for (const auto& lane : lanes) {
    const char* colour = lane.role == LaneRole::Output ? edge_colour : lane_colour(lane.role);
    json chart = lane_chart(lane, span, origin, colour);
    chart["bands"] = bands;
    chart["vlines"] = vlines;
    chart["labels"] = charts.empty(); // the marks' words once, on the top lane
    if (lane.role == LaneRole::Rate && rate) {
      // The expected peak as a band of rates over the whole lane; the axis holds it.
      const double peak = static_cast<double>(
          std::max_element(lane.changes.begin(), lane.changes.end(), [](const auto& a, const auto& b) {
            return a.value < b.value;
          })->value);
      const double lo = rate->lower.value_or(0.0), hi = rate->upper.value_or(std::max(peak, lo));
      chart["hbands"] = {
          {{"from", lo},
           {"to", hi},
           {"colour", "rgba(191,57,137,0.15)"},
           {"label", "expected peak " + format_number(lo) + " .. " + format_number(hi) + " steps/s"},
           {"cls", "expected"}}};
      chart["y"]["min"] = 0.0;
      chart["y"]["max"] = std::max(peak, hi) * 1.1;
    }
    if (lane.role == LaneRole::Rate && !profile.empty()) {
      add_profile(chart, profile, origin);
      // The axis holds the profile's peak too.
      double top = chart["y"].value("max", 0.0) / 1.1;
      for (const auto& c : lane.changes) top = std::max(top, static_cast<double>(c.value));
      for (const auto& k : profile) top = std::max(top, k.rate);
      chart["y"]["min"] = 0.0;
      chart["y"]["max"] = top * 1.1;
      notes += profile_words(profile) + "; ";
    }
    if (lane.role == LaneRole::Count && m.at)
      notes += fmt::format("{}: {} at the edge; ", lane.name, value_at(lane, *m.at));
    if (lane.thinned > 0) notes += fmt::format("{}: {} changes thinned to fit; ", lane.name, lane.thinned);
    charts.push_back(std::move(chart));
  }
  // The time axis once, under the bottom lane.
  for (auto& c : charts) c["x"] = time_axis("", rel(span.begin, origin), x_max);
  charts.back()["x"]["label"] = "time from the window start";
  if (!notes.empty()) notes.resize(notes.size() - 2);
  if (!want) notes += std::string(notes.empty() ? "" : "; ") + "no limit: reported only";
  if (!m.at) notes += std::string(notes.empty() ? "" : "; ") + "no edge captured";
  return {
      {"kind", "timing"}, {"title", "timing of " + m.name}, {"charts", std::move(charts)}, {"notes", notes}};
}

json limits_figure(std::span<const ShownMeasurement> rows) {
  json charts = json::array();
  for (const auto& [m, shown] : rows) {
    if (!m->lower && !m->upper) continue;
    const double v = std::isfinite(m->value) ? m->value : 0.0;
    double lo = v, hi = v;
    for (const auto& l : {m->lower, m->upper})
      if (l) lo = std::min(lo, *l), hi = std::max(hi, *l);
    const auto [x0, x1] = padded(lo, hi, 0.25, std::max(std::abs(hi) * 1e-3, 1e-6));
    json vlines = json::array();
    for (const auto& l : {m->lower, m->upper})
      if (l) vlines.push_back(vline(*l, kLimit, format_value(*l, m->unit), "limit", true));
    json point = std::isfinite(m->value) ? json(m->value) : json(nullptr);
    charts.push_back(
        {{"measurement", m->name},
         {"height", 70},
         {"x",
          {{"label",
            m->name + ": " + format_value(m->value, m->unit, limit_beyond(m->value, m->lower, m->upper))},
           {"min", x0},
           {"max", x1}}},
         {"y", {{"label", ""}, {"min", 0}, {"max", 2}, {"hidden", true}}},
         {"data", {{v}, {point.is_null() ? json(nullptr) : json(1)}}},
         {"series", {{{"label", m->name}, {"colour", outcome_colour(shown)}, {"draw", "points"}}}},
         {"bands",
          {{{"from", m->lower ? *m->lower : x0},
            {"to", m->upper ? *m->upper : x1},
            {"colour", kBand},
            {"label", ""},
            {"cls", "expected"}}}},
         {"vlines", std::move(vlines)},
         {"labels", true}});
  }
  if (charts.empty()) return nullptr;
  return {{"kind", "limits"}, {"title", "measurements against their limits"}, {"charts", std::move(charts)}};
}

json histogram_figure(std::span<const double> values, const std::string& unit,
                      std::span<const LimitLine> limits) {
  if (values.empty()) return nullptr;
  const double vmin = *std::min_element(values.begin(), values.end());
  const double vmax = *std::max_element(values.begin(), values.end());
  double lo = vmin, hi = vmax;
  for (const auto& l : limits) lo = std::min(lo, l.value), hi = std::max(hi, l.value);
  const auto [x0, x1] = padded(lo, hi, 0.05, 1e-3);
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
  // Each bin from its left edge (stepped, filled), closed by a zero at the last bin's right.
  json xs = json::array(), ys = json::array();
  for (std::size_t i = 0; i < bins; ++i) {
    xs.push_back(vmin + width * static_cast<double>(i));
    ys.push_back(counts[i]);
  }
  xs.push_back(vmin + width * static_cast<double>(bins));
  ys.push_back(0);
  json vlines = json::array();
  for (const auto& l : limits)
    vlines.push_back(vline(l.value, kLimit, l.name + " limit " + format_value(l.value, unit), "limit", true));
  const std::string axis = unit == "us" ? "µs" : unit;
  json chart = {{"height", 180},
                {"x", {{"label", axis}, {"min", x0}, {"max", x1}}},
                {"y", {{"label", "count"}, {"min", 0}}},
                {"data", {xs, ys}},
                {"series", {{{"label", "count"}, {"colour", "#0969da"}, {"draw", "bars"}}}},
                {"bands", json::array()},
                {"vlines", vlines},
                {"labels", true}};
  return {
      {"kind", "histogram"},
      {"title", fmt::format("histogram of {} values", values.size())},
      {"charts", {chart}},
      {"notes", fmt::format("{} samples in {} bins of {}", values.size(), bins, format_value(width, unit))}};
}

json probes_figure(std::span<const Probe> probes, std::optional<double> band_lo_ns,
                   std::optional<double> band_hi_ns) {
  if (probes.empty()) return nullptr;
  double lo = static_cast<double>(probes.front().width.count()), hi = lo;
  for (const auto& p : probes) {
    lo = std::min(lo, static_cast<double>(p.width.count()));
    hi = std::max(hi, static_cast<double>(p.width.count()));
  }
  for (const auto& b : {band_lo_ns, band_hi_ns})
    if (b) lo = std::min(lo, *b), hi = std::max(hi, *b);
  const auto [x0, x1] = padded(lo, hi, 0.05, 1000.0);
  // By width (uPlot's x ascends), each probe numbered in the order it ran.
  std::vector<std::size_t> order(probes.size());
  for (std::size_t i = 0; i < order.size(); ++i) order[i] = i;
  std::stable_sort(order.begin(), order.end(),
                   [&](std::size_t a, std::size_t b) { return probes[a].width < probes[b].width; });
  json xs = json::array(), accepted = json::array(), rejected = json::array(), numbers = json::array();
  for (const std::size_t i : order) {
    xs.push_back(probes[i].width.count());
    accepted.push_back(probes[i].accepted ? json(1) : json(nullptr));
    rejected.push_back(probes[i].accepted ? json(nullptr) : json(0));
    numbers.push_back(std::to_string(i + 1));
  }
  json bands = json::array();
  if (band_lo_ns || band_hi_ns)
    bands.push_back({{"from", band_lo_ns.value_or(x0)},
                     {"to", band_hi_ns.value_or(x1)},
                     {"colour", "rgba(212,167,44,0.25)"},
                     {"label", "filter band"},
                     {"cls", "expected"}});
  json chart = {{"height", 120},
                {"x", time_axis("pulse width", x0, x1)},
                {"y", {{"label", ""}, {"min", -0.5}, {"max", 1.5}, {"ticks", {"rejected", "accepted"}}}},
                {"data", {xs, accepted, rejected}},
                {"series",
                 {{{"label", "accepted"}, {"colour", "#1a7f37"}, {"draw", "points"}, {"numbers", numbers}},
                  {{"label", "rejected"}, {"colour", kGrey}, {"draw", "points"}, {"numbers", numbers}}}},
                {"bands", bands},
                {"vlines", json::array()},
                {"labels", true}};
  return {{"kind", "probes"}, {"title", "debounce probes against the filter band"}, {"charts", {chart}}};
}

json motion_figure(const MotionRecord& motion, std::span<const Marker> markers, std::optional<Nanos> from,
                   std::optional<Nanos> to, std::optional<Nanos> origin) {
  if (motion.empty()) return nullptr;
  const Nanos t0 = from.value_or(motion.points.front().time);
  const Nanos t1 = to.value_or(motion.points.back().time);
  const Nanos o = origin.value_or(motion.points.front().time);
  // The points inside [t0, t1] and one either side: the line reaches the plot's edges even
  // where the recorded knots are far apart.
  json xs = json::array(), speed = json::array(), position = json::array();
  const auto& all = motion.points;
  for (std::size_t i = 0; i < all.size(); ++i) {
    const bool next_inside = i + 1 < all.size() && all[i + 1].time >= t0;
    const bool prev_inside = i > 0 && all[i - 1].time <= t1;
    if ((all[i].time >= t0 && all[i].time <= t1) || (all[i].time < t0 && next_inside) ||
        (all[i].time > t1 && prev_inside)) {
      xs.push_back(rel(all[i].time, o));
      speed.push_back(all[i].speed);
      position.push_back(all[i].position);
    }
  }
  json vlines = json::array();
  const auto mark = [&](Nanos t, const std::string& label, const char* colour, const char* cls, bool dashed) {
    if (t >= t0 && t <= t1)
      vlines.push_back(vline(rel(t, o), colour, label + " " + format_time(t - o), cls, dashed));
  };
  for (const auto& e : motion.events) mark(e.time, e.what, kGrey, "event", false);
  for (const auto& m : markers) mark(m.time, m.label, m.colour, m.cls, true);
  json chart = {{"height", 240},
                {"x", time_axis(origin ? "time from applied" : "run time", rel(t0, o), rel(t1, o))},
                {"y", {{"label", "speed (counts/s)"}}},
                {"y2", {{"label", "position (counts)"}}},
                {"data", {xs, speed, position}},
                {"series",
                 {{{"label", "speed"}, {"colour", "#0969da"}, {"draw", "line"}},
                  {{"label", "position"}, {"colour", "#8250df"}, {"draw", "line"}, {"scale", "y2"}}}},
                {"bands", json::array()},
                {"vlines", vlines},
                {"labels", true}};
  return {{"kind", "motion"}, {"title", "speed and position against time"}, {"charts", {chart}}};
}

json trend_figure(std::span<const TrendPoint> nights, const std::string& unit, std::optional<double> lower,
                  std::optional<double> upper) {
  std::vector<double> shown;
  for (const TrendPoint& p : nights)
    if (p.value) shown.push_back(*p.value);
  if (shown.empty()) return nullptr;
  // The limits are always on the canvas, however far the values are from them.
  if (lower) shown.push_back(*lower);
  if (upper) shown.push_back(*upper);
  const auto [lo, hi] = std::minmax_element(shown.begin(), shown.end());
  const auto [y0, y1] = padded(*lo, *hi, 0.1, 1e-3);
  json labels = json::array();
  // One point series per word, in the report's colours (Judgement's order).
  constexpr Judgement kWords[] = {Judgement::Pass, Judgement::Fail, Judgement::Caught, Judgement::NotJudged,
                                  Judgement::Error};
  json data = json::array(); // x, the joining line, then a series per word
  for (std::size_t k = 0; k < 2 + std::size(kWords); ++k) data.push_back(json::array());
  json series = json::array();
  series.push_back(json{{"label", "value"}, {"colour", "#0969da"}, {"draw", "line"}});
  for (const Judgement w : kWords)
    series.push_back(json{{"label", to_string(w)}, {"colour", outcome_colour(w)}, {"draw", "points"}});
  for (std::size_t i = 0; i < nights.size(); ++i) {
    const TrendPoint& p = nights[i];
    data[0].push_back(i);
    labels.push_back(p.label);
    data[1].push_back(p.value ? json(*p.value) : json(nullptr));
    for (std::size_t w = 0; w < std::size(kWords); ++w)
      data[2 + w].push_back(p.value && p.word == kWords[w] ? json(*p.value) : json(nullptr));
  }
  json hlines = json::array();
  for (const auto& [limit, word] : {std::pair{lower, "lower"}, std::pair{upper, "upper"}})
    if (limit)
      hlines.push_back({{"at", *limit},
                        {"colour", kLimit},
                        {"label", fmt::format("{} limit {}", word, format_value(*limit, unit))},
                        {"cls", "limit"}});
  json chart = {{"height", 170},
                {"x",
                 {{"label", "night"},
                  {"min", -0.5},
                  {"max", static_cast<double>(nights.size()) - 0.5},
                  {"names", labels}}},
                {"y", {{"label", unit == "us" ? "µs" : unit}, {"min", y0}, {"max", y1}}},
                {"data", data},
                {"series", series},
                {"bands", json::array()},
                {"vlines", json::array()},
                {"hlines", hlines},
                {"labels", true}};
  return {{"kind", "trend"},
          {"title", fmt::format("{} over {} night(s)", unit, nights.size())},
          {"charts", {chart}}};
}

} // namespace hilrig::rig
