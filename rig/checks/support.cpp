#include "rig/checks/support.hpp"

#include <algorithm>
#include <cmath>
#include <iterator>
#include <utility>

namespace hilrig::checks {

std::size_t nearest_rank_index(std::size_t n, double p) {
  if (n == 0) return 0;
  const double rank = std::ceil(p / 100.0 * static_cast<double>(n));
  const auto r = static_cast<std::size_t>(std::max(1.0, rank));
  return std::min(r, n) - 1;
}

std::optional<Edge> next_edge(std::span<const Edge> edges, Nanos from, Nanos until, Level level) {
  const auto it =
      std::lower_bound(edges.begin(), edges.end(), from, [](const Edge& e, Nanos t) { return e.time < t; });
  for (auto i = it; i != edges.end() && i->time < until; ++i) {
    if (i->level == level) return *i;
  }
  return std::nullopt;
}

Level level_at(std::span<const Edge> edges, Nanos t, Level before) {
  const auto it =
      std::upper_bound(edges.begin(), edges.end(), t, [](Nanos x, const Edge& e) { return x < e.time; });
  return it == edges.begin() ? before : std::prev(it)->level;
}

const char* level_name(Level l) { return is_high(l) ? "high" : "low"; }

} // namespace hilrig::checks
