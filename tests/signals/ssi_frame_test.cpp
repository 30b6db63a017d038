// SSI frame layout and Gray code: hand-computed words and the 7361 examples
// (docs/spec/ssi7361-examples.md M-03, M-15, M-16) at the frame level.
#include <gtest/gtest.h>

#include <stdexcept>

#include "signals/gray_code.hpp"
#include "signals/ssi_frame.hpp"

namespace hilrig::signals {
namespace {

TEST(GrayCode, HandComputedCodes) {
  // Reflected binary: 0,1,3,2,6,7,5,4 for 0..7; 8 = 1000b -> 1100b.
  const std::uint32_t gray[] = {0, 1, 3, 2, 6, 7, 5, 4};
  for (std::uint32_t v = 0; v < 8; ++v) {
    EXPECT_EQ(binary_to_gray(v), gray[v]) << v;
    EXPECT_EQ(gray_to_binary(gray[v]), v) << v;
  }
  EXPECT_EQ(binary_to_gray(8u), 12u);
  // 2^32-1 = all ones -> 1000...0 in Gray.
  EXPECT_EQ(binary_to_gray(0xFFFF'FFFFu), 0x8000'0000u);
  EXPECT_EQ(gray_to_binary(0x8000'0000u), 0xFFFF'FFFFu);
}

TEST(GrayCode, NeighboursDifferInOneBit) {
  for (std::uint32_t v = 0; v < 5000; ++v) {
    const std::uint32_t d = binary_to_gray(v) ^ binary_to_gray(v + 1);
    EXPECT_EQ(d & (d - 1), 0u) << v; // exactly one bit set
    EXPECT_NE(d, 0u);
  }
}

TEST(SsiFrame, StreamBitOneIsTheMsb) {
  // A 12-bit binary frame of 0x800: only stream bit 1 is set.
  SsiFrameFormat f;
  f.frame_bits = 12;
  f.data_bits = 12;
  const std::uint32_t w = compose_frame(f, 0x800);
  EXPECT_EQ(w, 0x800u);
  EXPECT_TRUE(stream_bit(w, 12, 1));
  for (unsigned k = 2; k <= 12; ++k) EXPECT_FALSE(stream_bit(w, 12, k));
}

TEST(SsiFrame, M15aEmbeddedSixteenBitFieldAtBitNine) {
  // M-15 case a: N=16, M=9; frame 0000000010101011110011011 (0xABCD in bits 9..24, bit 25 = 1)
  // -> raw 87,963. Bit 25 is modelled as one status bit after the data.
  SsiFrameFormat f = ssi7361_frame(9, 16);
  f.status_bits = 1;
  EXPECT_EQ(compose_frame(f, 0xABCD, 1), 87'963u);
  const SsiFrameFields got = decompose_frame(f, 87'963u);
  EXPECT_EQ(got.value, 43'981u);
  EXPECT_EQ(got.status, 1u);
}

TEST(SsiFrame, M15bTwentyBitFieldAtBitOne) {
  // M-15 case b: frame 0000000000000000001111111 = raw 127; N=20, M=1 -> field 3.
  const SsiFrameFormat f = ssi7361_frame(1, 20);
  EXPECT_EQ(decompose_frame(f, 127).value, 3u);
  SsiFrameFormat with_tail = f;
  with_tail.status_bits = 5; // stream bits 21..25 all ones
  EXPECT_EQ(compose_frame(with_tail, 3, 0x1F), 127u);
}

TEST(SsiFrame, M16BalluffErrorBitBeforeTheData) {
  // M-16: Balluff 24-bit, M=4, N=21, error bit at stream bit 3 (raw bit 23, 0x400000);
  // position 1,000,000 = 0xF4240 shifted by 26-4-21 = 1 -> 0x1E8480, plus 0x400000 = 0x5E8480.
  SsiFrameFormat f = ssi7361_frame(4, 21);
  f.status_bits = 1;
  f.status_msb = 3;
  EXPECT_EQ(compose_frame(f, 1'000'000, 1), 0x005E'8480u);
  EXPECT_EQ(compose_frame(f, 1'000'000, 1), 6'194'304u);
  const SsiFrameFields got = decompose_frame(f, 0x005E'8480u);
  EXPECT_EQ(got.value, 1'000'000u);
  EXPECT_EQ(got.status, 1u);
}

TEST(SsiFrame, M16DmePlausibilityBitIsStreamBitTwentyFive) {
  // DME3000 25-bit: plausibility at stream bit 25 = raw bit 01 (mask 1); normally 1.
  SsiFrameFormat f = ssi7361_frame(1, 24);
  f.status_bits = 1;
  EXPECT_EQ(compose_frame(f, 0, 1), 1u);
  EXPECT_EQ(compose_frame(f, 1, 0), 2u);
}

TEST(SsiFrame, M03AllOnesFrameIsFullScale) {
  // M-03: every bit 1 -> raw 33,554,431; with the default N=24, M=1 the field is 2^24-1.
  const SsiFrameFormat f = ssi7361_frame();
  EXPECT_EQ(decompose_frame(f, 33'554'431u).value, 16'777'215u);
}

TEST(SsiFrame, GrayFieldIsCodedInsideTheFrame) {
  // 12-bit Gray field at stream bit 1 of a 13-bit frame: 8 -> Gray 1100b, shifted left by 1.
  SsiFrameFormat f;
  f.frame_bits = 13;
  f.data_bits = 12;
  f.code = SsiCode::Gray;
  EXPECT_EQ(compose_frame(f, 8), 12u << 1);
  EXPECT_EQ(decompose_frame(f, 12u << 1).value, 8u);
}

TEST(SsiFrame, EvenAndOddParity) {
  // 4-bit data 1011b has three ones: even parity bit 1, odd parity bit 0; parity after data.
  SsiFrameFormat f;
  f.frame_bits = 5;
  f.data_bits = 4;
  f.parity = SsiParity::Even;
  EXPECT_EQ(compose_frame(f, 0b1011), 0b10111u);
  EXPECT_TRUE(decompose_frame(f, 0b10111).parity_ok);
  EXPECT_FALSE(decompose_frame(f, 0b10011).parity_ok); // one data bit flipped
  f.parity = SsiParity::Odd;
  EXPECT_EQ(compose_frame(f, 0b1011), 0b10110u);
  EXPECT_TRUE(decompose_frame(f, 0b10110).parity_ok);
}

TEST(SsiFrame, RejectsFieldsThatDoNotFit) {
  EXPECT_THROW((void)ssi7361_frame(2, 25), std::invalid_argument); // M+N = 27 > 26
  EXPECT_NO_THROW((void)ssi7361_frame(1, 25));
  SsiFrameFormat f;
  f.frame_bits = 33;
  EXPECT_THROW(f.validate(), std::invalid_argument);
  f = SsiFrameFormat{};
  f.status_bits = 2;
  f.status_msb = 24; // overlaps data bits 1..24
  EXPECT_THROW(f.validate(), std::invalid_argument);
  f = SsiFrameFormat{};
  f.data_bits = 25;
  f.parity = SsiParity::Even; // 26 bits in a 25-bit frame
  EXPECT_THROW(f.validate(), std::invalid_argument);
}

} // namespace
} // namespace hilrig::signals
