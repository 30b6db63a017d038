#pragma once
// A mechanical press: a motor drives a flywheel; a combination clutch/brake (one valve)
// couples the flywheel to the crankshaft, whose crank-slider moves the ram. Everything is
// referred to the crankshaft. The valve energized engages the clutch and releases the
// brake; de-energized, the clutch releases and the spring brake engages, each after the
// valve's delay, the brake torque rising linearly over its rise time.
//
// Crank side (Lagrange, ram mass m on the crank-slider): with J(theta) = J_c + m s'^2,
//   J dw/dt + m s' s'' w^2 = T_clutch - m g s' - b_c w - (T_coulomb + T_brake(t)) sgn w
// Flywheel: J_f dw_f/dt = T_motor(w_f) - b_f w_f - T_clutch, T_motor(w) = T_stall (1 - w/w_sync).
// Clutch locked: both move as one; it slips when the torque it must carry exceeds its
// capacity, and locks again when the speeds meet. At standstill the crank stays held while
// the gravity load is within the brake's and Coulomb friction's holding torque.

#include <optional>
#include <vector>

#include <Eigen/Dense>

#include "models/plants/crank_slider.hpp"
#include "models/plants/plant.hpp"

namespace hilrig::plants {

struct PressParams {
  double flywheel_inertia = 5.0;   // J_f, kg·m²
  double crank_inertia = 1.0;      // J_c (crankshaft, gears, clutch hub), kg·m²
  double motor_stall_torque = 0.0; // T_stall, N·m (0: no motor)
  double motor_sync_speed = 0.0;   // w_sync, rad/s (the motor's no-load speed)
  double flywheel_viscous = 0.0;   // b_f, N·m·s/rad
  double crank_viscous = 0.0;      // b_c, N·m·s/rad
  double coulomb_torque = 0.0;     // N·m, on the crank
  double clutch_torque = 1e4;      // capacity, N·m
  double brake_torque = 1000.0;    // at full engagement, N·m
  double valve_delay = 0.0;        // s, valve command to clutch/brake response
  double brake_rise = 0.0;         // s, brake torque 0 -> full
  double ram_mass = 0.0;           // kg
  CrankSlider crank{0.05, 0.3};    // m
  double gravity = 9.80665;        // m/s²
};

struct PressStart {
  double angle = 0.0; // crank angle from TDC, rad
  double speed = 0.0; // crank (and flywheel) speed, rad/s
  bool valve = true;  // clutch engaged, brake released
  bool motor = true;  // motor on
  // The flywheel's speed when it differs from the crank's (a clutch about to engage).
  std::optional<double> flywheel_speed;
};

class PressPlant final : public Plant {
public:
  enum class Mode : std::uint8_t { Locked, Slipping, Free, Stuck };

  PressPlant(const PressParams& params, const PressStart& start, Nanos step = Nanos{100'000},
             std::vector<ParamChange<PressParams>> changes = {});

  [[nodiscard]] std::unique_ptr<Plant> clone() const override { return std::make_unique<PressPlant>(*this); }
  void assign(const Plant& other) override { *this = static_cast<const PressPlant&>(other); }
  [[nodiscard]] Knot state() const override { return Knot{now_, x_(0), x_(1)}; }
  Knot advance(Nanos until) override;
  void input(PlantInput which, bool level) override;
  [[nodiscard]] const std::vector<Nanos>& standstills() const override { return standstills_; }

  [[nodiscard]] Mode mode() const { return mode_; }
  [[nodiscard]] double flywheel_speed() const { return x_(2); }
  [[nodiscard]] const PressParams& params() const { return p_; }
  // Kinetic plus potential energy of crank, ram and flywheel (J), for energy balances.
  [[nodiscard]] double energy() const;
  // The brake torque at time t as engaged so far (N·m) and whether the clutch is engaged.
  [[nodiscard]] double brake_torque_at(Nanos t) const;
  [[nodiscard]] bool clutch_engaged_at(Nanos t) const;

private:
  using Vec = Eigen::Vector3d; // crank angle, crank speed, flywheel speed

  [[nodiscard]] Vec derivative(Nanos t0, double t, const Vec& x) const;
  [[nodiscard]] double event(Nanos t0, double t, const Vec& x) const;      // > 0 until the mode's event
  [[nodiscard]] double crank_load(Nanos t0, double t, const Vec& x) const; // all but the clutch
  [[nodiscard]] double clutch_needed(Nanos t0, double t, const Vec& x) const;
  [[nodiscard]] double holding_torque(Nanos t) const;
  [[nodiscard]] double brake_at(Nanos t0, double t) const; // t s into a step from t0
  [[nodiscard]] double motor_torque(double w) const;
  [[nodiscard]] double crank_inertia(double theta) const; // J_c + m s'^2
  [[nodiscard]] double gravity_torque(double theta) const {
    return -p_.ram_mass * p_.gravity * p_.crank.d_height(theta);
  }
  [[nodiscard]] Nanos next_breakpoint() const;
  void classify(); // the mode and the signs after a breakpoint or an event
  void on_event();

  PressParams p_;
  Nanos step_;
  std::vector<ParamChange<PressParams>> changes_;
  std::size_t next_change_ = 0;
  Nanos now_{0};
  Vec x_;
  Mode mode_ = Mode::Free;
  double dir_ = 0.0;         // sign of crank motion the friction and brake oppose in this step
  double speed_scale_ = 0.0; // the fastest |speed| since the last standstill
  double speed_floor_ = 0.0; // a speed within rounding of zero (rk4.hpp)
  double slip_ = 0.0;        // sign of flywheel minus crank speed while slipping
  bool valve_ = true;
  bool motor_ = true;
  Nanos valve_at_ = Nanos::min(); // last valve command
  bool clutch_before_ = true;     // clutch state before the last command took effect
  double brake_before_ = 0.0;     // brake fraction before the last command took effect
  std::vector<Nanos> standstills_;
};

} // namespace hilrig::plants
