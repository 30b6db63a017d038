// Modbus RTU framing without a line (Modbus over Serial Line V1.02): the CRC (§6.2.2, checked
// against a bit-by-bit reference written from the spec's description and the classic
// request 01 03 00 00 00 0A -> CRC C5 CD), the 3.5-character silence (§2.5.1.1), and frames
// cut by length or by silence.
#include <gtest/gtest.h>

#include <cstdint>
#include <random>
#include <vector>

#include "drivers/modbus/rtu_framing.hpp"
#include "tests/modbus/plain_map.hpp"

namespace hilrig::drivers::modbus {
namespace {

using Bytes = std::vector<std::uint8_t>;

// §6.2.2: preset 0xFFFF, XOR each byte in, shift right 8 times, XOR 0xA001 when a 1 falls out.
std::uint16_t reference_crc(const Bytes& bytes) {
  std::uint16_t crc = 0xFFFF;
  for (std::uint8_t b : bytes) {
    crc = static_cast<std::uint16_t>(crc ^ b);
    for (int i = 0; i < 8; ++i) {
      crc = (crc & 1U) != 0 ? static_cast<std::uint16_t>((crc >> 1U) ^ 0xA001U)
                            : static_cast<std::uint16_t>(crc >> 1U);
    }
  }
  return crc;
}

Bytes framed(Bytes bytes) {
  const std::uint16_t crc = reference_crc(bytes);
  bytes.push_back(static_cast<std::uint8_t>(crc & 0xFFU)); // low byte first
  bytes.push_back(static_cast<std::uint8_t>(crc >> 8U));
  return bytes;
}

TEST(ModbusRtuFraming, CrcMatchesTheSpecsAlgorithm) {
  EXPECT_EQ(framed({1, 3, 0, 0, 0, 0x0A}), (Bytes{1, 3, 0, 0, 0, 0x0A, 0xC5, 0xCD}));
  std::mt19937 rng(19); // fixed seed: deterministic
  for (int i = 0; i < 500; ++i) {
    Bytes b(static_cast<std::size_t>(rng() % 256));
    for (auto& x : b) x = static_cast<std::uint8_t>(rng());
    EXPECT_EQ(rtu_crc(b), reference_crc(b));
    const Bytes f = framed(b);
    EXPECT_EQ(rtu_crc_ok(f), f.size() >= 4);
  }
}

TEST(ModbusRtuFraming, SilenceIsThreePointFiveCharacters) {
  // 19,200 baud 8E1: 11 bits a character; 3.5 × 11 / 19,200 s = 2,005,208.3 ns, rounded up.
  EXPECT_EQ(rtu_silence({19'200, 8, Parity::Even, 1}), nanoseconds(2'005'209));
  // 9,600 8N1: 10 bits; 3.5 × 10 / 9,600 s = 3,645,833.3 ns.
  EXPECT_EQ(rtu_silence({9'600, 8, Parity::None, 1}), nanoseconds(3'645'834));
  // Above 19,200 baud the spec fixes t3.5 at 1.750 ms.
  EXPECT_EQ(rtu_silence({19'201, 8, Parity::Even, 1}), microseconds(1'750));
  EXPECT_EQ(rtu_silence({115'200, 8, Parity::None, 1}), microseconds(1'750));
}

TEST(ModbusRtuFraming, KnownFunctionIsCompleteByLength) {
  const Bytes read = framed({1, 4, 0, 13, 0, 1});
  for (std::size_t cut = 0; cut < read.size(); ++cut) {
    EXPECT_EQ(
        next_rtu_frame(Bytes(read.begin(), read.begin() + static_cast<std::ptrdiff_t>(cut)), false).kind,
        RtuFrameKind::Incomplete);
  }
  const RtuFrame f = next_rtu_frame(read, false);
  EXPECT_EQ(f.kind, RtuFrameKind::Request);
  EXPECT_EQ(f.length, 8U);
  // FC 16 with 2 registers: 7 header bytes + byte count 4 + CRC 2.
  const Bytes write = framed({1, 16, 0x04, 0x00, 0, 2, 4, 0, 1, 0, 2});
  EXPECT_EQ(next_rtu_frame(write, false).length, 13U);
}

TEST(ModbusRtuFraming, UnknownFunctionEndsAtTheSilence) {
  const Bytes f = framed({1, 0x42, 1, 2, 3, 4});
  EXPECT_EQ(next_rtu_frame(f, false).kind, RtuFrameKind::Incomplete);
  const RtuFrame at_silence = next_rtu_frame(f, true);
  EXPECT_EQ(at_silence.kind, RtuFrameKind::Request);
  EXPECT_EQ(at_silence.length, f.size());
  PlainMap m;
  Bytes rsp;
  const RtuAnswer a = answer_rtu_request(m, 1, f, rsp);
  EXPECT_TRUE(a.addressed);
  EXPECT_EQ(a.status, RegisterStatus::IllegalFunction);
  EXPECT_EQ(rsp, framed({1, 0xC2, 0x01}));
}

TEST(ModbusRtuFraming, ShortPduWithAGoodCrcGetsException3) {
  const Bytes f = framed({1, 4, 0, 13}); // FC 4 without its count
  EXPECT_EQ(next_rtu_frame(f, false).kind, RtuFrameKind::Incomplete);
  ASSERT_EQ(next_rtu_frame(f, true).kind, RtuFrameKind::Request);
  PlainMap m;
  Bytes rsp;
  EXPECT_EQ(answer_rtu_request(m, 1, f, rsp).status, RegisterStatus::IllegalDataValue);
  EXPECT_EQ(rsp, framed({1, 0x84, 0x03}));
}

TEST(ModbusRtuFraming, BadCrcThenAGoodFrameWithNoSilenceBetween) {
  Bytes bad = framed({1, 4, 0, 13, 0, 1});
  bad[6] ^= 0xFFU;
  Bytes both = bad;
  const Bytes good = framed({1, 4, 0, 0, 0, 1});
  both.insert(both.end(), good.begin(), good.end());
  EXPECT_EQ(next_rtu_frame(both, false).kind, RtuFrameKind::Incomplete);
  const RtuFrame first = next_rtu_frame(both, true);
  EXPECT_EQ(first.kind, RtuFrameKind::BadCrc);
  EXPECT_EQ(first.length, 8U);
  const RtuFrame second = next_rtu_frame(good, false);
  EXPECT_EQ(second.kind, RtuFrameKind::Request);
}

TEST(ModbusRtuFraming, NoiseIsDroppedAtMostOneFrameAtATime) {
  const Bytes noise(kMaxRtuAdu + 10, 0x55); // no silence for longer than any frame
  const RtuFrame f = next_rtu_frame(noise, false);
  EXPECT_EQ(f.kind, RtuFrameKind::BadCrc);
  EXPECT_EQ(f.length, kMaxRtuAdu);
}

TEST(ModbusRtuFraming, OtherUnitIgnoredBroadcastNotAnswered) {
  PlainMap m;
  Bytes rsp;
  const RtuAnswer other = answer_rtu_request(m, 1, framed({2, 4, 0, 0, 0, 1}), rsp);
  EXPECT_FALSE(other.addressed);
  EXPECT_TRUE(rsp.empty());
  const RtuAnswer b = answer_rtu_request(m, 1, framed({0, 6, 0x04, 0x00, 0x12, 0x34}), rsp);
  EXPECT_TRUE(b.addressed && b.broadcast);
  EXPECT_TRUE(rsp.empty());
  EXPECT_EQ(m.holding[0], 0x1234);      // carried out (Serial Line §2.2)
  for (std::size_t n = 0; n < 4; ++n) { // no room for unit, function and CRC: not a frame
    EXPECT_FALSE(answer_rtu_request(m, 1, Bytes(n, 1), rsp).addressed) << n;
  }
  EXPECT_TRUE(rsp.empty());
}

} // namespace
} // namespace hilrig::drivers::modbus
