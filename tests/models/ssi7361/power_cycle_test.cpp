// A power cycle of the 7361 (digest §5): parameters live in non-volatile EEPROM and survive
// power loss (seeds/004_2d8564fc60a2b9d4.txt:1304-1306), the preset's offset is stored there
// too (L1311-1313), and cycling power clears the module's errors (L254-256, L921-923). With
// no transducer the module reads every bit as 1 (L2173-2180): block A of the examples (M-02:
// N 10, scalars 1000/1024) reads 1023 * 1000 / 1024 = 999 (M-04); applying the preset
// 125,420 (M-05) makes the Data Value 125,420; the factory defaults would read 16,777,215.
// [MODEL] choices the manual leaves open: while off the clock stops at idle high, no frame is
// read and every status word reads 0; E2Err survives (the corrupted parameter is still in
// EEPROM); the first frame after power-up starts first_frame after the supply is back.

#include <gtest/gtest.h>

#include <vector>

#include "ssi7361_rig.hpp"

namespace hilrig::models::ssi7361::test {
namespace {

const Aq kAqA{format_word(1, 10), 1000, 1024, 125'420, 500};

Params first_frame_at(Nanos t) {
  Params p;
  p.first_frame = t;
  return p;
}

TEST(Ssi7361PowerCycle, TheSetupAndThePresetOffsetSurvive) {
  Rig rig(first_frame_at(100_us));
  rig.run_for(2_ms);
  ASSERT_EQ(rig.program(kBlockA, kAqA) & ibit::kParameterErrors, 0);
  rig.run_for(1_ms);
  ASSERT_EQ(rig.dv(), 999);
  ASSERT_EQ(rig.program(qbit::kApplyPreset) & ibit::kCommandError, 0);
  rig.run_for(1_ms);
  ASSERT_EQ(rig.dv(), 125'420);
  const std::uint64_t writes = rig.module().eeprom_writes();

  rig.module().power_off();
  rig.run_for(5_ms);
  rig.module().power_on();
  rig.run_for(1_ms);
  EXPECT_EQ(rig.dv(), 125'420);
  EXPECT_EQ(rig.module().setup().rut_ms, 500);
  EXPECT_EQ(rig.module().eeprom_writes(), writes); // power-up reads the EEPROM, writes nothing
}

TEST(Ssi7361PowerCycle, ErrorsAreClearedButACorruptedEepromStaysCorrupted) {
  Rig rig(first_frame_at(100_us));
  rig.run_for(2_ms);
  EXPECT_EQ(rig.program(0) & ibit::kCommandError, ibit::kCommandError); // no command bit (L2031)
  rig.module().power_off();
  rig.run_for(1_ms);
  rig.module().power_on();
  rig.run_for(1_ms);
  EXPECT_EQ(rig.status_bits(), 0); // CMDErr gone, no ACK

  rig.module().corrupt_eeprom();
  EXPECT_EQ(rig.program(0) & (ibit::kCommandError | ibit::kEepromError),
            ibit::kCommandError | ibit::kEepromError); // programming during E2Err (L2029)
  rig.module().power_off();
  rig.run_for(1_ms);
  rig.module().power_on();
  rig.run_for(1_ms);
  EXPECT_EQ(rig.status_bits(), ibit::kEepromError);
  // E2CLR is still the remedy (L253-255): factory defaults, E2Err cleared.
  EXPECT_EQ(rig.program(qbit::kE2Clear) & ibit::kEepromError, 0);
}

TEST(Ssi7361PowerCycle, NoFramesWhileOffAndTheFirstOneFirstFrameAfterPowerUp) {
  Rig rig(first_frame_at(100_us));
  std::vector<Nanos> falls;
  rig.clock_line().reader().on_edge([&](const Edge& e) {
    if (e.level == Level::Low) falls.push_back(e.time);
  });
  rig.run_until(10'150_us); // inside the frame that started at 10.1 ms (F1 at 0.1 ms + k * 500 us)
  rig.module().power_off();
  EXPECT_EQ(rig.clock_line().reader().level(), Level::High);
  const std::uint64_t frames = rig.module().frames();
  falls.clear();
  rig.run_until(15_ms);
  EXPECT_TRUE(falls.empty());
  EXPECT_EQ(rig.module().frames(), frames);
  for (const std::uint16_t w : rig.status()) EXPECT_EQ(w, 0);
  rig.module().power_on();
  EXPECT_EQ(rig.raw(), 0U); // no frame read since power-up
  rig.run_until(16_ms);
  ASSERT_FALSE(falls.empty());
  EXPECT_EQ(falls.front(), 15'100_us);
  EXPECT_EQ(rig.raw(), 0x1FFFFFFU); // all ones again (L683-684)
}

TEST(Ssi7361PowerCycle, ATransmitWrittenWhileOffStartsNoCycle) {
  Rig rig(first_frame_at(100_us));
  rig.run_for(1_ms);
  rig.module().power_off();
  rig.module().write_command(cmd::kQ, qbit::kTransmit | qbit::kApplyPreset);
  rig.run_for(1_ms);
  rig.module().power_on();
  rig.run_for(1_ms);
  EXPECT_EQ(rig.status_bits() & ibit::kAcknowledge, 0);
  // The next 0->1 edge is a cycle again.
  rig.module().write_command(cmd::kQ, qbit::kApplyPreset);
  rig.module().write_command(cmd::kQ, qbit::kTransmit | qbit::kApplyPreset);
  EXPECT_EQ(rig.status_bits() & ibit::kAcknowledge, ibit::kAcknowledge);
}

TEST(Ssi7361PowerCycle, TheDataValueIsZeroUntilTheFirstFrameAfterPowerUpCompletes) {
  // [MODEL] A28 (the manual is silent): raw, Data Value and rate 0 until a frame is read. The
  // first frame's F1 is first_frame = 100 us after power-up; its 25th bit is sampled 25 T =
  // 200 us after F1 (§2.1 [MODEL]), so it completes 300 us after power-up.
  Rig rig(first_frame_at(100_us));
  rig.run_for(2_ms);
  ASSERT_EQ(rig.program(kBlockA, kAqA) & ibit::kParameterErrors, 0);
  ASSERT_EQ(rig.program(qbit::kApplyPreset) & ibit::kCommandError, 0);
  rig.run_for(1_ms);
  ASSERT_EQ(rig.dv(), 125'420); // M-05
  rig.module().power_off();
  rig.run_for(5_ms);
  const Nanos on = rig.now();
  rig.module().power_on();
  // Not 999's offset LO = 124,421 applied to a raw 0 nobody sent.
  EXPECT_EQ(rig.dv(), 0);
  rig.run_until(on + 299'999_ns);
  EXPECT_EQ(rig.raw(), 0U);
  EXPECT_EQ(rig.dv(), 0);
  rig.run_until(on + 300'001_ns);
  EXPECT_EQ(rig.raw(), 0x1FFFFFFU);
  EXPECT_EQ(rig.dv(), 125'420);
}

TEST(Ssi7361PowerCycle, ANegativeCountDirectionReadsZeroNotTwoToTheNBeforeTheFirstFrame) {
  // Count Direction Negative: x = 2^N - field (L1247-1248); from the all-ones frame with the
  // factory N = 24 (M-21) x = 16,777,216 - 16,777,215 = 1. A raw 0 would give 2^24: before the
  // first frame the Data Value is 0 instead (A28), at construction as after a power cycle.
  Rig rig(first_frame_at(1_ms));
  ASSERT_EQ(rig.program(qbit::kProgramDirection | qbit::kCountDirection) & ibit::kCommandError, 0);
  EXPECT_EQ(rig.dv(), 0);
  rig.run_until(1'199_us);
  EXPECT_EQ(rig.dv(), 0);
  rig.run_until(1'201_us);
  EXPECT_EQ(rig.dv(), 1);
  rig.module().power_off();
  rig.run_for(1_ms);
  const Nanos on = rig.now();
  rig.module().power_on(); // F1 first_frame = 1 ms later, complete 200 us after it
  EXPECT_EQ(rig.dv(), 0);
  rig.run_until(on + 1'199_us);
  EXPECT_EQ(rig.dv(), 0);
  rig.run_until(on + 1'201_us);
  EXPECT_EQ(rig.dv(), 1);
}

} // namespace
} // namespace hilrig::models::ssi7361::test
