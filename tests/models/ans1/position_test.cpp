// Global Machine Position scaling, offset and preset (spec §4.1) with the manual's worked
// examples (docs/spec/ans1-examples.md W-01..W-11).
#include <gtest/gtest.h>

#include <random>

#include "models/ans1/position.hpp"
#include "models/ans1/quiet_interval.hpp"

namespace hilrig::models::ans1 {
namespace {

PositionSetup scaling(std::uint16_t cpc, std::uint16_t fsc) {
  PositionSetup s;
  s.counts_per_cycle = cpc;
  s.full_scale_count = fsc;
  return s;
}

TEST(Ans1Position, W01CircularOffset) {
  // Scaled position 10 with SMO -20 on FSC 360: (10 - 20) mod 360 = 350 (L780).
  EXPECT_EQ(global_position(10, -20, 360), 350);
}

TEST(Ans1Position, W02QuarterTurnOfDefaultScaling) {
  const PositionSetup s; // CPC 4096, FSC 360 by default
  EXPECT_EQ(s.counts_per_cycle, 4096);
  EXPECT_EQ(s.full_scale_count, 360);
  EXPECT_EQ(global_position(1024, s), 90); // 1024 * 360 / 4096
  EXPECT_EQ(global_position(0, s), 0);
  EXPECT_EQ(global_position(4095, s), 359);
}

struct RangeCase {
  const char* id;
  std::uint16_t cpc;
  std::uint16_t fsc;
};

class Ans1PositionRange : public ::testing::TestWithParam<RangeCase> {};

// Tables 2.1 and 2.2 (W-03..W-10): over one cycle of CPC counts GMP covers exactly
// 0..FSC-1, each value at least once, rising by 0 or 1 per count, then rolls back to 0.
TEST_P(Ans1PositionRange, CoversZeroToFscMinusOneOverOneCycle) {
  const RangeCase c = GetParam();
  const PositionSetup s = scaling(c.cpc, c.fsc);
  std::vector<int> seen(c.fsc, 0);
  int previous = -1;
  for (std::int64_t raw = 0; raw < c.cpc; ++raw) {
    const int g = global_position(raw, s);
    ASSERT_GE(g, 0);
    ASSERT_LT(g, c.fsc);
    if (previous >= 0) {
      ASSERT_TRUE(g == previous || g == previous + 1) << c.id << " raw " << raw;
    }
    ++seen[static_cast<std::size_t>(g)];
    previous = g;
  }
  EXPECT_EQ(global_position(std::int64_t{0}, s), 0);
  EXPECT_EQ(global_position(std::int64_t{c.cpc} - 1, s), c.fsc - 1) << c.id;
  EXPECT_EQ(global_position(std::int64_t{c.cpc}, s), 0) << c.id << ": the next count rolls over";
  for (int v = 0; v < c.fsc; ++v) {
    EXPECT_GT(seen[static_cast<std::size_t>(v)], 0) << c.id << " never shows " << v;
  }
}

INSTANTIATE_TEST_SUITE_P(ManualTables, Ans1PositionRange,
                         ::testing::Values(RangeCase{"W03", 4096, 360}, RangeCase{"W04", 3072, 2700},
                                           RangeCase{"W05", 2048, 360}, RangeCase{"W06", 1024, 90},
                                           RangeCase{"W07", 2000, 1440}, RangeCase{"W08", 1500, 810},
                                           RangeCase{"W09", 1000, 360}, RangeCase{"W10", 500, 90}));

TEST(Ans1Position, W05HalfTurnCycleRollsOverAtRaw2048) {
  const PositionSetup s = scaling(2048, 360);
  EXPECT_EQ(global_position(2047, s), 359);
  EXPECT_EQ(global_position(2048, s), 0);
  EXPECT_EQ(global_position(4095, s), 359); // second half-turn repeats the cycle
}

TEST(Ans1Position, W04ThreeQuarterTurnScale) {
  // 2700 counts over 3072 transducer counts (3/4 turn): raw 3071 -> 2699 (not "3699", A2).
  const PositionSetup s = scaling(3072, 2700);
  EXPECT_EQ(global_position(3071, s), 2699);
  EXPECT_EQ(global_position(1536, s), 1350); // half the cycle
}

TEST(Ans1Position, W11MaximumEncoderResolutionIs1024Lines) {
  // 4X decoding and CPC <= 4096 for one turn per cycle: 4096 / 4 = 1024 lines.
  constexpr int kMaxCpc = 4096;
  EXPECT_EQ(kMaxCpc / 4, 1024);
  const PositionSetup s = scaling(4096, 4096);
  EXPECT_EQ(global_position(4 * 1024 - 1, s), 4095);
}

TEST(Ans1Position, NegativeEncoderCountsWrapIntoTheCycle) {
  // An encoder turning backwards from power-up counts below zero; q = raw mod CPC >= 0.
  const PositionSetup s = scaling(2000, 1440);
  EXPECT_EQ(global_position(-1, s), 1439); // 1999 * 1440 / 2000 = 1439.28 -> 1439
  EXPECT_EQ(global_position(-2000, s), 0);
  EXPECT_EQ(global_position(-1000, s), 720);
}

TEST(Ans1Position, LargeCountsDoNotOverflow) {
  const PositionSetup s = scaling(4096, 360);
  const std::int64_t many_turns = std::int64_t{1} << 40;
  EXPECT_EQ(global_position(many_turns * 4096 + 1024, s), 90);
  EXPECT_EQ(global_position(-many_turns * 4096 + 1024, s), 90);
}

TEST(Ans1Position, PresetMakesGmpTheTargetForAnyScaledPosition) {
  // Property (seeded): after SMO = target - s, GMP == target and SMO is within +-(FSC-1).
  std::mt19937 rng(1234);
  for (int i = 0; i < 2000; ++i) {
    const auto fsc = static_cast<std::uint16_t>(1 + rng() % 4096);
    const auto s = static_cast<std::int32_t>(rng() % fsc);
    const auto target = static_cast<std::uint16_t>(rng() % fsc);
    const std::int32_t smo = preset_offset(target, s);
    EXPECT_LE(smo, fsc - 1);
    EXPECT_GE(smo, -(fsc - 1));
    EXPECT_EQ(global_position(s, smo, fsc), target);
  }
}

TEST(Ans1Position, LimitSwitchPositionAddsItsOffsetCircularly) {
  EXPECT_EQ(ls_position(350, 20, 360), 10);
  EXPECT_EQ(ls_position(10, -20, 360), 350);
  EXPECT_EQ(ls_position(100, 0, 360), 100);
}

TEST(Ans1Position, BitParametersRoundTrip) {
  for (std::uint16_t w = 0; w < 32; ++w) {
    PositionSetup s;
    set_bit_parameters(s, w);
    EXPECT_EQ(bit_parameters(s), w);
  }
  PositionSetup s;
  set_bit_parameters(s, 0x08);
  EXPECT_EQ(s.sensor, SensorType::Quadrature);
  set_bit_parameters(s, 0x04);
  EXPECT_TRUE(s.slave_mode);
  EXPECT_EQ(s.sensor, SensorType::Resolver);
}

// counts_inside (the quiet run's ends, schedule_count_leave) against the count-by-count walk it
// replaces, on random scalings (FSC up to CPC, and beyond it), offsets, intervals (narrow,
// wide, at either end of the FSC, some not holding the present GMP) and counts of either sign.
namespace quiet_run {

std::int64_t walked(std::int64_t count, std::int64_t step, const PositionSetup& setup,
                    const QuietInterval& quiet) {
  std::int64_t k = 0;
  while (k < setup.counts_per_cycle && quiet.contains(global_position(count + step * (k + 1), setup))) {
    ++k;
  }
  return k;
}

TEST(Ans1Position, CountsInsideIsTheCountByCountWalk) {
  std::mt19937_64 rng(20261127);
  const auto pick = [&](std::int64_t lo, std::int64_t hi) {
    return std::uniform_int_distribution<std::int64_t>(lo, hi)(rng);
  };
  int whole_cycles = 0;
  int stopped = 0;
  for (int i = 0; i < 20000; ++i) {
    PositionSetup s;
    s.counts_per_cycle = static_cast<std::uint16_t>(pick(0, 3) == 0 ? pick(2, 12) : pick(2, 4096));
    const std::int64_t fsc_max = pick(0, 9) == 0 ? 4 * std::int64_t{s.counts_per_cycle} : s.counts_per_cycle;
    s.full_scale_count = static_cast<std::uint16_t>(pick(1, std::min<std::int64_t>(fsc_max, 65535)));
    const std::int64_t fsc = s.full_scale_count;
    s.scaled_offset = static_cast<std::int32_t>(pick(-(fsc - 1), fsc - 1));
    const std::int64_t count =
        pick(-3 * std::int64_t{s.counts_per_cycle}, 3 * std::int64_t{s.counts_per_cycle});
    const std::uint16_t at = global_position(count, s);
    QuietInterval q = QuietInterval::around(at, s.full_scale_count);
    switch (pick(0, 4)) {
    case 0: // a narrowed run around the present GMP
      q.lo = static_cast<std::uint16_t>(pick(q.lo, at));
      q.hi = static_cast<std::uint16_t>(pick(at, q.hi));
      break;
    case 1: // pinned
      q.pin(at);
      break;
    case 2: // anywhere, maybe not holding the present GMP
      q.lo = static_cast<std::uint16_t>(pick(0, fsc - 1));
      q.hi = static_cast<std::uint16_t>(pick(q.lo, fsc - 1));
      break;
    case 3: // the whole FSC
      q.lo = 0;
      q.hi = static_cast<std::uint16_t>(fsc - 1);
      break;
    default: // around() as it is
      break;
    }
    for (const std::int64_t step : {std::int64_t{1}, std::int64_t{-1}}) {
      const std::int64_t want = walked(count, step, s, q);
      ASSERT_EQ(counts_inside(count, step, s, q), want)
          << "cpc " << s.counts_per_cycle << " fsc " << fsc << " smo " << s.scaled_offset << " count "
          << count << " step " << step << " quiet " << q.lo << ".." << q.hi;
      whole_cycles += want == s.counts_per_cycle ? 1 : 0;
      stopped += want < s.counts_per_cycle ? 1 : 0;
    }
  }
  // Both outcomes were exercised, many times.
  EXPECT_GT(whole_cycles, 1000);
  EXPECT_GT(stopped, 10000);
}

TEST(Ans1Position, CountsInsideOfAWorkedScaling) {
  // CPC 4096, FSC 360, SMO 0: count c has GMP floor(c * 360 / 4096). GMP 90 is counts
  // 1024..1035 (1036 * 360 / 4096 = 91.05), GMP 89 from 1013 (1013 * 360 / 4096 = 89.03).
  PositionSetup s;
  const QuietInterval q{89, 90};
  EXPECT_EQ(counts_inside(1024, 1, s, q), 1035 - 1024);
  EXPECT_EQ(counts_inside(1024, -1, s, q), 1024 - 1013);
  // With SMO -90 the same counts read GMP 0 and 359: 1024..1035 is GMP 0, 1013..1023 is 359.
  s.scaled_offset = -90;
  EXPECT_EQ(counts_inside(1024, 1, s, QuietInterval{0, 5}),
            1092 - 1024); // GMP 5 ends at 1092 (1093 * 360 / 4096 = 96.06)
  EXPECT_EQ(counts_inside(1024, -1, s, QuietInterval{0, 5}), 0); // 1023 reads 359
}

} // namespace quiet_run

} // namespace
} // namespace hilrig::models::ans1
