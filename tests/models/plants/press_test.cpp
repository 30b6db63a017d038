// The press plant against closed-form solutions. Tolerances: event times within 1 ns of
// the exact instant (the event lies in (t - 1 ns, t]); angles and speeds of motions RK4
// integrates exactly (constant torque) within 1e-9 rad; smooth nonlinear motion
// (viscous, the crank-slider's gravity) within a relative 1e-9.

#include <cmath>
#include <numbers>

#include <gtest/gtest.h>

#include "models/plants/press.hpp"
#include "plant_test_support.hpp"

namespace hilrig::plants {
namespace {

using testing::run_to;
using testing::run_to_standstill;

PressParams frictionless() {
  PressParams p;
  p.flywheel_inertia = 5.0;
  p.crank_inertia = 2.0;
  p.brake_torque = 0.0;
  p.clutch_torque = 1e6;
  return p;
}

// Stop time of a constant torque: t = J w0 / T. Swept over inertias, speeds and torques.
TEST(PressPlant, ConstantBrakeTorqueStopsAtJw0OverT) {
  for (const double j : {0.5, 2.0, 7.3})
    for (const double w0 : {3.0, 31.41592653589793, 62.8})
      for (const double t : {150.0, 1000.0, 4321.0}) {
        PressParams p = frictionless();
        p.crank_inertia = j;
        p.brake_torque = t;
        PressPlant press(p, PressStart{0.0, w0, false, false, {}});
        const Nanos still = run_to_standstill(press, seconds(10));
        const double exact_ns = j * w0 / t * 1e9;
        EXPECT_GE(static_cast<double>(still.count()), exact_ns - 1e-3) << j << " " << w0 << " " << t;
        EXPECT_LT(static_cast<double>(still.count()), exact_ns + 1.0) << j << " " << w0 << " " << t;
        EXPECT_NEAR(press.state().angle, w0 * w0 * j / (2.0 * t), 1e-9);
        EXPECT_EQ(press.mode(), PressPlant::Mode::Stuck);
        // It stays: the angle does not move after the standstill.
        const double held = press.state().angle;
        (void)run_to(press, still + milliseconds(50));
        EXPECT_EQ(press.state().angle, held);
      }
}

// Coulomb friction adds to the brake: t = J w0 / (T_brake + T_coulomb).
TEST(PressPlant, CoulombFrictionAddsToTheBrake) {
  PressParams p = frictionless();
  p.brake_torque = 800.0;
  p.coulomb_torque = 200.0;
  PressPlant press(p, PressStart{0.0, 20.0, false, false, {}});
  const Nanos still = run_to_standstill(press, seconds(1));
  EXPECT_NEAR(static_cast<double>(still.count()), 2.0 * 20.0 / 1000.0 * 1e9, 1.0);
}

// The valve drops at t_c: after the delay the clutch releases and the brake torque rises
// linearly over r to T. During the rise the crank loses T r / (2 J); then it decelerates
// at T / J. Stop at t_c + d + r + (w0 - T r / 2J) J / T.
TEST(PressPlant, BrakeDelayAndRiseShiftTheStopAsPredicted) {
  for (const double d : {0.0, 0.012, 0.0305})
    for (const double r : {0.0, 0.02, 0.0451}) {
      PressParams p = frictionless();
      p.brake_torque = 600.0;
      p.valve_delay = d;
      p.brake_rise = r;
      const double w0 = 12.0;
      PressPlant press(p, PressStart{0.0, w0, true, false, {}});
      const Nanos tc = milliseconds(10);
      (void)run_to(press, tc);
      EXPECT_NEAR(press.state().angle, w0 * 0.01, 1e-12);
      press.input(PlantInput::Valve, false);
      const double j = p.crank_inertia;
      const double t = p.brake_torque;
      const double w1 = w0 - t * r / (2.0 * j);
      const double exact = 0.01 + d + r + w1 * j / t;
      const Nanos still = run_to_standstill(press, seconds(2));
      EXPECT_NEAR(static_cast<double>(still.count()), exact * 1e9, 1.0) << d << " " << r;
      const double angle = w0 * (0.01 + d) + w0 * r - t * r * r / (6.0 * j) + w1 * w1 * j / (2.0 * t);
      EXPECT_NEAR(press.state().angle, angle, 1e-9) << d << " " << r;
    }
}

// A worn brake from t_w (a parameter change at a time): T until t_w, 0.7 T after.
TEST(PressPlant, WornBrakeFromATimeStopsLater) {
  PressParams p = frictionless();
  p.brake_torque = 1000.0;
  PressParams worn = p;
  worn.brake_torque = 0.7 * p.brake_torque;
  const double w0 = 30.0;
  PressPlant press(p, PressStart{0.0, w0, false, false, {}}, Nanos{100'000},
                   {ParamChange<PressParams>{milliseconds(20), worn}});
  const Nanos still = run_to_standstill(press, seconds(2));
  const double w_at = w0 - 1000.0 * 0.02 / 2.0;
  EXPECT_NEAR(static_cast<double>(still.count()), (0.02 + w_at * 2.0 / 700.0) * 1e9, 1.0);
}

// Viscous friction alone: w = w0 e^{-bt/J}, angle = w0 J/b (1 - e^{-bt/J}).
TEST(PressPlant, ViscousFrictionDecaysExponentially) {
  PressParams p = frictionless();
  p.crank_viscous = 1.5;
  const double w0 = 40.0;
  PressPlant press(p, PressStart{0.0, w0, false, false, {}});
  const double tau = p.crank_inertia / p.crank_viscous;
  for (const double t : {0.05, 0.3333, 1.0, 2.5}) {
    const Knot k = run_to(press, Nanos::from_seconds(t));
    EXPECT_NEAR(k.speed, w0 * std::exp(-t / tau), 1e-9 * w0) << t;
    EXPECT_NEAR(k.angle, w0 * tau * (1.0 - std::exp(-t / tau)), 1e-9 * w0 * tau) << t;
  }
  EXPECT_TRUE(press.standstills().empty()); // viscous friction alone never stops the shaft
}

// Energy over a stroke with the ram's gravity through the crank-slider and no losses:
// (J_f + J_c + m s'^2) w^2 / 2 + m g s stays constant.
TEST(PressPlant, EnergyIsConservedOverAStrokeWithoutLosses) {
  PressParams p = frictionless();
  p.flywheel_inertia = 30.0;
  p.crank_inertia = 1.5;
  p.ram_mass = 800.0;
  p.crank = CrankSlider{0.06, 0.35};
  PressPlant press(p, PressStart{0.0, 10.0, true, false, {}});
  const double e0 = press.energy();
  double fastest = 10.0;
  while (press.state().angle < 2.0 * std::numbers::pi) {
    (void)press.advance(seconds(10));
    EXPECT_NEAR(press.energy(), e0, 1e-9 * e0);
    fastest = std::max(fastest, press.state().speed);
  }
  // From TDC the ram's fall speeds the crank up (then the upstroke takes it back).
  EXPECT_GT(fastest, 10.5);
  EXPECT_NEAR(press.state().speed, 10.0, 1e-3); // back at TDC (within the last step)
}

// Energy balance while braking: the brake and Coulomb friction take (T_b + T_c) per radian,
// so E0 - E(stop) = (T_b + T_c) * angle at the stop, with gravity storing the rest.
TEST(PressPlant, BrakeWorkBalancesTheEnergyLostOverAStop) {
  for (const double start : {0.0, 1.0, 2.5, 4.0}) {
    PressParams p = frictionless();
    p.crank_inertia = 3.0;
    p.ram_mass = 800.0;
    p.crank = CrankSlider{0.06, 0.35};
    p.brake_torque = 2000.0;
    p.coulomb_torque = 150.0;
    PressPlant press(p, PressStart{start, 25.0, false, false, {}});
    const double e0 = press.energy();
    (void)run_to_standstill(press, seconds(5));
    ASSERT_EQ(press.standstills().size(), 1U);
    const double work = (p.brake_torque + p.coulomb_torque) * (press.state().angle - start);
    EXPECT_NEAR(e0 - press.energy(), work, 1e-9 * e0) << start;
  }
}

// The clutch engages a spinning flywheel onto a crank at rest: it slips at its capacity T_k
// until the speeds meet at t = w_f / (T_k (1/J_c + 1/J_f)), then locks at the momentum
// speed J_f w_f / (J_f + J_c).
TEST(PressPlant, SlippingClutchLocksWhenTheSpeedsMeet) {
  PressParams p = frictionless();
  p.clutch_torque = 500.0;
  p.crank_inertia = 1.0;
  p.flywheel_inertia = 5.0;
  PressPlant press(p, PressStart{0.0, 0.0, true, false, 20.0});
  EXPECT_EQ(press.mode(), PressPlant::Mode::Slipping);
  while (press.mode() != PressPlant::Mode::Locked) (void)press.advance(seconds(1));
  const double exact = 20.0 / (500.0 * (1.0 / 1.0 + 1.0 / 5.0));
  EXPECT_NEAR(static_cast<double>(press.now().count()), exact * 1e9, 1.0);
  EXPECT_NEAR(press.state().speed, 5.0 * 20.0 / 6.0, 1e-6);
  EXPECT_EQ(press.flywheel_speed(), press.state().speed);
}

// The motor's torque-speed line: locked, no load, the press runs up to the motor's
// synchronous speed as w_s (1 - e^{-t T_s / (w_s J)}).
TEST(PressPlant, MotorRunsUpAlongItsTorqueSpeedLine) {
  PressParams p = frictionless();
  p.motor_stall_torque = 300.0;
  p.motor_sync_speed = 15.0;
  PressPlant press(p, PressStart{0.0, 0.0, true, true, {}});
  const double j = p.crank_inertia + p.flywheel_inertia;
  const double rate = p.motor_stall_torque / (p.motor_sync_speed * j);
  for (const double t : {0.1, 0.5, 2.0}) {
    const Knot k = run_to(press, Nanos::from_seconds(t));
    EXPECT_NEAR(k.speed, 15.0 * (1.0 - std::exp(-rate * t)), 1e-9 * 15.0) << t;
  }
}

// At standstill the brake holds the ram's gravity load while it can; a brake weaker than
// the gravity torque at that crank angle lets the crank run back.
TEST(PressPlant, BrakeHoldsTheRamOnlyWithinItsTorque) {
  PressParams p = frictionless();
  p.ram_mass = 2000.0;
  p.crank = CrankSlider{0.1, 0.5};
  p.crank_inertia = 2.0;
  p.brake_torque = 2500.0;
  // Start on the upstroke (past BDC), slow: the gravity torque at ~1.6 pi is ~1900 N·m.
  PressPlant held(p, PressStart{1.6 * std::numbers::pi, 0.5, false, false, {}});
  (void)run_to_standstill(held, seconds(1));
  ASSERT_EQ(held.standstills().size(), 1U);
  EXPECT_EQ(held.mode(), PressPlant::Mode::Stuck);
  p.brake_torque = 1000.0;
  PressPlant slips(p, PressStart{1.6 * std::numbers::pi, 0.5, false, false, {}});
  (void)run_to(slips, seconds(2));
  // It turned back and ran down past where the held one stopped, to rest near BDC where the
  // gravity torque is within the brake's.
  EXPECT_LT(slips.state().angle, held.state().angle - 0.1);
  EXPECT_EQ(slips.mode(), PressPlant::Mode::Stuck);
  EXPECT_LE(p.ram_mass * p.gravity * std::abs(p.crank.d_height(slips.state().angle)), p.brake_torque);
}

// A crank too light to take a nanosecond to stop (J w0 / T = 1e-9 x 10 / 2000 = 5e-12 s, and
// down to 1e-300 kg·m² within the documented range "> 0"): the standstill is located at the
// first nanosecond (the event lies in (t - 1 ns, t]) and the crank stands within that
// nanosecond's travel of where it was (w0 x 1 ns = 1e-8 rad; the exact stop is w0² J / 2T =
// 2.5e-11 rad on), never carried backwards past its start by the deceleration (T / J = 2e12
// rad/s² over the rest of the ns, 1e-6 rad).
TEST(PressPlant, ACrankThatStopsWithinANanosecondStandsWhereItStopped) {
  for (const double j : {1e-7, 1e-9, 1e-12, 1e-300}) {
    PressParams p = frictionless();
    p.crank_inertia = j;
    p.brake_torque = 2000.0;
    PressPlant press(p, PressStart{0.7, 10.0, false, false, {}});
    const Nanos still = run_to_standstill(press, seconds(1));
    EXPECT_EQ(still, Nanos{1}) << j;
    EXPECT_GE(press.state().angle, 0.7) << j;
    EXPECT_LE(press.state().angle, 0.7 + 10.0 * 1e-9) << j;
    EXPECT_EQ(press.state().speed, 0.0) << j;
    EXPECT_EQ(press.mode(), PressPlant::Mode::Stuck) << j;
  }
}

// A heavy ram on a long rod (1e6 kg, r 10 m, l 100 m: the documented maxima, docs/plants.md):
// near top dead centre the crank's inertia J_c + m (ds/dθ)² swings from 2 to ~1e8 kg·m² within
// a fraction of a degree, which a fixed 100 us step cannot follow (it gained ~2000x the energy
// there is and read 4e7 counts/s). Without losses the energy stays what it was at every step,
// and the crank, slowed by the ram it lifts, never turns faster than it started.
TEST(PressPlant, AHeavyRamNearDeadCentreKeepsItsEnergy) {
  PressParams p = frictionless();
  p.flywheel_inertia = 20.0;
  p.crank_inertia = 2.0;
  p.ram_mass = 1e6;
  p.crank = CrankSlider{10.0, 100.0};
  // The clutch released (no brake torque here): a slipping clutch would take energy by rights.
  PressPlant press(p, PressStart{0.0, 10.0, false, false, {}});
  const double e0 = press.energy();
  while (press.now() < milliseconds(100)) {
    const Knot k = press.advance(milliseconds(100));
    ASSERT_NEAR(press.energy(), e0, 1e-9 * e0) << k.time.count(); // e0 ~1.1e9 J, mostly the ram's height
    ASSERT_LE(std::abs(k.speed), 10.0 * (1.0 + 1e-9)) << k.time.count();
  }
}

} // namespace
} // namespace hilrig::plants
