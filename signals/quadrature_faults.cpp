#include "signals/quadrature_faults.hpp"

#include <algorithm>
#include <cmath>
#include <iterator>
#include <random>
#include <stdexcept>
#include <utility>
#include <vector>

namespace hilrig::signals {

namespace {

bool is_ab(QuadChannel ch) { return ch != QuadChannel::Z; }

// The true encoder count at any time: the count of the last A/B edge at or before it.
class CountLookup {
public:
  explicit CountLookup(const QuadratureTrace& trace) : initial_(trace.initial_count) {
    for (const QuadEdge& e : trace.edges)
      if (is_ab(e.channel)) steps_.push_back(e);
  }
  [[nodiscard]] std::int64_t at(Nanos t) const {
    const auto it = std::upper_bound(steps_.begin(), steps_.end(), t,
                                     [](Nanos time, const QuadEdge& e) { return time < e.time; });
    return it == steps_.begin() ? initial_ : std::prev(it)->count;
  }

private:
  std::int64_t initial_;
  std::vector<QuadEdge> steps_;
};

void sort_by_time(std::vector<QuadEdge>& edges) {
  std::stable_sort(edges.begin(), edges.end(),
                   [](const QuadEdge& x, const QuadEdge& y) { return x.time < y.time; });
}

// Inverts `channel` during each window: its edges become the sorted union of its own
// toggles and the window boundaries; two toggles at the same nanosecond cancel.
void xor_windows(QuadratureTrace& trace, QuadChannel channel,
                 const std::vector<std::pair<Nanos, Nanos>>& windows) {
  std::vector<Nanos> toggles;
  std::vector<QuadEdge> kept;
  for (const QuadEdge& e : trace.edges) {
    if (e.channel == channel)
      toggles.push_back(e.time);
    else
      kept.push_back(e);
  }
  for (const auto& [from, to] : windows) {
    if (to <= from) continue;
    toggles.push_back(from);
    toggles.push_back(to);
  }
  std::sort(toggles.begin(), toggles.end());
  std::vector<Nanos> net;
  for (const Nanos t : toggles) {
    if (!net.empty() && net.back() == t)
      net.pop_back();
    else
      net.push_back(t);
  }
  const CountLookup counts(trace);
  bool level = trace.initial_level(channel);
  for (const Nanos t : net) {
    level = !level;
    kept.push_back(QuadEdge{t, counts.at(t), channel, level_of(level)});
  }
  trace.edges = std::move(kept);
  sort_by_time(trace.edges);
}

std::uint64_t below(std::mt19937_64& rng, std::uint64_t n) { return n == 0 ? 0 : rng() % n; }

} // namespace

void inject_glitch(QuadratureTrace& trace, QuadChannel channel, Nanos at, Nanos width) {
  if (width <= Nanos::zero()) throw std::invalid_argument("inject_glitch: width must be > 0");
  xor_windows(trace, channel, {{at, at + width}});
}

void inject_missing_edge(QuadratureTrace& trace, std::size_t index) {
  if (index >= trace.edges.size() || !is_ab(trace.edges[index].channel))
    throw std::invalid_argument("inject_missing_edge: index must name an A or B edge");
  const QuadChannel ch = trace.edges[index].channel;
  for (std::size_t j = index + 1; j < trace.edges.size(); ++j) {
    if (trace.edges[j].channel == ch) {
      trace.edges.erase(trace.edges.begin() + static_cast<std::ptrdiff_t>(j));
      break;
    }
  }
  trace.edges.erase(trace.edges.begin() + static_cast<std::ptrdiff_t>(index));
}

void inject_simultaneous_edges(QuadratureTrace& trace, std::size_t index) {
  if (index >= trace.edges.size() || !is_ab(trace.edges[index].channel))
    throw std::invalid_argument("inject_simultaneous_edges: index must name an A or B edge");
  const QuadChannel other = trace.edges[index].channel == QuadChannel::A ? QuadChannel::B : QuadChannel::A;
  for (std::size_t j = index + 1; j < trace.edges.size(); ++j) {
    if (trace.edges[j].channel == other) {
      trace.edges[j].time = trace.edges[index].time;
      sort_by_time(trace.edges);
      return;
    }
  }
  throw std::invalid_argument("inject_simultaneous_edges: no later edge on the other channel");
}

void inject_noise_burst(QuadratureTrace& trace, const NoiseBurst& burst) {
  if (burst.length <= Nanos::zero() || burst.min_width <= Nanos::zero() || burst.max_width < burst.min_width)
    throw std::invalid_argument("inject_noise_burst: needs length > 0 and 0 < min_width <= max_width");
  std::mt19937_64 rng(burst.seed);
  std::vector<std::pair<Nanos, Nanos>> on_a;
  std::vector<std::pair<Nanos, Nanos>> on_b;
  const auto length = static_cast<std::uint64_t>(burst.length.count());
  const auto spread = static_cast<std::uint64_t>((burst.max_width - burst.min_width).count()) + 1;
  for (std::size_t i = 0; i < burst.pulses; ++i) {
    const bool b = (rng() >> 63) != 0;
    const Nanos at = burst.start + Nanos{static_cast<std::int64_t>(below(rng, length))};
    const Nanos width = burst.min_width + Nanos{static_cast<std::int64_t>(below(rng, spread))};
    (b ? on_b : on_a).emplace_back(at, at + width);
  }
  xor_windows(trace, QuadChannel::A, on_a);
  xor_windows(trace, QuadChannel::B, on_b);
}

void inject_phase_error(QuadratureTrace& trace, double fraction) {
  std::vector<QuadEdge>& edges = trace.edges;
  const std::vector<QuadEdge> original = edges;
  Nanos previous_b = Nanos::min();
  for (std::size_t i = 0; i < edges.size(); ++i) {
    if (edges[i].channel != QuadChannel::B) continue;
    const Nanos t = original[i].time;
    Nanos anchor = t;
    if (fraction > 0) {
      for (std::size_t k = i + 1; k < edges.size(); ++k)
        if (original[k].channel == QuadChannel::A) {
          anchor = original[k].time;
          break;
        }
    } else {
      for (std::size_t k = i; k-- > 0;)
        if (original[k].channel == QuadChannel::A) {
          anchor = original[k].time;
          break;
        }
    }
    Nanos moved = t + Nanos::from_seconds(std::abs(fraction) * (anchor - t).seconds());
    // B keeps its own order: a shifted edge never passes the next B edge.
    Nanos next_b = Nanos::max();
    for (std::size_t k = i + 1; k < edges.size(); ++k)
      if (original[k].channel == QuadChannel::B) {
        next_b = original[k].time;
        break;
      }
    moved = std::clamp(moved, previous_b, next_b);
    edges[i].time = moved;
    previous_b = moved;
  }
  sort_by_time(edges);
}

} // namespace hilrig::signals
