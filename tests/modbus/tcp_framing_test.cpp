// Modbus TCP framing without sockets (Modbus Messaging on TCP/IP Implementation Guide V1.0b,
// §3.1.3: MBAP = transaction id 2, protocol id 2 (0 = Modbus), length 2 (unit id + PDU),
// unit id 1; Modbus Application Protocol V1.1b3 §4.1: a PDU is at most 253 bytes, so the
// length field is 2..254). Expected bytes are built from those layouts (mbap_bytes.hpp).
#include <gtest/gtest.h>

#include <cstdint>
#include <random>
#include <vector>

#include "drivers/modbus/tcp_framing.hpp"
#include "tests/modbus/mbap_bytes.hpp"
#include "tests/modbus/plain_map.hpp"

namespace hilrig::drivers::modbus {
namespace {

using Bytes = std::vector<std::uint8_t>;

using test::mbap_frame;

TEST(ModbusTcpFraming, AFrameIsAsLongAsItsLengthFieldSays) {
  const Bytes read = mbap_frame(0x1234, 0, 1, {4, 0, 0, 0, 1}); // FC 4, address 0, count 1
  for (std::size_t cut = 0; cut < read.size(); ++cut) {
    EXPECT_EQ(next_tcp_frame(Bytes(read.begin(), read.begin() + static_cast<std::ptrdiff_t>(cut))).kind,
              TcpFrameKind::Incomplete)
        << cut << " bytes";
  }
  Bytes two = read;
  two.insert(two.end(), read.begin(), read.end());
  const TcpFrame f = next_tcp_frame(two);
  EXPECT_EQ(f.kind, TcpFrameKind::Request);
  EXPECT_EQ(f.length, 12U); // 6 + length 6: the second frame is left for the next call
}

TEST(ModbusTcpFraming, AStreamOfFramesSplitsBackIntoThem) {
  // Round trip: random frames (any PDU of 1..253 bytes, protocol id 0 or not) concatenated,
  // then cut apart again, however the stream is chunked.
  std::mt19937 rng(19); // fixed seed: deterministic
  for (int trial = 0; trial < 50; ++trial) {
    Bytes stream;
    std::vector<std::pair<TcpFrameKind, std::size_t>> sent;
    for (int i = 0; i < 20; ++i) {
      Bytes pdu(1 + rng() % 253);
      for (auto& b : pdu) b = static_cast<std::uint8_t>(rng());
      const auto protocol = static_cast<std::uint16_t>(rng() % 3 == 0 ? rng() % 0x10000 : 0);
      const Bytes f = mbap_frame(static_cast<std::uint16_t>(i), protocol, 1, pdu);
      sent.emplace_back(protocol == 0 ? TcpFrameKind::Request : TcpFrameKind::Foreign, f.size());
      stream.insert(stream.end(), f.begin(), f.end());
    }
    std::size_t at = 0;
    for (const auto& [kind, length] : sent) {
      const std::span<const std::uint8_t> rest(stream.data() + at, stream.size() - at);
      EXPECT_EQ(next_tcp_frame(rest.first(length - 1)).kind, TcpFrameKind::Incomplete);
      const TcpFrame f = next_tcp_frame(rest);
      EXPECT_EQ(f.kind, kind);
      ASSERT_EQ(f.length, length);
      at += length;
    }
    EXPECT_EQ(at, stream.size());
  }
}

TEST(ModbusTcpFraming, LengthFieldOutsideTwoTo254IsInvalid) {
  // Sweep across both edges: 1 (no function code) and 255 (a PDU of 254 > 253) are impossible.
  for (const int length : {0, 1, 2, 3, 253, 254, 255, 256, 0xFFFF}) {
    const TcpFrame f = next_tcp_frame(mbap_frame(1, 0, 1, Bytes(300, 0x03), length));
    const bool possible = length >= 2 && length <= 254;
    EXPECT_EQ(f.kind, possible ? TcpFrameKind::Request : TcpFrameKind::Invalid) << "length " << length;
    if (possible) {
      EXPECT_EQ(f.length, 6U + static_cast<std::size_t>(length));
    }
  }
}

TEST(ModbusTcpFraming, ProtocolIdOtherThanZeroIsForeign) {
  for (const std::uint16_t protocol : {std::uint16_t{0x0001}, std::uint16_t{0x0100}, std::uint16_t{0xFFFF}}) {
    const TcpFrame f = next_tcp_frame(mbap_frame(7, protocol, 1, {4, 0, 0, 0, 1}));
    EXPECT_EQ(f.kind, TcpFrameKind::Foreign) << protocol;
    EXPECT_EQ(f.length, 12U); // skipped whole, so the next frame parses
  }
  EXPECT_EQ(next_tcp_frame(mbap_frame(7, 0, 1, {4, 0, 0, 0, 1})).kind, TcpFrameKind::Request);
}

TEST(ModbusTcpFraming, AnswerEchoesTransactionAndUnitIds) {
  PlainMap m;
  m.input[2] = 0xBEEF;
  Bytes rsp;
  EXPECT_EQ(answer_tcp_request(m, mbap_frame(0xA55A, 0, 0x11, {4, 0, 2, 0, 1}), rsp), RegisterStatus::Ok);
  // FC 4 response: function, byte count 2, the register (MB application protocol §6.4).
  EXPECT_EQ(rsp, mbap_frame(0xA55A, 0, 0x11, {4, 2, 0xBE, 0xEF}));
}

TEST(ModbusTcpFraming, TruncatedPduWithConsistentLengthGetsException3) {
  PlainMap m;
  const Bytes full{3, 0x04, 0x00, 0x00, 0x01}; // FC 3 at 1024, 1 register
  for (std::size_t keep = 1; keep < full.size(); ++keep) {
    const Bytes frame =
        mbap_frame(9, 0, 1, Bytes(full.begin(), full.begin() + static_cast<std::ptrdiff_t>(keep)));
    ASSERT_EQ(next_tcp_frame(frame).kind, TcpFrameKind::Request);
    Bytes rsp;
    EXPECT_EQ(answer_tcp_request(m, frame, rsp), RegisterStatus::IllegalDataValue) << keep;
    EXPECT_EQ(rsp, mbap_frame(9, 0, 1, {0x83, 0x03})) << keep; // exception: function | 0x80, code 03
  }
  Bytes rsp;
  EXPECT_EQ(answer_tcp_request(m, mbap_frame(9, 0, 1, full), rsp), RegisterStatus::Ok);
}

TEST(ModbusTcpFraming, BytesWithoutAFunctionCodeAreNotAnswered) {
  PlainMap m;
  Bytes rsp;
  const Bytes header = mbap_frame(3, 0, 1, {});
  EXPECT_EQ(answer_tcp_request(m, header, rsp), RegisterStatus::IllegalDataValue);
  EXPECT_TRUE(rsp.empty());
}

TEST(ModbusTcpFraming, UnknownFunctionGetsException1) {
  PlainMap m;
  Bytes rsp;
  EXPECT_EQ(answer_tcp_request(m, mbap_frame(3, 0, 1, {0x41, 1, 2, 3}), rsp),
            RegisterStatus::IllegalFunction);
  EXPECT_EQ(rsp, mbap_frame(3, 0, 1, {0xC1, 0x01}));
}

} // namespace
} // namespace hilrig::drivers::modbus
