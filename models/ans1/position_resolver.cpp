#include "models/ans1/position_resolver.hpp"

#include <cmath>
#include <numbers>

#include "signals/stator_band.hpp"

namespace hilrig::models::ans1 {

ResolverExcitation::ResolverExcitation(double frequency_hz, double amplitude)
    : frequency_hz_(frequency_hz), amplitude_(amplitude),
      half_period_(Nanos::from_seconds(0.5 / frequency_hz)),
      first_peak_(Nanos::from_seconds(0.25 / frequency_hz)) {}

double ResolverExcitation::value(Nanos t) const {
  return amplitude_ * std::sin(2.0 * std::numbers::pi * frequency_hz_ * t.seconds());
}

Nanos ResolverExcitation::latest_peak(Nanos t) const {
  if (t < first_peak_) {
    return first_peak_; // before the first peak: the caller checks the time
  }
  const std::int64_t k = (t - first_peak_) / half_period_;
  return first_peak_ + half_period_ * k;
}

Nanos ResolverExcitation::next_peak(Nanos t) const {
  return t < first_peak_ ? first_peak_ : latest_peak(t) + half_period_;
}

ResolverReading decode_resolver(double sin_stator, double cos_stator, double reference, double min_ratio,
                                double max_ratio) {
  ResolverReading r;
  if (reference == 0.0) {
    return r;
  }
  // Dividing by the reference removes the carrier and its sign (negative peaks).
  const double s = sin_stator / reference;
  const double c = cos_stator / reference;
  r.ratio = std::hypot(s, c);
  r.valid = signals::stator_ratio_in_band(r.ratio, min_ratio, max_ratio); // closed, with rounding slack
  if (!r.valid) {
    return r;
  }
  double turns = std::atan2(s, c) / (2.0 * std::numbers::pi);
  if (turns < 0.0) {
    turns += 1.0;
  }
  // Truncate like a 12-bit converter: count k from theta = 2 pi k / 4096 on. The small
  // tolerance keeps an angle synthesized exactly at a count from reading one count low.
  const auto counts = static_cast<std::int64_t>(std::floor(turns * kResolverCounts + 1e-6));
  r.angle = static_cast<std::uint16_t>(counts % kResolverCounts);
  return r;
}

} // namespace hilrig::models::ans1
