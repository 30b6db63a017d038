#include "models/plants/press.hpp"

#include <algorithm>
#include <cmath>

#include "models/plants/rk4.hpp"

namespace hilrig::plants {

namespace {
double sign(double v) { return v > 0.0 ? 1.0 : v < 0.0 ? -1.0 : 0.0; }
} // namespace

double speed_floor(double scale) {
  // A relative 1e-12 of the fastest speed since the shaft last stood: above the rounding the
  // speed carries through the steps, and as a time (floor / deceleration) a 1e-12 part of
  // the stop's duration.
  return 1e-12 * scale;
}

PressPlant::PressPlant(const PressParams& params, const PressStart& start, Nanos step,
                       std::vector<ParamChange<PressParams>> changes)
    : p_(params), step_(step), changes_(std::move(changes)), valve_(start.valve), motor_(start.motor),
      clutch_before_(start.valve), brake_before_(start.valve ? 0.0 : 1.0) {
  std::stable_sort(changes_.begin(), changes_.end(),
                   [](const auto& a, const auto& b) { return a.at < b.at; });
  x_ = Vec(start.angle, start.speed, start.flywheel_speed.value_or(start.speed));
  mode_ = start.valve && x_(2) == x_(1) ? Mode::Locked : Mode::Free;
  classify();
}

bool PressPlant::clutch_engaged_at(Nanos t) const {
  if (valve_at_ == Nanos::min()) return valve_;
  return t < valve_at_ + Nanos::from_seconds(p_.valve_delay) ? clutch_before_ : valve_;
}

double PressPlant::brake_torque_at(Nanos t) const {
  double fraction = brake_before_;
  if (valve_at_ != Nanos::min()) {
    const Nanos response = valve_at_ + Nanos::from_seconds(p_.valve_delay);
    if (t >= response) {
      const double rise = p_.brake_rise > 0.0 ? (t - response).seconds() / p_.brake_rise : 1.0;
      fraction = valve_ ? 0.0 : std::max(brake_before_, std::min(1.0, rise));
    }
  }
  return fraction * p_.brake_torque;
}

double PressPlant::holding_torque(Nanos t) const { return p_.coulomb_torque + brake_torque_at(t); }

double PressPlant::crank_load(Nanos t0, double t, const Vec& x) const {
  const double s1 = p_.crank.d_height(x(0));
  const double s2 = p_.crank.d2_height(x(0));
  // The brake torque inside a step: steps stop at the brake's breakpoints, so it is linear
  // in t there; evaluated exactly at t0 + t.
  const double brake = brake_at(t0, t);
  return -p_.ram_mass * s1 * s2 * x(1) * x(1) + gravity_torque(x(0)) - p_.crank_viscous * x(1) -
         (p_.coulomb_torque + brake) * dir_;
}

double PressPlant::brake_at(Nanos t0, double t) const {
  const double at_start = brake_torque_at(t0);
  if (valve_ || valve_at_ == Nanos::min() || p_.brake_rise <= 0.0) return at_start;
  const Nanos response = valve_at_ + Nanos::from_seconds(p_.valve_delay);
  if (t0 < response || at_start >= p_.brake_torque) return at_start;
  return std::min(p_.brake_torque, at_start + p_.brake_torque * t / p_.brake_rise);
}

double PressPlant::motor_torque(double w) const {
  if (!motor_ || p_.motor_sync_speed <= 0.0) return 0.0;
  return p_.motor_stall_torque * (1.0 - w / p_.motor_sync_speed);
}

double PressPlant::crank_inertia(double theta) const {
  const double s1 = p_.crank.d_height(theta);
  return p_.crank_inertia + p_.ram_mass * s1 * s1;
}

PressPlant::Vec PressPlant::derivative(Nanos t0, double t, const Vec& x) const {
  const double flywheel = motor_torque(x(2)) - p_.flywheel_viscous * x(2);
  switch (mode_) {
  case Mode::Locked: {
    const double a = (crank_load(t0, t, x) + motor_torque(x(1)) - p_.flywheel_viscous * x(1)) /
                     (crank_inertia(x(0)) + p_.flywheel_inertia);
    return Vec(x(1), a, a);
  }
  case Mode::Slipping: {
    const double clutch = p_.clutch_torque * slip_;
    return Vec(x(1), (crank_load(t0, t, x) + clutch) / crank_inertia(x(0)),
               (flywheel - clutch) / p_.flywheel_inertia);
  }
  case Mode::Free:
    return Vec(x(1), crank_load(t0, t, x) / crank_inertia(x(0)), flywheel / p_.flywheel_inertia);
  case Mode::Stuck:
    break;
  }
  return Vec(0.0, 0.0, flywheel / p_.flywheel_inertia);
}

double PressPlant::clutch_needed(Nanos t0, double t, const Vec& x) const {
  // Locked: the crank's acceleration is the common one; the clutch supplies what the
  // crank's own loads do not.
  return crank_inertia(x(0)) * derivative(t0, t, x)(1) - crank_load(t0, t, x);
}

double PressPlant::event(Nanos t0, double t, const Vec& x) const {
  switch (mode_) {
  case Mode::Free:
    // Standstill: the speed has fallen to within rounding of zero (speed_floor_), so a stop
    // that falls exactly on a nanosecond is located on it, not one after.
    return dir_ != 0.0 ? x(1) * dir_ - speed_floor_ : 1.0;
  case Mode::Slipping:
    return (x(2) - x(1)) * slip_;
  case Mode::Locked:
    return p_.clutch_torque - std::abs(clutch_needed(t0, t, x));
  case Mode::Stuck:
    break;
  }
  return 1.0;
}

void PressPlant::classify() {
  if (clutch_engaged_at(now_)) {
    if (mode_ != Mode::Locked) {
      const double diff = x_(2) - x_(1);
      if (diff != 0.0) {
        mode_ = Mode::Slipping;
        slip_ = sign(diff);
      } else {
        mode_ = Mode::Locked;
      }
    }
    dir_ = x_(1) != 0.0 ? sign(x_(1)) : sign(motor_torque(0.0) + gravity_torque(x_(0)));
    if (mode_ == Mode::Locked) {
      const double needed = clutch_needed(now_, 0.0, x_);
      if (std::abs(needed) > p_.clutch_torque) {
        mode_ = Mode::Slipping;
        slip_ = sign(needed);
      }
    }
    return;
  }
  if (x_(1) != 0.0) {
    mode_ = Mode::Free;
    dir_ = sign(x_(1));
    return;
  }
  const double load = gravity_torque(x_(0));
  if (std::abs(load) <= holding_torque(now_)) {
    mode_ = Mode::Stuck;
    dir_ = 0.0;
  } else {
    mode_ = Mode::Free;
    dir_ = sign(load);
  }
}

void PressPlant::on_event() {
  switch (mode_) {
  case Mode::Free:
    // Standstill: the speed crossed zero within the last nanosecond.
    x_(1) = 0.0;
    classify();
    if (mode_ == Mode::Stuck) standstills_.push_back(now_);
    speed_scale_ = 0.0;
    break;
  case Mode::Slipping: {
    // The speeds met: lock with the momentum both carried.
    const double jc = crank_inertia(x_(0));
    const double w = (jc * x_(1) + p_.flywheel_inertia * x_(2)) / (jc + p_.flywheel_inertia);
    x_(1) = w;
    x_(2) = w;
    mode_ = Mode::Locked;
    classify();
    break;
  }
  case Mode::Locked:
    mode_ = Mode::Slipping;
    slip_ = sign(clutch_needed(now_, 0.0, x_));
    break;
  case Mode::Stuck:
    break;
  }
}

Nanos PressPlant::next_breakpoint() const {
  Nanos next = Nanos::max();
  if (next_change_ < changes_.size()) next = changes_[next_change_].at;
  if (valve_at_ != Nanos::min()) {
    const Nanos response = valve_at_ + Nanos::from_seconds(p_.valve_delay);
    if (response > now_) next = std::min(next, response);
    const Nanos full = response + Nanos::from_seconds(p_.brake_rise);
    if (!valve_ && full > now_) next = std::min(next, full);
  }
  return next;
}

namespace {

// Where a step and its two halves agree: the angle to 1e-9 rad (a 4,096-count encoder's count
// is 1.5e-3 rad), each speed to 1e-9 of itself (or of 1 rad/s, near rest).
bool halves_agree(const Eigen::Vector3d& whole, const Eigen::Vector3d& halves) {
  const auto close = [](double a, double b, double scale) { return std::abs(a - b) <= 1e-9 * scale; };
  return close(whole(0), halves(0), 1.0) && close(whole(1), halves(1), std::max(1.0, std::abs(whole(1)))) &&
         close(whole(2), halves(2), std::max(1.0, std::abs(whole(2))));
}

} // namespace

Knot PressPlant::advance(Nanos until) {
  while (next_change_ < changes_.size() && changes_[next_change_].at <= now_)
    p_ = changes_[next_change_++].params;
  classify();
  Nanos end = std::min({until, now_ + step_, next_breakpoint()});
  if (end <= now_) return state();
  const Nanos t0 = now_;
  const auto f = [this, t0](double t, const Vec& x) { return derivative(t0, t, x); };
  const auto at = [&](std::int64_t ns) { return rk4_step(f, 0.0, x_, static_cast<double>(ns) * 1e-9); };
  // Step doubling: a step its two halves disagree with is halved until they agree. Near dead
  // centre a heavy ram on a long rod swings the crank's inertia by orders of magnitude within
  // a fraction of a degree, and a fixed step diverges there (gaining energy the press never
  // had); where the motion is smooth the halves agree and the step is taken as it is.
  std::int64_t n = (end - now_).count();
  Vec x1 = at(n);
  while (n > 1) {
    const std::int64_t half = n / 2;
    const Vec mid = at(half);

    const Vec x2 = rk4_step(f, static_cast<double>(half) * 1e-9, mid, static_cast<double>(n - half) * 1e-9);
    if (halves_agree(x1, x2)) break;
    n = half;
    x1 = mid;
  }
  end = t0 + Nanos{n};
  speed_scale_ = std::max(speed_scale_, std::abs(x_(1)));
  speed_floor_ = speed_floor(speed_scale_);
  if (event(t0, 0.0, x_) > 0.0 && event(t0, static_cast<double>(n) * 1e-9, x1) <= 0.0) {
    const std::int64_t k =
        locate_event([&](std::int64_t ns) { return event(t0, static_cast<double>(ns) * 1e-9, at(ns)); }, n);
    const Vec from = x_;
    x_ = at(k);
    // A standstill is drawn into as one uniform deceleration from the step's start
    // (campaign/plant_motion.cpp segment()): the shaft stands where that puts it. The true
    // stop lies within the located ns, so this is within half a ns of travel of it, where
    // the integrated angle at k is not: a crank that stops well inside a ns (a tiny inertia
    // against the brake) is carried through the rest of it at its enormous deceleration,
    // backwards, by far more than that.
    if (mode_ == Mode::Free) x_(0) = from(0) + 0.5 * from(1) * static_cast<double>(k) * 1e-9;
    now_ = t0 + Nanos{k};
    on_event();
    return state();
  }
  x_ = x1;
  now_ = end;
  return state();
}

void PressPlant::input(PlantInput which, bool level) {
  if (which == PlantInput::MotorEnable) {
    motor_ = level;
    return;
  }
  if (which != PlantInput::Valve || level == valve_) return;
  clutch_before_ = clutch_engaged_at(now_);
  brake_before_ = brake_torque_at(now_) / std::max(p_.brake_torque, 1e-300);
  valve_ = level;
  valve_at_ = now_;
  classify();
}

double PressPlant::energy() const {
  return 0.5 * crank_inertia(x_(0)) * x_(1) * x_(1) + 0.5 * p_.flywheel_inertia * x_(2) * x_(2) +
         p_.ram_mass * p_.gravity * p_.crank.height(x_(0));
}

} // namespace hilrig::plants
