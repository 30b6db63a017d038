#include "rig/checks/throughput.hpp"

#include <algorithm>
#include <fmt/format.h>
#include <iterator>
#include <vector>

namespace hilrig::checks {
namespace {

struct Sample {
  Nanos latency;
  Nanos crossing;
};

// The first edge of `level` in [from, until) that follows at least `quiet` of no edge (the
// line idle at the other level); an edge with none before it follows the capture's start.
std::optional<Edge> next_burst_edge(std::span<const Edge> edges, Nanos from, Nanos until, Level level,
                                    Nanos quiet) {
  auto it =
      std::lower_bound(edges.begin(), edges.end(), from, [](const Edge& e, Nanos t) { return e.time < t; });
  for (; it != edges.end() && it->time < until; ++it) {
    if (it->level != level) continue;
    if (it == edges.begin() || it->time - std::prev(it)->time >= quiet) return *it;
  }
  return std::nullopt;
}

} // namespace

CheckResult check_throughput(std::span<const Nanos> crossings, std::span<const Edge> output,
                             const ThroughputSpec& spec, Nanos seen_until) {
  CheckResult r;
  r.kind = "throughput";
  if (crossings.empty()) {
    // No crossing, no latency: the check judged nothing, whatever min_count says.
    // The count it read (0) and the least it asks for stay in the evidence (junit.xml, compare).
    Measurement count =
        error(spec.name + ".count", "nothing judged: the stimulus never crossed the setpoint");
    count.value = 0.0;
    count.lower = static_cast<double>(spec.min_count);
    r.measurements.push_back(std::move(count));
    return r;
  }
  std::vector<Sample> samples;
  samples.reserve(crossings.size());
  std::size_t missing = 0;
  std::size_t cut = 0; // no edge yet when the capture ended, inside limit_us of the crossing
  std::optional<TraceWindow> first_missing;
  for (std::size_t i = 0; i < crossings.size(); ++i) {
    const Nanos c = crossings[i];
    // An edge exactly timeout after the crossing is in time (limits are inclusive); an edge at
    // the next crossing belongs to that crossing. With `early` the crossings split the time
    // between them in half: the nearest edge answers, early or late, and is judged by its
    // latency rather than lost to a neighbour.
    Nanos from = c;
    Nanos until = spec.timeout == Nanos::max() ? Nanos::max() : c + spec.timeout + Nanos{1};
    if (spec.early) {
      const Nanos back = i > 0                      ? (c - crossings[i - 1]) / 2
                         : i + 1 < crossings.size() ? (crossings[i + 1] - c) / 2
                                                    : *spec.early;
      from = c - std::max(back, *spec.early);
      if (i + 1 < crossings.size()) until = std::min(until, c + (crossings[i + 1] - c + Nanos{1}) / 2);
    } else if (i + 1 < crossings.size()) {
      until = std::min(until, crossings[i + 1]);
    }
    const auto e = spec.quiet ? next_burst_edge(output, from, until, spec.expected, *spec.quiet)
                              : next_edge(output, from, until, spec.expected);
    if (e) {
      samples.push_back({e->time - c, c});
    } else if (c + spec.limit > seen_until) {
      ++cut; // a board within the limit may answer after the run: nothing to judge
    } else {
      if (!first_missing) first_missing = TraceWindow{from, until};
      ++missing;
    }
  }
  std::string missing_detail =
      cut == 0 ? "every crossing produced an output edge"
               : fmt::format("every crossing judged produced an output edge ({} not judged: "
                             "the capture ended within limit_us of it)",
                             cut);
  if (first_missing) {
    // Without `early` the search starts at the crossing; an open end (no timeout, the last
    // crossing) is not a time to print.
    const TraceWindow& w = *first_missing;
    const std::string where = !spec.early ? fmt::format("after the crossing at {} ns", w.begin.count())
                              : w.end == Nanos::max()
                                  ? fmt::format("from {} ns on", w.begin.count())
                                  : fmt::format("in {} .. {} ns", w.begin.count(), w.end.count());
    missing_detail = fmt::format("missing edge: no {} edge{} {} (first of {})", level_name(spec.expected),
                                 spec.quiet ? " after a quiet gap" : "", where, missing);
  }
  const std::size_t judged = crossings.size() - cut;
  const std::string cut_detail =
      cut == 0
          ? std::string()
          : fmt::format("; {} crossing(s) within limit_us of the capture's end at {} ns with no edge yet, "
                        "not judged",
                        cut, seen_until.count());
  if (judged < spec.min_count) {
    // Fewer crossings than min_count: no board could reach it, so the shortfall is the
    // stimulus's (an error), not the board's fail. The latencies there are are still judged.
    Measurement count =
        error(spec.name + ".count",
              fmt::format("nothing judged against min_count: the stimulus crossed the setpoint "
                          "{} time(s){}, fewer than min_count ({}); latencies measured: {}{}",
                          judged, cut == 0 ? "" : " in time to be judged", spec.min_count, samples.size(),
                          cut_detail));
    count.value = static_cast<double>(samples.size());
    count.lower = static_cast<double>(spec.min_count);
    r.measurements.push_back(std::move(count));
  } else {
    r.measurements.push_back(measure(
        spec.name + ".count", static_cast<double>(samples.size()), "", static_cast<double>(spec.min_count),
        std::nullopt,
        fmt::format("{} latencies from {} crossings{}", samples.size(), crossings.size(), cut_detail)));
  }
  r.measurements.push_back(measure(spec.name + ".missing", static_cast<double>(missing), "", std::nullopt,
                                   0.0, missing_detail, first_missing));
  if (!samples.empty()) {
    std::stable_sort(samples.begin(), samples.end(),
                     [](const Sample& a, const Sample& b) { return a.latency < b.latency; });
    const auto stat = [&](const std::string& what, std::size_t idx, std::optional<Nanos> upper,
                          std::optional<Nanos> lower = std::nullopt) {
      const Sample& s = samples[idx];
      r.measurements.push_back(measure_time(spec.name + "." + what, s.latency, TimeUnit::Us, lower, upper,
                                            fmt::format("{} latency: crossing at {} ns to {} edge at {} ns",
                                                        what, s.crossing.count(), level_name(spec.expected),
                                                        (s.crossing + s.latency).count()),
                                            TraceWindow{std::min(s.crossing, s.crossing + s.latency),
                                                        std::max(s.crossing, s.crossing + s.latency)},
                                            s.crossing + s.latency));
    };
    const std::size_t n = samples.size();
    stat("min", 0, std::nullopt, spec.early ? std::optional<Nanos>{-*spec.early} : spec.min_limit);
    stat("median", nearest_rank_index(n, 50.0), std::nullopt);
    stat("p99", nearest_rank_index(n, 99.0),
         spec.p99_limit ? spec.p99_limit : std::optional<Nanos>{spec.limit});
    stat("max", n - 1, spec.limit);
    rig::Series lat{"latency", "us", {}};
    lat.values.reserve(n);
    // In crossing order, not sorted: the series is the raw record.
    std::vector<Sample> by_time = samples;
    std::stable_sort(by_time.begin(), by_time.end(),
                     [](const Sample& a, const Sample& b) { return a.crossing < b.crossing; });
    for (const auto& s : by_time) lat.values.push_back(to_us(s.latency));
    r.series.push_back(std::move(lat));
  }
  return r;
}

} // namespace hilrig::checks
