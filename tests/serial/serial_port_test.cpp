#include "drivers/serial/serial_port.hpp"

#include <fcntl.h>
#include <pty.h>
#include <termios.h>
#include <unistd.h>

#include <gtest/gtest.h>

#include <array>
#include <vector>

using namespace hilrig;
using hilrig::serial::SerialPort;
using hilrig::serial::SerialPortSettings;

namespace {

// A pty pair: the rig opens the slave side as its "serial port"; the test plays the board
// on the master side.
struct Pty {
  Pty() {
    termios raw{};
    cfmakeraw(&raw);
    std::array<char, 128> name{};
    if (openpty(&master, &slave, name.data(), &raw, nullptr) != 0) throw std::runtime_error("openpty");
    slave_name = name.data();
  }
  ~Pty() {
    ::close(master);
    ::close(slave);
  }
  int master = -1;
  int slave = -1;
  std::string slave_name;
};

} // namespace

TEST(SerialPort, BytesWrittenByTheRigArriveAtTheBoardInOrder) {
  Pty pty;
  boost::asio::io_context io;
  SerialPort port(io, SerialPortSettings{pty.slave_name, SerialFormat{19200, 8, Parity::Even, 1}, false});
  const std::vector<std::uint8_t> frame{0x01, 0x03, 0x00, 0x00, 0x00, 0x14, 0x45, 0xC5};
  port.write(frame);
  while (port.queued_writes() > 0) io.run_one(); // the read stays pending; run only the write
  std::array<std::uint8_t, 16> got{};
  const ssize_t n = ::read(pty.master, got.data(), got.size());
  ASSERT_EQ(n, static_cast<ssize_t>(frame.size()));
  EXPECT_TRUE(std::equal(frame.begin(), frame.end(), got.begin()));
}

TEST(SerialPort, BytesFromTheBoardReachEveryHandlerWithATimestamp) {
  Pty pty;
  boost::asio::io_context io;
  SerialPort port(io, SerialPortSettings{pty.slave_name, SerialFormat{}, false});
  std::vector<std::uint8_t> got;
  std::vector<Nanos> stamps;
  port.on_byte([&](std::uint8_t b, Nanos t) {
    got.push_back(b);
    stamps.push_back(t);
    if (got.size() == 4) port.close(); // ends io.run()
  });
  const std::array<std::uint8_t, 4> reply{0xDE, 0xAD, 0xBE, 0xEF};
  ASSERT_EQ(::write(pty.master, reply.data(), reply.size()), 4);
  io.run();
  EXPECT_EQ(got, (std::vector<std::uint8_t>{0xDE, 0xAD, 0xBE, 0xEF}));
  for (const Nanos t : stamps) EXPECT_GT(t, Nanos{0});
}

TEST(SerialPort, MissingDeviceIsANamedError) {
  boost::asio::io_context io;
  try {
    SerialPort port(io, SerialPortSettings{"/dev/hilrig-no-such-port", SerialFormat{}, false});
    FAIL() << "opening a missing device must throw";
  } catch (const std::system_error& e) {
    EXPECT_NE(std::string(e.what()).find("/dev/hilrig-no-such-port"), std::string::npos);
  }
}

TEST(SerialPort, Rs485RequestOnAPtyIsRefusedAndReported) {
  // A pty has no RS-485 transceiver: the rig must know direction control is not active.
  Pty pty;
  boost::asio::io_context io;
  SerialPort port(io, SerialPortSettings{pty.slave_name, SerialFormat{}, true});
  EXPECT_FALSE(port.rs485_active());
}
