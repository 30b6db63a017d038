#include "signals/discrete_bounce.hpp"

#include <cmath>
#include <random>
#include <stdexcept>

namespace hilrig::signals {

std::vector<Nanos> draw_bounce_gaps(const ContactBounce& bounce) {
  const std::size_t gaps = 2 * bounce.bounces;
  std::vector<Nanos> widths;
  if (gaps == 0) return widths;
  if (bounce.min_width <= Nanos::zero()) throw std::invalid_argument("ContactBounce: min_width must be > 0");
  const Nanos spare = bounce.window - bounce.min_width * static_cast<std::int64_t>(gaps);
  if (spare < Nanos::zero())
    throw std::invalid_argument("ContactBounce: window too short for min_width gaps");
  std::mt19937_64 rng(bounce.seed);
  std::vector<double> draws(gaps);
  double total = 0.0;
  for (double& u : draws) {
    u = static_cast<double>((rng() >> 11) + 1); // 1 .. 2^53, exact in a double
    total += u;
  }
  const auto spare_ns = static_cast<double>(spare.count());
  for (const double u : draws)
    widths.push_back(bounce.min_width + Nanos{static_cast<std::int64_t>(std::floor(spare_ns * (u / total)))});
  return widths;
}

std::vector<Edge> bounce_edges(Nanos t, Level target, const ContactBounce& bounce) {
  if (bounce.window < Nanos::zero()) throw std::invalid_argument("ContactBounce: window must be >= 0");
  std::vector<Nanos> gaps = bounce.widths;
  if (gaps.empty()) {
    gaps = draw_bounce_gaps(bounce);
  } else {
    if (gaps.size() != 2 * bounce.bounces)
      throw std::invalid_argument("ContactBounce: widths must hold 2 * bounces gaps");
    Nanos sum{0};
    for (const Nanos g : gaps) {
      if (g <= Nanos::zero()) throw std::invalid_argument("ContactBounce: gaps must be > 0");
      sum += g;
    }
    if (sum > bounce.window) throw std::invalid_argument("ContactBounce: gaps exceed the window");
  }
  std::vector<Edge> edges;
  edges.reserve(gaps.size() + 1);
  Level level = target;
  edges.push_back(Edge{t, level});
  for (const Nanos g : gaps) {
    t += g;
    level = !level;
    edges.push_back(Edge{t, level});
  }
  return edges;
}

} // namespace hilrig::signals
