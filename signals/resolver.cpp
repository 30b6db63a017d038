#include "signals/resolver.hpp"

#include <cmath>
#include <numbers>
#include <stdexcept>
#include <string>
#include <utility>

namespace hilrig::signals {

namespace {
constexpr double kTwoPi = 2.0 * std::numbers::pi;
} // namespace

AngleFunction angle_at_constant_speed(double start_turns, double turns_per_second, Nanos t0) {
  return [=](Nanos t) { return start_turns + turns_per_second * (t - t0).seconds(); };
}

Resolver::Resolver(ResolverParams params, AngleFunction turns) {
  if (!(params.excitation_hz >= kMinExcitationHz && params.excitation_hz <= kMaxExcitationHz))
    throw std::invalid_argument("resolver excitation must be 2.2..7 kHz, got " +
                                std::to_string(params.excitation_hz) + " Hz");
  if (!(params.excitation_amplitude > 0.0))
    throw std::invalid_argument("resolver excitation amplitude must be > 0");
  if (!(params.transformation_ratio > 0.0))
    throw std::invalid_argument("resolver transformation ratio must be > 0");
  if (!turns) throw std::invalid_argument("resolver needs an angle trajectory");
  state_ = std::make_shared<State>(State{params, std::move(turns), ResolverFaults{}});
}

double Resolver::carrier(const State& s, Nanos t, double phase_shift) {
  const ResolverParams& p = s.params;
  // Phase from the integer nanosecond count, reduced per carrier period, keeps the
  // carrier exact for long runs.
  const double cycles = p.excitation_hz * t.seconds();
  const double frac = cycles - std::floor(cycles);
  return p.excitation_amplitude * std::sin(kTwoPi * frac + p.excitation_phase_rad + phase_shift);
}

double Resolver::winding_sin(const State& s, Nanos t) {
  const ResolverFaults& f = s.faults;
  if (f.sin_open || f.excitation_lost) return 0.0;
  const double theta = kTwoPi * s.turns(t);
  return s.params.transformation_ratio * f.sin_gain * carrier(s, t, f.sin_phase_rad) * std::sin(theta);
}

double Resolver::winding_cos(const State& s, Nanos t) {
  const ResolverFaults& f = s.faults;
  if (f.cos_open || f.excitation_lost) return 0.0;
  const double theta = kTwoPi * s.turns(t);
  return s.params.transformation_ratio * f.cos_gain * carrier(s, t, f.cos_phase_rad) * std::cos(theta);
}

double Resolver::reference(Nanos t) const { return carrier(*state_, t, 0.0); }

ResolverEnvelope Resolver::envelope(Nanos t) const {
  const State& s = *state_;
  const ResolverFaults& f = s.faults;
  const double theta = kTwoPi * s.turns(t);
  const double tr = s.params.transformation_ratio;
  ResolverEnvelope e;
  if (!f.excitation_lost) {
    e.sin = f.sin_open ? 0.0 : tr * f.sin_gain * std::sin(theta);
    e.cos = f.cos_open ? 0.0 : tr * f.cos_gain * std::cos(theta);
  }
  return e;
}

ResolverSample Resolver::sample(Nanos t) const {
  return ResolverSample{t, reference(t), winding_sin(*state_, t), winding_cos(*state_, t)};
}

void Resolver::sample_block(Nanos start, double rate_hz, std::span<ResolverSample> out) const {
  if (!(rate_hz > 0.0)) throw std::invalid_argument("sample rate must be > 0");
  for (std::size_t i = 0; i < out.size(); ++i)
    out[i] = sample(start + Nanos::from_seconds(static_cast<double>(i) / rate_hz));
}

std::vector<ResolverSample> Resolver::sample_block(Nanos start, double rate_hz, std::size_t count) const {
  std::vector<ResolverSample> out(count);
  sample_block(start, rate_hz, std::span<ResolverSample>(out));
  return out;
}

Waveform Resolver::reference_waveform() const {
  return [s = state_](Nanos t) { return carrier(*s, t, 0.0); };
}

Waveform Resolver::sin_waveform() const {
  return [s = state_](Nanos t) { return winding_sin(*s, t); };
}

Waveform Resolver::cos_waveform() const {
  return [s = state_](Nanos t) { return winding_cos(*s, t); };
}

} // namespace hilrig::signals
