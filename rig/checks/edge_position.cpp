#include "rig/checks/edge_position.hpp"

#include <cmath>
#include <fmt/format.h>
#include <optional>
#include <string>
#include <utility>

namespace hilrig::checks {
namespace {

// The representative of `p` modulo m nearest to `ref`, so a window across the wrap still
// compares as a small difference.
double nearest_wrap(double p, double ref, double m) {
  if (m <= 0.0) return p;
  return ref + std::remainder(p - ref, m);
}

struct Common {
  std::string name;
  Level level;
  double tolerance;
  double modulus;
  std::size_t min_edges;
  std::optional<Nanos> from{}; // the edges judged: those in [from, to]
  std::optional<Nanos> to{};
  std::string target{}; // where the edges are due, for "the shaft never reached <target>"
};

// " from 100000000 ns to 1300000000 ns": the time span judged, where the check sets one.
std::string span_words(const Common& c) {
  std::string out;
  if (c.from) out += fmt::format(" from {} ns", c.from->count());
  if (c.to) out += fmt::format(" to {} ns", c.to->count());
  return out;
}

// `expected(edge, speed)` gives the expected position and a sentence saying how.
template <class Expected>
CheckResult judge_edges(std::span<const Edge> output, const PositionFn& position, const PositionFn& speed,
                        const Common& c, const ReachedFn& reached, const char* kind, Expected expected) {
  CheckResult r;
  r.kind = kind;
  std::size_t n = 0;
  for (const Edge& e : output) {
    if (e.level != c.level) continue;
    if ((c.from && e.time < *c.from) || (c.to && e.time > *c.to)) continue;
    const double s = speed ? speed(e.time) : 0.0;
    auto [want, how] = expected(s);
    const double read = position(e.time);
    const double fired = nearest_wrap(read, want, c.modulus);
    std::optional<TraceWindow> window;
    // Position is inside the tolerance from t(want - tol) to t(want + tol); linear at speed s.
    // Only when those are times: a speed or position that is not a number (or a speed so
    // small the window outlasts 64-bit nanoseconds) has no window, and its measurement errs.
    const double to_lo = (want - c.tolerance - fired) / s;
    const double to_hi = (want + c.tolerance - fired) / s;
    constexpr double kMaxSeconds = 9e9;                                               // |Nanos| < 9.2e18
    if (s != 0.0 && std::abs(to_lo) < kMaxSeconds && std::abs(to_hi) < kMaxSeconds) { // false for NaN
      Nanos a = e.time + Nanos::from_seconds(to_lo);
      Nanos b = e.time + Nanos::from_seconds(to_hi);
      if (b < a) std::swap(a, b);
      window = TraceWindow{a, b};
    }
    Measurement m =
        measure(fmt::format("{}.edge{}", c.name, n), fired, "counts", want - c.tolerance, want + c.tolerance,
                fmt::format("{} edge at {} ns fired at {} counts; expected {} ± {}", level_name(c.level),
                            e.time.count(), fired + 0.0, how, c.tolerance),
                window, e.time);
    // Wrapped, the value keeps the rounding of the position as read (4e10 counts: ~1e-5) but
    // its limits are small numbers (101 +- tol: a slack of ~1e-10), so a board exactly at the
    // limit could fail. Judged by the same rule where the position was read: the limits moved
    // by the turns between the two.
    if (c.modulus > 0.0 && m.outcome != Outcome::Error) {
      const double turns = read - fired;
      m.outcome = rig::judge(read, turns + want - c.tolerance, turns + want + c.tolerance);
    }
    r.measurements.push_back(std::move(m));
    ++n;
  }
  if (n < c.min_edges && reached) {
    if (const Reaches reaches = reached(); reaches.complete < c.min_edges) {
      const std::size_t times = reaches.complete;
      const std::string span = c.to && !c.from ? fmt::format(" up to {} ns", c.to->count()) : span_words(c);
      const std::string open =
          reaches.open_at_end
              ? fmt::format(
                    ", the last with the shaft still within {} counts of it when the span ended (a board "
                    "within the tolerance may fire after that: not judged)",
                    c.tolerance)
              : std::string();
      Measurement m =
          error(c.name + ".edges",
                times == 0 && !reaches.open_at_end
                    ? fmt::format("nothing judged: the shaft never reached {}{} (the stimulus never came)",
                                  c.target, span)
                    : fmt::format("nothing judged against min_edges: the shaft reached {} {} time(s){}{}, "
                                  "fewer than min_edges ({}); {} edges: {}",
                                  c.target, times + (reaches.open_at_end ? 1 : 0), span, open, c.min_edges,
                                  level_name(c.level), n));
      m.value = static_cast<double>(n);
      m.lower = static_cast<double>(c.min_edges);
      r.measurements.insert(r.measurements.begin(), std::move(m));
      return r;
    }
  }
  if (n == 0 && c.min_edges == 0) {
    r.measurements.push_back(
        error(c.name + ".edges",
              fmt::format("nothing judged: no {} edge on the output{}", level_name(c.level), span_words(c))));
    return r;
  }
  r.measurements.insert(r.measurements.begin(),
                        measure(c.name + ".edges", static_cast<double>(n), "",
                                static_cast<double>(c.min_edges), std::nullopt,
                                n == 0 ? fmt::format("missing edge: no {} edge on the output{}",
                                                     level_name(c.level), span_words(c))
                                       : fmt::format("{} {} edges", n, level_name(c.level))));
  return r;
}

} // namespace

CheckResult check_advance(std::span<const Edge> output, const PositionFn& position, const PositionFn& speed,
                          const AdvanceSpec& spec, const ReachedFn& reached) {
  const Common c{spec.name,      spec.level,
                 spec.tolerance, spec.modulus,
                 spec.min_edges, std::nullopt,
                 std::nullopt,   fmt::format("setpoint {} less its advance", spec.setpoint)};
  return judge_edges(output, position, speed, c, reached, "advance_counts", [&](double s) {
    const double adv =
        spec.advance_counts ? *spec.advance_counts : s * static_cast<double>(spec.advance.count()) / 1e9;
    // Shortest round-trip digits (a value a hair off never reads as another); + 0.0 makes -0 a 0,
    // and a negative advance (reverse motion) reads "+ 0.125", not "- -0.125".
    const double a = adv + 0.0;
    return std::pair{spec.setpoint - adv,
                     fmt::format("{} {} {} (speed {} counts/s) = {}", spec.setpoint, a < 0 ? '+' : '-',
                                 std::abs(a), s + 0.0, spec.setpoint - adv + 0.0)};
  });
}

CheckResult check_edge_at_position(std::span<const Edge> output, const PositionFn& position,
                                   const PositionFn& speed, const EdgeAtPositionSpec& spec,
                                   const ReachedFn& reached) {
  const Common c{spec.name,      spec.level, spec.tolerance, spec.modulus,
                 spec.min_edges, spec.from,  spec.to,        fmt::format("position {}", spec.position)};
  return judge_edges(output, position, speed, c, reached, "edge_at_position", [&](double) {
    return std::pair{spec.position, fmt::format("{}", spec.position)};
  });
}

} // namespace hilrig::checks
