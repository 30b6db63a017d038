// When the assembled-move rules are judged. Blend and Dwell Moves "are programmed in exactly
// the same way. When you start the move, a bit in the command data determines which type of
// Assembled Move is run" (L1179, L2762, LSW bit 9 L2472). So a rule of one type only is judged
// at Run: "The Programmed Speed must also be different from the speed of the previous
// segment" is a restriction "when programming Blend Moves" (L1113, L1118); the Dwell Move
// (L1148-L1162) has none, and its segments reverse by their sign (L1152). A refused Run is a
// Command Error without Move Complete (L2831, L2860: Move Complete "is not set on a command
// error for any other type of command" than Jog and Registration).
// Numbers: v_s = 100 steps/s, A = D = 10 steps/ms/s; 1000 steps at 1100 steps/s take 1.0 s
// (moves_test: 60 + 880 + 60 steps, 0.1 + 0.8 + 0.1 s).
#include "tests/models/smd23e/smd23e_fixture.hpp"

namespace hilrig::models::smd23e::test {
namespace {

class Smd23eAssembledRules : public Smd23eBench {
protected:
  // One programming cycle (L1191-L1201); true when no segment set Command Error (L1196).
  bool program(const std::vector<MoveWords>& segments) {
    command(msw::kProgramMove);
    for (const MoveWords& m : segments) {
      write(msw::kProgramMove | msw::kProgramSegment, kDrive, m);
      write(msw::kProgramMove, kDrive, m);
    }
    write(0);
    return !bit1(sw1::kCommandError);
  }
  void run_blend() { command(msw::kRunAssembled); }
  void run_dwell(std::uint16_t dwell_ms) {
    command(msw::kRunAssembled, kDrive | lsw::kDwellType, MoveWords{.word9 = dwell_ms});
  }
};

TEST_F(Smd23eAssembledRules, DwellSegmentsOfEqualSpeedGoOutAndBack) {
  configure();
  ASSERT_TRUE(program({{.value = 1000, .vp = 1100}, {.value = -1000, .vp = 1100}}));
  run_dwell(50);
  run_to(1'025_ms); // segment 1 ended at 1.0 s: stopped out at +1000, dwelling
  EXPECT_EQ(position_word(), 1000);
  EXPECT_TRUE(bit1(sw1::kStopped));
  EXPECT_FALSE(bit1(sw1::kMoveComplete));
  run_to(1'100_ms); // segment 2 set off at 1.05 s, counter-clockwise (L1152)
  EXPECT_TRUE(bit1(sw1::kMovingCcw));
  run_to(2'049'999_us);
  EXPECT_FALSE(bit1(sw1::kMoveComplete));
  run_to(2'050'001_us);
  EXPECT_TRUE(bit1(sw1::kMoveComplete));
  EXPECT_FALSE(bit1(sw1::kCommandError));
  EXPECT_EQ(position_word(), 0); // net 0
}

TEST_F(Smd23eAssembledRules, TheSameSegmentsRunAsADwellAndAreRefusedAsABlend) {
  configure();
  ASSERT_TRUE(program({{.value = 1000, .vp = 1100}, {.value = 1000, .vp = 1100}}));
  run_dwell(0);
  run_to(3_s);
  ASSERT_TRUE(bit1(sw1::kMoveComplete));
  ASSERT_EQ(position_word(), 2000);
  run_blend();
  EXPECT_TRUE(bit1(sw1::kCommandError));
  EXPECT_FALSE(bit1(sw1::kMoveComplete)); // reset by the command written, not set again
  run_to(6_s);
  EXPECT_EQ(position_word(), 2000); // no motion
  EXPECT_FALSE(bit1(sw1::kMoveComplete));
}

// Each case: the second segment's v_p against the first's 1100 (L1118's "previous segment").
struct SecondSpeed {
  const char* name;
  std::int32_t vp;
  bool blend_runs;
};

class Smd23eBlendSpeedNeighbours : public Smd23eAssembledRules,
                                   public ::testing::WithParamInterface<SecondSpeed> {};

TEST_P(Smd23eBlendSpeedNeighbours, OnlyAnEqualSpeedIsRefusedAtRun) {
  configure();
  EXPECT_TRUE(program({{.value = 1000, .vp = 1100}, {.value = 1000, .vp = GetParam().vp}}));
  run_blend();
  run_to(5_s);
  EXPECT_EQ(bit1(sw1::kCommandError), !GetParam().blend_runs);
  EXPECT_EQ(bit1(sw1::kMoveComplete), GetParam().blend_runs);
  EXPECT_EQ(position_word(), GetParam().blend_runs ? 2000 : 0); // only |offset| counts (L1117)
}

INSTANTIATE_TEST_SUITE_P(Cases, Smd23eBlendSpeedNeighbours,
                         ::testing::Values(SecondSpeed{"OneBelow", 1099, true},
                                           SecondSpeed{"Equal", 1100, false},
                                           SecondSpeed{"OneAbove", 1101, true}),
                         [](const ::testing::TestParamInfo<SecondSpeed>& i) {
                           return std::string(i.param.name);
                         });

TEST_F(Smd23eAssembledRules, AnEqualSpeedTwoSegmentsBackIsNoPreviousSegment) {
  configure();
  ASSERT_TRUE(
      program({{.value = 1000, .vp = 1100}, {.value = 1000, .vp = 2100}, {.value = 1000, .vp = 1100}}));
  run_blend();
  run_to(5_s);
  EXPECT_FALSE(bit1(sw1::kCommandError));
  EXPECT_TRUE(bit1(sw1::kMoveComplete));
  EXPECT_EQ(position_word(), 3000);
}

// "All of the segments in a Blend or Dwell Move must be written to the SMD23E before the move
// can be run" (L1179, L1115); a refused segment (L1196) was not: [MODEL] the cycle leaves no
// move, and Run is a Command Error of either type. v_p must be at least v_s (L1118, L2791).
struct MiddleSpeed {
  const char* name;
  std::int32_t vp;
  bool accepted;
};

class Smd23eRefusedSegment : public Smd23eAssembledRules,
                             public ::testing::WithParamInterface<MiddleSpeed> {};

TEST_P(Smd23eRefusedSegment, LeavesNoMoveToRun) {
  configure();
  const bool clean = program(
      {{.value = 1000, .vp = 1100}, {.value = 1000, .vp = GetParam().vp}, {.value = 1000, .vp = 2100}});
  EXPECT_EQ(clean, GetParam().accepted);
  command(msw::kResetErrors);
  run_blend();
  run_to(20_s); // the middle segment at v_s = 100 steps/s takes 10 s
  EXPECT_EQ(bit1(sw1::kCommandError), !GetParam().accepted);
  EXPECT_EQ(position_word(), GetParam().accepted ? 3000 : 0);
  command(msw::kResetErrors);
  run_dwell(0);
  run_to(40_s);
  EXPECT_EQ(bit1(sw1::kCommandError), !GetParam().accepted);
  EXPECT_EQ(bit1(sw1::kMoveComplete), GetParam().accepted);
  EXPECT_EQ(position_word(), GetParam().accepted ? 6000 : 0);
}

INSTANTIATE_TEST_SUITE_P(Cases, Smd23eRefusedSegment,
                         ::testing::Values(MiddleSpeed{"BelowStartingSpeed", 99, false},
                                           MiddleSpeed{"AtStartingSpeed", 100, true}),
                         [](const ::testing::TestParamInfo<MiddleSpeed>& i) {
                           return std::string(i.param.name);
                         });

TEST_F(Smd23eAssembledRules, ANewCycleAfterARefusedOneRuns) {
  configure();
  ASSERT_FALSE(program({{.value = 1000, .vp = 1100}, {.value = 1000, .vp = 99}}));
  command(msw::kResetErrors);
  ASSERT_TRUE(program({{.value = 1000, .vp = 1100}}));
  run_blend();
  run_to(2_s);
  EXPECT_TRUE(bit1(sw1::kMoveComplete));
  EXPECT_EQ(position_word(), 1000);
}

// Sixteen segments is the most (L1199, L2800): sixteen run, a seventeenth refuses the cycle.
TEST_F(Smd23eAssembledRules, SixteenSegmentsRunASeventeenthLeavesNoMove) {
  for (const int count : {16, 17}) {
    configure();
    preset(0);
    std::vector<MoveWords> segments;
    for (int i = 0; i < count; ++i) {
      segments.push_back({.value = 1000, .vp = 1100 + 100 * i});
    }
    EXPECT_EQ(program(segments), count == 16) << count;
    command(msw::kResetErrors);
    run_blend();
    run_to(sched.now() + 20_s);
    EXPECT_EQ(position_word(), count == 16 ? 16'000 : 0) << count;
    EXPECT_EQ(bit1(sw1::kCommandError), count == 17) << count;
  }
}

} // namespace
} // namespace hilrig::models::smd23e::test
