#pragma once
// A resolver-to-digital converter model: synchronous demodulation of the sampled stator
// signals against the converter's own reference, one carrier period per window, then a
// type-II tracking loop (phase detector sin(theta - phi), PI filter, integrator), so a
// constant speed is tracked with zero steady-state error. Like the AD2S1210 it flags loss
// of signal and degradation of signal from the demodulated amplitude sqrt(sin^2 + cos^2),
// and loss of tracking from the loop error.
// Feed it at least ~8 samples per carrier period; the sample grid need not divide the
// period (each window's reference-energy centroid is where its angle is compared).

#include <cstddef>
#include <cstdint>
#include <span>

#include "core/time.hpp"
#include "signals/resolver.hpp"

namespace hilrig::signals {

struct RdParams {
  double excitation_hz = 5'000.0;    // the converter's reference; one demodulation window per period
  double excitation_phase_rad = 0.0; // reference phase at t = 0 (windows start at its zero crossing)
  double nominal_amplitude = 1.0;    // expected demodulated amplitude: TR (stator / reference)
  double loop_bandwidth_hz = 100.0;  // natural frequency of the type-II loop
  double damping = 0.7;
  double los_threshold = 0.5; // amplitude below this fraction of nominal: loss of signal
  double dos_low = 0.85;      // amplitude outside [dos_low, dos_high] x nominal: degradation
  double dos_high = 1.15;
  double lot_threshold_turns = 1.0 / 256.0; // |tracking error| above: loss of tracking (16 counts @12 bit)
  unsigned resolution_bits = 12;            // counts() width: 4096 counts/turn as on the ANS1 (L768)
};

struct RdStatus {
  bool loss_of_signal = false;
  bool degradation = false;
  bool loss_of_tracking = false;
  [[nodiscard]] bool any() const { return loss_of_signal || degradation || loss_of_tracking; }
};

class RdConverter {
public:
  // Throws std::invalid_argument for an excitation outside 2.2..7 kHz or a bad loop setting.
  explicit RdConverter(RdParams params);

  // Samples in time order (the reference is the converter's own excitation).
  void feed(const ResolverSample& s);
  void feed(std::span<const ResolverSample> samples);

  [[nodiscard]] bool tracking() const { return state_ == Phase::Tracking; }
  // Angle estimate in turns, [0, 1), at the end of the last completed window.
  [[nodiscard]] double angle_turns() const;
  // The estimate carried forward to t at the estimated speed.
  [[nodiscard]] double angle_turns_at(Nanos t) const;
  [[nodiscard]] double velocity_turns_per_s() const;
  [[nodiscard]] std::uint32_t counts() const; // floor(angle * 2^bits)
  [[nodiscard]] Nanos last_update() const { return last_end_; }
  [[nodiscard]] std::size_t updates() const { return updates_; }
  [[nodiscard]] double amplitude() const { return amplitude_; }     // last demodulated amplitude
  [[nodiscard]] double error_turns() const { return error_turns_; } // last loop error
  [[nodiscard]] RdStatus status() const { return status_; }         // of the last window
  [[nodiscard]] RdStatus latched() const { return latched_; }       // sticky until clear_faults()
  void clear_faults() { latched_ = RdStatus{}; }

private:
  enum class Phase : std::uint8_t { Empty, HaveAngle, Tracking };
  void close_window();
  [[nodiscard]] std::int64_t window_of(Nanos t) const;

  RdParams params_;
  double kp_ = 0.0;
  double ki_ = 0.0;
  // Current window's sums: reference energy, correlations, and time moment (for the centroid).
  std::int64_t window_ = 0;
  bool open_ = false;
  Nanos window_origin_{0}; // first sample time in the window: moment base
  double sum_rr_ = 0.0;
  double sum_sr_ = 0.0;
  double sum_cr_ = 0.0;
  double sum_trr_ = 0.0;
  Nanos last_sample_{0};

  Phase state_ = Phase::Empty;
  double phi_ = 0.0;   // radians, unwrapped, at last_end_
  double omega_ = 0.0; // rad/s
  Nanos last_end_{0};
  double first_angle_ = 0.0; // acquisition: first window's angle and centroid
  Nanos first_centroid_{0};
  std::size_t updates_ = 0;
  double amplitude_ = 0.0;
  double error_turns_ = 0.0;
  RdStatus status_{};
  RdStatus latched_{};
};

} // namespace hilrig::signals
