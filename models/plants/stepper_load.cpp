#include "models/plants/stepper_load.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>

#include "models/plants/rk4.hpp"

namespace hilrig::plants {

StepperLoad::StepperLoad(const StepperParams& params, Nanos step,
                         std::vector<ParamChange<StepperParams>> changes)
    : p_(params), step_(step), changes_(std::move(changes)) {
  std::stable_sort(changes_.begin(), changes_.end(),
                   [](const auto& a, const auto& b) { return a.at < b.at; });
}

double StepperLoad::electrical_command() const {
  return static_cast<double>(commanded_) * (std::numbers::pi / 2.0) / static_cast<double>(p_.microsteps);
}

double StepperLoad::commanded_angle() const {
  return electrical_command() / static_cast<double>(p_.rotor_teeth);
}

// The detent's sin is taken only when it can change the torque: a zero detent torque makes
// the term a signed zero, which leaves a non-zero holding term as it is (x - (+-0) == x).
StepperLoad::Vec StepperLoad::derivative(const Vec& x) const {
  const double n = static_cast<double>(p_.rotor_teeth);
  const double holding = p_.holding_torque * std::sin(electrical_command() - n * x(0));
  const double detent =
      p_.detent_torque != 0.0 || holding == 0.0 ? p_.detent_torque * std::sin(4.0 * n * x(0)) : 0.0;
  const double torque = holding - detent - p_.viscous * x(1) - p_.load_torque;
  return Vec(x(1), torque / (p_.rotor_inertia + p_.load_inertia));
}

Knot StepperLoad::advance(Nanos until) {
  while (next_change_ < changes_.size() && changes_[next_change_].at <= now_)
    p_ = changes_[next_change_++].params;
  Nanos end = std::min(until, now_ + step_);
  if (next_change_ < changes_.size()) end = std::min(end, changes_[next_change_].at);
  if (end <= now_) return state();
  const auto f = [this](double, const Vec& x) { return derivative(x); };
  x_ = rk4_step(f, 0.0, x_, (end - now_).seconds());
  now_ = end;
  return state();
}

// After advance() from s to e the changes at or before s are in force and none lies in (s, e)
// (a step ends at the next one): those before e. One at e itself takes effect at the next
// advance() (input() at e still sees the parameters before it).
void StepperLoad::resume_at(const Knot& later) {
  now_ = later.time;
  x_ = Vec(later.angle, later.speed);
  while (next_change_ < changes_.size() && changes_[next_change_].at < now_)
    p_ = changes_[next_change_++].params;
}

void StepperLoad::input(PlantInput which, bool level) {
  if (which == PlantInput::Direction) forward_ = level;
  if (which != PlantInput::Step) return;
  if (level != step_level_ && (level || p_.step_every_edge)) commanded_ += forward_ ? 1 : -1;
  step_level_ = level;
}

double StepperLoad::lag_full_steps() const {
  return (electrical_command() - static_cast<double>(p_.rotor_teeth) * x_(0)) / (std::numbers::pi / 2.0);
}

std::int64_t StepperLoad::lost_full_steps() const {
  return 4 * static_cast<std::int64_t>(std::llround(lag_full_steps() / 4.0));
}

} // namespace hilrig::plants
