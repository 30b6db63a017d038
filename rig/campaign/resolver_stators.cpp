#include "rig/campaign/resolver_stators.hpp"

#include <cmath>
#include <numbers>
#include <utility>

namespace hilrig::campaign {

std::vector<StatorRatioWindow> stator_fault_windows(const Scenario& scenario, Stator stator) {
  using duts::FaultSite;
  std::vector<StatorRatioWindow> out;
  for (const DeviceFaultEvent& f : scenario.device_faults) {
    const bool acts = f.site == FaultSite::OpenStators || f.site == FaultSite::StatorRatio ||
                      (f.site == FaultSite::OpenSin && stator == Stator::Sine) ||
                      (f.site == FaultSite::OpenCos && stator == Stator::Cosine);
    if (acts) out.push_back({f.at, f.until, f.site == FaultSite::StatorRatio ? f.ratio : 0.0});
  }
  return out;
}

StatorForm::StatorForm(double counts_per_turn, const ResolverSpec& resolver, Stator stator,
                       std::vector<StatorRatioWindow> faults)
    : ratio_(resolver.ratio), amplitude_(resolver.amplitude),
      omega_(2.0 * std::numbers::pi * resolver.excitation_hz),
      phase_(resolver.phase_deg * std::numbers::pi / 180.0),
      radians_per_count_(2.0 * std::numbers::pi / counts_per_turn), stator_(stator),
      faults_(std::move(faults)) {}

double StatorForm::ratio_at(Nanos t) const {
  double r = ratio_;
  for (const StatorRatioWindow& w : faults_)
    if (t >= w.at && t < w.until) r = w.ratio;
  return r;
}

double StatorForm::operator()(Nanos t, double position) const {
  const double angle = radians_per_count_ * position;
  const double carrier = ratio_at(t) * amplitude_ * std::sin(omega_ * t.seconds() + phase_);
  return carrier * (stator_ == Stator::Sine ? std::sin(angle) : std::cos(angle));
}

// The same products in the same order as operator() (ratio * amplitude * wave, times sin or
// cos of the angle), so each value is the bit-identical double.
StatorForm::Pair StatorForm::pair(const StatorForm& sine, const StatorForm& cosine, Nanos t,
                                  double position) {
  const double angle = sine.radians_per_count_ * position;
  const double wave = std::sin(sine.omega_ * t.seconds() + sine.phase_);
  return {sine.ratio_at(t) * sine.amplitude_ * wave * std::sin(angle),
          cosine.ratio_at(t) * cosine.amplitude_ * wave * std::cos(angle)};
}

Waveform stator_waveform(ShaftPosition position, double counts_per_turn, const ResolverSpec& resolver,
                         Stator stator, std::vector<StatorRatioWindow> faults) {
  return [position = std::move(position),
          form = StatorForm(counts_per_turn, resolver, stator, std::move(faults))](Nanos t) {
    return form(t, position(t));
  };
}

Waveform stator_waveform(std::shared_ptr<const signals::MotionProfile> profile, double counts_per_turn,
                         const ResolverSpec& resolver, Stator stator, std::vector<StatorRatioWindow> faults) {
  return stator_waveform([profile = std::move(profile)](Nanos t) { return profile->position(t); },
                         counts_per_turn, resolver, stator, std::move(faults));
}

} // namespace hilrig::campaign
