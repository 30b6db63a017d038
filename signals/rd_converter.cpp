#include "signals/rd_converter.hpp"

#include <cmath>
#include <numbers>
#include <stdexcept>

namespace hilrig::signals {

namespace {
constexpr double kTwoPi = 2.0 * std::numbers::pi;

double wrap_pi(double a) { return a - kTwoPi * std::floor((a + std::numbers::pi) / kTwoPi); }
double wrap_turn(double x) { return x - std::floor(x); }
} // namespace

RdConverter::RdConverter(RdParams params) : params_(params) {
  if (!(params_.excitation_hz >= kMinExcitationHz && params_.excitation_hz <= kMaxExcitationHz))
    throw std::invalid_argument("R/D excitation must be 2.2..7 kHz");
  if (!(params_.loop_bandwidth_hz > 0.0 && params_.damping > 0.0 && params_.nominal_amplitude > 0.0))
    throw std::invalid_argument("R/D loop bandwidth, damping and nominal amplitude must be > 0");
  if (params_.resolution_bits < 1 || params_.resolution_bits > 24)
    throw std::invalid_argument("R/D resolution must be 1..24 bits");
  const double wn = kTwoPi * params_.loop_bandwidth_hz;
  kp_ = 2.0 * params_.damping * wn; // PI loop filter of a second-order type-II PLL
  ki_ = wn * wn;
}

std::int64_t RdConverter::window_of(Nanos t) const {
  // Window k spans one reference period starting at a rising zero crossing of the reference.
  const double cycles = params_.excitation_hz * t.seconds() + params_.excitation_phase_rad / kTwoPi;
  return static_cast<std::int64_t>(std::floor(cycles));
}

void RdConverter::feed(std::span<const ResolverSample> samples) {
  for (const ResolverSample& s : samples) feed(s);
}

void RdConverter::feed(const ResolverSample& s) {
  const std::int64_t w = window_of(s.time);
  if (open_ && w != window_) close_window();
  if (!open_) {
    open_ = true;
    window_ = w;
    window_origin_ = s.time;
    sum_rr_ = sum_sr_ = sum_cr_ = sum_trr_ = 0.0;
  }
  const double rr = s.reference * s.reference;
  sum_rr_ += rr;
  sum_sr_ += s.sin * s.reference;
  sum_cr_ += s.cos * s.reference;
  sum_trr_ += (s.time - window_origin_).seconds() * rr;
  last_sample_ = s.time;
}

void RdConverter::close_window() {
  open_ = false;
  // The window ends where the next begins (the sample grid need not divide the period).
  const double end_cycles = static_cast<double>(window_ + 1) - params_.excitation_phase_rad / kTwoPi;
  const Nanos end = Nanos::from_seconds(end_cycles / params_.excitation_hz);
  if (sum_rr_ <= 0.0) {
    // No reference energy: nothing can be demodulated.
    status_ = RdStatus{true, true, false};
    latched_.loss_of_signal = latched_.degradation = true;
    amplitude_ = 0.0;
    if (state_ == Phase::Tracking) phi_ += omega_ * (end - last_end_).seconds();
    last_end_ = end;
    return;
  }
  // Synchronous demodulation: the stator/reference correlation over a carrier period gives
  // TR * sin(theta) and TR * cos(theta) at the window's reference-energy centroid.
  const double s = sum_sr_ / sum_rr_;
  const double c = sum_cr_ / sum_rr_;
  const Nanos centroid = window_origin_ + Nanos::from_seconds(sum_trr_ / sum_rr_);
  amplitude_ = std::hypot(s, c);
  const double rel = amplitude_ / params_.nominal_amplitude;
  status_ = RdStatus{};
  status_.loss_of_signal = rel < params_.los_threshold;
  status_.degradation = rel < params_.dos_low || rel > params_.dos_high;
  ++updates_;

  if (status_.loss_of_signal) {
    // Coast at the last speed; no angle can be trusted.
    if (state_ == Phase::Tracking) phi_ += omega_ * (end - last_end_).seconds();
    last_end_ = end;
  } else if (state_ == Phase::Empty) {
    first_angle_ = std::atan2(s, c);
    first_centroid_ = centroid;
    phi_ = first_angle_;
    last_end_ = end;
    state_ = Phase::HaveAngle;
  } else if (state_ == Phase::HaveAngle) {
    // Acquisition: speed from the first two windows, so the loop starts near lock.
    const double measured = std::atan2(s, c);
    const double dt = (centroid - first_centroid_).seconds();
    omega_ = wrap_pi(measured - first_angle_) / dt;
    phi_ = first_angle_ + wrap_pi(measured - first_angle_) + omega_ * (end - centroid).seconds();
    last_end_ = end;
    state_ = Phase::Tracking;
  } else {
    const double dt = (end - last_end_).seconds();
    const double phi_end = phi_ + omega_ * dt;
    const double phi_at_centroid = phi_end - omega_ * (end - centroid).seconds();
    // Phase detector sin(theta - phi), normalised by the amplitude (ratiometric).
    const double e = (s * std::cos(phi_at_centroid) - c * std::sin(phi_at_centroid)) / amplitude_;
    omega_ += ki_ * e * dt;
    phi_ = phi_end + kp_ * e * dt;
    last_end_ = end;
    error_turns_ = std::asin(std::fmax(-1.0, std::fmin(1.0, e))) / kTwoPi;
    status_.loss_of_tracking = std::fabs(error_turns_) > params_.lot_threshold_turns;
  }
  latched_.loss_of_signal = latched_.loss_of_signal || status_.loss_of_signal;
  latched_.degradation = latched_.degradation || status_.degradation;
  latched_.loss_of_tracking = latched_.loss_of_tracking || status_.loss_of_tracking;
}

double RdConverter::angle_turns() const { return wrap_turn(phi_ / kTwoPi); }

double RdConverter::angle_turns_at(Nanos t) const {
  return wrap_turn((phi_ + omega_ * (t - last_end_).seconds()) / kTwoPi);
}

double RdConverter::velocity_turns_per_s() const { return omega_ / kTwoPi; }

std::uint32_t RdConverter::counts() const {
  const double full = std::ldexp(1.0, static_cast<int>(params_.resolution_bits));
  const auto c = static_cast<std::uint32_t>(std::floor(angle_turns() * full));
  return c & ((1u << params_.resolution_bits) - 1u);
}

} // namespace hilrig::signals
