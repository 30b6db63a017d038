#pragma once
// The resolver front end (spec §2.1): the ANS1 drives the rotor with its reference and reads
// the two stator pairs. The model samples both stators at each excitation peak, demodulates
// by the reference's sign and value there, and converts atan2 to 12 bits (4,096 counts/turn).
// A stator amplitude out of range is a resolver fault.
#include <cstdint>
#include <optional>

#include "core/analog.hpp"
#include "core/time.hpp"

namespace hilrig::models::ans1 {

inline constexpr int kResolverCounts = 4096;

class ResolverExcitation {
public:
  ResolverExcitation(double frequency_hz, double amplitude);
  // The reference on R1/R2 at time t: amplitude * sin(2 pi f t).
  [[nodiscard]] double value(Nanos t) const;
  // The latest peak (positive or negative) at or before t.
  [[nodiscard]] Nanos latest_peak(Nanos t) const;
  // The first peak strictly after t.
  [[nodiscard]] Nanos next_peak(Nanos t) const;
  // Between two peaks (a positive and a negative one).
  [[nodiscard]] Nanos half_period() const { return half_period_; }
  [[nodiscard]] double frequency_hz() const { return frequency_hz_; }
  [[nodiscard]] double amplitude() const { return amplitude_; }

private:
  double frequency_hz_;
  double amplitude_;
  Nanos half_period_;
  Nanos first_peak_;
};

struct ResolverReading {
  bool valid = false;      // amplitude within range
  std::uint16_t angle = 0; // 0..4095, counts increasing with atan2(sin, cos)
  double ratio = 0.0;      // stator amplitude / reference amplitude
};

// Demodulates one sample pair taken where the reference was `reference` (non-zero).
[[nodiscard]] ResolverReading decode_resolver(double sin_stator, double cos_stator, double reference,
                                              double min_ratio, double max_ratio);

// The signed change from one 12-bit angle to the next, taking the shorter way round.
[[nodiscard]] constexpr std::int32_t angle_step(std::uint16_t from, std::uint16_t to) {
  std::int32_t d = static_cast<std::int32_t>(to) - static_cast<std::int32_t>(from);
  if (d >= kResolverCounts / 2) {
    d -= kResolverCounts;
  } else if (d < -kResolverCounts / 2) {
    d += kResolverCounts;
  }
  return d;
}

} // namespace hilrig::models::ans1
