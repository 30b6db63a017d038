#include "drivers/virtual/can_bus.hpp"

#include <gtest/gtest.h>

#include <vector>

using namespace hilrig;
using namespace hilrig::literals;
using namespace hilrig::virt;

namespace {
CanFrame classic(std::uint32_t id, std::vector<std::uint8_t> bytes, bool extended = false) {
  CanFrame f;
  f.id = id;
  f.extended = extended;
  f.len = static_cast<std::uint8_t>(bytes.size());
  for (std::size_t i = 0; i < bytes.size(); ++i) f.data[i] = bytes[i];
  return f;
}
const CanBitTiming k500k2M{500'000, 2'000'000}; // 2000 ns and 500 ns bits
} // namespace

TEST(CanCrc, CheckValuesOfTheCatalogue) {
  // CRC catalogue (Greg Cook, reveng) check values over ASCII "123456789" with a zero
  // register: CRC-15/CAN 0x059E, CRC-17/CAN-FD 0x04F03, CRC-21/CAN-FD 0x0ED841.
  std::vector<std::uint8_t> bits;
  for (char c : std::string("123456789")) {
    for (int i = 7; i >= 0; --i) bits.push_back(static_cast<std::uint8_t>((c >> i) & 1));
  }
  EXPECT_EQ(can_crc(bits.data(), bits.size(), kCanCrc15), 0x059EU);
  EXPECT_EQ(can_crc(bits.data(), bits.size(), CanCrc{17, 0x1'685B, 0}), 0x0'4F03U);
  EXPECT_EQ(can_crc(bits.data(), bits.size(), CanCrc{21, 0x10'2899, 0}), 0x0E'D841U);
}

TEST(CanFrameBits, StandardEmptyFrameWithAllZeroBits) {
  // ID 0x000, DLC 0: SOF, 11 ID bits, RTR, IDE, r0 and 4 DLC bits are 19 dominant (0) bits;
  // the CRC-15 of all zeros is 0, so SOF..CRC is 34 zeros. A stuff bit (1) follows every 5th
  // zero: after zeros 5, 10, 15, 20, 25, 30 -> 6 stuff bits (the last run, 31..34, is 4).
  // 34 + 6 + CRC del 1 + ACK 1 + ACK del 1 + EOF 7 + IFS 3 = 53 bits; 106 us at 500 kbit/s.
  const CanFrame f = classic(0x000, {});
  const CanFrameBits bits = can_frame_bits(f);
  EXPECT_EQ(bits.nominal, 53U);
  EXPECT_EQ(bits.data, 0U);
  EXPECT_EQ(bits.stuff, 6U);
  EXPECT_EQ(can_frame_duration(bits, k500k2M), 106_us);
  // Worst case: floor((34 - 1) / 4) = 8 stuff bits -> 55 bits.
  EXPECT_EQ(can_frame_bits_worst(f).nominal, 55U);
}

TEST(CanFrameBits, StandardEightByteWorstCase) {
  // 47 + 64 = 111 bits before stuffing (incl. 3-bit intermission); stuffed region 34 + 64 = 98
  // bits, worst case floor((98 - 1) / 4) = 24 stuff bits: 135 bits = 270 us at 500 kbit/s.
  const CanFrame f = classic(0x7FF, {0, 0, 0, 0, 0, 0, 0, 0});
  EXPECT_EQ(can_frame_bits_worst(f).nominal, 135U);
  EXPECT_EQ(can_frame_bits_worst(f).stuff, 24U);
  EXPECT_EQ(can_frame_duration(can_frame_bits_worst(f), k500k2M), 270_us);
}

TEST(CanFrameBits, StandardFrameDeadBeef) {
  // ID 0x123, DLC 4, DE AD BE EF: 34 + 32 = 66 unstuffed bits SOF..CRC, CRC-15 = 0x4E6B
  // (computed with tests/tools/can_frame_bits.py, written apart from this code). The stream,
  // stuff bits in brackets:
  //   0 00100100011 000 0100 11011110101011011011111[0]0111011111[0]0 0111001101011
  // SOF ID          RTR/IDE/r0 DLC  data ... (EF ends 01111, then CRC 100111001101011)
  // -> 2 stuff bits: 66 + 2 + 13 = 81 bits = 162 us at 500 kbit/s.
  const CanFrameBits bits = can_frame_bits(classic(0x123, {0xDE, 0xAD, 0xBE, 0xEF}));
  EXPECT_EQ(bits.nominal, 81U);
  EXPECT_EQ(bits.stuff, 2U);
  EXPECT_EQ(can_frame_duration(bits, k500k2M), 162_us);
}

TEST(CanFrameBits, ExtendedEightByteFrame) {
  // ID 0x18FF50E5 (extended), data 01..08: 54 + 64 = 118 bits SOF..CRC, CRC-15 = 0x1FE8
  // (tests/tools/can_frame_bits.py). Stuffed stream (stuff bits in brackets):
  //   01100011111[0]11111[0]0101000011100101000100000[1]00000[1]100000[1]0100000[1]
  //   001100000[1]100000[1]0010100000[1]1100000[1]01110000100000[1]1111[0]111101000
  // -> 12 stuff bits: 67 + 64 = 131 bits before stuffing + 12 = 143 bits = 286 us at 500k.
  // Worst case: floor((118 - 1) / 4) = 29 -> 160 bits.
  const CanFrame f = classic(0x18FF50E5, {1, 2, 3, 4, 5, 6, 7, 8}, true);
  const CanFrameBits bits = can_frame_bits(f);
  EXPECT_EQ(bits.nominal, 143U);
  EXPECT_EQ(bits.stuff, 12U);
  EXPECT_EQ(can_frame_duration(bits, k500k2M), 286_us);
  EXPECT_EQ(can_frame_bits_worst(f).nominal, 160U);
}

TEST(CanFrameBits, RemoteFrameHasNoDataField) {
  // Standard remote frame, DLC 8: 47 bits before stuffing whatever the DLC; worst case
  // floor((34 - 1) / 4) = 8 -> 55 bits.
  CanFrame f = classic(0x7FF, {});
  f.rtr = true;
  f.len = 8;
  EXPECT_EQ(can_frame_bits_worst(f).nominal, 55U);
}

TEST(CanFrameBits, FdFrameWithBitRateSwitch) {
  // FD base frame, ID 0x555, BRS, 16 bytes of 0x55 (DLC 10 = 1010). Bits:
  //   SOF 0 | ID 10101010101 | RRS 0 IDE 0 FDF 1 res 0 | BRS 1 -> 17 bits at the nominal rate
  //   ESI 0 | DLC 1010 | data 128 bits 0101... -> never 5 equal bits: no dynamic stuff bits
  //   stuff count 4 (0 stuff bits: Gray 000, parity 0) + CRC-17 17 + fixed stuff bits
  //   1 + floor((4 + 17 - 1) / 4) = 6 -> ESI..CRC = 1 + 4 + 128 + 4 + 17 + 6 = 160 data bits
  //   CRC del 1 + ACK 1 + ACK del 1 + EOF 7 + IFS 3 = 13 more nominal -> 30 nominal.
  // Duration: 30 x 2000 ns + 160 x 500 ns = 60 us + 80 us = 140 us.
  CanFrame f;
  f.id = 0x555;
  f.fd = true;
  f.brs = true;
  f.len = 16;
  for (std::size_t i = 0; i < 16; ++i) f.data[i] = 0x55;
  const CanFrameBits bits = can_frame_bits(f);
  EXPECT_EQ(bits.nominal, 30U);
  EXPECT_EQ(bits.data, 160U);
  EXPECT_EQ(bits.stuff, 6U);
  EXPECT_EQ(can_frame_duration(bits, k500k2M), 140_us);
  // Without BRS the same 190 bits all go at 500 kbit/s: 380 us.
  f.brs = false;
  EXPECT_EQ(can_frame_bits(f).nominal, 190U);
  EXPECT_EQ(can_frame_duration(can_frame_bits(f), k500k2M), 380_us);
}

TEST(CanFrameBits, FdWorstCaseWithCrc21) {
  // FD base frame, 64 bytes, BRS. Dynamic region SOF..data = 22 + 512 = 534 bits; in the worst
  // case stuff bits follow unstuffed bits 4, 8, 12, ... but never the last one:
  // floor((534 - 2) / 4) = 133. BRS is bit 16, so those after bits 4, 8, 12 go at the nominal
  // rate (3) and the other 130 at the data rate. Fixed: 1 + floor((4 + 21 - 1) / 4) = 7.
  // Nominal: 17 (SOF..BRS) + 3 + 13 = 33. Data: (534 - 17) + 130 + 4 + 21 + 7 = 679.
  CanFrame f;
  f.id = 0x100;
  f.fd = true;
  f.brs = true;
  f.len = 64;
  const CanFrameBits bits = can_frame_bits_worst(f);
  EXPECT_EQ(bits.nominal, 33U);
  EXPECT_EQ(bits.data, 679U);
  EXPECT_EQ(bits.stuff, 140U);
}

TEST(CanFrameBits, InvalidFramesAreRejected) {
  CanFrame f;
  f.len = 9;
  EXPECT_THROW((void)can_frame_bits(f), std::invalid_argument);
  f.fd = true;
  f.len = 10; // not an FD length
  EXPECT_THROW((void)can_frame_bits(f), std::invalid_argument);
  f.len = 8;
  f.id = 0x800; // 12 bits in a standard ID
  EXPECT_THROW((void)can_frame_bits(f), std::invalid_argument);
}

TEST(CanDlc, FdLengthsRoundTrip) {
  const std::uint8_t lengths[] = {0, 1, 2, 3, 4, 5, 6, 7, 8, 12, 16, 20, 24, 32, 48, 64};
  for (std::uint8_t dlc = 0; dlc < 16; ++dlc) {
    EXPECT_EQ(can_dlc_to_len(dlc, true), lengths[dlc]);
    EXPECT_EQ(can_len_to_dlc(lengths[dlc]), dlc);
  }
  EXPECT_EQ(can_dlc_to_len(12, false), 8U);
}
