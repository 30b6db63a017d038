// The Modbus RTU server opening a serial device by path (here the slave side of a pty, so
// the test drives the line from the master side), single-threaded: the test writes a frame,
// turns the server's crank with serve_once() until it has taken the frame, and reads the
// reply. Frames and CRCs are built by hand from Modbus over Serial Line v1.02 §6.2.2.
#include <gtest/gtest.h>

#include <poll.h>
#include <unistd.h>

#include <algorithm>
#include <array>
#include <cstdint>
#include <vector>

#include "drivers/modbus/pty.hpp"
#include "drivers/modbus/rtu_server.hpp"

namespace hilrig::test {
namespace {

// A stand-in device: input registers 0..3 = 0x1111, 0x2222, 0x3333, 0x4444; no holding ones.
class FourInputs final : public RegisterMap {
public:
  RegisterStatus read_input_registers(std::uint16_t address, std::span<std::uint16_t> out) override {
    if (address + out.size() > 4) return RegisterStatus::IllegalDataAddress;
    for (std::size_t i = 0; i < out.size(); ++i)
      out[i] = static_cast<std::uint16_t>(0x1111U * (address + i + 1U));
    return RegisterStatus::Ok;
  }
  RegisterStatus read_holding_registers(std::uint16_t /*address*/,
                                        std::span<std::uint16_t> /*out*/) override {
    return RegisterStatus::IllegalDataAddress;
  }
  RegisterStatus write_holding_registers(std::uint16_t /*address*/,
                                         std::span<const std::uint16_t> /*values*/) override {
    return RegisterStatus::IllegalDataAddress;
  }
};

std::vector<std::uint8_t> frame(std::vector<std::uint8_t> bytes) {
  std::uint16_t crc = 0xFFFF;
  for (std::uint8_t b : bytes) {
    crc = static_cast<std::uint16_t>(crc ^ b);
    for (int i = 0; i < 8; ++i) {
      crc = (crc & 1U) != 0 ? static_cast<std::uint16_t>((crc >> 1U) ^ 0xA001U)
                            : static_cast<std::uint16_t>(crc >> 1U);
    }
  }
  bytes.push_back(static_cast<std::uint8_t>(crc & 0xFFU));
  bytes.push_back(static_cast<std::uint8_t>(crc >> 8U));
  return bytes;
}

// Sends a request and serves (at most 1,000 rounds) until the server has taken one more frame.
std::vector<std::uint8_t> exchange(drivers::modbus::RtuServer& server, int line,
                                   const std::vector<std::uint8_t>& req, std::size_t reply_length) {
  const std::uint64_t before = server.stats().requests.load() + server.stats().other_unit.load();
  EXPECT_EQ(::write(line, req.data(), req.size()), static_cast<ssize_t>(req.size()));
  for (int i = 0; i < 1000 && server.stats().requests.load() + server.stats().other_unit.load() == before;
       ++i) {
    server.serve_once();
  }
  std::vector<std::uint8_t> got;
  while (got.size() < reply_length) {
    pollfd p{line, POLLIN, 0};
    if (::poll(&p, 1, 2000) <= 0) break; // a bound, not a measurement
    std::array<std::uint8_t, 256> buf{};
    const ssize_t r = ::read(line, buf.data(), std::min(buf.size(), reply_length - got.size()));
    if (r <= 0) break;
    got.insert(got.end(), buf.begin(), buf.begin() + r);
  }
  return got;
}

TEST(ModbusRtuServerOnADevice, ServesItsUnitAndReportsRs485Unsupported) {
  drivers::modbus::Pty pty;
  FourInputs map;
  drivers::modbus::RtuServerOptions o;
  o.device = pty.slave_path();
  o.unit = 17;
  o.rs485 = true; // a pty has no RS-485 mode: reported, not fatal
  drivers::modbus::RtuServer server(map, o);
  EXPECT_FALSE(server.rs485_active());
  EXPECT_FALSE(server.rs485_note().empty());
  int ticks = 0;
  server.on_tick([&ticks] { ++ticks; });
  // FC 4, registers 1..2 of unit 17 (0x11): 0x2222, 0x3333.
  EXPECT_EQ(exchange(server, pty.master_fd(), frame({17, 4, 0, 1, 0, 2}), 9),
            frame({17, 4, 4, 0x22, 0x22, 0x33, 0x33}));
  EXPECT_GE(ticks, 2) << "ticked while waiting and again before answering";
  // Register 3..4 runs past the map: exception 2.
  EXPECT_EQ(exchange(server, pty.master_fd(), frame({17, 4, 0, 3, 0, 2}), 5), frame({17, 0x84, 2}));
  EXPECT_EQ(server.stats().exceptions.load(), 1U);
}

TEST(ModbusRtuServerOnADevice, RejectsAUnitIdOutsideTheModbusRange) {
  drivers::modbus::Pty pty;
  FourInputs map;
  drivers::modbus::RtuServerOptions o;
  o.device = pty.slave_path();
  o.unit = 248; // 1..247 are unit addresses; 0 is broadcast (Modbus over Serial Line §2.2)
  EXPECT_THROW(drivers::modbus::RtuServer(map, o), std::invalid_argument);
}

} // namespace
} // namespace hilrig::test
