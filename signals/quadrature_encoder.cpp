#include "signals/quadrature_encoder.hpp"

#include <cmath>

namespace hilrig::signals {

double QuadratureEncoder::counts_per_unit() const {
  const double cpu = static_cast<double>(counts_per_turn()) / units_per_turn;
  return reversed ? -cpu : cpu;
}

std::int64_t QuadratureEncoder::count_at(double position) const {
  return static_cast<std::int64_t>(std::floor(counts(position) + 1.0 - edge_offset()));
}

bool QuadratureEncoder::index_high(std::int64_t count) const {
  if (index_width <= 0) return false;
  const std::int64_t cpt = counts_per_turn();
  std::int64_t phase = (count - index_count) % cpt;
  if (phase < 0) phase += cpt;
  return phase < index_width;
}

} // namespace hilrig::signals
