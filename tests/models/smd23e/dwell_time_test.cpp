// A Dwell Move's dwell time is the one sent with the Run Assembled Move command (L1179: "For
// Dwell Moves, the Dwell Time is sent to the SMD23E as part of the command"; word 9, L2436,
// L2736). Commands act on the 0→1 edge of their bit (L2403–2405), and only a Jog takes new
// values on the fly (L1026): word 9 rewritten, zeroed or kept while the move runs changes no
// gap.
//
// Numbers: v_s = 1000 steps/s, A = D = 100 steps/ms/s (100,000 steps/s², L848–851).
// Segments: +1000 at v_p = 10,000: ramps of 495 steps and 90 ms each way, cruise 10 steps
// (1 ms): 181 ms. −500 at v_p = 5000: ramps of (5000² − 1000²)/200,000 = 120 steps and 40 ms,
// cruise 260 steps (52 ms): 132 ms. +1000 again: 181 ms. Started at 0 with a 300 ms dwell,
// the segments end at 181, 181 + 300 + 132 = 613 and 613 + 300 + 181 = 1094 ms, at 1500.
#include "tests/models/smd23e/smd23e_fixture.hpp"

namespace hilrig::models::smd23e::test {
namespace {

class Smd23eDwellTime : public Smd23eBench {
protected:
  void SetUp() override {
    configure(ConfigWords{.vs = 1000});
    command(msw::kProgramMove);
    segment(1000, 10'000);
    segment(-500, 5000);
    segment(1000, 10'000);
    write(0);
  }
  void segment(std::int32_t offset, std::int32_t vp) {
    write(msw::kProgramMove | msw::kProgramSegment, kDrive,
          MoveWords{.value = offset, .vp = vp, .accel = 100, .decel = 100});
    write(msw::kProgramMove);
  }
  void run_dwell(std::uint16_t dwell_ms) {
    command(msw::kRunAssembled, kDrive | lsw::kDwellType, MoveWords{.word9 = dwell_ms});
  }
  // Move Complete comes with the last segment's last step, at t_s (±1 µs).
  void expect_complete_at(double t_s) {
    run_to(Nanos::from_seconds(t_s - 1e-6));
    EXPECT_FALSE(bit1(sw1::kMoveComplete));
    EXPECT_EQ(position_word(), 1499);
    run_to(Nanos::from_seconds(t_s + 1e-6));
    EXPECT_TRUE(bit1(sw1::kMoveComplete));
    EXPECT_EQ(position_word(), 1500);
  }
};

// What the host writes at 100 ms, during the first segment.
struct Rewrite {
  const char* name;
  std::uint16_t msw;
  std::uint16_t lsw;
  std::uint16_t word9;
};

class Smd23eDwellTimeRewrites : public Smd23eDwellTime, public ::testing::WithParamInterface<Rewrite> {};

TEST_P(Smd23eDwellTimeRewrites, KeepTheCommandsDwell) {
  const Rewrite w = GetParam();
  run_dwell(300);
  run_to(100_ms);
  dut.write_outputs(Words{w.msw, w.lsw, 0, 0, 0, 0, 0, 0, 0, w.word9});
  // The first gap is the whole 300 ms: no step between 181 and 481 ms.
  run_to(480_ms);
  EXPECT_EQ(position_word(), 1000);
  EXPECT_TRUE(bit1(sw1::kStopped));
  expect_complete_at(1.094);
}

INSTANTIATE_TEST_SUITE_P(
    Cases, Smd23eDwellTimeRewrites,
    ::testing::Values(Rewrite{"MswKeptWord9Kept", msw::kRunAssembled, kDrive | lsw::kDwellType, 300},
                      Rewrite{"MswKeptWord9Rewritten", msw::kRunAssembled, kDrive | lsw::kDwellType, 50},
                      Rewrite{"MswKeptWord9Zeroed", msw::kRunAssembled, kDrive | lsw::kDwellType, 0},
                      Rewrite{"MswClearedWordsZeroed", 0, kDrive, 0},
                      Rewrite{"MswClearedWord9Longer", 0, kDrive, 1000}),
    [](const ::testing::TestParamInfo<Rewrite>& i) { return std::string(i.param.name); });

// Word 9 rewritten during the first gap leaves that gap and the next at 300 ms.
TEST_F(Smd23eDwellTime, Word9RewrittenDuringAGapChangesNeitherGap) {
  run_dwell(300);
  run_to(300_ms);
  write(0, kDrive, MoveWords{.word9 = 50});
  expect_complete_at(1.094);
}

// A dwell of 0 in the command runs the segments back to back (ends 181, 313, 494 ms), even
// with word 9 written to 300 afterwards.
TEST_F(Smd23eDwellTime, AZeroDwellInTheCommandStaysZero) {
  run_dwell(0);
  run_to(100_ms);
  write(0, kDrive, MoveWords{.word9 = 300});
  expect_complete_at(0.494);
}

// A configuration written in the first pause (181 .. 481 ms) ends the move there: it erases
// the assembled move it runs (L1132) and invalidates the position (L2846); no later segment
// runs and Move Complete never comes.
TEST_F(Smd23eDwellTime, AConfigurationWrittenInAPauseEndsTheMove) {
  run_dwell(300);
  run_to(350_ms);
  ASSERT_EQ(position_word(), 1000);
  dut.write_outputs(config_block(ConfigWords{.vs = 1000}));
  dut.write_outputs(Words{0, kDrive, 0, 0, 0, 0, 0, 0, 0, 0});
  run_to(3_s);
  EXPECT_EQ(dut.step_position(sched.now()), 1000);
  EXPECT_TRUE(bit1(sw1::kPositionInvalid));
  EXPECT_FALSE(bit1(sw1::kMoveComplete));
}

} // namespace
} // namespace hilrig::models::smd23e::test
