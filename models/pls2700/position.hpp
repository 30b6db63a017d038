#pragma once
// Resolver decode and position arithmetic (pls2700.md §2.3, §4.1, §4.2). The module excites
// the rotor with its reference and samples both stator windings at a reference peak (no
// tracking converter): dividing by the reference there removes the carrier and its sign,
// atan2 gives the angle, truncated to the internal 8,192 counts per turn (L453).
#include <cstdint>

#include "core/time.hpp"
#include "signals/resolver.hpp"

namespace hilrig::models::pls2700 {

inline constexpr int kInternalCounts = 8192;

// The reference on R1/R2: amplitude * cos(2 pi f t); its peaks fall at k / (2f). A whole
// number of hertz (every reference the module takes is one, params_check.hpp), so each peak
// is known exactly: 7.5 kHz peaks every 66,666 2/3 ns, every third one on the 200 us grid.
class Excitation {
public:
  // Throws std::invalid_argument unless frequency_hz is a whole number in 1 .. kMaxWholeHz.
  Excitation(double frequency_hz, double amplitude);
  static constexpr double kMaxWholeHz = 1e6;
  [[nodiscard]] double value(Nanos t) const;
  // The latest peak (positive or negative) at or before t (t >= 0). A peak between two
  // nanoseconds is on the grid at the later one.
  [[nodiscard]] Nanos latest_peak(Nanos t) const;
  // The first peak at or after t (t >= 0), on the grid as latest_peak() has it.
  [[nodiscard]] Nanos peak_at_or_after(Nanos t) const;
  [[nodiscard]] double frequency_hz() const { return frequency_hz_; }
  [[nodiscard]] double amplitude() const { return amplitude_; }
  // The same reference as signals::Resolver writes it (A sin(2 pi f t + pi/2)), so a rig
  // builds carrier-synchronous stator signals from it.
  [[nodiscard]] signals::ResolverParams resolver_params(double transformation_ratio = 1.0) const;

private:
  // Peak k falls at k * half_num_ / half_den_ ns (the half period 1e9 / (2f) ns, reduced).
  [[nodiscard]] std::int64_t peaks_through(Nanos t) const; // index of the latest peak at or before t
  [[nodiscard]] Nanos peak_time(std::int64_t k) const;     // peak k, rounded up to the ns grid
  double frequency_hz_;
  double amplitude_;
  std::int64_t half_num_ = 1;
  std::int64_t half_den_ = 1;
};

struct StatorReading {
  bool valid = false; // demodulated amplitude within the fault band
  int raw = 0;        // 0..8191, increasing with atan2(sin, cos)
  double ratio = 0.0; // stator amplitude / reference amplitude
};

// Demodulates one pair of stator samples taken where the reference was `reference`.
[[nodiscard]] StatorReading decode_stators(double sin_stator, double cos_stator, double reference,
                                           double min_ratio, double max_ratio);

// 8192-count value of an angle in turns (any real; wrapped), truncating. The small tolerance
// keeps an angle synthesized exactly on a count from reading one count low.
[[nodiscard]] int raw_from_turns(double turns);

// §2.3: abs_pos = floor(raw * SF / 8192) [I]; exact shifts for SF 1024 and 4096.
[[nodiscard]] constexpr int absolute_position(int raw, int scale_factor) {
  return static_cast<int>((static_cast<std::int64_t>(raw) * scale_factor) / kInternalCounts);
}
[[nodiscard]] constexpr int mod(int value, int modulus) {
  const int r = value % modulus;
  return r < 0 ? r + modulus : r;
}
// R-CO-1: MP = (abs_pos + CO) mod SF.
[[nodiscard]] constexpr int machine_position(int abs_pos, int circular_offset, int scale_factor) {
  return mod(abs_pos + circular_offset, scale_factor);
}
// R-CO-2: the offset that turns the reading `current` into `desired` (Des == Cur: unchanged).
[[nodiscard]] constexpr int offset_for(int offset_old, int current, int desired, int scale_factor) {
  return mod(offset_old + desired - current, scale_factor);
}
// R-CO-3 AutoZero: the offset that makes the present reading 0.
[[nodiscard]] constexpr int autozero_offset(int offset_old, int current, int scale_factor) {
  return offset_for(offset_old, current, 0, scale_factor);
}
// The signed step from one circular value to the next, the shorter way round.
[[nodiscard]] constexpr int circular_step(int from, int to, int modulus) {
  int d = mod(to - from, modulus);
  if (d >= (modulus + 1) / 2) {
    d -= modulus;
  }
  return d;
}

} // namespace hilrig::models::pls2700
