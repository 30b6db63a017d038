// Setpoint pairs, stitching and advanced edges (spec §4.4-§4.6), with expected states worked
// out by hand from the digest's formulas.
#include <gtest/gtest.h>

#include "models/ans1/setpoint.hpp"

namespace hilrig::models::ans1 {
namespace {

constexpr std::uint16_t kFsc = 360;

SetpointPair pair(std::uint16_t from, std::uint16_t to, std::uint16_t on = 0, std::uint16_t off = 0) {
  return SetpointPair{from, to, on, off};
}

TEST(Ans1Setpoint, EqualityAtSetpointsOnAtFromOffAtTo) {
  const SetpointPair p = pair(10, 20);
  EXPECT_FALSE(in_pair(9, p, kFsc));
  EXPECT_TRUE(in_pair(10, p, kFsc)); // p == From: on
  EXPECT_TRUE(in_pair(19, p, kFsc));
  EXPECT_FALSE(in_pair(20, p, kFsc)); // p == To: off
}

TEST(Ans1Setpoint, PairWrapsThroughZero) {
  const SetpointPair p = pair(350, 10); // From > To: "inverted" pair (L1906)
  EXPECT_FALSE(in_pair(349, p, kFsc));
  EXPECT_TRUE(in_pair(350, p, kFsc));
  EXPECT_TRUE(in_pair(359, p, kFsc));
  EXPECT_TRUE(in_pair(0, p, kFsc));
  EXPECT_TRUE(in_pair(9, p, kFsc));
  EXPECT_FALSE(in_pair(10, p, kFsc));
  EXPECT_FALSE(in_pair(180, p, kFsc));
}

TEST(Ans1Setpoint, EqualNonZeroIsAlwaysOnAndZeroZeroIsUnused) {
  for (std::uint16_t p = 0; p < kFsc; ++p) {
    EXPECT_TRUE(in_pair(p, pair(45, 45), kFsc)) << p; // L1897
    EXPECT_FALSE(in_pair(p, pair(0, 0), kFsc)) << p;
  }
  EXPECT_EQ(pair_length(pair(45, 45), kFsc), 360);
  EXPECT_EQ(pair_length(pair(0, 0), kFsc), 0);
}

TEST(Ans1Setpoint, PairStartingAtZero) {
  EXPECT_TRUE(in_pair(0, pair(0, 10), kFsc));
  EXPECT_TRUE(in_pair(9, pair(0, 10), kFsc));
  EXPECT_FALSE(in_pair(359, pair(0, 10), kFsc));
}

TEST(Ans1Setpoint, ReversalSeesTheSameStatesBackwards) {
  // A plain pair depends only on position: sweeping down gives the mirror of sweeping up.
  const SetpointPair p = pair(300, 40);
  std::vector<bool> up;
  for (int x = 0; x < kFsc; ++x) {
    up.push_back(in_pair(static_cast<std::uint16_t>(x), p, kFsc));
  }
  for (int x = kFsc - 1; x >= 0; --x) {
    EXPECT_EQ(in_pair(static_cast<std::uint16_t>(x), p, kFsc), up[static_cast<std::size_t>(x)]);
  }
}

TEST(Ans1Setpoint, StitchDesignFormulaGivesNOns) {
  // On 2, Off 1, three Ons: L = 2*3 + 1*2 = 8 (L866), so To = From + 8.
  const SetpointPair p = pair(100, 108, 2, 1);
  const bool expected[] = {true, true, false, true, true, false, true, true};
  for (int d = 0; d < 8; ++d) {
    EXPECT_EQ(pair_on(static_cast<std::uint16_t>(100 + d), p, kFsc, {}), expected[d]) << d;
  }
  EXPECT_FALSE(pair_on(108, p, kFsc, {}));
  EXPECT_FALSE(pair_on(99, p, kFsc, {}));
}

TEST(Ans1Setpoint, StitchRemainderRules) {
  // On 4, Off 2 (period 6).
  // L = 13: two periods and r = 1 < On/2 -> off to the end (L873).
  EXPECT_FALSE(stitch_on(12, 13, 4, 2));
  // L = 14: r = 2 >= On/2 -> on to the end (L872).
  EXPECT_TRUE(stitch_on(12, 14, 4, 2));
  EXPECT_TRUE(stitch_on(13, 14, 4, 2));
  // L = 17: r = 5 >= On: a full On (12..15) then Off (16).
  EXPECT_TRUE(stitch_on(15, 17, 4, 2));
  EXPECT_FALSE(stitch_on(16, 17, 4, 2));
}

TEST(Ans1Setpoint, StitchMustFitTwoOnsAndOneOff) {
  EXPECT_TRUE(stitch_fits(pair(10, 15, 2, 1), kFsc));  // L = 5 = 2*2 + 1
  EXPECT_FALSE(stitch_fits(pair(10, 14, 2, 1), kFsc)); // L = 4
  EXPECT_TRUE(stitch_fits(pair(10, 14, 2, 0), kFsc));  // no stitch
}

TEST(Ans1Setpoint, StitchedPairWrapsThroughZero) {
  // From 358, On 2 Off 1, L 8 -> To 6: on 358, 359, off 0, on 1, 2, off 3, on 4, 5.
  const SetpointPair p = pair(358, 6, 2, 1);
  EXPECT_TRUE(pair_on(359, p, kFsc, {}));
  EXPECT_FALSE(pair_on(0, p, kFsc, {}));
  EXPECT_TRUE(pair_on(1, p, kFsc, {}));
  EXPECT_TRUE(pair_on(5, p, kFsc, {}));
  EXPECT_FALSE(pair_on(6, p, kFsc, {}));
}

TEST(Ans1Setpoint, LeadAdvanceMovesFromEdgeEarlier) {
  const SetpointPair p = pair(100, 200);
  const EdgeShift lead6{6, 0};
  EXPECT_FALSE(pair_on(93, p, kFsc, lead6));
  EXPECT_TRUE(pair_on(94, p, kFsc, lead6)); // 100 - 6
  EXPECT_TRUE(pair_on(199, p, kFsc, lead6));
  EXPECT_FALSE(pair_on(200, p, kFsc, lead6)); // To not moved
}

TEST(Ans1Setpoint, TrailAdvanceMovesToEdgeEarlier) {
  const SetpointPair p = pair(100, 200);
  const EdgeShift trail6{0, 6};
  EXPECT_FALSE(pair_on(99, p, kFsc, trail6));
  EXPECT_TRUE(pair_on(100, p, kFsc, trail6));
  EXPECT_TRUE(pair_on(193, p, kFsc, trail6));
  EXPECT_FALSE(pair_on(194, p, kFsc, trail6)); // 200 - 6
}

TEST(Ans1Setpoint, AdvanceAcrossZero) {
  // From 3 with a lead of 6 fires at 357; To 20 with trail 6 at 14.
  const SetpointPair p = pair(3, 20);
  const EdgeShift both{6, 6};
  EXPECT_FALSE(pair_on(356, p, kFsc, both));
  EXPECT_TRUE(pair_on(357, p, kFsc, both));
  EXPECT_TRUE(pair_on(0, p, kFsc, both));
  EXPECT_TRUE(pair_on(13, p, kFsc, both));
  EXPECT_FALSE(pair_on(14, p, kFsc, both));
}

TEST(Ans1Setpoint, ReverseTravelMovesEdgesTheOtherWay) {
  // Turning backwards the shifts are negative: edges move to higher positions.
  const SetpointPair p = pair(100, 200);
  const EdgeShift reverse{-6, -6};
  EXPECT_FALSE(pair_on(105, p, kFsc, reverse));
  EXPECT_TRUE(pair_on(106, p, kFsc, reverse));
  EXPECT_TRUE(pair_on(205, p, kFsc, reverse));
  EXPECT_FALSE(pair_on(206, p, kFsc, reverse));
}

TEST(Ans1Setpoint, TrailAdvancedToLeadTurnsThePairOff) {
  // Length 100: trail - lead >= 100 leaves nothing (L890).
  const SetpointPair p = pair(100, 200);
  for (std::uint16_t x = 0; x < kFsc; ++x) {
    EXPECT_FALSE(pair_on(x, p, kFsc, {0, 100})) << x;
    EXPECT_FALSE(pair_on(x, p, kFsc, {10, 150})) << x;
  }
  // One count left: only position 100.
  EXPECT_TRUE(pair_on(100, p, kFsc, {0, 99}));
  EXPECT_FALSE(pair_on(101, p, kFsc, {0, 99}));
}

TEST(Ans1Setpoint, AdvanceLongerThanTheGapCoversTheWholeCycle) {
  // Length 100 + lead 300 >= 360: on everywhere.
  const SetpointPair p = pair(100, 200);
  for (std::uint16_t x = 0; x < kFsc; ++x) {
    EXPECT_TRUE(pair_on(x, p, kFsc, {300, 0})) << x;
  }
}

TEST(Ans1Setpoint, LateWrapFaultKeepsToOnOnlyForWrappingPairs) {
  EXPECT_FALSE(pair_on(10, pair(350, 10), kFsc, {}, false));
  EXPECT_TRUE(pair_on(10, pair(350, 10), kFsc, {}, true));
  EXPECT_FALSE(pair_on(20, pair(10, 20), kFsc, {}, true)); // no wrap: unchanged
}

TEST(Ans1Setpoint, OverlapDetection) {
  using Pairs = std::array<SetpointPair, kPairsPerOutput>;
  EXPECT_FALSE(pairs_overlap(Pairs{pair(10, 20), pair(20, 30)}, kFsc)); // sharing an end is fine
  EXPECT_TRUE(pairs_overlap(Pairs{pair(10, 21), pair(20, 30)}, kFsc));
  EXPECT_TRUE(pairs_overlap(Pairs{pair(350, 10), pair(5, 20)}, kFsc));
  EXPECT_TRUE(pairs_overlap(Pairs{pair(45, 45), pair(100, 101)}, kFsc));
  EXPECT_FALSE(pairs_overlap(Pairs{pair(45, 45)}, kFsc));
  EXPECT_FALSE(pairs_overlap(Pairs{pair(350, 10), pair(10, 20), pair(20, 350)}, kFsc));
}

// Exact scan skipping keeps a stitched pair's GMP inside stitch_run (docs/virtual-time.md, part
// 4): every distance in the run has the pattern's value at d, and the distances just outside it
// either have the other value or lie across d = 0 or the run is the whole cycle. Every d of
// every fitting pattern (L866-L873) up to a short cycle, and the remainder cases of
// StitchRemainderRules.
TEST(Ans1Setpoint, StitchRunIsTheStretchOfOneValueAroundD) {
  const auto value = [](std::int32_t d, std::int32_t length, std::int32_t on, std::int32_t off) {
    return d < length && stitch_on(d, length, on, off);
  };
  int patterns = 0;
  for (const std::int32_t fsc : {24, 37}) {
    for (std::int32_t on = 1; on <= 6; ++on) {
      for (std::int32_t off = 1; off <= 6; ++off) {
        for (std::int32_t length = 2 * on + off; length <= fsc; ++length) {
          ++patterns;
          for (std::int32_t d = 0; d < fsc; ++d) {
            const StitchRun run = stitch_run(d, length, on, off, fsc);
            ASSERT_LE(0, run.first);
            ASSERT_LE(run.first, d);
            ASSERT_LE(d, run.last);
            ASSERT_LT(run.last, fsc);
            for (std::int32_t e = run.first; e <= run.last; ++e) {
              ASSERT_EQ(value(e, length, on, off), value(d, length, on, off))
                  << "fsc " << fsc << " on " << on << " off " << off << " length " << length << " d " << d
                  << " e " << e;
            }
          }
        }
      }
    }
  }
  EXPECT_GT(patterns, 1000);
  // On 4 Off 2, L 17: On 12..15 then Off 16, then off to the end of the cycle.
  EXPECT_EQ(stitch_run(13, 17, 4, 2, kFsc).first, 12);
  EXPECT_EQ(stitch_run(13, 17, 4, 2, kFsc).last, 15);
  EXPECT_EQ(stitch_run(16, 17, 4, 2, kFsc).last, 16);
  EXPECT_EQ(stitch_run(200, 17, 4, 2, kFsc).first, 17);
  EXPECT_EQ(stitch_run(200, 17, 4, 2, kFsc).last, kFsc - 1);
  // L 14: r = 2 >= On/2, on from 12 to the end (L872); an Off of the whole part before it.
  EXPECT_EQ(stitch_run(13, 14, 4, 2, kFsc).first, 12);
  EXPECT_EQ(stitch_run(13, 14, 4, 2, kFsc).last, 13);
  EXPECT_EQ(stitch_run(11, 14, 4, 2, kFsc).first, 10);
  EXPECT_EQ(stitch_run(11, 14, 4, 2, kFsc).last, 11);
}

} // namespace
} // namespace hilrig::models::ans1
