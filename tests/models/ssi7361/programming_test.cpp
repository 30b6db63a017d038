// The Transmit/Acknowledge Programming Cycle (digest §3, §5.3-5.4): presets and the linear
// offset, every error bit, the fixed check order and the old setup kept on error.

#include <gtest/gtest.h>

#include "ssi7361_rig.hpp"

namespace hilrig::models::ssi7361::test {
namespace {

// The checkout's block A (Table 3.1, L860-867): 266, 1000/1024, preset, RUT 500 ms.
Aq checkout_block(std::int32_t preset) {
  return {.format = 266, .multiplier = 1000, .divisor = 1024, .preset = preset, .rut = 500};
}

// A module with no transducer (raw 0x1FFFFFF) after the checkout's block A: DV 999 (M-04).
struct Ssi7361Checkout : ::testing::Test {
  Ssi7361Checkout() { rig.run_for(1_ms); }
  void block_a(std::int32_t preset = 125'420) {
    ASSERT_EQ(rig.program(kBlockA, checkout_block(preset)), kAck);
  }
  Rig rig;
};

TEST_F(Ssi7361Checkout, M02_BlockAProgramsEverythingButTheApply) {
  block_a();
  EXPECT_EQ(rig.dv(), 999); // format and scalars in effect; stored preset not applied
}

TEST_F(Ssi7361Checkout, M05_M06_ApplyPresetGives125420) {
  block_a();
  // M-02 block B: %Q = 1 with every %AQ word 0 - they are not used (else FMT/SCLErr).
  EXPECT_EQ(rig.program(qbit::kApplyPreset), kAck); // %I = 0x8000 while ACK (L921, L937)
  // LO = 125,420 - 999 = 124,421; DV = 125,420 = 0x0001E9EC (M-06 words).
  EXPECT_EQ(rig.dv(), 125'420);
  EXPECT_EQ(rig.status()[status::kDataLow], 0xE9EC);
  EXPECT_EQ(rig.status()[status::kDataHigh], 0x0001);
  EXPECT_EQ(rig.status_bits(), 0); // ACK drops with TRMT
}

TEST_F(Ssi7361Checkout, M06_PresetWordsAreLowWordFirst) {
  // Preset 125,420 as the ladder's %R5/%R6: 0xE9EC (reads -5,652 as INT) and 0x0001.
  const std::uint16_t words[6] = {266, 1000, 1024, 0xE9EC, 0x0001, 500};
  rig.module().write_command_words(1, words);
  rig.module().write_command(cmd::kQ, kBlockA | qbit::kApplyPreset | qbit::kTransmit);
  EXPECT_EQ(rig.status_bits(), kAck);
  EXPECT_EQ(rig.dv(), 125'420);
  // A negative preset: -5 = 0xFFFFFFFB.
  ASSERT_EQ(rig.program(qbit::kPresetValue | qbit::kApplyPreset, {.preset = -5}), kAck);
  EXPECT_EQ(rig.status()[status::kDataLow], 0xFFFB);
  EXPECT_EQ(rig.status()[status::kDataHigh], 0xFFFF);
}

TEST_F(Ssi7361Checkout, M07_NewPresetValueDoesNotMoveTheDataValueUntilApplied) {
  block_a();
  ASSERT_EQ(rig.program(qbit::kApplyPreset), kAck);
  ASSERT_EQ(rig.program(qbit::kPresetValue, {.preset = 0}), kAck);
  EXPECT_EQ(rig.dv(), 125'420); // cycle 1: stored only (L1228-1229)
  ASSERT_EQ(rig.program(qbit::kApplyPreset), kAck);
  EXPECT_EQ(rig.dv(), 0); // cycle 2: LO = 0 - 999
}

TEST_F(Ssi7361Checkout, M07_ResendingBlockAWithTheSameSetupKeepsTheOffset) {
  block_a();
  ASSERT_EQ(rig.program(qbit::kApplyPreset), kAck);
  block_a(0); // 0x803E, only the preset changed: the SSI setup is the same (A27 [MODEL])
  EXPECT_EQ(rig.dv(), 125'420);
}

TEST(Ssi7361Programming, M07_FormatAlwaysClearsTheOffsetWhenParameterised) {
  Params p;
  p.format_clears_offset = FormatClearsOffset::Always; // literal L1235-1236
  Rig rig(p);
  rig.run_for(1_ms);
  ASSERT_EQ(rig.program(kBlockA | qbit::kApplyPreset, checkout_block(125'420)), kAck);
  EXPECT_EQ(rig.dv(), 125'420);
  ASSERT_EQ(rig.program(kBlockA, checkout_block(0)), kAck);
  EXPECT_EQ(rig.dv(), 999);
}

TEST_F(Ssi7361Checkout, PresetAndApplyInOneCycleAppliesLast) {
  block_a();
  ASSERT_EQ(rig.program(qbit::kPresetValue | qbit::kApplyPreset, {.preset = 77}), kAck);
  EXPECT_EQ(rig.dv(), 77); // the new preset, applied after it was stored (L2080-2083)
}

TEST_F(Ssi7361Checkout, OffsetSurvivesScalarsAndDirectionButNotANewFormat) {
  block_a();
  ASSERT_EQ(rig.program(qbit::kApplyPreset), kAck); // LO = 124,421
  ASSERT_EQ(rig.program(qbit::kScalars, {.multiplier = 1, .divisor = 1}), kAck);
  EXPECT_EQ(rig.dv(), 1023 + 124'421); // LO kept (L1235-1236)
  ASSERT_EQ(rig.program(qbit::kProgramDirection | qbit::kCountDirection), kAck);
  EXPECT_EQ(rig.dv(), (1024 - 1023) + 124'421);
  ASSERT_EQ(rig.program(qbit::kFormat, {.format = format_word(1, 12)}), kAck);
  EXPECT_EQ(rig.dv(), 4096 - 4095); // new setup: LO cleared; field 4095, direction negative
}

TEST(Ssi7361Programming, M21_FactoryDefaultsAndTheirFormatWord280) {
  Rig rig;
  rig.run_for(1_ms);
  // Defaults M = 1, N = 24, binary, positive, 1/1, LO 0: all-ones gives 16,777,215.
  EXPECT_EQ(rig.dv(), 16'777'215);
  ASSERT_EQ(rig.program(qbit::kPresetValue | qbit::kApplyPreset, {.preset = 10}), kAck);
  EXPECT_EQ(rig.dv(), 10);
  // 0x0118 = 280 is the default setup: programming it changes nothing, so LO stays (A27).
  EXPECT_EQ(format_word(1, 24), 0x0118);
  ASSERT_EQ(rig.program(qbit::kFormat, {.format = 280}), kAck);
  EXPECT_EQ(rig.dv(), 10);
}

// ---------------------------------------------------------------- handshake

TEST(Ssi7361Programming, AcknowledgeFollowsTransmitAndDataAreLatchedAtTheEdge) {
  Rig rig;
  rig.run_for(1_ms);
  Ssi7361& m = rig.module();
  const std::uint16_t aq[6] = {format_word(1, 25), 1, 2, 0, 0, 100};
  m.write_command_words(1, aq);
  m.write_command(cmd::kQ, qbit::kFormat | qbit::kScalars);
  EXPECT_EQ(rig.status_bits(), 0); // no TRMT edge yet
  m.write_command(cmd::kQ, qbit::kTransmit | qbit::kFormat | qbit::kScalars);
  EXPECT_EQ(rig.status_bits(), kAck);
  EXPECT_EQ(rig.dv(), 0x1FFFFFF / 2);                         // 1/2 applied
  m.write_command(cmd::kDivisor, 4);                          // changed while TRMT = 1: not taken
  m.write_command(cmd::kQ, qbit::kTransmit | qbit::kScalars); // still 1: no new cycle
  rig.run_for(1_ms);
  EXPECT_EQ(rig.dv(), 0x1FFFFFF / 2);
  m.write_command(cmd::kQ, qbit::kScalars);
  EXPECT_EQ(rig.status_bits(), 0);                            // ACK drops with TRMT
  m.write_command(cmd::kQ, qbit::kTransmit | qbit::kScalars); // a new edge takes DIV = 4 now
  EXPECT_EQ(rig.dv(), 0x1FFFFFF / 4);
}

TEST(Ssi7361Programming, AcknowledgeDelayIsAParameter) {
  Params p;
  p.acknowledge_delay = 2_ms;
  Rig rig(p);
  rig.run_for(1_ms);
  Ssi7361& m = rig.module();
  m.write_command(cmd::kRut, 50);
  m.write_command(cmd::kQ, qbit::kTransmit | qbit::kRut);
  rig.run_for(2_ms - 1_ns);
  EXPECT_EQ(rig.status_bits(), 0);
  rig.run_for(1_ns);
  EXPECT_EQ(rig.status_bits(), kAck);
  m.write_command(cmd::kQ, qbit::kRut);
  rig.run_for(2_ms - 1_ns);
  EXPECT_EQ(rig.status_bits(), kAck);
  rig.run_for(1_ns);
  EXPECT_EQ(rig.status_bits(), 0);
}

// ---------------------------------------------------------------- parameter errors

TEST(Ssi7361Programming, FormatErrorForMOrNOutOfRange) {
  Rig rig;
  rig.run_for(1_ms);
  struct Case {
    unsigned m, n;
    bool valid;
  };
  // N 2..25, M 1..24, M + N <= 26 (L2012-2013).
  for (const Case c : {Case{1, 1, false}, Case{1, 26, false}, Case{0, 24, false}, Case{25, 1, false},
                       Case{2, 25, false}, Case{24, 2, true}, Case{1, 25, true}, Case{1, 2, true}}) {
    const std::uint16_t expected = c.valid ? kAck : (kAck | ibit::kFormatError);
    EXPECT_EQ(rig.program(qbit::kFormat, {.format = format_word(c.m, c.n)}), expected) << c.m << "," << c.n;
  }
}

TEST(Ssi7361Programming, ScalarErrorForOutOfRangeOrMulAboveDiv) {
  Rig rig;
  rig.run_for(1_ms);
  struct Case {
    std::uint16_t mul, div;
    bool valid;
  };
  for (const Case c :
       {Case{0, 10, false}, Case{1, 0, false}, Case{1001, 1000, false}, Case{32768, 32768, false},
        Case{32767, 32767, true}, Case{1, 1, true}, Case{50, 127, true}}) {
    const std::uint16_t expected = c.valid ? kAck : (kAck | ibit::kScalarError);
    EXPECT_EQ(rig.program(qbit::kScalars, {.multiplier = c.mul, .divisor = c.div}), expected)
        << c.mul << "/" << c.div;
  }
}

TEST(Ssi7361Programming, MultiplierBelowDivisorWhenParameterised) {
  Params p;
  p.multiplier_may_equal_divisor = false; // L2165 "1 to (Scalar Divisor - 1)" (A4)
  Rig rig(p);
  EXPECT_EQ(rig.program(qbit::kScalars, {.multiplier = 1, .divisor = 1}), kAck | ibit::kScalarError);
  EXPECT_EQ(rig.program(qbit::kScalars, {.multiplier = 1000, .divisor = 1024}), kAck);
}

TEST(Ssi7361Programming, PresetErrorOutsidePlusMinus33554431) {
  Rig rig;
  rig.run_for(1_ms);
  // A2: +-33,554,431 accepted, +-33,554,432 rejected.
  EXPECT_EQ(rig.program(qbit::kPresetValue, {.preset = 33'554'432}), kAck | ibit::kPresetError);
  EXPECT_EQ(rig.program(qbit::kPresetValue, {.preset = -33'554'432}), kAck | ibit::kPresetError);
  EXPECT_EQ(rig.program(qbit::kPresetValue | qbit::kApplyPreset, {.preset = 33'554'431}), kAck);
  EXPECT_EQ(rig.dv(), 33'554'431);
  EXPECT_EQ(rig.program(qbit::kPresetValue | qbit::kApplyPreset, {.preset = -33'554'431}), kAck);
  EXPECT_EQ(rig.dv(), -33'554'431);
  EXPECT_EQ(rig.status()[status::kDataLow], 0x0001); // 0xFE000001, low word first
  EXPECT_EQ(rig.status()[status::kDataHigh], 0xFE00);
}

TEST(Ssi7361Programming, RutErrorOutside1To1000ms) {
  Rig rig;
  EXPECT_EQ(rig.program(qbit::kRut, {.rut = 0}), kAck | ibit::kRutError);
  EXPECT_EQ(rig.program(qbit::kRut, {.rut = 1001}), kAck | ibit::kRutError);
  EXPECT_EQ(rig.program(qbit::kRut, {.rut = 1}), kAck);
  EXPECT_EQ(rig.program(qbit::kRut, {.rut = 1000}), kAck);
}

TEST(Ssi7361Programming, FirstErrorInTheFixedOrderWins) {
  // Order (L1950-1956): N, M, MUL, DIV, Preset, RUT: one error bit, the first found.
  const Aq all_bad{
      .format = format_word(1, 1), .multiplier = 0, .divisor = 0, .preset = 40'000'000, .rut = 0};
  Rig rig;
  EXPECT_EQ(rig.program(qbit::kFormat | qbit::kScalars | qbit::kPresetValue | qbit::kRut, all_bad),
            kAck | ibit::kFormatError);
  Rig rig2;
  EXPECT_EQ(rig2.program(qbit::kScalars | qbit::kPresetValue | qbit::kRut, all_bad),
            kAck | ibit::kScalarError);
  Rig rig3;
  EXPECT_EQ(rig3.program(qbit::kPresetValue | qbit::kRut, all_bad), kAck | ibit::kPresetError);
}

TEST_F(Ssi7361Checkout, OldSetupAndOffsetKeptWhenAnyCheckFails) {
  block_a();
  ASSERT_EQ(rig.program(qbit::kApplyPreset), kAck);
  // A valid new format with invalid scalars: nothing is taken (L1962), LO included.
  EXPECT_EQ(rig.program(qbit::kFormat | qbit::kScalars | qbit::kApplyPreset,
                        {.format = format_word(1, 20), .multiplier = 5, .divisor = 4}),
            kAck | ibit::kScalarError);
  EXPECT_EQ(rig.dv(), 125'420);
  // SCLErr is pending, so the next cycle must reprogram the scalars (else MsgIgn); this one
  // does, validly, but its RUT is out of range: again nothing is taken.
  EXPECT_EQ(rig.program(qbit::kFormat | qbit::kScalars | qbit::kRut,
                        {.format = format_word(1, 20), .multiplier = 1, .divisor = 1, .rut = 0}),
            kAck | ibit::kRutError);
  EXPECT_EQ(rig.dv(), 125'420);
}

// ---------------------------------------------------------------- MsgIgn and CMDErr

TEST_F(Ssi7361Checkout, MessageIgnoredUntilTheParameterInErrorIsReprogrammed) {
  block_a();
  EXPECT_EQ(rig.program(qbit::kFormat, {.format = format_word(20, 10)}), kAck | ibit::kFormatError);
  // Programming something else: ignored, FMTErr still pending (L2039-2041).
  EXPECT_EQ(rig.program(qbit::kScalars, {.multiplier = 1, .divisor = 1}),
            kAck | ibit::kFormatError | ibit::kMessageIgnored);
  EXPECT_EQ(rig.dv(), 999); // scalars not taken
  // The format again, still wrong: FMTErr alone.
  EXPECT_EQ(rig.program(qbit::kFormat, {.format = format_word(20, 10)}), kAck | ibit::kFormatError);
  // Fixed, together with the scalars: all taken, every error cleared.
  EXPECT_EQ(rig.program(qbit::kFormat | qbit::kScalars,
                        {.format = format_word(1, 10), .multiplier = 1, .divisor = 1}),
            kAck);
  EXPECT_EQ(rig.dv(), 1023);
}

TEST_F(Ssi7361Checkout, CommandErrorForEachOfItsFourConditions) {
  block_a();
  // (2) no command bit 07-01 set.
  EXPECT_EQ(rig.program(0), kAck | ibit::kCommandError);
  // (3) a must-be-zero bit in %Q (bits 08-14) ...
  EXPECT_EQ(rig.program(qbit::kScalars | 0x0080, {.multiplier = 1, .divisor = 1}),
            kAck | ibit::kCommandError);
  EXPECT_EQ(rig.program(qbit::kScalars | 0x2000, {.multiplier = 1, .divisor = 1}),
            kAck | ibit::kCommandError);
  // ... or in %AQ1 (bits 06, 14, 15), checked even without the Format bit (A19).
  EXPECT_EQ(rig.program(qbit::kFormat, {.format = static_cast<std::uint16_t>(266 | 0x0020)}),
            kAck | ibit::kCommandError);
  EXPECT_EQ(rig.program(qbit::kScalars, {.format = 0x4000, .multiplier = 1, .divisor = 1}),
            kAck | ibit::kCommandError);
  // (4) CntDir without PgmDir.
  EXPECT_EQ(rig.program(qbit::kCountDirection), kAck | ibit::kCommandError);
  EXPECT_EQ(rig.dv(), 999); // nothing was taken
  // Cleared by the next valid cycle (L2037).
  EXPECT_EQ(rig.program(qbit::kProgramDirection), kAck);
  // (1) programming while an EEPROM error is present: see EepromError below.
}

TEST_F(Ssi7361Checkout, EepromErrorBlocksProgrammingUntilE2ClrLoadsTheDefaults) {
  block_a();
  ASSERT_EQ(rig.program(qbit::kApplyPreset), kAck);
  rig.module().corrupt_eeprom();
  EXPECT_EQ(rig.status_bits(), ibit::kEepromError); // %I bit 13
  EXPECT_EQ(rig.program(qbit::kScalars, {.multiplier = 1, .divisor = 1}),
            kAck | ibit::kEepromError | ibit::kCommandError); // CMDErr condition (1)
  EXPECT_EQ(rig.dv(), 125'420);
  // E2CLR alone is a valid cycle (A18): E2Err cleared, factory defaults, LO = 0 (M-21).
  EXPECT_EQ(rig.program(qbit::kE2Clear), kAck);
  EXPECT_EQ(rig.status_bits(), 0);
  EXPECT_EQ(rig.dv(), 16'777'215);
  // Without E2Err, E2CLR has no effect (L2121): alone it leaves no command bit 07-01, CMDErr
  // condition 2 (L2031); the setup and LO stay.
  ASSERT_EQ(rig.program(qbit::kPresetValue | qbit::kApplyPreset, {.preset = 3}), kAck);
  EXPECT_EQ(rig.program(qbit::kE2Clear), kAck | ibit::kCommandError);
  EXPECT_EQ(rig.dv(), 3);
}

TEST_F(Ssi7361Checkout, E2ClrWithoutAnEepromErrorNeitherClearsNorMasksACommandError) {
  block_a();
  ASSERT_EQ(rig.program(qbit::kApplyPreset), kAck);
  // A pending CMDErr (condition 2, L2031: no command bit) ...
  ASSERT_EQ(rig.program(0), kAck | ibit::kCommandError);
  // ... is not cleared by E2CLR alone, which has no effect without E2Err (L2119-2121) ...
  EXPECT_EQ(rig.program(qbit::kE2Clear), kAck | ibit::kCommandError);
  EXPECT_EQ(rig.dv(), 125'420);
  EXPECT_EQ(rig.status_bits(), ibit::kCommandError);
  // ... and E2CLR beside a command is ignored: the command alone decides, a valid one
  // clears CMDErr (L2037) without loading the defaults (LO and the setup stay).
  EXPECT_EQ(rig.program(qbit::kE2Clear | qbit::kProgramDirection), kAck);
  EXPECT_EQ(rig.status_bits(), 0);
  EXPECT_EQ(rig.dv(), 125'420);
}

TEST_F(Ssi7361Checkout, E2ClrIsCommittedEvenWhenALaterCheckFails) {
  block_a();
  rig.module().corrupt_eeprom();
  // E2CLR with an invalid RUT: the defaults are loaded (E2Err cleared), the RUT is refused.
  EXPECT_EQ(rig.program(qbit::kE2Clear | qbit::kRut, {.rut = 0}), kAck | ibit::kRutError);
  EXPECT_EQ(rig.dv(), 16'777'215);
}

TEST_F(Ssi7361Checkout, E2ClrWithOtherCommandsProgramsThemOverTheDefaults) {
  block_a();
  rig.module().corrupt_eeprom();
  EXPECT_EQ(rig.program(qbit::kE2Clear | qbit::kScalars, {.multiplier = 1, .divisor = 2}), kAck);
  EXPECT_EQ(rig.dv(), 16'777'215 / 2); // defaults (M=1, N=24) with the new 1/2
}

} // namespace
} // namespace hilrig::models::ssi7361::test
