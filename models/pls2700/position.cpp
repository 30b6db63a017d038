#include "models/pls2700/position.hpp"

#include <cmath>
#include <numbers>
#include <numeric>
#include <stdexcept>
#include <string>

#include "signals/stator_band.hpp"

namespace hilrig::models::pls2700 {

Excitation::Excitation(double frequency_hz, double amplitude)
    : frequency_hz_(frequency_hz), amplitude_(amplitude) {
  if (!(frequency_hz >= 1.0 && frequency_hz <= kMaxWholeHz && std::floor(frequency_hz) == frequency_hz))
    throw std::invalid_argument("pls2700: a reference frequency in whole hertz, 1 .. 1000000 (got " +
                                std::to_string(frequency_hz) + ")");
  constexpr std::int64_t kNanosPerSecond = 1'000'000'000;
  const std::int64_t twice_hz = 2 * static_cast<std::int64_t>(frequency_hz);
  const std::int64_t common = std::gcd(kNanosPerSecond, twice_hz);
  half_num_ = kNanosPerSecond / common;
  half_den_ = twice_hz / common;
}

double Excitation::value(Nanos t) const {
  return amplitude_ * std::cos(2.0 * std::numbers::pi * frequency_hz_ * t.seconds());
}

// floor(t * den / num), split so no product exceeds num * den (< 2e15).
std::int64_t Excitation::peaks_through(Nanos t) const {
  const std::int64_t whole = t.count() / half_num_;
  const std::int64_t rest = t.count() % half_num_;
  return whole * half_den_ + rest * half_den_ / half_num_;
}

// ceil(k * num / den), split likewise.
Nanos Excitation::peak_time(std::int64_t k) const {
  const std::int64_t whole = k / half_den_;
  const std::int64_t rest = k % half_den_;
  return Nanos{whole * half_num_ + (rest * half_num_ + half_den_ - 1) / half_den_};
}

Nanos Excitation::latest_peak(Nanos t) const {
  if (t < Nanos{0}) {
    return Nanos{0};
  }
  return peak_time(peaks_through(t)); // k num / den <= t, so its ceiling is too (t is whole)
}

Nanos Excitation::peak_at_or_after(Nanos t) const {
  if (t < Nanos{0}) {
    return Nanos{0};
  }
  const std::int64_t k = peaks_through(t);
  const Nanos before = peak_time(k);
  return before < t ? peak_time(k + 1) : before;
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
