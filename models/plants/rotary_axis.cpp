#include "models/plants/rotary_axis.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>

#include "models/plants/rk4.hpp"

namespace hilrig::plants {

namespace {
double sign(double v) { return v > 0.0 ? 1.0 : v < 0.0 ? -1.0 : 0.0; }
} // namespace

RotaryAxis::RotaryAxis(const RotaryParams& params, const RotaryStart& start, Nanos step,
                       std::vector<ParamChange<RotaryParams>> changes)
    : p_(params), step_(step), changes_(std::move(changes)), motor_(start.motor) {
  std::stable_sort(changes_.begin(), changes_.end(),
                   [](const auto& a, const auto& b) { return a.at < b.at; });
  for (const auto& c : changes_)
    if (c.params.two_mass != p_.two_mass)
      throw std::invalid_argument("a rotary axis stays rigid or two-mass through a run");
  if (p_.two_mass && p_.coulomb_torque != 0.0)
    throw std::invalid_argument("Coulomb friction is modelled on the rigid axis only");
  x_ = p_.two_mass ? Eigen::VectorXd(Eigen::Vector4d(start.angle, start.speed, start.angle, start.speed))
                   : Eigen::VectorXd(Eigen::Vector2d(start.angle, start.speed));
  build();
  classify();
}

void RotaryAxis::build() {
  if (!p_.two_mass) {
    const double j = p_.motor_inertia + p_.load_inertia;
    Eigen::MatrixXd a(2, 2);
    a << 0.0, 1.0, 0.0, -(p_.motor_viscous + p_.load_viscous) / j;
    Eigen::MatrixXd b(2, 1);
    b << 0.0, 1.0 / j;
    flow_ = LinearFlow(a, b);
    return;
  }
  const double jm = p_.motor_inertia;
  const double jl = p_.load_inertia;
  const double k = p_.stiffness;
  const double c = p_.coupling_damping;
  Eigen::MatrixXd a(4, 4);
  a << 0.0, 1.0, 0.0, 0.0,                                   //
      -k / jm, -(c + p_.motor_viscous) / jm, k / jm, c / jm, //
      0.0, 0.0, 0.0, 1.0,                                    //
      k / jl, c / jl, -k / jl, -(c + p_.load_viscous) / jl;
  Eigen::MatrixXd b = Eigen::MatrixXd::Zero(4, 2);
  b(1, 0) = 1.0 / jm;
  b(3, 1) = 1.0 / jl;
  flow_ = LinearFlow(a, b);
}

Knot RotaryAxis::state() const {
  if (p_.two_mass && p_.encoder_on_load) return Knot{now_, x_(2), x_(3)};
  return Knot{now_, x_(0), x_(1)};
}

double RotaryAxis::load_torque(Nanos t) const {
  double torque = 0.0;
  for (const LoadStep& s : p_.load)
    if (s.from <= t) torque = s.torque;
  return torque;
}

Eigen::VectorXd RotaryAxis::input_vector() const {
  const double motor = motor_ ? p_.motor_torque : 0.0;
  if (p_.two_mass) return Eigen::Vector2d(motor, load_torque(now_));
  Eigen::VectorXd u(1);
  u << (stuck_ ? 0.0 : motor + load_torque(now_) - p_.coulomb_torque * dir_);
  return u;
}

void RotaryAxis::classify() {
  if (p_.two_mass) return;
  if (x_(1) != 0.0) {
    stuck_ = false;
    dir_ = sign(x_(1));
    return;
  }
  const double drive = (motor_ ? p_.motor_torque : 0.0) + load_torque(now_);
  stuck_ = std::abs(drive) <= p_.coulomb_torque;
  dir_ = stuck_ ? 0.0 : sign(drive);
}

Nanos RotaryAxis::next_breakpoint() const {
  Nanos next = Nanos::max();
  if (next_change_ < changes_.size()) next = changes_[next_change_].at;
  for (const LoadStep& s : p_.load)
    if (s.from > now_) next = std::min(next, s.from);
  return next;
}

Knot RotaryAxis::advance(Nanos until) {
  bool changed = false;
  while (next_change_ < changes_.size() && changes_[next_change_].at <= now_) {
    p_ = changes_[next_change_++].params;
    changed = true;
  }
  if (changed) build();
  classify();
  const Nanos end = std::min({until, now_ + step_, next_breakpoint()});
  if (end <= now_) return state();
  const std::int64_t n = (end - now_).count();
  if (stuck_) {
    now_ = end;
    return state();
  }
  const Eigen::VectorXd u = input_vector();
  const auto at = [&](std::int64_t ns) { return flow_.after(static_cast<double>(ns) * 1e-9, x_, u); };
  const Eigen::VectorXd x1 = at(n);
  // Standstill: the speed has fallen to within rounding of zero, so a stop that falls exactly
  // on a nanosecond is located on it.
  speed_scale_ = std::max(speed_scale_, std::abs(x_(1)));
  const double floor = speed_floor(speed_scale_);
  if (!p_.two_mass && dir_ != 0.0 && x1(1) * dir_ <= floor) {
    // Coulomb friction brought the shaft to rest inside the step.
    const std::int64_t k = locate_event([&](std::int64_t ns) { return at(ns)(1) * dir_ - floor; }, n);
    x_ = at(k);
    x_(1) = 0.0;
    now_ += Nanos{k};
    classify();
    if (stuck_) standstills_.push_back(now_);
    speed_scale_ = 0.0;
    return state();
  }
  x_ = x1;
  now_ = end;
  return state();
}

void RotaryAxis::input(PlantInput which, bool level) {
  if (which != PlantInput::MotorEnable) return;
  motor_ = level;
  classify();
}

} // namespace hilrig::plants
