#pragma once
// A resolver as the rig synthesizes it for an ANS1 or a 2700 (ans1.md §2.1, pls2700.md
// §2.4): the rotor is excited by the board's reference Vref(t); the stator windings give
//   V_sin(t) = TR * Vref(t) * sin(theta(t)),   V_cos(t) = TR * Vref(t) * cos(theta(t)),
// with the carrier in phase with the reference and theta = 2*pi * turns. The angle comes
// as a function of time in turns (or from a MotionProfile whose unit the caller names).
// Faults (open coil, imbalance, carrier phase shift, excitation loss) act on the windings.

#include <cstddef>
#include <functional>
#include <memory>
#include <span>
#include <vector>

#include "core/analog.hpp"
#include "core/time.hpp"
#include "signals/motion_profile.hpp"

namespace hilrig::signals {

// Shaft angle in turns as a function of time (not wrapped; 1.25 = a quarter past one turn).
using AngleFunction = std::function<double(Nanos)>;

// Constant speed from `start_turns` at `t0`.
[[nodiscard]] AngleFunction angle_at_constant_speed(double start_turns, double turns_per_second,
                                                    Nanos t0 = Nanos{0});
// A profile's position divided by `units_per_turn` (e.g. 4096 for a profile in ANS1 counts).
[[nodiscard]] inline AngleFunction angle_from_profile(MotionProfile profile, double units_per_turn) {
  return [p = std::move(profile), units_per_turn](Nanos t) { return p.position(t) / units_per_turn; };
}

// The reference range a foreign resolver must suit on the ANS1 (L1455).
inline constexpr double kMinExcitationHz = 2'200.0;
inline constexpr double kMaxExcitationHz = 7'000.0;

struct ResolverParams {
  double excitation_hz = 5'000.0;    // 2.2..7 kHz, else rejected
  double excitation_amplitude = 1.0; // Vref peak, volts
  double excitation_phase_rad = 0.0; // Vref(t) = A * sin(2*pi*f*t + phase), t in seconds
  double transformation_ratio = 1.0; // TR; the ANS1 takes 0.9..1.0 directly (L1456), any > 0 here
};

struct ResolverFaults {
  bool sin_open = false; // SIN winding open: reads zero
  bool cos_open = false; // COS winding open: reads zero
  double sin_gain = 1.0; // amplitude imbalance between the windings
  double cos_gain = 1.0;
  double sin_phase_rad = 0.0; // carrier phase of each winding against the reference
  double cos_phase_rad = 0.0;
  bool excitation_lost = false; // rotor not excited: both windings zero
};

// Stator envelopes: what a synchronous demodulator recovers, TR * sin(theta) and
// TR * cos(theta) (unit reference), with the amplitude faults applied.
struct ResolverEnvelope {
  double sin = 0.0;
  double cos = 0.0;
};

// One instant of the three signals; `reference` is the board's own excitation, which a
// broken rotor lead does not change.
struct ResolverSample {
  Nanos time;
  double reference = 0.0;
  double sin = 0.0;
  double cos = 0.0;
};

// Copies share one state (angle, parameters, faults), as the waveforms handed out do.
class Resolver {
public:
  // Throws std::invalid_argument for an excitation outside 2.2..7 kHz, a non-positive
  // amplitude or TR, or an empty angle function.
  Resolver(ResolverParams params, AngleFunction turns);

  [[nodiscard]] const ResolverParams& params() const { return state_->params; }
  // Faults take effect at once, also in waveforms handed out before.
  void set_faults(const ResolverFaults& faults) { state_->faults = faults; }
  [[nodiscard]] const ResolverFaults& faults() const { return state_->faults; }

  [[nodiscard]] double angle_turns(Nanos t) const { return state_->turns(t); }
  [[nodiscard]] double reference(Nanos t) const;
  [[nodiscard]] ResolverEnvelope envelope(Nanos t) const;
  [[nodiscard]] ResolverSample sample(Nanos t) const;
  // Samples at `rate_hz` from `start`: sample i at start + round(i / rate_hz).
  void sample_block(Nanos start, double rate_hz, std::span<ResolverSample> out) const;
  [[nodiscard]] std::vector<ResolverSample> sample_block(Nanos start, double rate_hz,
                                                         std::size_t count) const;

  // The signals as core Waveforms, for a virtual analog channel. They share this
  // resolver's state (faults set later apply).
  [[nodiscard]] Waveform reference_waveform() const;
  [[nodiscard]] Waveform sin_waveform() const;
  [[nodiscard]] Waveform cos_waveform() const;

private:
  struct State {
    ResolverParams params;
    AngleFunction turns;
    ResolverFaults faults;
  };
  [[nodiscard]] static double carrier(const State& s, Nanos t, double phase_shift);
  [[nodiscard]] static double winding_sin(const State& s, Nanos t);
  [[nodiscard]] static double winding_cos(const State& s, Nanos t);
  std::shared_ptr<State> state_;
};

} // namespace hilrig::signals
