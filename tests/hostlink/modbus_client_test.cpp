// The Modbus RTU host link against a scripted board on a pty pair: the board side is
// written by hand from the Modbus spec (frames and CRC-16/MODBUS), not with libmodbus, so
// the client is checked against an independent peer.
#include "drivers/hostlink/modbus_client.hpp"

#include <poll.h>
#include <pty.h>
#include <termios.h>
#include <unistd.h>

#include <gtest/gtest.h>

#include <array>
#include <functional>
#include <thread>
#include <vector>

using namespace hilrig;
using namespace hilrig::hostlink;

namespace {

// CRC-16/MODBUS (poly 0xA001 reflected, init 0xFFFF), low byte first on the wire.
std::uint16_t crc16_modbus(const std::vector<std::uint8_t>& bytes) {
  std::uint16_t crc = 0xFFFF;
  for (std::uint8_t b : bytes) {
    crc = static_cast<std::uint16_t>(crc ^ b);
    for (int i = 0; i < 8; ++i) {
      crc = (crc & 1U) != 0 ? static_cast<std::uint16_t>((crc >> 1) ^ 0xA001)
                            : static_cast<std::uint16_t>(crc >> 1);
    }
  }
  return crc;
}

std::vector<std::uint8_t> with_crc(std::vector<std::uint8_t> pdu) {
  const std::uint16_t crc = crc16_modbus(pdu);
  pdu.push_back(static_cast<std::uint8_t>(crc & 0xFF));
  pdu.push_back(static_cast<std::uint8_t>(crc >> 8));
  return pdu;
}

// A board on the master side of a pty: reads one request of `request_len` bytes, then
// answers with whatever `reply` returns (nothing: a silent peer).
class ScriptedBoard {
public:
  ScriptedBoard() {
    termios raw{};
    cfmakeraw(&raw);
    std::array<char, 128> name{};
    if (openpty(&master_, &slave_, name.data(), &raw, nullptr) != 0) throw std::runtime_error("openpty");
    device = name.data();
  }
  ~ScriptedBoard() {
    if (thread_.joinable()) thread_.join();
    ::close(master_);
    ::close(slave_);
  }
  void serve_one(std::size_t request_len,
                 std::function<std::vector<std::uint8_t>(const std::vector<std::uint8_t>&)> reply) {
    thread_ = std::thread([this, request_len, reply = std::move(reply)] {
      std::vector<std::uint8_t> req;
      while (req.size() < request_len) {
        pollfd p{master_, POLLIN, 0};
        if (::poll(&p, 1, 2000) <= 0) return; // bounded: a test never hangs
        std::array<std::uint8_t, 64> buf{};
        const ssize_t n = ::read(master_, buf.data(), buf.size());
        if (n <= 0) return;
        req.insert(req.end(), buf.begin(), buf.begin() + n);
      }
      request = req;
      const auto out = reply(req);
      if (!out.empty()) (void)!::write(master_, out.data(), out.size());
    });
  }
  void join() {
    if (thread_.joinable()) thread_.join();
  }
  std::string device;
  std::vector<std::uint8_t> request;

private:
  int master_ = -1;
  int slave_ = -1;
  std::thread thread_;
};

RtuSettings settings_for(const ScriptedBoard& board) {
  RtuSettings s;
  s.device = board.device;
  s.unit = 1;
  s.response_timeout = milliseconds(100);
  return s;
}

} // namespace

TEST(ModbusCrc, MatchesThePublishedExampleFrame) {
  // "01 04 00 00 00 02 71 CB": read 2 input registers from unit 1, a frame found in every
  // Modbus RTU primer.
  EXPECT_EQ(with_crc({0x01, 0x04, 0x00, 0x00, 0x00, 0x02}),
            (std::vector<std::uint8_t>{0x01, 0x04, 0x00, 0x00, 0x00, 0x02, 0x71, 0xCB}));
}

TEST(ModbusRtuClient, ReadsInputRegistersFromAWellBehavedBoard) {
  ScriptedBoard board;
  board.serve_one(8, [](const auto&) { return with_crc({0x01, 0x04, 0x04, 0x12, 0x34, 0xAB, 0xCD}); });
  auto client = ModbusClient::rtu(settings_for(board));
  std::array<std::uint16_t, 2> words{};
  EXPECT_EQ(client->read_input_registers(0, words), RegisterStatus::Ok);
  board.join();
  EXPECT_EQ(board.request, (std::vector<std::uint8_t>{0x01, 0x04, 0x00, 0x00, 0x00, 0x02, 0x71, 0xCB}));
  EXPECT_EQ(words[0], 0x1234);
  EXPECT_EQ(words[1], 0xABCD);
}

TEST(ModbusRtuClient, WritesHoldingRegistersAsOneFunction16Frame) {
  ScriptedBoard board;
  // FC16 request: unit, 0x10, addr hi/lo, qty hi/lo, byte count, data..., CRC = 13 bytes for 2 words.
  board.serve_one(13, [](const auto&) { return with_crc({0x01, 0x10, 0x04, 0x00, 0x00, 0x02}); });
  auto client = ModbusClient::rtu(settings_for(board));
  const std::array<std::uint16_t, 2> words{0x8000, 0x0001};
  EXPECT_EQ(client->write_holding_registers(1024, words), RegisterStatus::Ok);
  board.join();
  EXPECT_EQ(board.request, with_crc({0x01, 0x10, 0x04, 0x00, 0x00, 0x02, 0x04, 0x80, 0x00, 0x00, 0x01}));
}

TEST(ModbusRtuClient, ExceptionReplyIsTheDevicesAnswerNotALinkError) {
  ScriptedBoard board;
  board.serve_one(8, [](const auto&) { return with_crc({0x01, 0x84, 0x02}); }); // illegal data address
  auto client = ModbusClient::rtu(settings_for(board));
  std::array<std::uint16_t, 2> words{};
  EXPECT_EQ(client->read_input_registers(0, words), RegisterStatus::IllegalDataAddress);
}

TEST(ModbusRtuClient, CorruptedCrcIsANamedErrorWithTheTransaction) {
  ScriptedBoard board;
  board.serve_one(8, [](const auto&) {
    auto frame = with_crc({0x01, 0x04, 0x04, 0x12, 0x34, 0xAB, 0xCD});
    frame.back() ^= 0x5A; // one byte hit on the line
    return frame;
  });
  auto client = ModbusClient::rtu(settings_for(board));
  std::array<std::uint16_t, 2> words{};
  try {
    (void)client->read_input_registers(0, words);
    FAIL() << "a bad CRC must not be taken as data";
  } catch (const HostLinkError& e) {
    EXPECT_EQ(e.failure(), LinkFailure::BadCrc);
    EXPECT_NE(e.transaction().find("read input registers 0..1"), std::string::npos) << e.what();
  }
}

TEST(ModbusRtuClient, SilentPeerIsATimeoutWithTheTransaction) {
  ScriptedBoard board;
  board.serve_one(8, [](const auto&) { return std::vector<std::uint8_t>{}; });
  auto client = ModbusClient::rtu(settings_for(board));
  std::array<std::uint16_t, 1> words{};
  try {
    (void)client->read_holding_registers(7, words);
    FAIL() << "no reply must be an error";
  } catch (const HostLinkError& e) {
    EXPECT_EQ(e.failure(), LinkFailure::Timeout);
    EXPECT_NE(std::string(e.what()).find("read holding registers 7..7"), std::string::npos) << e.what();
  }
}

TEST(ModbusTcpClient, RefusedConnectionNamesTheEndpoint) {
  TcpSettings s;
  s.host = "127.0.0.1";
  s.port = 1; // nothing listens on port 1 on loopback
  try {
    (void)ModbusClient::tcp(s);
    FAIL() << "connecting to a closed port must throw";
  } catch (const HostLinkError& e) {
    EXPECT_EQ(e.failure(), LinkFailure::ConnectionLost);
    EXPECT_NE(std::string(e.what()).find("127.0.0.1:1"), std::string::npos);
  }
}
