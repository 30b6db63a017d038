#pragma once
// Global Machine Speed (spec §4.2): every 14.6 ms the measured speed X is folded into the
// exponential filter S = k S + (1 - k) X with k = RPMFilter / 65536. S is signed machine
// cycles per minute ([MODEL] for A13: CPC counts make one cycle, the only definition that
// works for an encoder). X is the change in transducer counts over the update period ([MODEL]
// for A14).
#include <algorithm>
#include <cstdint>

#include "core/time.hpp"

namespace hilrig::models::ans1 {

// k = RPMFilter / 65536 (L822): 40960 -> 0.625.
[[nodiscard]] constexpr double filter_coefficient(std::uint16_t rpm_filter) {
  return static_cast<double>(rpm_filter) / 65536.0;
}

// Machine cycles per minute from a count change over a period.
[[nodiscard]] double measured_rpm(std::int64_t delta_counts, std::uint16_t counts_per_cycle, Nanos period);

[[nodiscard]] constexpr double filter_step(double previous, double measured, std::uint16_t rpm_filter) {
  const double k = filter_coefficient(rpm_filter);
  return k * previous + (1.0 - k) * measured;
}

// A speed-like host word (DA16 w2 speed, w3 production rate) saturates at +-32767, the
// range of the words a speed is set against (RPM Enable setpoints, L2019-L2020) [MODEL]: a
// reverse speed saturates at the mirror of a forward one, never at -32768, so the widest
// window -32767 .. 32767 holds both. `whole` is already a whole number.
inline constexpr double kSpeedWordLimit = 32767.0;
[[nodiscard]] constexpr std::int16_t saturated_speed_word(double whole) {
  return static_cast<std::int16_t>(std::clamp(whole, -kSpeedWordLimit, kSpeedWordLimit));
}

// DA16 word 2: rounded to the nearest RPM ([MODEL], rounding not stated), saturated.
[[nodiscard]] std::int16_t reported_rpm(double speed);

class SpeedFilter {
public:
  // Folds one measurement period into S.
  void update(std::int64_t delta_counts, std::uint16_t counts_per_cycle, Nanos period,
              std::uint16_t rpm_filter);
  [[nodiscard]] double value() const { return value_; }
  [[nodiscard]] double last_measured() const { return measured_; }
  [[nodiscard]] std::int16_t reported() const { return reported_rpm(value_); }

private:
  double value_ = 0.0;
  double measured_ = 0.0;
  friend bool operator==(const SpeedFilter&, const SpeedFilter&) = default;
};

} // namespace hilrig::models::ans1
