#include "signals/quadrature_encoder.hpp"

#include <algorithm>
#include <cmath>

namespace hilrig::signals {

double QuadratureEncoder::counts_per_unit() const {
  const double cpu = static_cast<double>(counts_per_turn()) / units_per_turn;
  return reversed ? -cpu : cpu;
}

std::int64_t QuadratureEncoder::count_at(double position) const {
  return static_cast<std::int64_t>(std::floor(snapped_counts(position) + 1.0 - edge_offset()));
}

double QuadratureEncoder::snap_to_count(double c, double magnitude) {
  const double whole = std::nearbyint(c);
  const double scale = std::max({std::abs(magnitude), std::abs(c), 1.0});
  return std::abs(c - whole) <= std::ldexp(scale, -49) ? whole : c;
}

bool QuadratureEncoder::index_high(std::int64_t count) const {
  if (index_width <= 0) return false;
  const std::int64_t cpt = counts_per_turn();
  std::int64_t phase = (count - index_count) % cpt;
  if (phase < 0) phase += cpt;
  return phase < index_width;
}

} // namespace hilrig::signals
