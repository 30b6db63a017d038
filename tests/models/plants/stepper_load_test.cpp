// The stepper load: it follows a constant-acceleration step train while J alpha is well
// under the holding torque (the lag settles near asin(J alpha / T_hold) electrical), and
// loses whole electrical turns (4 full steps each) when J alpha exceeds it.

#include <bit>
#include <cmath>
#include <cstdint>
#include <numbers>
#include <vector>

#include <gtest/gtest.h>

#include "models/plants/rk4.hpp"
#include "models/plants/stepper_load.hpp"
#include "plant_test_support.hpp"

namespace hilrig::plants {
namespace {

using testing::run_to;

StepperParams nema23() {
  StepperParams p;
  p.rotor_inertia = 4.8e-5;
  p.load_inertia = 1e-4;
  p.holding_torque = 1.0;
  p.detent_torque = 0.0;
  p.viscous = 1e-3;
  p.microsteps = 8;
  return p;
}

struct RampResult {
  double max_lag = 0.0;  // full steps
  double mean_lag = 0.0; // over the second half of the ramp, full steps
  std::int64_t lost = 0;
};

// Steps at the instants of a constant acceleration alpha from rest: step k at sqrt(2 k d / alpha).
RampResult ramp(const StepperParams& p, double alpha, Nanos duration) {
  StepperLoad s(p);
  s.input(PlantInput::Direction, true);
  const double d = 2.0 * std::numbers::pi / (4.0 * p.rotor_teeth * p.microsteps);
  RampResult r;
  std::int64_t n = 0;
  for (std::int64_t k = 1;; ++k) {
    const Nanos at = Nanos::from_seconds(std::sqrt(2.0 * static_cast<double>(k) * d / alpha));
    if (at > duration) break;
    (void)run_to(s, at);
    s.input(PlantInput::Step, true);
    s.input(PlantInput::Step, false);
    r.max_lag = std::max(r.max_lag, std::abs(s.lag_full_steps()));
    if (at > duration / 2) {
      r.mean_lag += s.lag_full_steps();
      ++n;
    }
  }
  r.mean_lag /= static_cast<double>(n);
  r.lost = s.lost_full_steps();
  return r;
}

TEST(StepperLoad, OneStepSettlesOnTheCommandedAngle) {
  StepperParams p = nema23();
  p.viscous = 0.01;
  StepperLoad s(p);
  s.input(PlantInput::Direction, true);
  s.input(PlantInput::Step, true);
  (void)run_to(s, milliseconds(500));
  EXPECT_NEAR(s.state().angle, 2.0 * std::numbers::pi / 1600.0, 1e-9);
  EXPECT_EQ(s.commanded(), 1);
}

// Without detent torque the detent's sin is skipped (StepperLoad::derivative); the knots must
// be bit for bit those of the whole torque formula, T sin(e - N th) - 0 sin(4 N th) - b w - T_l,
// integrated here by hand with the same RK4 step, under a train of steps and a reversal.
TEST(StepperLoad, DetentFreeStepsAreThoseOfTheWholeFormula) {
  StepperParams p = nema23();
  p.load_torque = 0.02;
  StepperLoad s(p);
  const double n = static_cast<double>(p.rotor_teeth);
  const double j = p.rotor_inertia + p.load_inertia;
  std::int64_t commanded = 0;
  Eigen::Vector2d x = Eigen::Vector2d::Zero();
  Nanos now{0};
  s.input(PlantInput::Direction, true);
  for (int pulse = 0; pulse < 400; ++pulse) {
    const bool forward = pulse < 300;
    s.input(PlantInput::Direction, forward);
    s.input(PlantInput::Step, true);
    s.input(PlantInput::Step, false);
    commanded += forward ? 1 : -1;
    const double e =
        static_cast<double>(commanded) * (std::numbers::pi / 2.0) / static_cast<double>(p.microsteps);
    const auto f = [&](double, const Eigen::Vector2d& y) {
      const double torque = p.holding_torque * std::sin(e - n * y(0)) -
                            p.detent_torque * std::sin(4.0 * n * y(0)) - p.viscous * y(1) - p.load_torque;
      return Eigen::Vector2d(y(1), torque / j);
    };
    const Nanos until = now + Nanos{3'000 + 7'919 * (pulse % 5)}; // whole steps and a part of one
    while (now < until) {
      const Nanos end = std::min(until, now + Nanos{10'000});
      x = rk4_step(f, 0.0, x, (end - now).seconds());
      now = end;
      const Knot k = s.advance(until);
      ASSERT_EQ(k.time, now);
      ASSERT_EQ(k.angle, x(0)) << pulse;
      ASSERT_EQ(k.speed, x(1)) << pulse;
    }
  }
  EXPECT_NE(x(0), 0.0);
}

// A copy of the plant at one knot of an integration, resumed at a later knot of it
// (resume_at), is the integrated plant there: the same knot, the same steps after it bit for
// bit, and the parameters in force the same (a change at the knot itself takes effect at the
// next step; step_every_edge changing there decides whether a falling edge steps).
TEST(StepperLoad, ResumedAtALaterKnotIsTheIntegratedPlant) {
  StepperParams a = nema23();
  a.detent_torque = 0.03;
  StepperParams b = a;
  b.holding_torque = 0.7;
  b.step_every_edge = true;
  StepperParams c = a;
  c.viscous = 0.0;
  c.load_torque = 0.05;
  // Changes on the 10 us grid (at a knot) and off it (a step cut short).
  const std::vector<ParamChange<StepperParams>> changes{
      {Nanos{40'000}, b}, {Nanos{83'333}, c}, {Nanos{150'000}, a}, {Nanos{161'000}, b}};
  StepperLoad integrated(nema23(), Nanos{10'000}, changes);
  integrated.input(PlantInput::Direction, true);
  integrated.input(PlantInput::Step, true);
  const StepperLoad start = integrated; // the knot at 0
  int resumed = 0;
  // The integration towards a far instant, as a plan takes it; the start resumed at each of
  // its knots (on the grid, at the changes, off the grid after one).
  while (integrated.now() < Nanos{200'000}) {
    const Knot k = integrated.advance(Nanos{1'000'000});
    StepperLoad copy = start;
    copy.resume_at(k);
    ASSERT_EQ(copy.state().time, k.time);
    ASSERT_EQ(std::bit_cast<std::uint64_t>(copy.state().angle), std::bit_cast<std::uint64_t>(k.angle));
    ASSERT_EQ(std::bit_cast<std::uint64_t>(copy.state().speed), std::bit_cast<std::uint64_t>(k.speed));
    // An input at the knot, then a few steps: the same as the integrated plant's.
    StepperLoad twin = integrated;
    for (StepperLoad* s : {&copy, &twin}) {
      s->input(PlantInput::Step, false); // a step only under step_every_edge
      s->input(PlantInput::Step, true);
    }
    ASSERT_EQ(copy.commanded(), twin.commanded()) << k.time.count();
    for (int i = 0; i < 5; ++i) {
      const Knot x = copy.advance(k.time + Nanos{37'000});
      const Knot y = twin.advance(k.time + Nanos{37'000});
      ASSERT_EQ(x.time, y.time);
      ASSERT_EQ(std::bit_cast<std::uint64_t>(x.angle), std::bit_cast<std::uint64_t>(y.angle));
      ASSERT_EQ(std::bit_cast<std::uint64_t>(x.speed), std::bit_cast<std::uint64_t>(y.speed));
    }
    ++resumed;
  }
  EXPECT_GE(resumed, 20);
}

TEST(StepperLoad, FollowsAnAccelerationWellWithinTheHoldingTorque) {
  StepperParams p = nema23();
  p.viscous = 0.0;
  const double alpha_max = p.holding_torque / (p.rotor_inertia + p.load_inertia);
  for (const double f : {0.1, 0.3, 0.5}) {
    const RampResult r = ramp(p, f * alpha_max, milliseconds(100));
    // Far from the 2 full steps where it would slip; on average the lag the closed form
    // gives (the torque J alpha needs) plus half a microstep (the staircase command trails
    // the ideal ramp by that on average), within 0.05 full steps (the undamped ringing).
    EXPECT_LT(r.max_lag, 1.0) << f;
    EXPECT_NEAR(r.mean_lag, std::asin(f) / (std::numbers::pi / 2.0) + 0.5 / 8.0, 0.05) << f;
    EXPECT_EQ(r.lost, 0) << f;
  }
}

TEST(StepperLoad, LosesStepsWhenTheLoadCannotFollow) {
  const StepperParams p = nema23();
  const double alpha_max = p.holding_torque / (p.rotor_inertia + p.load_inertia);
  for (const double f : {1.5, 3.0}) {
    const RampResult r = ramp(p, f * alpha_max, milliseconds(100));
    EXPECT_GE(r.lost, 4) << f;
    EXPECT_EQ(r.lost % 4, 0) << f;
  }
}

} // namespace
} // namespace hilrig::plants
