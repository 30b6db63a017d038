#include "rig/campaign/resolver_stators.hpp"

#include <cmath>
#include <numbers>
#include <utility>

namespace hilrig::campaign {

Waveform stator_waveform(ShaftPosition position, double counts_per_turn, const ResolverSpec& resolver,
                         Stator stator) {
  const double peak = resolver.ratio * resolver.amplitude;
  const double omega = 2.0 * std::numbers::pi * resolver.excitation_hz;
  const double radians_per_count = 2.0 * std::numbers::pi / counts_per_turn;
  const double phase = resolver.phase_deg * std::numbers::pi / 180.0;
  return [position = std::move(position), peak, omega, phase, radians_per_count, stator](Nanos t) {
    const double angle = radians_per_count * position(t);
    const double carrier = peak * std::sin(omega * t.seconds() + phase);
    return carrier * (stator == Stator::Sine ? std::sin(angle) : std::cos(angle));
  };
}

Waveform stator_waveform(std::shared_ptr<const signals::MotionProfile> profile, double counts_per_turn,
                         const ResolverSpec& resolver, Stator stator) {
  return stator_waveform([profile = std::move(profile)](Nanos t) { return profile->position(t); },
                         counts_per_turn, resolver, stator);
}

} // namespace hilrig::campaign
