#include "rig/results/timing_figures.hpp"

#include <algorithm>
#include <cmath>

namespace hilrig::rig {
namespace {

// ns per unit of a time measurement; 0 for a unit that is not a time.
double ns_per(const std::string& unit) {
  if (unit == "ns") return 1.0;
  if (unit == "us") return 1e3;
  if (unit == "ms") return 1e6;
  if (unit == "s") return 1e9;
  return 0.0;
}

Nanos after(Nanos from, double value, double scale) {
  return from + Nanos{static_cast<std::int64_t>(std::llround(value * scale))};
}

} // namespace

bool has_timing(const Measurement& m) {
  if (!m.window) return false;
  if (m.at) return m.window->end > m.window->begin;
  return m.outcome != Outcome::Pass; // the edge the check waited for never came
}

bool is_time_from_start(const Measurement& m) { return ns_per(m.unit) > 0.0; }

std::optional<TraceWindow> expected_window(const Measurement& m) {
  const TraceWindow w = m.window.value_or(TraceWindow{Nanos{0}, Nanos{0}});
  const double scale = ns_per(m.unit);
  if (scale == 0.0 || w.end == Nanos::max()) return w;
  if (!m.lower && !m.upper) return std::nullopt;
  return TraceWindow{m.lower ? after(w.begin, *m.lower, scale) : w.begin,
                     m.upper ? after(w.begin, *m.upper, scale) : Nanos::max()};
}

TraceWindow figure_span(const Measurement& m) {
  const TraceWindow w = m.window.value_or(TraceWindow{Nanos{0}, Nanos{0}});
  const TraceWindow want = expected_window(m).value_or(w);
  std::int64_t lo = std::min(w.begin, want.begin).count();
  std::int64_t hi = lo;
  for (const Nanos t : {w.begin, w.end, want.begin, want.end})
    if (t != Nanos::max()) hi = std::max(hi, t.count());
  if (m.at) lo = std::min(lo, m.at->count()), hi = std::max(hi, m.at->count());
  if (w.end == Nanos::max() || want.end == Nanos::max()) hi = std::max(hi + (hi - lo), lo + 1'000'000);
  const std::int64_t pad = std::max<std::int64_t>((hi - lo) / 5, 1000);
  return TraceWindow{Nanos{std::max<std::int64_t>(lo - pad, 0)}, Nanos{hi + pad}};
}

std::vector<const Measurement*> timing_figures(const CheckResult& c) {
  std::vector<const Measurement*> rows;
  for (const auto& m : c.measurements) rows.push_back(&m);
  std::stable_sort(rows.begin(), rows.end(), [](const Measurement* a, const Measurement* b) {
    const auto rank = [](const Measurement* m) {
      return m->outcome != Outcome::Pass ? 0 : expected_window(*m) ? 1 : 2;
    };
    return rank(a) < rank(b);
  });
  std::vector<const Measurement*> drawn;
  for (const Measurement* m : rows) {
    if (!has_timing(*m) || drawn.size() == kTimingFigures) continue;
    const auto same = [&](const Measurement* d) {
      return d->window->begin == m->window->begin && d->window->end == m->window->end && d->at == m->at;
    };
    if (std::none_of(drawn.begin(), drawn.end(), same)) drawn.push_back(m);
  }
  return drawn;
}

Measurement as_drawn(const CheckResult& c, const Measurement& m) {
  Measurement drawn = m;
  if (c.kind != "pulse_width" || !is_time_from_start(m)) return drawn;
  for (const auto& other : c.measurements) {
    if (other.unit != m.unit) continue;
    if (other.lower) drawn.lower = other.lower;
    if (other.upper) drawn.upper = other.upper;
  }
  return drawn;
}

std::optional<RateBand> expected_rate(const CheckResult& c) {
  if (c.kind != "shaft_move") return std::nullopt;
  for (const auto& m : c.measurements)
    if (m.name.ends_with(".peak_speed") && (m.lower || m.upper)) return RateBand{m.lower, m.upper};
  return std::nullopt;
}

const WindowTrace* trace_for(const CheckResult& c, const Measurement& m) {
  if (!m.window) return nullptr;
  for (const auto& t : c.traces)
    if (t.around.begin == m.window->begin && t.around.end == m.window->end) return &t;
  return nullptr;
}

} // namespace hilrig::rig
