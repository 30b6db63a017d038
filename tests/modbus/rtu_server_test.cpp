// The Modbus RTU server (`hilrig serve ans1 --pty`) on the line: a frame with a bad CRC is
// dropped and counted and the next good one answered; a frame for another unit id is not
// answered (the client sees a Timeout) and the server answers its own unit afterwards; a
// broadcast write is carried out and never answered; bad addresses get exception replies.
// Raw frames are written straight onto the pty slave, with a CRC computed here (Modbus over
// Serial Line v1.02, §6.2.2: CRC-16, polynomial 0xA001 reflected, initial 0xFFFF, low byte
// first), so the server is checked against the spec, not against its own framing code.
#include <gtest/gtest.h>

#include <fcntl.h>
#include <poll.h>
#include <unistd.h>

#include <algorithm>
#include <array>
#include <cstdint>
#include <memory>
#include <vector>

#include "drivers/hostlink/modbus_client.hpp"
#include "tests/modbus/serve_thread.hpp"

namespace hilrig::test {
namespace {

std::uint16_t crc16(const std::vector<std::uint8_t>& bytes) {
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

std::vector<std::uint8_t> frame(std::vector<std::uint8_t> bytes) {
  const std::uint16_t crc = crc16(bytes);
  bytes.push_back(static_cast<std::uint8_t>(crc & 0xFFU));
  bytes.push_back(static_cast<std::uint8_t>(crc >> 8U));
  return bytes;
}

// A second opener of the pty slave that writes and reads raw bytes on the line.
class RawLine {
public:
  explicit RawLine(const std::string& path) : fd_(::open(path.c_str(), O_RDWR | O_NOCTTY | O_CLOEXEC)) {}
  RawLine(const RawLine&) = delete;
  RawLine& operator=(const RawLine&) = delete;
  ~RawLine() {
    if (fd_ >= 0) ::close(fd_);
  }
  [[nodiscard]] bool ok() const { return fd_ >= 0; }
  bool send(const std::vector<std::uint8_t>& bytes) {
    return ::write(fd_, bytes.data(), bytes.size()) == static_cast<ssize_t>(bytes.size());
  }
  // Reads n bytes; gives up after 2 s without a byte (a bound, not a measurement).
  std::vector<std::uint8_t> receive(std::size_t n) {
    std::vector<std::uint8_t> got;
    while (got.size() < n) {
      pollfd p{fd_, POLLIN, 0};
      if (::poll(&p, 1, 2000) <= 0) break;
      std::array<std::uint8_t, 256> buf{};
      const ssize_t r = ::read(fd_, buf.data(), std::min(buf.size(), n - got.size()));
      if (r <= 0) break;
      got.insert(got.end(), buf.begin(), buf.begin() + r);
    }
    return got;
  }

private:
  int fd_;
};

std::unique_ptr<hostlink::ModbusClient> client(const cli::ServeEndpoint& e, int unit,
                                               Nanos timeout = milliseconds(500)) {
  hostlink::RtuSettings s;
  s.device = e.serial_path;
  s.format = {19200, 8, Parity::Even, 1};
  s.unit = unit;
  s.response_timeout = timeout;
  return hostlink::ModbusClient::rtu(s);
}

// Waits (bounded: up to 5,000 rounds of 1 ms) until the counter reaches `value`.
bool reaches(const std::atomic<std::uint64_t>& counter, std::uint64_t value) {
  for (int i = 0; i < 5000 && counter.load() < value; ++i) {
    ::poll(nullptr, 0, 1);
  }
  return counter.load() >= value;
}

// DA0 after power-up (docs/spec/ans1.md §5.5, line 944): status word 13 is module ID 83.
void expect_answers(hostlink::ModbusClient& c) {
  std::array<std::uint16_t, 1> w{};
  ASSERT_EQ(c.read_input_registers(13, w), RegisterStatus::Ok);
  EXPECT_EQ(w[0], 83);
}

TEST(ModbusRtuServer, BadCrcIsDroppedAndTheNextRequestAnswered) {
  ServeThread server(ans1_on_pty());
  const auto& stats = *server.endpoint().rtu_stats;
  auto c = client(server.endpoint(), 1);
  RawLine line(server.endpoint().serial_path);
  ASSERT_TRUE(line.ok());
  // FC 4, input register 13, count 1, with the CRC's low byte flipped.
  std::vector<std::uint8_t> bad = frame({1, 4, 0, 13, 0, 1});
  bad[6] = static_cast<std::uint8_t>(bad[6] ^ 0xFFU);
  ASSERT_TRUE(line.send(bad));
  // Had the server answered the bad frame, this read would receive that stale reply first.
  expect_answers(*c);
  EXPECT_EQ(stats.crc_errors.load(), 1U);
  EXPECT_EQ(stats.requests.load(), 1U);
}

TEST(ModbusRtuServer, AnotherUnitIdIsNotAnswered) {
  ServeThread server(ans1_on_pty(1));
  const auto& stats = *server.endpoint().rtu_stats;
  {
    auto other = client(server.endpoint(), 2, milliseconds(100));
    std::array<std::uint16_t, 1> w{};
    try {
      (void)other->read_input_registers(13, w);
      ADD_FAILURE() << "unit 2 was answered by unit 1";
    } catch (const hostlink::HostLinkError& e) {
      EXPECT_EQ(e.failure(), hostlink::LinkFailure::Timeout) << e.what();
    }
  }
  ASSERT_TRUE(reaches(stats.other_unit, 1));
  auto own = client(server.endpoint(), 1);
  expect_answers(*own);
  EXPECT_EQ(stats.requests.load(), 1U);
}

TEST(ModbusRtuServer, BroadcastWriteIsCarriedOutAndNotAnswered) {
  ServeThread server(ans1_on_pty());
  const auto& stats = *server.endpoint().rtu_stats;
  auto c = client(server.endpoint(), 1);
  RawLine line(server.endpoint().serial_path);
  ASSERT_TRUE(line.ok());
  // FC 6 to unit 0: command word 5 (holding register 1029 = 0x0405) = 0x002A.
  ASSERT_TRUE(line.send(frame({0, 6, 0x04, 0x05, 0x00, 0x2A})));
  // A reply to the broadcast would be read here as this request's confirmation and fail it.
  std::array<std::uint16_t, 1> w{};
  ASSERT_EQ(c->read_holding_registers(1029, w), RegisterStatus::Ok);
  EXPECT_EQ(w[0], 0x2A);
  EXPECT_EQ(stats.broadcasts.load(), 1U);
  EXPECT_EQ(stats.requests.load(), 2U);
}

TEST(ModbusRtuServer, OutOfRangeAddressesGetIllegalDataAddress) {
  // The ANS1's map (README "Host register map"): status words 0..19 at input registers 0..19,
  // command words 0..19 at holding registers 1024..1043; nothing else.
  ServeThread server(ans1_on_pty());
  const auto& stats = *server.endpoint().rtu_stats;
  auto c = client(server.endpoint(), 1);
  std::array<std::uint16_t, 2> w{};
  EXPECT_EQ(c->read_input_registers(19, w), RegisterStatus::IllegalDataAddress); // 19..20
  EXPECT_EQ(c->read_holding_registers(1023, w), RegisterStatus::IllegalDataAddress);
  EXPECT_EQ(c->read_holding_registers(1043, w), RegisterStatus::IllegalDataAddress); // 1043..1044
  EXPECT_EQ(c->write_holding_registers(1043, w), RegisterStatus::IllegalDataAddress);
  EXPECT_EQ(c->write_holding_registers(0, w), RegisterStatus::IllegalDataAddress);
  EXPECT_EQ(stats.exceptions.load(), 5U);
  // The edges themselves are served, and the server keeps answering.
  EXPECT_EQ(c->read_input_registers(18, w), RegisterStatus::Ok);
  EXPECT_EQ(c->read_holding_registers(1042, w), RegisterStatus::Ok);
  expect_answers(*c);
}

TEST(ModbusRtuServer, UnknownFunctionGetsIllegalFunction) {
  // FC 0x41 with no data is a complete 4-byte frame; the reply is 0xC1, code 1.
  ServeThread server(ans1_on_pty());
  RawLine line(server.endpoint().serial_path);
  ASSERT_TRUE(line.ok());
  ASSERT_TRUE(line.send(frame({1, 0x41})));
  EXPECT_EQ(line.receive(5), frame({1, 0xC1, 1}));
  // FC 4 with a count of 0 is Illegal Data Value (code 3).
  ASSERT_TRUE(line.send(frame({1, 4, 0, 0, 0, 0})));
  EXPECT_EQ(line.receive(5), frame({1, 0x84, 3}));
  // And a good read is answered: FC 4, register 13 = 83 (0x0053).
  ASSERT_TRUE(line.send(frame({1, 4, 0, 13, 0, 1})));
  EXPECT_EQ(line.receive(7), frame({1, 4, 2, 0x00, 0x53}));
}

TEST(ModbusRtuServer, UnknownFunctionWithDataGetsIllegalFunctionAndTheNextRequestIsAnswered) {
  // FC 8 (Diagnostics, not served) with a sub-function and data: its length is not fixed by
  // the function code, so the frame ends at the 3.5-character silence (Serial Line §2.5.1.1)
  // and is answered with exception 01; the next request, sent once that reply is in, is
  // answered at once rather than lost in the rest of the first frame.
  ServeThread server(ans1_on_pty());
  const auto& stats = *server.endpoint().rtu_stats;
  RawLine line(server.endpoint().serial_path);
  ASSERT_TRUE(line.ok());
  for (const std::vector<std::uint8_t>& unknown :
       {std::vector<std::uint8_t>{1, 8, 0, 0, 0x12, 0x34}, std::vector<std::uint8_t>{1, 0x42, 1, 2, 3, 4, 5},
        std::vector<std::uint8_t>{1, 0x64}}) {
    ASSERT_TRUE(line.send(frame(unknown)));
    EXPECT_EQ(line.receive(5), frame({1, static_cast<std::uint8_t>(unknown[1] | 0x80U), 1}));
    ASSERT_TRUE(line.send(frame({1, 4, 0, 13, 0, 1})));
    EXPECT_EQ(line.receive(7), frame({1, 4, 2, 0x00, 0x53}));
  }
  EXPECT_EQ(stats.crc_errors.load(), 0U);
  EXPECT_EQ(stats.requests.load(), 6U);
  EXPECT_EQ(stats.exceptions.load(), 3U);
}

TEST(ModbusRtuServer, ShortRequestWithAGoodCrcGetsIllegalDataValue) {
  // FC 4 without its count: the CRC is good, the PDU is short -> exception 03, and the line
  // stays in step for the next request.
  ServeThread server(ans1_on_pty());
  RawLine line(server.endpoint().serial_path);
  ASSERT_TRUE(line.ok());
  ASSERT_TRUE(line.send(frame({1, 4, 0, 13})));
  EXPECT_EQ(line.receive(5), frame({1, 0x84, 3}));
  ASSERT_TRUE(line.send(frame({1, 4, 0, 13, 0, 1})));
  EXPECT_EQ(line.receive(7), frame({1, 4, 2, 0x00, 0x53}));
}

TEST(ModbusRtuServer, AFrameCutShortEndsAtTheSilenceAndTheNextRequestIsAnswered) {
  // Serial Line v1.02 §2.5.1.1: a silence of 3.5 characters ends a frame, so the first three
  // bytes of an FC 4 request, left alone on the line, are a frame of their own (a bad CRC,
  // dropped) and the whole request sent after them is answered, not joined to them.
  ServeThread server(ans1_on_pty());
  const auto& stats = *server.endpoint().rtu_stats;
  RawLine line(server.endpoint().serial_path);
  ASSERT_TRUE(line.ok());
  ASSERT_TRUE(line.send({1, 4, 0}));
  ASSERT_TRUE(reaches(stats.crc_errors, 1));
  ASSERT_TRUE(line.send(frame({1, 4, 0, 13, 0, 1})));
  EXPECT_EQ(line.receive(7), frame({1, 4, 2, 0x00, 0x53}));
  EXPECT_EQ(stats.requests.load(), 1U);
}

TEST(ModbusRtuServer, AnotherSlavesReplyOnTheBusEndsAtTheSilence) {
  // On a shared RS-485 line the server hears the other slaves' replies. Unit 6's reply to an
  // FC 16 (unit, function, start, quantity, CRC: 8 bytes) read as a request would want a byte
  // count and data; the silence after it ends it instead, and our request that follows is
  // answered.
  ServeThread server(ans1_on_pty());
  const auto& stats = *server.endpoint().rtu_stats;
  RawLine line(server.endpoint().serial_path);
  ASSERT_TRUE(line.ok());
  ASSERT_TRUE(line.send(frame({6, 0x10, 0x04, 0x00, 0x00, 0x02})));
  for (int i = 0; i < 5000 && stats.other_unit.load() + stats.crc_errors.load() == 0; ++i)
    ::poll(nullptr, 0, 1);
  ASSERT_EQ(stats.other_unit.load() + stats.crc_errors.load(), 1U);
  ASSERT_TRUE(line.send(frame({1, 4, 0, 13, 0, 1})));
  EXPECT_EQ(line.receive(7), frame({1, 4, 2, 0x00, 0x53}));
}

} // namespace
} // namespace hilrig::test
