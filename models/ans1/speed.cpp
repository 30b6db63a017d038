#include "models/ans1/speed.hpp"

#include <cmath>

namespace hilrig::models::ans1 {

double measured_rpm(std::int64_t delta_counts, std::uint16_t counts_per_cycle, Nanos period) {
  if (period <= Nanos::zero() || counts_per_cycle == 0) {
    return 0.0;
  }
  const double cycles = static_cast<double>(delta_counts) / static_cast<double>(counts_per_cycle);
  return cycles * 60.0 / period.seconds();
}

std::int16_t reported_rpm(double speed) { return saturated_speed_word(std::round(speed)); }

void SpeedFilter::update(std::int64_t delta_counts, std::uint16_t counts_per_cycle, Nanos period,
                         std::uint16_t rpm_filter) {
  measured_ = measured_rpm(delta_counts, counts_per_cycle, period);
  value_ = filter_step(value_, measured_, rpm_filter);
}

} // namespace hilrig::models::ans1
