#include "drivers/virtual/can_bus.hpp"

#include <gtest/gtest.h>

#include <random>
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

// can_check_frame is the check can_frame_bits makes first (CanNode::send makes only it): it
// throws for what can_frame_bits throws for and passes the frames it takes.
TEST(CanFrameBits, CheckFrameRejectsWhatTheBitsReject) {
  CanFrame f;
  f.len = 9; // classic: 8 at most
  EXPECT_THROW(can_check_frame(f), std::invalid_argument);
  f.len = 8;
  f.brs = true; // an FD bit in a classic frame
  EXPECT_THROW(can_check_frame(f), std::invalid_argument);
  f.fd = true;
  f.len = 10; // not an FD length
  EXPECT_THROW(can_check_frame(f), std::invalid_argument);
  f.len = 12;
  f.rtr = true; // FD has no remote frames
  EXPECT_THROW(can_check_frame(f), std::invalid_argument);
  f.rtr = false;
  f.id = 0x800; // 12 bits in a standard ID
  EXPECT_THROW(can_check_frame(f), std::invalid_argument);
  f.extended = true; // 29 bits hold it
  EXPECT_NO_THROW(can_check_frame(f));
  EXPECT_NO_THROW((void)can_frame_bits(f));
  f.id = 0x2000'0000; // 30 bits
  EXPECT_THROW(can_check_frame(f), std::invalid_argument);
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

namespace {

// can_frame_bits worked out the slow way, as a transmitter sends the frame: the unstuffed bits
// of the layout in can_bus.hpp one per element (the classic CRC by can_crc over them), then
// each bit sent and a stuff bit (its complement) sent after it whenever the last 5 bits sent
// are equal -- except after an FD frame's last data bit, where the fixed stuff bit stands.
CanFrameBits reference_bits(const CanFrame& f) {
  std::vector<std::uint8_t> bits;
  const auto push = [&](std::uint32_t v, int count) {
    for (int i = count - 1; i >= 0; --i) bits.push_back(static_cast<std::uint8_t>((v >> i) & 1U));
  };
  push(0, 1);
  push(f.extended ? f.id >> 18 : f.id, 11);
  if (f.extended) {
    push(1, 1); // SRR
    push(1, 1); // IDE
    push(f.id & 0x3FFFFU, 18);
  }
  std::size_t brs = 0;
  if (f.fd) {
    push(0, 1);                  // RRS
    if (!f.extended) push(0, 1); // IDE
    push(1, 1);                  // FDF
    push(0, 1);                  // res
    brs = bits.size();
    push(f.brs ? 1 : 0, 1);
    push(f.esi ? 1 : 0, 1);
  } else {
    push(f.rtr ? 1 : 0, 1);
    push(0, 2); // IDE r0, or r1 r0
  }
  push(can_len_to_dlc(f.len), 4);
  if (!f.rtr)
    for (std::size_t i = 0; i < f.len; ++i) push(f.data[i], 8);
  if (!f.fd) push(can_crc(bits.data(), bits.size(), kCanCrc15), 15);

  std::vector<std::uint8_t> sent;
  std::uint32_t nominal_stuff = 0;
  std::uint32_t data_stuff = 0;
  for (std::size_t i = 0; i < bits.size(); ++i) {
    sent.push_back(bits[i]);
    const std::size_t k = sent.size();
    const bool five = k >= 5 && sent[k - 1] == sent[k - 2] && sent[k - 2] == sent[k - 3] &&
                      sent[k - 3] == sent[k - 4] && sent[k - 4] == sent[k - 5];
    if (!five || (f.fd && i + 1 == bits.size())) continue;
    sent.push_back(static_cast<std::uint8_t>(1U - bits[i]));
    (f.fd && f.brs && i >= brs ? data_stuff : nominal_stuff) += 1;
  }
  const auto n = static_cast<std::uint32_t>(bits.size());
  CanFrameBits out;
  if (!f.fd) {
    out.nominal = n + nominal_stuff + 13;
    out.stuff = nominal_stuff;
    return out;
  }
  const std::uint32_t crc = f.len <= 16 ? 17 : 21;
  const std::uint32_t fixed = 1 + (4 + crc - 1) / 4;
  out.stuff = nominal_stuff + data_stuff + fixed;
  if (f.brs) {
    out.nominal = static_cast<std::uint32_t>(brs) + 1 + nominal_stuff + 13;
    out.data = n - static_cast<std::uint32_t>(brs) - 1 + data_stuff + 4 + crc + fixed;
  } else {
    out.nominal = n + nominal_stuff + 4 + crc + fixed + 13;
  }
  return out;
}

} // namespace

// can_frame_bits packs the bits and counts stuff bits a byte at a time; on random frames of
// every format it gives what sending them bit by bit gives. The data bytes are drawn mostly
// from long runs of equal bits (0x00, 0xFF, 0x0F, 0xE0, ...), so frames need many stuff bits,
// at every bit offset, up to and after the last data bit.
TEST(CanFrameBits, RandomFramesMatchSendingThemBitByBit) {
  std::mt19937_64 rng(20261127);
  const std::uint8_t runs[] = {0x00, 0xFF, 0x0F, 0xF0, 0xE0, 0x1F, 0x07, 0xF8, 0x83, 0x7C};
  const std::uint8_t fd_lengths[] = {0, 1, 2, 3, 4, 5, 6, 7, 8, 12, 16, 20, 24, 32, 48, 64};
  std::size_t with_stuff = 0;
  for (int k = 0; k < 20'000; ++k) {
    CanFrame f;
    f.extended = rng() % 2 == 0;
    f.fd = rng() % 3 == 0;
    const std::uint64_t pick = rng();
    const std::uint32_t id_mask = f.extended ? 0x1FFF'FFFFU : 0x7FFU;
    f.id = static_cast<std::uint32_t>(pick % 4 == 0 ? 0 : pick % 4 == 1 ? id_mask : rng()) & id_mask;
    if (f.fd) {
      f.brs = rng() % 2 == 0;
      f.esi = rng() % 2 == 0;
      f.len = fd_lengths[rng() % 16];
    } else {
      f.rtr = rng() % 5 == 0;
      f.len = static_cast<std::uint8_t>(rng() % 9);
    }
    for (std::size_t i = 0; i < f.len; ++i)
      f.data[i] = rng() % 3 == 0 ? static_cast<std::uint8_t>(rng()) : runs[rng() % std::size(runs)];
    const CanFrameBits want = reference_bits(f);
    const CanFrameBits got = can_frame_bits(f);
    ASSERT_EQ(got.nominal, want.nominal) << k;
    ASSERT_EQ(got.data, want.data) << k;
    ASSERT_EQ(got.stuff, want.stuff) << k;
    if (want.stuff > (f.fd ? 7U : 0U)) ++with_stuff;
  }
  EXPECT_GT(with_stuff, 15'000U); // the draw gives stuff bits to most frames
}
