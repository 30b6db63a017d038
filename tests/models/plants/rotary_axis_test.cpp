// The rotary axis against closed-form solutions; the exact discretization leaves only
// rounding: angles within 1e-12 rad of the formulas, standstills within 1 ns.

#include <cmath>

#include <gtest/gtest.h>

#include "models/plants/rotary_axis.hpp"
#include "plant_test_support.hpp"

namespace hilrig::plants {
namespace {

using testing::run_to;
using testing::run_to_standstill;

// Coulomb friction alone: constant deceleration, stop at J w0 / T_c, then held.
TEST(RotaryAxis, CoulombFrictionStopsAtJw0OverT) {
  for (const double tc : {0.05, 0.2, 0.73})
    for (const double w0 : {-40.0, 5.0, 100.0}) {
      RotaryParams p;
      p.coulomb_torque = tc;
      RotaryAxis axis(p, RotaryStart{0.0, w0, false});
      const double j = p.motor_inertia + p.load_inertia;
      const Nanos still = run_to_standstill(axis, seconds(100));
      EXPECT_NEAR(static_cast<double>(still.count()), j * std::abs(w0) / tc * 1e9, 1.0) << tc << " " << w0;
      EXPECT_NEAR(axis.state().angle, w0 * std::abs(w0) * j / (2.0 * tc), 1e-12 * w0 * w0 * j / tc);
      const double held = axis.state().angle;
      (void)run_to(axis, still + milliseconds(10));
      EXPECT_EQ(axis.state().angle, held);
    }
}

TEST(RotaryAxis, ViscousFrictionDecaysExponentially) {
  RotaryParams p;
  p.motor_viscous = 0.004;
  p.load_viscous = 0.006;
  const double j = p.motor_inertia + p.load_inertia;
  const double tau = j / (p.motor_viscous + p.load_viscous);
  RotaryAxis axis(p, RotaryStart{0.0, 50.0, false});
  for (const double t : {0.01, 0.25, 1.7}) {
    const Knot k = run_to(axis, Nanos::from_seconds(t));
    EXPECT_NEAR(k.speed, 50.0 * std::exp(-t / tau), 1e-12 * 50.0);
    EXPECT_NEAR(k.angle, 50.0 * tau * (1.0 - std::exp(-t / tau)), 1e-12 * 50.0 * tau);
  }
}

// A load torque step at 5 ms accelerates the rigid axis at T / J from then on; the motor
// enable adds its torque from the moment it rises.
TEST(RotaryAxis, LoadProfileAndMotorEnableActFromTheirInstants) {
  RotaryParams p;
  p.load = {LoadStep{milliseconds(5), -0.3}};
  p.motor_torque = 0.5;
  RotaryAxis axis(p, RotaryStart{0.0, 0.0, false});
  const double j = p.motor_inertia + p.load_inertia;
  EXPECT_NEAR(run_to(axis, milliseconds(20)).speed, -0.3 / j * 0.015, 1e-12);
  axis.input(PlantInput::MotorEnable, true);
  EXPECT_NEAR(run_to(axis, milliseconds(30)).speed, (-0.3 * 0.025 + 0.5 * 0.01) / j, 1e-12);
}

// Two masses through a spring k, no damping, the motor torque T stepped on from rest: the
// twist is T J_l / (k (J_m + J_l)) (1 - cos w_n t) with w_n = sqrt(k (J_m + J_l) / (J_m J_l)),
// and the centre of mass accelerates at T / (J_m + J_l).
TEST(RotaryAxis, TwoMassCouplingRingsAtItsNaturalFrequency) {
  RotaryParams p;
  p.two_mass = true;
  p.motor_inertia = 1e-3;
  p.load_inertia = 4e-3;
  p.stiffness = 50.0;
  p.motor_torque = 0.1;
  const double jm = p.motor_inertia;
  const double jl = p.load_inertia;
  const double wn = std::sqrt(p.stiffness * (jm + jl) / (jm * jl)); // 250 rad/s
  ASSERT_NEAR(wn, 250.0, 1e-12);
  RotaryAxis axis(p, RotaryStart{0.0, 0.0, true});
  for (const double t : {0.001, 0.0125663706, 0.02, 0.0251327412, 0.1}) {
    (void)run_to(axis, Nanos::from_seconds(t));
    const double ts = static_cast<double>(Nanos::from_seconds(t).count()) * 1e-9;
    const Eigen::VectorXd& x = axis.x();
    const double twist = x(0) - x(2);
    EXPECT_NEAR(twist, 0.1 * jl / (p.stiffness * (jm + jl)) * (1.0 - std::cos(wn * ts)), 1e-12) << t;
    EXPECT_NEAR((jm * x(0) + jl * x(2)) / (jm + jl), 0.1 / (2.0 * (jm + jl)) * ts * ts, 1e-12) << t;
  }
  // The encoder reads the load side.
  EXPECT_EQ(axis.state().angle, axis.x()(2));
}

// A coupling that breaks (k = 0 from t): the load coasts at the speed it had.
TEST(RotaryAxis, BrokenCouplingLeavesTheLoadCoasting) {
  RotaryParams p;
  p.two_mass = true;
  p.stiffness = 80.0;
  p.coupling_damping = 0.05;
  p.motor_torque = 0.2;
  RotaryParams broken = p;
  broken.stiffness = 0.0;
  broken.coupling_damping = 0.0;
  RotaryAxis axis(p, RotaryStart{0.0, 0.0, true}, Nanos{100'000},
                  {ParamChange<RotaryParams>{milliseconds(40), broken}});
  (void)run_to(axis, milliseconds(40));
  const double w = axis.x()(3);
  (void)run_to(axis, milliseconds(90));
  EXPECT_NEAR(axis.x()(3), w, 1e-12);
}

} // namespace
} // namespace hilrig::plants
