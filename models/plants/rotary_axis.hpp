#pragma once
// A rotary axis: a motor turning a load, rigidly or through a compliant coupling (two
// masses). Linear between events, so it is integrated exactly (LinearFlow): the state
// after a step is e^{A h} x + Gamma(h) u with the input u held over the step.
//   rigid:     (J_m + J_l) dw/dt = T_motor + T_load(t) - (b_m + b_l) w - T_coulomb sgn w
//   two-mass:  J_m dw_m/dt = T_motor - k (th_m - th_l) - c (w_m - w_l) - b_m w_m
//              J_l dw_l/dt = T_load(t) + k (th_m - th_l) + c (w_m - w_l) - b_l w_l
// Coulomb friction is modelled on the rigid axis only (its standstill is an event: the
// shaft stays when the drive is within the friction). The encoder reads the motor or the
// load side.

#include <vector>

#include <Eigen/Dense>

#include "models/plants/linear_flow.hpp"
#include "models/plants/plant.hpp"

namespace hilrig::plants {

struct LoadStep {
  Nanos from;          // the load torque holds this value from here to the next step
  double torque = 0.0; // N·m, on the load (negative opposes forward motion)
};

struct RotaryParams {
  double motor_inertia = 1e-3;   // J_m, kg·m²
  double load_inertia = 1e-2;    // J_l, kg·m²
  bool two_mass = false;         // compliant coupling between motor and load
  double stiffness = 0.0;        // k, N·m/rad (two-mass; 0 = a broken coupling)
  double coupling_damping = 0.0; // c, N·m·s/rad (two-mass)
  double motor_viscous = 0.0;    // b_m, N·m·s/rad
  double load_viscous = 0.0;     // b_l, N·m·s/rad
  double coulomb_torque = 0.0;   // N·m (rigid only)
  double motor_torque = 0.0;     // N·m while the motor is enabled
  bool encoder_on_load = true;   // two-mass: which side the encoder reads
  std::vector<LoadStep> load;    // the load torque profile (0 before the first step)
};

struct RotaryStart {
  double angle = 0.0; // rad (both sides, the coupling relaxed)
  double speed = 0.0; // rad/s
  bool motor = true;  // enabled
};

class RotaryAxis final : public Plant {
public:
  RotaryAxis(const RotaryParams& params, const RotaryStart& start, Nanos step = Nanos{100'000},
             std::vector<ParamChange<RotaryParams>> changes = {});

  [[nodiscard]] std::unique_ptr<Plant> clone() const override { return std::make_unique<RotaryAxis>(*this); }
  void assign(const Plant& other) override { *this = static_cast<const RotaryAxis&>(other); }
  [[nodiscard]] Knot state() const override;
  Knot advance(Nanos until) override;
  void input(PlantInput which, bool level) override;
  [[nodiscard]] const std::vector<Nanos>& standstills() const override { return standstills_; }

  // The full state: rigid [angle, speed]; two-mass [motor angle, motor speed, load angle, load speed].
  [[nodiscard]] const Eigen::VectorXd& x() const { return x_; }
  [[nodiscard]] bool stuck() const { return stuck_; }

private:
  void build(); // the flow for the current parameters
  [[nodiscard]] double load_torque(Nanos t) const;
  [[nodiscard]] Eigen::VectorXd input_vector() const;
  [[nodiscard]] Nanos next_breakpoint() const;
  void classify();

  RotaryParams p_;
  Nanos step_;
  std::vector<ParamChange<RotaryParams>> changes_;
  std::size_t next_change_ = 0;
  LinearFlow flow_;
  Nanos now_{0};
  Eigen::VectorXd x_;
  bool motor_ = true;
  bool stuck_ = false;
  double speed_scale_ = 0.0; // the fastest |speed| since the last standstill
  double dir_ = 0.0;         // rigid: the sign of motion Coulomb friction opposes this step
  std::vector<Nanos> standstills_;
};

} // namespace hilrig::plants
