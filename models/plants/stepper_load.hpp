#pragma once
// A hybrid stepper motor turning a load, driven by step pulses. The rotor has N teeth
// (50 for a 1.8 degree motor: 200 full steps a turn); a full step moves the commanded
// electrical angle by pi/2, a microstep by pi/2 / microsteps. The torque:
//   (J_rotor + J_load) dw/dt = T_hold sin(phi_cmd - N th) - T_detent sin(4 N th)
//                              - b w - T_load
// Equilibria repeat every electrical turn (4 full steps): a rotor that falls behind the
// command by more than 2 full steps slips to the next equilibrium and has lost 4 full
// steps (or a multiple). A constant acceleration alpha is followed only while
// J alpha < T_hold (the lag then settles near asin(J alpha / T_hold) electrical).
// Nonlinear: RK4 with a fixed step, the step ending at every step pulse.

#include <cstdint>

#include <Eigen/Dense>

#include "models/plants/plant.hpp"

namespace hilrig::plants {

struct StepperParams {
  double rotor_inertia = 4.8e-5; // kg·m² (a NEMA 23 rotor)
  double load_inertia = 0.0;     // kg·m²
  double holding_torque = 1.0;   // N·m, peak of the sinusoid
  double detent_torque = 0.0;    // N·m, peak (unpowered cogging)
  double viscous = 0.0;          // N·m·s/rad
  double load_torque = 0.0;      // N·m, constant, opposing forward motion
  int rotor_teeth = 50;          // N
  int microsteps = 1;            // per full step
  bool step_every_edge = false;  // both edges of the step line are steps (a line toggling once a step)
};

class StepperLoad final : public Plant {
public:
  StepperLoad(const StepperParams& params, Nanos step = Nanos{10'000},
              std::vector<ParamChange<StepperParams>> changes = {});

  [[nodiscard]] std::unique_ptr<Plant> clone() const override { return std::make_unique<StepperLoad>(*this); }
  void assign(const Plant& other) override { *this = static_cast<const StepperLoad&>(other); }
  // A step ends at until, the integration step's end or a parameter change: nothing is
  // located; after it the state is the knot and the parameters of the changes before it.
  [[nodiscard]] bool resumes_at_knots() const override { return true; }
  void resume_at(const Knot& later) override;
  [[nodiscard]] Knot state() const override { return Knot{now_, x_(0), x_(1)}; }
  Knot advance(Nanos until) override;
  void input(PlantInput which, bool level) override;
  [[nodiscard]] const std::vector<Nanos>& standstills() const override { return standstills_; }

  // Microsteps commanded so far (signed).
  [[nodiscard]] std::int64_t commanded() const { return commanded_; }
  // How far the rotor is behind the command, in full steps (negative: ahead).
  [[nodiscard]] double lag_full_steps() const;
  // Full steps lost: the lag rounded to whole electrical turns (4 full steps each).
  [[nodiscard]] std::int64_t lost_full_steps() const;
  // The angle the command asks for, rad.
  [[nodiscard]] double commanded_angle() const;

private:
  using Vec = Eigen::Vector2d;
  [[nodiscard]] Vec derivative(const Vec& x) const;
  [[nodiscard]] double electrical_command() const;

  StepperParams p_;
  Nanos step_;
  std::vector<ParamChange<StepperParams>> changes_;
  std::size_t next_change_ = 0;
  Nanos now_{0};
  Vec x_ = Vec::Zero();
  std::int64_t commanded_ = 0;
  bool forward_ = true;
  bool step_level_ = false;
  std::vector<Nanos> standstills_; // the stepper locates no standstill (it rings about each step)
};

} // namespace hilrig::plants
