#include "models/pls2700/position.hpp"

#include <cmath>
#include <numbers>

#include "signals/stator_band.hpp"

namespace hilrig::models::pls2700 {

Excitation::Excitation(double frequency_hz, double amplitude)
    : frequency_hz_(frequency_hz), amplitude_(amplitude),
      half_period_(Nanos::from_seconds(0.5 / frequency_hz)) {}

double Excitation::value(Nanos t) const {
  return amplitude_ * std::cos(2.0 * std::numbers::pi * frequency_hz_ * t.seconds());
}

Nanos Excitation::latest_peak(Nanos t) const {
  if (t < Nanos{0}) {
    return Nanos{0};
  }
  return half_period_ * (t / half_period_);
}

Nanos Excitation::peak_at_or_after(Nanos t) const {
  const Nanos before = latest_peak(t);
  return before < t ? before + half_period_ : before;
}

signals::ResolverParams Excitation::resolver_params(double transformation_ratio) const {
  signals::ResolverParams p;
  p.excitation_hz = frequency_hz_;
  p.excitation_amplitude = amplitude_;
  p.excitation_phase_rad = std::numbers::pi / 2.0;
  p.transformation_ratio = transformation_ratio;
  return p;
}

int raw_from_turns(double turns) {
  const double counts = std::floor(turns * kInternalCounts + 1e-6);
  const double wrapped = counts - std::floor(counts / kInternalCounts) * kInternalCounts;
  return static_cast<int>(wrapped) % kInternalCounts;
}

StatorReading decode_stators(double sin_stator, double cos_stator, double reference, double min_ratio,
                             double max_ratio) {
  StatorReading r;
  if (reference == 0.0) {
    return r;
  }
  const double s = sin_stator / reference;
  const double c = cos_stator / reference;
  r.ratio = std::hypot(s, c);
  r.valid = signals::stator_ratio_in_band(r.ratio, min_ratio, max_ratio); // closed, with rounding slack
  if (r.valid) {
    r.raw = raw_from_turns(std::atan2(s, c) / (2.0 * std::numbers::pi));
  }
  return r;
}

} // namespace hilrig::models::pls2700
