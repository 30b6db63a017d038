// Advances in time and in counts (spec §4.6), with the manual's W-13 numbers.
#include <gtest/gtest.h>

#include "models/ans1/advance.hpp"

namespace hilrig::models::ans1 {
namespace {

OutputSetup fixed(std::uint16_t lead, std::uint16_t trail) {
  OutputSetup s;
  s.advance_mode = AdvanceMode::Fixed;
  s.lead_ms = lead;
  s.trail_ms = trail;
  return s;
}

TEST(Ans1Advance, W13LeadAdvanceCountsAt100And150Rpm) {
  // 10 ms at 100 RPM on FSC 360 = 10 ms x 600 counts/s = 6; at 150 RPM, 900 counts/s -> 9.
  EXPECT_EQ(advance_counts(fixed(10, 0), 100.0, 360).lead, 6);
  EXPECT_EQ(advance_counts(fixed(10, 0), 150.0, 360).lead, 9);
}

TEST(Ans1Advance, TrailAdvanceUsesItsOwnTime) {
  // 20 ms at 100 RPM: 12 counts; lead 0.
  const AdvanceCounts a = advance_counts(fixed(0, 20), 100.0, 360);
  EXPECT_EQ(a.lead, 0);
  EXPECT_EQ(a.trail, 12);
  EXPECT_FALSE(a.clamped);
}

TEST(Ans1Advance, ReverseSpeedGivesTheSameMagnitude) {
  EXPECT_EQ(advance_counts(fixed(10, 0), -100.0, 360).lead, 6);
}

TEST(Ans1Advance, VariableAdvanceTakenLiterally) {
  // Fixed 10 ms, VAT 1000 us/RPM at 100 RPM: lead = 10 + (100/2) * 1 = 60 ms -> 36 counts;
  // trail = Fixed = 10 ms -> 6 counts (L917).
  OutputSetup s;
  s.advance_mode = AdvanceMode::Variable;
  s.lead_ms = 10;
  s.variable_us_per_rpm = 1000;
  const AdvanceTimes t = advance_times(s, 100.0);
  EXPECT_DOUBLE_EQ(t.lead_ms, 60.0);
  EXPECT_DOUBLE_EQ(t.trail_ms, 10.0);
  const AdvanceCounts a = advance_counts(s, 100.0, 360);
  EXPECT_EQ(a.lead, 36);
  EXPECT_EQ(a.trail, 6);
}

TEST(Ans1Advance, LongerThanOneCycleIsClamped) {
  // 700 ms at 100 RPM: 70000 ms*RPM > 60000 -> RPM Clamped, held at FSC - 1 (L2313).
  const AdvanceCounts a = advance_counts(fixed(700, 0), 100.0, 360);
  EXPECT_TRUE(a.clamped);
  EXPECT_EQ(a.lead, 359);
  // 500 ms at 100 RPM: 300 counts, not clamped.
  const AdvanceCounts b = advance_counts(fixed(500, 0), 100.0, 360);
  EXPECT_FALSE(b.clamped);
  EXPECT_EQ(b.lead, 300);
  // The largest programmable time at a high speed.
  EXPECT_TRUE(advance_counts(fixed(32767, 32767), 32767.0, 360).clamped);
}

TEST(Ans1Advance, ExactlyOneCycleIsShownWholeAndNotClamped) {
  // RPM Clamped only when an advance exceeds one machine cycle (L2313); DA19 w9/w10 show the
  // counts the edge is advanced (L2621, L2622). At 100 RPM a cycle takes 600 ms = 360 counts.
  for (const double speed : {100.0, -100.0}) {
    const AdvanceCounts at = advance_counts(fixed(600, 600), speed, 360);
    EXPECT_FALSE(at.clamped) << speed;
    EXPECT_EQ(at.lead, 360) << speed;
    EXPECT_EQ(at.trail, 360) << speed;
    const AdvanceCounts inside = advance_counts(fixed(599, 599), speed, 360); // 359.4
    EXPECT_FALSE(inside.clamped) << speed;
    EXPECT_EQ(inside.lead, 359) << speed;
    EXPECT_EQ(inside.trail, 359) << speed;
    const AdvanceCounts beyond = advance_counts(fixed(601, 0), speed, 360); // held at FSC - 1
    EXPECT_TRUE(beyond.clamped) << speed;
    EXPECT_EQ(beyond.lead, 359) << speed;
    EXPECT_TRUE(advance_counts(fixed(0, 601), speed, 360).clamped) << speed;
  }
}

TEST(Ans1Advance, RoundsToTheNearestCount) {
  // 10 ms at 125 RPM on FSC 360: 7.5 counts -> 8; at 124 RPM, 7.44 -> 7.
  EXPECT_EQ(advance_counts(fixed(10, 0), 125.0, 360).lead, 8);
  EXPECT_EQ(advance_counts(fixed(10, 0), 124.0, 360).lead, 7);
}

TEST(Ans1Advance, NoModeNoAdvance) {
  OutputSetup s;
  s.lead_ms = 100;
  EXPECT_EQ(advance_counts(s, 100.0, 360).lead, 0);
}

TEST(Ans1Advance, DegreesPer100RpmConversion) {
  // 6 degrees at 100 RPM (600 deg/s) is 10 ms (L900).
  EXPECT_DOUBLE_EQ(advance_ms_from_degrees_per_100rpm(6.0), 10.0);
}

TEST(Ans1Advance, WrongScaleVariantDoubles) {
  EXPECT_EQ(advance_counts(fixed(10, 0), 100.0, 360, 2.0).lead, 12);
}

} // namespace
} // namespace hilrig::models::ans1
