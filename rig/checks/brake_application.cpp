#include "rig/checks/brake_application.hpp"

#include <algorithm>
#include <set>

#include "rig/checks/support.hpp"

namespace hilrig::checks {
namespace {

constexpr Nanos kTick{1'000'000};         // L1039: the input checked every millisecond
constexpr Nanos kSampleStart{16'000'000}; // L1039: sampling begins 16 ms after the transition
constexpr int kSamples = 16;              // L1039-L1040: the next sixteen
constexpr int kNoiseReleased = 8;         // L1039: released for 8 of them: noise
constexpr int kQualifyApplied = 12;       // L1040: applied for 12 of the 16, else noise
// A cycle is decided no sooner than its 8th sample (16 + 7 ms): starts of one application
// seen through different edges of its bounce lie closer than that to one another.
constexpr Nanos kSameApplication{16'000'000};
constexpr std::size_t kMaxPhases = 4096; // tick phases tried; more distinct ones: undecided

// The first tick (phase + n ms) at or after t.
Nanos tick_at_or_after(Nanos t, Nanos phase) {
  const std::int64_t d = (t - phase).count();
  const std::int64_t n = d <= 0 ? 0 : (d + kTick.count() - 1) / kTick.count();
  return phase + n * kTick;
}

struct Seen {
  std::optional<Nanos> start{}; // the qualified cycle's t0 on the board's ticks
  std::optional<Nanos> edge{};  // the transition whose tick started it (nullopt: a restart)
  std::vector<Nanos> rejected{};
};

// The board whose ticks have `phase`: the first tick from `after` on that sees the line applied
// after a tick that saw it released.
std::optional<Nanos> seen_transition(std::span<const Edge> line, Level before, Level applied, Nanos after,
                                     Nanos phase, Nanos end, std::optional<Nanos>& edge) {
  for (auto e = next_edge(line, after, Nanos::max(), applied); e && e->time <= end;
       e = next_edge(line, e->time + Nanos{1}, Nanos::max(), applied)) {
    const Nanos t = tick_at_or_after(std::max(e->time, after), phase);
    if (t > end) return std::nullopt;
    if (level_at(line, t, before) == applied && level_at(line, t - kTick, before) != applied) {
      edge = e->time;
      return t;
    }
  }
  return std::nullopt;
}

Seen on_ticks(std::span<const Edge> line, Level before, Level applied, Nanos from, Nanos end, Nanos phase) {
  Seen out;
  std::optional<Nanos> edge;
  std::optional<Nanos> t0 = seen_transition(line, before, applied, from, phase, end, edge);
  while (t0) {
    int released = 0;
    std::optional<Nanos> abort_at;
    for (int k = 0; k < kSamples && !abort_at; ++k) {
      const Nanos at = *t0 + kSampleStart + k * kTick;
      if (at > end) return out;
      if (level_at(line, at, before) != applied && ++released >= kNoiseReleased) abort_at = at;
    }
    if (!abort_at) {
      const Nanos decision = *t0 + kSampleStart + kSamples * kTick;
      if (decision > end) return out;
      if (kSamples - released >= kQualifyApplied) {
        out.start = t0;
        out.edge = edge;
        return out;
      }
      abort_at = decision;
    }
    out.rejected.push_back(edge.value_or(*t0));
    if (level_at(line, *abort_at, before) == applied) {
      t0 = abort_at; // restart at once, re-timed (digest A9)
      edge.reset();
    } else {
      t0 = seen_transition(line, before, applied, *abort_at + Nanos{1}, phase, end, edge);
    }
  }
  return out;
}

} // namespace

BrakeApplication brake_application(std::span<const Edge> line, Level before, Level applied_level, Nanos from,
                                   Nanos end, BrakeDebounce rule) {
  BrakeApplication out;
  if (rule == BrakeDebounce::None) {
    const auto e = next_edge(line, from, Nanos::max(), applied_level);
    if (e && e->time <= end) out.applied = e->time;
    return out;
  }
  // The outcome changes only where a tick meets an edge or the capture's end: each such phase
  // and the one 1 ns after it (a tick at the end is inside the capture, 1 ns later it is not).
  std::set<std::int64_t> phases;
  const auto add = [&](Nanos t) {
    const std::int64_t p = ((t.count() % kTick.count()) + kTick.count()) % kTick.count();
    phases.insert(p);
    phases.insert((p + 1) % kTick.count());
  };
  add(end);
  for (const Edge& e : line) {
    add(e.time);
    if (phases.size() > kMaxPhases) {
      out.depends_on_phase = true;
      return out;
    }
  }
  std::optional<Nanos> earliest;
  Nanos latest{0};
  bool some = false;
  bool none = false;
  for (const std::int64_t p : phases) {
    Seen s = on_ticks(line, before, applied_level, from, end, Nanos{p});
    if (out.rejected.empty()) out.rejected = std::move(s.rejected);
    if (!s.start) {
      none = true;
      continue;
    }
    some = true;
    const Nanos first = s.edge.value_or(*s.start); // the board's t0 is no sooner than its transition
    earliest = earliest ? std::min(*earliest, first) : first;
    latest = std::max(latest, first);
  }
  if (some && (none || latest - *earliest >= kSameApplication)) {
    out.depends_on_phase = true;
    return out;
  }
  out.applied = earliest;
  out.latest = earliest ? latest : Nanos{0};
  return out;
}

} // namespace hilrig::checks
