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

// An analog lane (a resolver stator) from its samples: a sampled signal has no value between
// its samples (the stators are sampled at the excitation's peaks, one a period), so the lane
// starts at its first sample inside the span, not at a value held from the last peak before
// it (up to a period early). A span with no sample inside shows that last one at its own time
// (its declared initial value at the span's start when there is none). Every sample is kept,
// repeats too: the line through them is only truthful through each. Volts to
// kRealLaneResolution.
void real_samples(rig::TraceLane& lane, const std::vector<rig::LaneChange>& inside, Nanos before_time,
                  double before_value, const rig::TraceWindow& span) {
  if (inside.empty())
    lane.changes.push_back({before_time >= Nanos{0} ? before_time : span.begin, 0, before_value});
  lane.changes.insert(lane.changes.end(), inside.begin(), inside.end());
  for (rig::LaneChange& c : lane.changes) c.real = real_lane_value(c.real);
  thin(lane, span);
}

} // namespace

double real_lane_value(double volts) {
  return std::round(volts * kRealLaneStepsPerVolt) / kRealLaneStepsPerVolt;
}

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

namespace {

// A lane's last change before its window's span.
struct Before {
  Nanos time{-1};
  std::int64_t value = 0;
  double real = 0.0;
};

// One window being cut: its lanes' values before the span and their changes inside it.
struct Cutting {
  rig::WindowTrace* window;
  const Lanes* lanes;
  std::vector<Before> before;
  std::vector<std::vector<rig::LaneChange>> inside;
};

// A trace signal feeding lane `lane` of cutting[cutting].
struct Target {
  std::size_t cutting;
  std::size_t lane;
};

// The pass over a trace recorded in time order, the same values as the general pass (below in
// cut_window_traces) with less work a sample: a signal's last sample before a window's span is
// its last sample before the first one at or after span.begin (kept once a signal, not once a
// window), and a window whose span has ended takes no more. Each signal's windows in order of
// span.begin; those open (begun, not ended) take the sample.
void feed_in_time_order(const TraceRecorder& trace, const std::vector<std::vector<Target>>& targets,
                        std::vector<Cutting>& cutting) {
  struct Feed {
    std::vector<Target> waiting; // by span.begin
    std::size_t next = 0;        // waiting[next..] have not begun
    std::vector<Target> open;
    Before last; // as the general pass keeps it for a window not begun
  };
  const auto span_of = [&](const Target& t) -> const rig::TraceWindow& {
    return cutting[t.cutting].window->span;
  };
  std::vector<Feed> feeds(targets.size());
  for (std::size_t sig = 0; sig < targets.size(); ++sig) {
    if (targets[sig].empty()) continue;
    Feed& f = feeds[sig];
    f.waiting = targets[sig];
    std::stable_sort(f.waiting.begin(), f.waiting.end(),
                     [&](const Target& a, const Target& b) { return span_of(a).begin < span_of(b).begin; });
    // Every window of a signal starts from the same value (the signal's initial one).
    f.last = cutting[f.waiting.front().cutting].before[f.waiting.front().lane];
  }
  // Once a sample is past every window's begin and end, so is every later one: it would only
  // move a signal's windows to open with the last sample before it (what the loop after the
  // pass does) and move on that last sample, which no window reads any more. The pass stops
  // there, the rest of the recording not read back.
  Nanos past = Nanos::min();
  for (const Cutting& c : cutting) past = std::max({past, c.window->span.begin, c.window->span.end});
  trace.visit_samples_while(0, [&](std::span<const TraceSample> chunk) {
    for (const TraceSample& s : chunk) {
      if (s.time > past) return false;
      Feed& f = feeds[s.signal];
      if (f.waiting.empty()) continue;
      for (; f.next < f.waiting.size() && span_of(f.waiting[f.next]).begin <= s.time; ++f.next) {
        const Target& t = f.waiting[f.next];
        cutting[t.cutting].before[t.lane] = f.last; // every sample before this one is before the span
        f.open.push_back(t);
      }
      if (s.time >= f.last.time) f.last = Before{s.time, s.value, s.real};
      std::size_t kept = 0;
      for (const Target& t : f.open) {
        if (s.time > span_of(t).end) continue; // ended: no later sample is inside
        cutting[t.cutting].inside[t.lane].push_back(rig::LaneChange{s.time, s.value, s.real});
        f.open[kept++] = t;
      }
      f.open.resize(kept);
    }
    return true;
  });
  for (Feed& f : feeds)
    for (; f.next < f.waiting.size(); ++f.next) {
      const Target& t = f.waiting[f.next];
      cutting[t.cutting].before[t.lane] = f.last;
    }
}

// The window's lanes from what the pass collected: each lane its value at span.begin and its
// changes, thinned; a rate lane from its step line's changes.
void finish(Cutting& c) {
  const Lanes& lanes = *c.lanes;
  rig::WindowTrace& w = *c.window;
  for (std::size_t l = 0; l < lanes.size(); ++l) {
    rig::TraceLane& lane = w.lanes[l];
    if (lane.role == rig::LaneRole::Rate) {
      // From the step line's own lane, before it is thinned.
      for (std::size_t s = 0; s < lanes.size(); ++s)
        if (lanes[s].first + kRateSuffix == lane.name && lanes[s].second != rig::LaneRole::Rate)
          lane.changes = step_rate(
              c.inside[s], c.before[s].time >= Nanos{0} ? std::optional(c.before[s].time) : std::nullopt,
              w.span);
      thin(lane, w.span);
      continue;
    }
    auto& in = c.inside[l];
    std::stable_sort(in.begin(), in.end(),
                     [](const rig::LaneChange& a, const rig::LaneChange& b) { return a.time < b.time; });
    if (lane.real) {
      real_samples(lane, in, c.before[l].time, c.before[l].real, w.span);
      continue;
    }
    lane.changes.push_back(rig::LaneChange{w.span.begin, c.before[l].value, c.before[l].real});
    for (const rig::LaneChange& ch : in)
      if (ch.value != lane.changes.back().value) lane.changes.push_back(ch);
    thin(lane, w.span);
  }
}

} // namespace

std::vector<rig::WindowTrace> cut_window_traces(const rig::CheckResult& check, const TraceRecorder& trace,
                                                const Lanes& lanes) {
  return std::move(cut_window_traces(std::vector<WindowCut>{{&check, lanes}}, trace).front());
}

std::vector<std::vector<rig::WindowTrace>> cut_window_traces(const std::vector<WindowCut>& cuts,
                                                             const TraceRecorder& trace) {
  std::vector<std::vector<rig::WindowTrace>> out(cuts.size());
  for (std::size_t k = 0; k < cuts.size(); ++k) {
    for (const rig::Measurement* m : rig::timing_figures(*cuts[k].check)) {
      rig::WindowTrace w{*m->window, rig::figure_span(rig::as_drawn(*cuts[k].check, *m)), {}};
      for (const auto& [name, role] : cuts[k].lanes) w.lanes.push_back(rig::TraceLane{name, role, {}, 0});
      out[k].push_back(std::move(w));
    }
  }
  // Each trace signal's (window, lane) pairs: the lane of its check that it feeds (the last
  // lane of that name), in each of the check's windows.
  const auto& signals = trace.signals();
  std::vector<std::vector<Target>> targets(signals.size());
  std::vector<Cutting> cutting;
  for (std::size_t k = 0; k < cuts.size(); ++k) {
    const Lanes& lanes = cuts[k].lanes;
    if (out[k].empty() || lanes.empty()) continue;
    std::vector<int> lane_of(signals.size(), -1);
    for (std::size_t l = 0; l < lanes.size(); ++l)
      if (lanes[l].second != rig::LaneRole::Rate)
        lane_of[static_cast<std::size_t>(trace.find(lanes[l].first))] = static_cast<int>(l);
    std::vector<Before> before(lanes.size());
    for (std::size_t l = 0; l < lanes.size(); ++l) {
      if (lanes[l].second == rig::LaneRole::Rate) continue;
      const SignalInfo& info = signals[static_cast<std::size_t>(trace.find(lanes[l].first))];
      before[l].value = info.has_initial ? info.initial : 0;
      before[l].real = info.initial_real;
      if (info.kind == SignalKind::Real)
        for (auto& w : out[k]) w.lanes[l].real = true;
    }
    for (auto& w : out[k]) {
      for (std::size_t sig = 0; sig < signals.size(); ++sig)
        if (lane_of[sig] >= 0)
          targets[sig].push_back(Target{cutting.size(), static_cast<std::size_t>(lane_of[sig])});
      cutting.push_back(Cutting{&w, &lanes, before, std::vector<std::vector<rig::LaneChange>>(lanes.size())});
    }
  }
  if (cutting.empty()) return out;
  if (trace.in_time_order()) {
    feed_in_time_order(trace, targets, cutting);
  } else {
    trace.visit_samples(0, [&](std::span<const TraceSample> chunk) {
      for (const TraceSample& s : chunk) {
        for (const Target& t : targets[s.signal]) {
          Cutting& c = cutting[t.cutting];
          const rig::TraceWindow& span = c.window->span;
          if (s.time < span.begin) {
            if (s.time >= c.before[t.lane].time) c.before[t.lane] = Before{s.time, s.value, s.real};
          } else if (s.time <= span.end) {
            c.inside[t.lane].push_back(rig::LaneChange{s.time, s.value, s.real});
          }
        }
      }
    });
  }
  for (Cutting& c : cutting) finish(c);
  return out;
}

} // namespace hilrig::campaign
