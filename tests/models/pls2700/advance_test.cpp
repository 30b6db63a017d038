// Advances (pls2700.md §4.6, R-ADV-1..R-ADV-7; W5, W9) and throughput (§3.1): output edges on
// the pins against the synthesized shaft. The shaft turns 32 raw counts (of 8192) per
// 200 us update, exactly: 19.53125 rev/s = 1171.875 RPM, starting half a raw count past 0, so
// at update k (t = k * 200 us) raw = 32k; with SF 4096 MP = 16k and the speed is
// 16 counts / 0.2 ms = 80 counts/ms; with SF 1024 MP = 4k and 20 counts/ms.
#include <gtest/gtest.h>

#include <random>

#include "models/pls2700/error_codes.hpp"
#include "pls2700_bench.hpp"
#include "signals/move_builders.hpp"

namespace hilrig::models::pls2700 {
namespace {

using namespace hilrig::literals;
using testing::Bench;

constexpr double kTurnsPerSecond = 32.0 / 8192.0 / 0.0002;

signals::AngleFunction spinning() { return signals::angle_at_constant_speed(0.5 / 8192.0, kTurnsPerSecond); }

TEST(Pls2700Advance, W5W9AdvanceWords) {
  // W5 (L413-L415): ON 10 ms / OFF 5 ms -> host word 1005h; W9: 10/3 -> 1003h; legal on every
  // model on outputs 1..5 (OFF <= ON).
  for (const ModelTraits& m : kModels) {
    Bench b(m.variant);
    EXPECT_EQ(b.btw({0xC011, 0x1005, 0x0010, 0x0020}), error::kNone) << m.name;
    EXPECT_EQ(b.btw({0xC041, 0x1003, 0x0010, 0x0020}), error::kNone) << m.name;
    EXPECT_EQ(b.device().setup().outputs[3].advance_on_ms, 10);
    EXPECT_EQ(b.device().setup().outputs[3].advance_off_ms, 3);
  }
}

TEST(Pls2700Advance, NoAdvanceSwitchesAtTheSetpoints) {
  // ON 2000 / OFF 3000 at 16 MP counts per update: on at k = 125 (25 ms), off at the first
  // k with 16k >= 3000: k = 188 (37.6 ms).
  Bench b(ModelVariant::M2741);
  EXPECT_EQ(b.btw({0x8801, 0x4096, 0xC011, 0x0000, 0x2000, 0x3000}), error::kNone);
  b.shaft(1, spinning());
  b.run_until(50_ms);
  ASSERT_EQ(b.edges(1).size(), 2u);
  EXPECT_EQ(b.edges(1)[0].time, 25_ms);
  EXPECT_EQ(b.edges(1)[1].time, 37'600_us);
}

TEST(Pls2700Advance, AdvancesMoveEdgesEarlierBySpeedTimesTime) {
  // R-ADV-4: v = 80 counts/ms; a_on 10 ms -> 800 counts: ON point 2000 - 800 = 1200 -> k = 75
  // (15 ms, 10 ms before the 25 ms crossing); a_off 5 ms -> 400: OFF point 2600 -> k = 163
  // (32.6 ms; the shaft crosses 3000 at 37.5 ms, 4.9 ms later).
  Bench b(ModelVariant::M2741);
  EXPECT_EQ(b.btw({0x8801, 0x4096, 0xC011, 0x1005, 0x2000, 0x3000}), error::kNone);
  b.shaft(1, spinning());
  b.run_until(50_ms);
  ASSERT_EQ(b.edges(1).size(), 2u);
  EXPECT_EQ(b.edges(1)[0].time, 15_ms);
  EXPECT_EQ(b.edges(1)[1].time, 32'600_us);
}

TEST(Pls2700Advance, Minus04AcceptsOffAboveOnAndTheWindowShrinks) {
  // R-ADV-2 (L431): on the 2731-04 a_off 10 > a_on 5 is legal. SF 1024, v = 20 counts/ms:
  // ON 500 - 100 = 400 -> k = 100 (20 ms); OFF 750 - 200 = 550 -> first 4k >= 550: k = 138
  // (27.6 ms). The same word on a 2731 is F1h (OFF advance > ON advance).
  Bench b(ModelVariant::M2731_04);
  EXPECT_EQ(b.btw({0x8801, 0x1024, 0xC011, 0x0510, 0x0500, 0x0750}), error::kNone);
  b.shaft(1, spinning());
  b.run_until(40_ms);
  ASSERT_EQ(b.edges(1).size(), 2u);
  EXPECT_EQ(b.edges(1)[0].time, 20_ms);
  EXPECT_EQ(b.edges(1)[1].time, 27'600_us);
  Bench standard(ModelVariant::M2731);
  EXPECT_EQ(standard.btw({0xC011, 0x0510, 0x0500, 0x0750}), 0xF1);
}

TEST(Pls2700Advance, AdvancesOnlyOnOutputs1To5OfSingleChannelModels) {
  // R-ADV-1 (L413, L1109, L1399): 2731/2731-04/2741 outputs 6-8 need 0000h; 2732/2742 take
  // advances on all eight.
  for (const ModelTraits& m : kModels) {
    Bench b(m.variant);
    const std::uint8_t six = b.btw({0xC061, 0x0100, 0x0010, 0x0020});
    EXPECT_EQ(six, m.channels == 1 ? 0xE6 : 0x00) << m.name;
    b.btw({0x8400});
    const std::uint8_t eight = b.btw({0xC081, 0x0000, 0x0010, 0x0020});
    EXPECT_EQ(eight, 0x00) << m.name;
  }
}

TEST(Pls2700Throughput, OutputEdgeWithinOneUpdateOfTheCrossing) {
  // §3.1: 0 <= t_edge - t_cross < T_upd (d_conv = d_drv = 0 in the model). SF 1024, ON 256
  // = a quarter turn exactly; random start angles and speeds, seed fixed.
  std::mt19937 rng(1771);
  std::uniform_real_distribution<double> start(0.0, 0.2);
  std::uniform_real_distribution<double> rpm(1.0, 600.0);
  for (ModelVariant model : {ModelVariant::M2731, ModelVariant::M2732}) {
    const Nanos period = traits(model).update_period;
    for (int trial = 0; trial < 40; ++trial) {
      Bench b(model);
      ASSERT_EQ(b.btw({0x8801, 0x1024, 0xC011, 0x0000, 0x0256, 0x0512}), error::kNone);
      const double theta0 = start(rng);
      const double tps = rpm(rng) / 60.0;
      b.shaft(1, signals::angle_at_constant_speed(theta0, tps));
      b.hold(2, 0, 360);
      const Nanos cross = Nanos::from_seconds((0.25 - theta0) / tps);
      b.run_until(cross + 2_ms);
      ASSERT_FALSE(b.edges(1).empty());
      const Nanos delay = b.edges(1)[0].time - cross;
      EXPECT_GE(delay, -1_ns) << traits(model).name << " trial " << trial;
      EXPECT_LT(delay, period) << traits(model).name << " trial " << trial;
    }
  }
}

TEST(Pls2700Throughput, WithinOneUpdateAtAnyPowerUpPhase) {
  // pls2700 manual (seeds/002_46e90574ec92805f.txt:455-457): "New Position Throughput Time
  // 200 uSec: 2731, 2731-04, 2741 Modules 400 uSec: 2732, 2732-04, 2742, 2742-18 Modules".
  // Whatever the power-up phase, the update locks to a reference peak, so the latency stays
  // below one update (an update sampling an earlier peak would add up to 100 us, 1/(2 f)).
  std::mt19937 rng(457);
  std::uniform_real_distribution<double> start(0.0, 0.2);
  std::uniform_real_distribution<double> rpm(1.0, 600.0);
  for (ModelVariant model : {ModelVariant::M2741, ModelVariant::M2742}) {
    const Nanos period = traits(model).update_period;
    std::uniform_int_distribution<std::int64_t> phase(0, period.count() - 1);
    for (int trial = 0; trial < 40; ++trial) {
      Params params;
      params.update_phase = Nanos{phase(rng)};
      Bench b(model, params);
      ASSERT_EQ(b.btw({0x8801, 0x4096, 0xC011, 0x0000, 0x1024, 0x2048}), error::kNone);
      const double theta0 = start(rng);
      const double tps = rpm(rng) / 60.0;
      b.shaft(1, signals::angle_at_constant_speed(theta0, tps));
      b.hold(2, 0, 360);
      const Nanos cross = Nanos::from_seconds((0.25 - theta0) / tps);
      b.run_until(cross + 2_ms);
      ASSERT_FALSE(b.edges(1).empty());
      const Nanos delay = b.edges(1)[0].time - cross;
      EXPECT_GE(delay, -1_ns) << traits(model).name << " phase " << params.update_phase.count();
      EXPECT_LT(delay, period) << traits(model).name << " phase " << params.update_phase.count();
    }
  }
}

TEST(Pls2700Throughput, TrapezoidMoveSwitchesAtThePositions) {
  // A rest-to-rest move over one turn (profile in turns) on a 2742 (400 us): output 1 on
  // 1024..2047 of SF 4096, i.e. a quarter to a half turn; exactly one on and one off edge,
  // each within one update after the profile crosses 0.25 and 0.5 turn.
  Bench b(ModelVariant::M2742);
  EXPECT_EQ(b.btw({0x8801, 0x4096, 0xC011, 0x0000, 0x1024, 0x2048}), error::kNone);
  signals::MotionProfile p(0.5 / 8192.0);
  signals::trapezoid_move(p, 1.0, {5.0, 50.0, 50.0});
  const signals::MotionProfile copy = p;
  b.profile(1, p);
  b.hold(2, 0, 360);
  b.run_until(p.end_time() + 10_ms);
  ASSERT_EQ(b.edges(1).size(), 2u);
  // Crossing times by bisection on the closed-form profile.
  const auto crossing = [&copy](double turns) {
    Nanos lo{0}, hi = copy.end_time();
    while (hi - lo > 1_ns) {
      const Nanos mid{(lo.count() + hi.count()) / 2};
      (copy.position(mid) < turns ? lo : hi) = mid;
    }
    return hi;
  };
  for (const auto& [edge, turns] : {std::pair{b.edges(1)[0], 0.25}, std::pair{b.edges(1)[1], 0.5}}) {
    const Nanos delay = edge.time - crossing(turns);
    EXPECT_GE(delay, -1_ns);
    EXPECT_LT(delay, 400_us);
  }
}

} // namespace
} // namespace hilrig::models::pls2700
