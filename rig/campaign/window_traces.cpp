#include "rig/campaign/window_traces.hpp"

#include <algorithm>
#include <cmath>
#include <optional>
#include <type_traits>
#include <variant>

#include "rig/campaign/run_trace.hpp"
#include "rig/campaign/scenario_reader.hpp"
#include "rig/results/timing_figures.hpp"

namespace hilrig::campaign {
namespace {

// Keeps the first and last change of each pixel column; counts what it left out.
void thin(rig::TraceLane& lane, const rig::TraceWindow& span) {
  if (lane.changes.size() <= 2 * kLaneColumns + 1) return;
  const double width = static_cast<double>((span.end - span.begin).count());
  const auto column = [&](Nanos t) {
    return std::min(kLaneColumns - 1, static_cast<std::size_t>(static_cast<double>((t - span.begin).count()) /
                                                               width * static_cast<double>(kLaneColumns)));
  };
  std::vector<rig::LaneChange> kept{lane.changes.front()}; // the value at span.begin
  for (std::size_t i = 1; i < lane.changes.size(); ++i) {
    const std::size_t col = column(lane.changes[i].time);
    const bool first = column(lane.changes[i - 1].time) != col || i == 1;
    const bool last = i + 1 == lane.changes.size() || column(lane.changes[i + 1].time) != col;
    if (first || last)
      kept.push_back(lane.changes[i]);
    else
      ++lane.thinned;
  }
  lane.changes = std::move(kept);
}

// A step line's rate from its changes in the span (every edge a step) and the step before it.
std::vector<rig::LaneChange> step_rate(const std::vector<rig::LaneChange>& inside,
                                       std::optional<Nanos> before, const rig::TraceWindow& span) {
  std::vector<rig::LaneChange> out{{span.begin, 0}};
  std::optional<Nanos> prev = before;
  Nanos interval{0};
  for (const rig::LaneChange& c : inside) {
    if (prev && interval > Nanos{0} && c.time > *prev + 2 * interval && out.back().value != 0)
      out.push_back({*prev + 2 * interval, 0}); // a pause: the next step was overdue
    if (prev && c.time > *prev) {
      interval = c.time - *prev;
      out.push_back({c.time, std::llround(1e9 / static_cast<double>(interval.count()))});
    }
    prev = c.time;
  }
  if (prev && interval > Nanos{0} && *prev + 2 * interval <= span.end)
    out.push_back({*prev + 2 * interval, 0});
  return out;
}

} // namespace

std::vector<std::pair<std::string, rig::LaneRole>> lanes_of(const checks::CheckParams& params,
                                                            const TraceRecorder& trace) {
  std::vector<std::pair<std::string, rig::LaneRole>> out;
  const bool on_shaft = std::visit(
      [](const auto& p) {
        using P = std::decay_t<decltype(p)>;
        return std::is_same_v<P, checks::ThroughputParams> || std::is_same_v<P, checks::AdvanceParams> ||
               std::is_same_v<P, checks::EdgeAtPositionParams>;
      },
      params);
  const auto add = [&](std::string_view name, rig::LaneRole role) {
    if (trace.find(name) >= 0) out.emplace_back(std::string(name), role);
  };
  if (on_shaft) {
    add(kEncoderA, rig::LaneRole::Stimulus);
    add(kEncoderB, rig::LaneRole::Stimulus);
    // A resolver board's stimulus: its stators as the board reads them (run_trace.hpp).
    add(kStatorSin, rig::LaneRole::Stimulus);
    add(kStatorCos, rig::LaneRole::Stimulus);
    add("shaft.count", rig::LaneRole::Count);
  }
  for (const std::string& line : checks::lines_of(params)) add(line, rig::LaneRole::Output);
  if (const auto* move = std::get_if<checks::ShaftMoveParams>(&params);
      move && trace.find(move->step_line) >= 0)
    out.emplace_back(move->step_line + kRateSuffix, rig::LaneRole::Rate);
  return out;
}

std::vector<rig::WindowTrace>
cut_window_traces(const rig::CheckResult& check, const TraceRecorder& trace,
                  const std::vector<std::pair<std::string, rig::LaneRole>>& lanes) {
  std::vector<rig::WindowTrace> out;
  for (const rig::Measurement* m : rig::timing_figures(check)) {
    rig::WindowTrace w{*m->window, rig::figure_span(rig::as_drawn(check, *m)), {}};
    for (const auto& [name, role] : lanes) w.lanes.push_back(rig::TraceLane{name, role, {}, 0});
    out.push_back(std::move(w));
  }
  if (out.empty() || lanes.empty()) return out;
  // The lane each trace signal feeds (-1: none), and each lane's value before its span.
  const auto& signals = trace.signals();
  std::vector<int> lane_of(signals.size(), -1);
  for (std::size_t l = 0; l < lanes.size(); ++l)
    if (lanes[l].second != rig::LaneRole::Rate)
      lane_of[static_cast<std::size_t>(trace.find(lanes[l].first))] = static_cast<int>(l);
  struct Before {
    Nanos time{-1};
    std::int64_t value = 0;
    double real = 0.0;
  };
  std::vector<std::vector<Before>> before(out.size(), std::vector<Before>(lanes.size()));
  for (std::size_t l = 0; l < lanes.size(); ++l) {
    if (lanes[l].second == rig::LaneRole::Rate) continue;
    const SignalInfo& info = signals[static_cast<std::size_t>(trace.find(lanes[l].first))];
    for (auto& b : before) {
      b[l].value = info.has_initial ? info.initial : 0;
      b[l].real = info.initial_real;
    }
    if (info.kind == SignalKind::Real)
      for (auto& w : out) w.lanes[l].real = true;
  }
  std::vector<std::vector<std::vector<rig::LaneChange>>> inside(
      out.size(), std::vector<std::vector<rig::LaneChange>>(lanes.size()));
  trace.visit_samples(0, [&](std::span<const TraceSample> chunk) {
    for (const TraceSample& s : chunk) {
      const int l = lane_of[s.signal];
      if (l < 0) continue;
      const auto lane = static_cast<std::size_t>(l);
      for (std::size_t w = 0; w < out.size(); ++w) {
        const rig::TraceWindow& span = out[w].span;
        if (s.time < span.begin) {
          if (s.time >= before[w][lane].time) before[w][lane] = Before{s.time, s.value, s.real};
        } else if (s.time <= span.end) {
          inside[w][lane].push_back(rig::LaneChange{s.time, s.value, s.real});
        }
      }
    }
  });
  for (std::size_t w = 0; w < out.size(); ++w) {
    for (std::size_t l = 0; l < lanes.size(); ++l) {
      rig::TraceLane& lane = out[w].lanes[l];
      if (lane.role == rig::LaneRole::Rate) {
        // From the step line's own lane, before it is thinned.
        for (std::size_t s = 0; s < lanes.size(); ++s)
          if (lanes[s].first + kRateSuffix == lane.name && lanes[s].second != rig::LaneRole::Rate)
            lane.changes = step_rate(
                inside[w][s], before[w][s].time >= Nanos{0} ? std::optional(before[w][s].time) : std::nullopt,
                out[w].span);
        thin(lane, out[w].span);
        continue;
      }
      auto& in = inside[w][l];
      std::stable_sort(in.begin(), in.end(),
                       [](const rig::LaneChange& a, const rig::LaneChange& b) { return a.time < b.time; });
      lane.changes.push_back(rig::LaneChange{out[w].span.begin, before[w][l].value, before[w][l].real});
      for (const rig::LaneChange& c : in)
        if (lane.real ? c.real != lane.changes.back().real : c.value != lane.changes.back().value)
          lane.changes.push_back(c);
      thin(lane, out[w].span);
    }
  }
  return out;
}

} // namespace hilrig::campaign
