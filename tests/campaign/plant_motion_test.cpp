// PlantMotion integrates its plan as the encoder reads it (grow(), the solver's grow_with):
// a stepper's next pulse usually replaces the plan a few steps in. The plan read that way must
// be the plan integrated whole: the same knots (each step of the plant from the input to the
// horizon), the same encoder edges before the next input, the same trajectory, samples and
// standstills at the end.

#include "rig/campaign/plant_motion.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <bit>
#include <cmath>
#include <cstdint>
#include <numbers>
#include <random>
#include <vector>

#include "models/plants/stepper_load.hpp"
#include "signals/quadrature_edges.hpp"

using namespace hilrig;

namespace {

// The SMD23E-240E on an inertia of campaigns/smd23e/smd23e_load_too_fast.toml: 240 oz-in
// holding torque, 50 teeth, 64 microsteps, one step per STEP edge, a 10 us integration step.
campaign::PlantSpec stepper_spec(std::mt19937_64& rng) {
  campaign::PlantSpec spec;
  spec.kind = campaign::PlantKind::StepperLoad;
  spec.step = Nanos{10'000};
  spec.stepper.holding_torque = 1.69477;
  spec.stepper.rotor_inertia = 4.8e-5;
  spec.stepper.load_inertia = 1.0e-2 * static_cast<double>(1 + rng() % 4);
  spec.stepper.detent_torque = (rng() & 1) != 0 ? 0.05 : 0.0;
  spec.stepper.viscous = (rng() & 1) != 0 ? 0.01 : 0.0;
  spec.stepper.microsteps = 64;
  spec.stepper.step_every_edge = true;
  return spec;
}

constexpr double kCountsPerTurn = 1024.0;

signals::QuadratureEncoder fine_encoder() {
  signals::QuadratureEncoder enc;
  enc.lines_per_turn = 4096; // 16,384 counts a turn (the profile: 1,024 units a turn)
  enc.units_per_turn = kCountsPerTurn;
  return enc;
}

bool same(const signals::Segment& a, const signals::Segment& b) {
  return a.start == b.start && a.duration == b.duration && a.position == b.position &&
         a.velocity == b.velocity && a.acceleration == b.acceleration && a.settled_end == b.settled_end;
}

} // namespace

TEST(PlantMotion, PlanGrownAsReadIsThePlanIntegratedWhole) {
  std::mt19937_64 rng(20261126);
  const Nanos end{400'000'000};
  const signals::QuadratureEncoder enc = fine_encoder();
  for (int trial = 0; trial < 6; ++trial) {
    const campaign::PlantSpec spec = stepper_spec(rng);
    campaign::PlantMotion whole(spec, kCountsPerTurn, end); // every plan integrated at once
    campaign::PlantMotion grown(spec, kCountsPerTurn, end); // integrated as the edges ask
    plants::StepperLoad oracle(spec.stepper, spec.step);    // the plant itself, step by step
    const double per_rad = kCountsPerTurn / (2.0 * std::numbers::pi);
    bool level = false;
    bool forward = true;
    Nanos t{0};
    int compared_edges = 0;
    int compared_knots = 0;
    while (t < end - Nanos{20'000'000}) {
      // Pulses from 3 us to 200 us apart, now and then up to 3 ms (a plan reaches 1.28 ms),
      // sometimes a reversal.
      const std::uint64_t longest = rng() % 8 == 0 ? 3'000'000 : 200'000;
      const Nanos next = t + Nanos{static_cast<std::int64_t>(3'000 + rng() % longest)};
      const bool reverse = rng() % 40 == 0;
      // What the encoder plays until the next input: the edges of the whole plan, and those of
      // the grown one asked for one at a time.
      (void)whole.standstills(); // integrates the whole plan
      std::vector<signals::QuadEdge> expected;
      for (const signals::QuadEdge& e : signals::solve_quadrature(whole.plan(), enc, end).edges)
        if (e.time < next) expected.push_back(e);
      signals::QuadratureEdgeSolver solver(grown.plan(), enc, end);
      solver.grow_with([&grown] {
        return grown.grow() ? signals::QuadratureEdgeSolver::Growth::Grown
                            : signals::QuadratureEdgeSolver::Growth::Whole;
      });
      std::array<signals::QuadEdge, 2> one{};
      std::vector<signals::QuadEdge> played;
      for (std::size_t n = solver.fill(one); n != 0; n = solver.fill(one)) {
        if (one[0].time >= next) break;
        played.insert(played.end(), one.begin(), one.begin() + static_cast<std::ptrdiff_t>(n));
      }
      ASSERT_EQ(played, expected) << "trial " << trial << " at " << t.count();
      compared_edges += static_cast<int>(played.size());
      EXPECT_EQ(grown.plan_end(), whole.plan_end());
      EXPECT_EQ(grown.plan_end(), std::min(t + spec.step * campaign::PlantMotion::kPlanSteps, end));
      // Each knot of the grown plan so far is the plant's own step from the input on.
      {
        auto plant = oracle.clone();
        const std::vector<signals::Segment>& segs = grown.plan().segments();
        for (const signals::Segment& s : segs) {
          ASSERT_EQ(s.start, plant->state().time);
          const plants::Knot k = plant->advance(grown.plan_end());
          ASSERT_EQ(s.start + s.duration, k.time);
          EXPECT_NEAR(s.end_position(), k.angle * per_rad, 1e-9 * (1.0 + std::abs(k.angle * per_rad)));
          ++compared_knots;
        }
      }
      // The resolver's and the turns' reading anywhere before the next input.
      for (int i = 0; i < 3; ++i) {
        const Nanos at =
            t + Nanos{static_cast<std::int64_t>(rng() % static_cast<std::uint64_t>((next - t).count()))};
        EXPECT_EQ(grown.position(at), whole.position(at));
        EXPECT_EQ(grown.velocity(at), whole.velocity(at));
      }
      // The next input: a step edge (a reversal first, now and then).
      t = next;
      while (oracle.state().time < t) (void)oracle.advance(t);
      if (reverse) {
        forward = !forward;
        for (campaign::PlantMotion* m : {&whole, &grown}) m->input(t, plants::PlantInput::Direction, forward);
        oracle.input(plants::PlantInput::Direction, forward);
      }
      level = !level;
      for (campaign::PlantMotion* m : {&whole, &grown}) m->input(t, plants::PlantInput::Step, level);
      oracle.input(plants::PlantInput::Step, level);
    }
    // After the last input the shaft rings on to the end: plans extended at their horizons.
    while (grown.plan_end() < end) {
      whole.extend();
      grown.extend();
    }
    const signals::MotionProfile a = whole.trajectory();
    const signals::MotionProfile b = grown.trajectory();
    ASSERT_EQ(a.segments().size(), b.segments().size());
    for (std::size_t i = 0; i < a.segments().size(); ++i)
      ASSERT_TRUE(same(a.segments()[i], b.segments()[i])) << "trial " << trial << ", segment " << i;
    EXPECT_EQ(a.end_time(), end);
    const auto sa = whole.samples();
    const auto sb = grown.samples();
    ASSERT_EQ(sa.size(), sb.size());
    for (std::size_t i = 0; i < sa.size(); ++i) {
      EXPECT_EQ(sa[i].time, sb[i].time);
      EXPECT_EQ(sa[i].position, sb[i].position);
    }
    EXPECT_EQ(whole.standstills(), grown.standstills());
    // The run's end: the trajectory made in the history's own storage is trajectory()'s, bit
    // for bit (positions chained from the segments' closed forms, the peak speed), and the
    // standstills are still there.
    const std::vector<Nanos> standstills = grown.standstills();
    const signals::MotionProfile c = grown.take_trajectory();
    ASSERT_EQ(c.segments().size(), b.segments().size());
    for (std::size_t i = 0; i < b.segments().size(); ++i)
      ASSERT_TRUE(same(c.segments()[i], b.segments()[i])) << "trial " << trial << ", segment " << i;
    EXPECT_EQ(c.start_time(), b.start_time());
    EXPECT_EQ(c.peak_speed(), b.peak_speed());
    EXPECT_EQ(c.position(c.start_time() - Nanos{1}), b.position(b.start_time() - Nanos{1}));
    EXPECT_EQ(grown.standstills(), standstills);
    EXPECT_GT(compared_edges, 500) << "trial " << trial;
    EXPECT_GT(compared_knots, 1000) << "trial " << trial;
  }
}

// An input resumes the stepper from the plan's last knot at or before its instant (the state
// the plan kept there) instead of integrating again from the last input. That must be the
// integration from the last input bit for bit: random stepper loads (odd integration steps,
// parameter changes, detent, friction, load torque), random step trains (pulses on knots, at
// and past the plan's horizon, between knots, a few ns apart, reversals), the plan read to
// random depths before each input; positions, velocities, the plan's knots and the encoder's
// edges compared with a PlantMotion that integrates from the last input (Resume::FromInput).
namespace {

std::uint64_t bits(double v) { return std::bit_cast<std::uint64_t>(v); }

bool same_bits(const signals::Segment& a, const signals::Segment& b) {
  return a.start == b.start && a.duration == b.duration && bits(a.position) == bits(b.position) &&
         bits(a.velocity) == bits(b.velocity) && bits(a.acceleration) == bits(b.acceleration) &&
         a.settled_end == b.settled_end;
}

plants::StepperParams random_stepper(std::mt19937_64& rng) {
  std::uniform_real_distribution<double> u(0.0, 1.0);
  plants::StepperParams p;
  p.holding_torque = 0.5 + 1.5 * u(rng);
  p.rotor_inertia = 4.8e-5;
  p.load_inertia = 1.0e-3 * static_cast<double>(rng() % 20);
  p.detent_torque = rng() % 3 == 0 ? 0.08 * u(rng) : 0.0;
  p.viscous = rng() % 3 == 0 ? 0.02 * u(rng) : 0.0;
  p.load_torque = rng() % 4 == 0 ? 0.3 * u(rng) : 0.0;
  p.microsteps = std::array{1, 8, 16, 64}[rng() % 4];
  p.step_every_edge = (rng() & 1) != 0;
  return p;
}

} // namespace

TEST(PlantMotion, InputResumedAtAKnotIsTheIntegrationFromTheLastInput) {
  std::mt19937_64 rng(20261127);
  const signals::QuadratureEncoder enc = fine_encoder();
  for (int trial = 0; trial < 12; ++trial) {
    campaign::PlantSpec spec;
    spec.kind = campaign::PlantKind::StepperLoad;
    spec.step = Nanos{static_cast<std::int64_t>(7'001 + rng() % 6'000)};
    spec.stepper = random_stepper(rng);
    const Nanos end{static_cast<std::int64_t>(150'000'000 + rng() % 100'000'000)};
    // Parameter changes: a few, or enough that many plans hold one (its steps then end off the
    // grid from the input, and the horizon cuts a step short).
    const int changes = static_cast<int>((rng() & 1) != 0 ? rng() % 4 : 40 + rng() % 60);
    for (int c = changes; c > 0; --c)
      spec.stepper_changes.push_back(
          {Nanos{static_cast<std::int64_t>(rng() % static_cast<std::uint64_t>(end.count()))},
           random_stepper(rng)});
    campaign::PlantMotion fast(spec, kCountsPerTurn, end);
    campaign::PlantMotion ref(spec, kCountsPerTurn, end, campaign::PlantMotion::Resume::FromInput);
    bool level = false;
    bool forward = true;
    Nanos t{0};
    int inputs = 0;
    int compared = 0;
    while (t < end - Nanos{2'000'000}) {
      // The next input: on a knot of the plan (a whole number of steps on, where no parameter
      // change intervenes), at its horizon or past it, a few ns or a few steps on.
      Nanos next = t;
      switch (rng() % 10) {
      case 0:
      case 1:
        next = t + spec.step * static_cast<std::int64_t>(1 + rng() % 12);
        break;
      case 2:
        next = fast.plan_end();
        break;
      case 3:
        next = fast.plan_end() + Nanos{static_cast<std::int64_t>(1 + rng() % 2'000'000)};
        break;
      case 4:
        next = t + Nanos{static_cast<std::int64_t>(rng() % 40)};
        break;
      default:
        next = t + Nanos{static_cast<std::int64_t>(1'000 + rng() % 200'000)};
        break;
      }
      // The plan read to a random depth first (none, a few knots, as far as the next input, whole).
      switch (rng() % 4) {
      case 0:
        break;
      case 1:
        for (int g = static_cast<int>(rng() % 6); g > 0; --g) (void)fast.grow();
        break;
      case 2:
        (void)fast.position(next);
        break;
      default:
        (void)fast.standstills();
        break;
      }
      // Readings between the two inputs.
      for (int i = 0; i < 2; ++i) {
        const Nanos at =
            t + Nanos{static_cast<std::int64_t>(rng() % static_cast<std::uint64_t>((next - t).count() + 1))};
        ASSERT_EQ(bits(fast.position(at)), bits(ref.position(at)))
            << "trial " << trial << " at " << at.count();
        ASSERT_EQ(bits(fast.velocity(at)), bits(ref.velocity(at)))
            << "trial " << trial << " at " << at.count();
      }
      // The edges the encoder would play from the plan up to the next input.
      if (rng() % 3 == 0) {
        (void)fast.standstills();
        (void)ref.standstills();
        ASSERT_EQ(signals::solve_quadrature(fast.plan(), enc, next).edges,
                  signals::solve_quadrature(ref.plan(), enc, next).edges)
            << "trial " << trial << " at " << t.count();
      }
      // A drive extends the plan at its horizon before any input after it.
      if (rng() % 2 == 0)
        while (fast.plan_end() < std::min(next, end)) {
          fast.extend();
          ref.extend();
        }
      t = std::min(next, end);
      if (rng() % 25 == 0) {
        forward = !forward;
        fast.input(t, plants::PlantInput::Direction, forward);
        ref.input(t, plants::PlantInput::Direction, forward);
      }
      level = !level;
      fast.input(t, plants::PlantInput::Step, level);
      ref.input(t, plants::PlantInput::Step, level);
      ++inputs;
      ASSERT_EQ(fast.plan().start_time(), t);
      ASSERT_EQ(bits(fast.position(t)), bits(ref.position(t))) << "trial " << trial << " at " << t.count();
      ASSERT_EQ(bits(fast.velocity(t)), bits(ref.velocity(t))) << "trial " << trial << " at " << t.count();
      ++compared;
    }
    while (fast.plan_end() < end) {
      fast.extend();
      ref.extend();
    }
    const signals::MotionProfile a = fast.trajectory();
    const signals::MotionProfile b = ref.trajectory();
    ASSERT_EQ(a.segments().size(), b.segments().size()) << "trial " << trial;
    for (std::size_t i = 0; i < a.segments().size(); ++i)
      ASSERT_TRUE(same_bits(a.segments()[i], b.segments()[i])) << "trial " << trial << ", segment " << i;
    EXPECT_EQ(signals::solve_quadrature(a, enc, end).edges, signals::solve_quadrature(b, enc, end).edges);
    const auto sa = fast.samples();
    const auto sb = ref.samples();
    ASSERT_EQ(sa.size(), sb.size());
    for (std::size_t i = 0; i < sa.size(); ++i) {
      EXPECT_EQ(sa[i].time, sb[i].time);
      EXPECT_EQ(bits(sa[i].position), bits(sb[i].position));
    }
    EXPECT_EQ(fast.standstills(), ref.standstills());
    EXPECT_GT(inputs, 150) << "trial " << trial;
    EXPECT_GT(a.segments().size(), 4'000U) << "trial " << trial;
  }
}
