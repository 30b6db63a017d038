// From the frame to the Data Value (digest §2.3): field extraction, Data Logic, Gray, Count
// Direction and scaling, with the manual's worked examples (docs/spec/ssi7361-examples.md).

#include <gtest/gtest.h>

#include <random>

#include "ssi7361_rig.hpp"

namespace hilrig::models::ssi7361::test {
namespace {

constexpr std::uint16_t kTransmit = qbit::kTransmit;

// Programs a format (and optionally scalars) with no error, or fails the test.
void setup_format(Rig& rig, std::uint16_t format, std::uint16_t mul = 1, std::uint16_t div = 1) {
  ASSERT_EQ(
      rig.program(qbit::kFormat | qbit::kScalars, {.format = format, .multiplier = mul, .divisor = div}),
      kTransmit);
}

TEST(Ssi7361DataValue, M01_M04_CheckoutFormat266WithoutTransducerGives999) {
  Rig rig; // no transducer: raw 0x1FFFFFF (M-03)
  rig.run_for(1_ms);
  // M-01: 266 = 0x010A is N = 10, M = 1, binary, positive, 125 kHz: valid (no FMTErr).
  setup_format(rig, 266, 1000, 1024);
  // M-04: field = (0x1FFFFFF >> 15) & 0x3FF = 1023; 1023 * 1000 / 1024 = 999.02 -> 999.
  EXPECT_EQ(rig.dv(), 999);
  EXPECT_EQ(rig.status()[status::kDataLow], 0x03E7);
  EXPECT_EQ(rig.status()[status::kDataHigh], 0x0000);
}

TEST(Ssi7361DataValue, M15_EmbeddedFieldPositions) {
  Rig rig;
  rig.attach_word_sensor();
  // Case a: N = 16, M = 9: bits 9..24; frame 0000000010101011110011011 = 0x1579B = 87,963.
  setup_format(rig, format_word(9, 16));
  rig.send(0x1579B);
  EXPECT_EQ(rig.raw(), 87'963u);
  EXPECT_EQ(rig.dv(), 43'981); // 0xABCD
  // Case b: N = 20, M = 1: bits 1..20; frame 0...01111111 = 127: field = 127 >> 5 = 3.
  setup_format(rig, format_word(1, 20));
  rig.send(127);
  EXPECT_EQ(rig.dv(), 3);
}

TEST(Ssi7361DataValue, M13_Ldt5umTo0p0005InchWith50Over127) {
  Rig rig;
  rig.attach_word_sensor();
  setup_format(rig, format_word(1, 25), 50, 127);
  rig.send(127);           // 127 x 5 um = 635 um = 0.025"
  EXPECT_EQ(rig.dv(), 50); // 127 * 50 / 127 = 50 units of 0.0005"
}

TEST(Ssi7361DataValue, M14_Dme3000ScalarPairs) {
  Rig rig;
  rig.attach_word_sensor();
  rig.send(2032); // 2032 x 0.125 mm = 254 mm = 10.000"
  struct Pair {
    std::uint16_t mul;
    std::int32_t expected;
  };
  for (const Pair p : {Pair{1000, 1000}, Pair{10, 10}, Pair{2000, 2000}, Pair{100, 100}}) {
    setup_format(rig, format_word(1, 25), p.mul, 2032); // passes SCLErr: MUL <= DIV <= 32767
    EXPECT_EQ(rig.dv(), p.expected) << p.mul << "/2032";
  }
}

TEST(Ssi7361DataValue, M16_TransducerErrorBitsStayInTheRawWordOnly) {
  Rig rig;
  rig.attach_word_sensor();
  // Balluff 24-bit (M = 4, N = 21): "Out of Range" at stream bit 3 = raw bit 23 (0x400000).
  // Position 1,000,000 = 0xF4240 at shift 26-4-21 = 1: raw = 0x400000 | 0xF4240 << 1.
  setup_format(rig, format_word(4, 21));
  rig.send(0x00400000u | (1'000'000u << 1));
  EXPECT_EQ(rig.raw(), 0x005E8480u);
  EXPECT_EQ(rig.raw(), 6'194'304u);
  EXPECT_EQ(rig.dv(), 1'000'000);
  EXPECT_EQ(rig.status_bits(), 0); // the error bit never raises a 7361 status bit
  // DME3000 (M = 2, N = 23): "Plausibility" at stream bit 25 = raw bit 01; 0 means a fault.
  setup_format(rig, format_word(2, 23));
  rig.send(0x0000100u); // bit 25 = 0
  EXPECT_EQ(rig.status()[status::kRawLow] & 0x0001, 0);
  EXPECT_EQ(rig.dv(), 0x80); // field = raw >> 1
  EXPECT_EQ(rig.status_bits(), 0);
}

TEST(Ssi7361DataValue, M17_StegmannAg626GrayMultiTurn) {
  Rig rig;
  // 512 turns x 2048 counts: N = 20, M = 4 (Table B.5); the encoder sends Gray.
  rig.attach_sensor(signals::ssi7361_frame(4, 20, signals::SsiCode::Gray),
                    [](Nanos) { return 5u * 2048u + 1000u; }); // turn 5, position 1000
  setup_format(rig, format_word(4, 20, true));
  rig.run_for(1_ms);
  EXPECT_EQ(rig.dv(), 11'240);
  EXPECT_EQ(rig.dv() / 2048, 5);
  EXPECT_EQ(rig.dv() % 2048, 1000);
}

TEST(Ssi7361DataValue, M19_RollOverAndSubFieldWrap) {
  Rig rig;
  std::uint32_t value = 1023;
  // Case a: a 10-bit rotary field (M = 16, N = 10): 1023 + 1 -> 0, 0 - 1 -> 1023.
  rig.attach_sensor(signals::ssi7361_frame(16, 10), [&](Nanos) { return value; });
  setup_format(rig, format_word(16, 10));
  rig.run_for(1_ms);
  EXPECT_EQ(rig.dv(), 1023);
  value = 1024; // the encoder's 10 bits roll over
  rig.run_for(1_ms);
  EXPECT_EQ(rig.dv(), 0);
  value = 0xFFFF'FFFFu; // 0 - 1
  rig.run_for(1_ms);
  EXPECT_EQ(rig.dv(), 1023);
}

TEST(Ssi7361DataValue, M19_EightBitValueReadThroughSevenBits) {
  Rig rig;
  rig.attach_word_sensor();
  // Case b: stream bits 18..25 carry 8 bits; the module reads M = 19, N = 7 (shift 0).
  setup_format(rig, format_word(19, 7));
  rig.send(127);
  EXPECT_EQ(rig.dv(), 127);
  rig.send(128); // 10000000b: the bit above the field is lost
  EXPECT_EQ(rig.dv(), 0);
}

TEST(Ssi7361DataValue, M20_FullScaleCount3600Over4096) {
  Rig rig;
  rig.attach_word_sensor();
  setup_format(rig, format_word(14, 12), 3600, 4096); // 12-bit single turn at bits 14..25
  rig.send(4095);
  EXPECT_EQ(rig.dv(), 3599); // 4095 * 3600 / 4096 = 3599.12 -> 3599: new FSC 3600
  rig.send(2048);
  EXPECT_EQ(rig.dv(), 1800); // 180.0 degrees
}

TEST(Ssi7361DataValue, M18_ScaleFactorCorrectionPairs) {
  Rig rig;
  rig.attach_word_sensor();
  rig.send(10'050);                                    // measured travel 10,050 counts for an expected 10,000
  setup_format(rig, format_word(1, 25), 4598, 10'000); // 0.4598, the closer pair to 0.459832
  setup_format(rig, format_word(1, 25), 46, 100);      // 0.46: also valid
  setup_format(rig, format_word(1, 25), 9950, 10'000); // corrected 0.995
  EXPECT_EQ(rig.dv(), 9999); // 10,050 * 9,950 / 10,000 = 9,999.75 -> 9,999 (truncated)
}

// Data Logic Negative inverts the N field bits before Gray decoding (A14); the raw word is
// reported as received. 4-bit field at M = 22 (shift 0).
TEST(Ssi7361DataValue, NegativeLogicInvertsTheFieldBeforeGray) {
  Rig rig;
  rig.attach_word_sensor();
  rig.send(0);
  setup_format(rig, format_word(22, 4, false, true));
  EXPECT_EQ(rig.dv(), 15); // ~0000 = 1111
  setup_format(rig, format_word(22, 4, true, true));
  EXPECT_EQ(rig.dv(), 10); // ~0000 = 1111 (Gray) -> 1010b
  EXPECT_EQ(rig.raw(), 0u);
  rig.send(6);
  setup_format(rig, format_word(22, 4, true, false));
  EXPECT_EQ(rig.dv(), 4); // 0110 (Gray) -> 0100b
}

TEST(Ssi7361DataValue, NegativeLogicAfterGrayWhenParameterised) {
  Params p;
  p.invert_before_gray = false; // the other order of A14
  Rig rig(p);
  rig.attach_word_sensor();
  rig.send(0);
  setup_format(rig, format_word(22, 4, true, true));
  EXPECT_EQ(rig.dv(), 15); // 0000 (Gray) -> 0000 -> inverted 1111
}

TEST(Ssi7361DataValue, NegativeCountDirectionIsTwoToTheNMinusField) {
  Rig rig;
  rig.attach_word_sensor();
  setup_format(rig, format_word(16, 10));
  ASSERT_EQ(rig.program(qbit::kProgramDirection | qbit::kCountDirection), kTransmit);
  rig.send(100);
  EXPECT_EQ(rig.dv(), 924); // 1024 - 100 (L1247-1248)
  EXPECT_EQ(rig.raw(), 100u);
  rig.send(0);
  EXPECT_EQ(rig.dv(), 1024);                                  // literally 2^N: outside the N-bit range (A12)
  ASSERT_EQ(rig.program(qbit::kProgramDirection), kTransmit); // back to Positive
  EXPECT_EQ(rig.dv(), 0);
}

TEST(Ssi7361DataValue, NegativeCountDirectionWrapsZeroWhenParameterised) {
  Params p;
  p.count_direction_wrap = true; // the PLC recipe 0 -> 0 (L1259-1261)
  Rig rig(p);
  rig.attach_word_sensor();
  setup_format(rig, format_word(16, 10));
  ASSERT_EQ(rig.program(qbit::kProgramDirection | qbit::kCountDirection), kTransmit);
  rig.send(0);
  EXPECT_EQ(rig.dv(), 0);
  rig.send(1);
  EXPECT_EQ(rig.dv(), 1023);
}

// Property: any binary field anywhere in the frame reads back whatever the other bits hold.
TEST(Ssi7361DataValue, BinaryFieldReadsBackAmidRandomBits) {
  std::mt19937 gen(7361);
  Rig rig;
  rig.attach_word_sensor();
  for (int i = 0; i < 150; ++i) {
    const unsigned m = std::uniform_int_distribution<unsigned>(1, 24)(gen);
    const unsigned n = std::uniform_int_distribution<unsigned>(2, 26 - m)(gen);
    const unsigned shift = 26 - m - n;
    const std::uint32_t mask = ((1u << n) - 1u) << shift;
    const std::uint32_t value = std::uniform_int_distribution<std::uint32_t>(0, (1u << n) - 1u)(gen);
    const std::uint32_t noise = std::uniform_int_distribution<std::uint32_t>(0, 0x1FFFFFF)(gen);
    setup_format(rig, format_word(m, n));
    rig.send((noise & ~mask & 0x1FFFFFFu) | (value << shift));
    ASSERT_EQ(rig.dv(), static_cast<std::int32_t>(value)) << "M=" << m << " N=" << n;
  }
}

// Round trip: what a Gray encoder sends (signals' Gray coder) the module decodes back.
TEST(Ssi7361DataValue, GrayEncoderRoundTrip) {
  std::mt19937 gen(2002);
  for (int i = 0; i < 40; ++i) {
    const unsigned m = std::uniform_int_distribution<unsigned>(1, 24)(gen);
    const unsigned n = std::uniform_int_distribution<unsigned>(2, 26 - m)(gen);
    Rig rig;
    std::uint32_t value = 0;
    rig.attach_sensor(signals::ssi7361_frame(m, n, signals::SsiCode::Gray), [&](Nanos) { return value; });
    setup_format(rig, format_word(m, n, true));
    for (int j = 0; j < 5; ++j) {
      value = std::uniform_int_distribution<std::uint32_t>(0, (1u << n) - 1u)(gen);
      rig.run_for(1_ms);
      ASSERT_EQ(rig.dv(), static_cast<std::int32_t>(value)) << "M=" << m << " N=" << n;
    }
  }
}

} // namespace
} // namespace hilrig::models::ssi7361::test
