// The Modbus TCP server over a real loopback socket, with a libmodbus client: normal reads
// and writes, and bad requests answered with the right exception while the server keeps
// answering. The served device is the virtual SMD23E (unconfigured: SW1 = 0x6408, M-05); FC 23
// is also tried on the ANS1.
#include <gtest/gtest.h>
#include <modbus/modbus.h>

#include <array>
#include <cerrno>
#include <memory>

#include "tests/modbus/serve_thread.hpp"

namespace hilrig::test {
namespace {

struct ModbusClose {
  void operator()(modbus_t* c) const {
    modbus_close(c);
    modbus_free(c);
  }
};
using Client = std::unique_ptr<modbus_t, ModbusClose>;

Client connect(std::uint16_t port) {
  Client c(modbus_new_tcp("127.0.0.1", port));
  if (!c || modbus_connect(c.get()) != 0) {
    ADD_FAILURE() << "cannot connect: " << modbus_strerror(errno);
    return nullptr;
  }
  modbus_set_response_timeout(c.get(), 2, 0);
  return c;
}

// Sends a raw PDU (unit id first) and returns the response PDU (function, data...).
std::vector<std::uint8_t> raw(modbus_t* c, std::vector<std::uint8_t> pdu) {
  if (modbus_send_raw_request(c, pdu.data(), static_cast<int>(pdu.size())) < 0) {
    return {};
  }
  std::array<std::uint8_t, MODBUS_TCP_MAX_ADU_LENGTH> rsp{};
  const int rc = modbus_receive_confirmation(c, rsp.data());
  if (rc < 8) {
    return {};
  }
  return {rsp.begin() + 7, rsp.begin() + rc};
}

void expect_still_answering(modbus_t* c) {
  std::array<std::uint16_t, 10> in{};
  ASSERT_EQ(modbus_read_input_registers(c, 0, 10, in.data()), 10) << modbus_strerror(errno);
  EXPECT_EQ(in[0], 0x6408);
}

TEST(ModbusTcpServer, ServesTheSmd23eMap) {
  ServeThread server{smd23e_on_tcp()};
  Client c = connect(server.port());
  ASSERT_TRUE(c);
  expect_still_answering(c.get());
  // FC 3 reads the input words at 0 too, and the output words at 1024 (spec §6.1).
  std::array<std::uint16_t, 2> w{};
  ASSERT_EQ(modbus_read_registers(c.get(), 0, 1, w.data()), 1);
  EXPECT_EQ(w[0], 0x6408);
  const std::array<std::uint16_t, 2> out{0x8000, 0x8000};
  ASSERT_EQ(modbus_write_registers(c.get(), 1024, 2, out.data()), 2);
  ASSERT_EQ(modbus_read_registers(c.get(), 1024, 2, w.data()), 2);
  EXPECT_EQ(w[0], 0x8000);
  EXPECT_EQ(w[1], 0x8000);
  // Coil 16,384 + 15 is the mode bit of output word 0.
  std::array<std::uint8_t, 1> bit{};
  ASSERT_EQ(modbus_read_bits(c.get(), 16'384 + 15, 1, bit.data()), 1);
  EXPECT_EQ(bit[0], 1);
}

TEST(ModbusTcpServer, UnknownFunctionGetsIllegalFunctionAndServerKeepsAnswering) {
  ServeThread server{smd23e_on_tcp()};
  Client c = connect(server.port());
  ASSERT_TRUE(c);
  EXPECT_EQ(raw(c.get(), {1, 0x41}), (std::vector<std::uint8_t>{0xC1, MODBUS_EXCEPTION_ILLEGAL_FUNCTION}));
  expect_still_answering(c.get());
  // An unknown function carrying data: the data is drained, the next request parses.
  EXPECT_EQ(raw(c.get(), {1, 0x42, 1, 2, 3, 4}),
            (std::vector<std::uint8_t>{0xC2, MODBUS_EXCEPTION_ILLEGAL_FUNCTION}));
  expect_still_answering(c.get());
}

TEST(ModbusTcpServer, OutOfRangeAddressGetsIllegalDataAddress) {
  ServeThread server{smd23e_on_tcp()};
  Client c = connect(server.port());
  ASSERT_TRUE(c);
  std::array<std::uint16_t, 2> regs{};
  EXPECT_EQ(modbus_read_input_registers(c.get(), 100, 2, regs.data()), -1);
  EXPECT_EQ(errno, EMBXILADD);
  expect_still_answering(c.get());
  EXPECT_EQ(modbus_write_register(c.get(), 1034, 1), -1); // one past the output words
  EXPECT_EQ(errno, EMBXILADD);
  EXPECT_EQ(modbus_read_registers(c.get(), 10, 1, regs.data()), -1);
  EXPECT_EQ(errno, EMBXILADD);
  expect_still_answering(c.get());
}

TEST(ModbusTcpServer, WrongQuantityGetsIllegalDataValue) {
  ServeThread server{smd23e_on_tcp()};
  Client c = connect(server.port());
  ASSERT_TRUE(c);
  // FC 3, address 0, quantity 0.
  EXPECT_EQ(raw(c.get(), {1, 3, 0, 0, 0, 0}),
            (std::vector<std::uint8_t>{0x83, MODBUS_EXCEPTION_ILLEGAL_DATA_VALUE}));
  // FC 16 at 1024, 2 registers but a byte count of 2.
  EXPECT_EQ(raw(c.get(), {1, 16, 0x04, 0x00, 0, 2, 2, 0, 1}),
            (std::vector<std::uint8_t>{0x90, MODBUS_EXCEPTION_ILLEGAL_DATA_VALUE}));
  expect_still_answering(c.get());
}

TEST(ModbusTcpServer, ServesSeveralClientsAndSurvivesADisconnect) {
  ServeThread server{smd23e_on_tcp()};
  {
    Client first = connect(server.port());
    ASSERT_TRUE(first);
    expect_still_answering(first.get());
  } // closed
  Client a = connect(server.port());
  Client b = connect(server.port());
  ASSERT_TRUE(a && b);
  expect_still_answering(a.get());
  expect_still_answering(b.get());
}

// FC 23 performs "the write operation ... before the read" (Modbus Application Protocol
// v1.1b3, §6.17) on every served device but the SMD23E: the ANS1's command word 19 (holding
// register 1024 + 19, its README's host register map) reads back as written in the same
// transaction.
TEST(ModbusTcpServer, ReadWriteMultipleWritesBeforeItReadsOnTheAns1) {
  ServeThread server{ans1_on_tcp()};
  Client c = connect(server.port());
  ASSERT_TRUE(c);
  const std::array<std::uint16_t, 1> written{0x1234};
  std::array<std::uint16_t, 1> read{};
  ASSERT_EQ(modbus_write_and_read_registers(c.get(), 1043, 1, written.data(), 1043, 1, read.data()), 1)
      << modbus_strerror(errno);
  EXPECT_EQ(read[0], 0x1234);
}

// The SMD23E's FC 23 (its manual, L2076): "If you use the Read/Write Registers function to
// write configuration data to the unit, then the data read with that command will not contain
// the response to the new configuration data. The response to the new data will be sent with
// the next data read." What lags is the unit's response; the write itself is carried out
// first (§6.17), so the output words written read back as written.
TEST(ModbusTcpServer, Smd23eReadWriteAnswersWithItsResponseFromBeforeTheWrite) {
  ServeThread server{smd23e_on_tcp()};
  Client c = connect(server.port());
  ASSERT_TRUE(c);
  // A valid configuration (Table 9.2): Configuration Mode with every input general purpose,
  // driver enabled, v_s = 0·1000 + 100, 2048 steps/turn, 1024 encoder pulses/turn, 50 % idle
  // current, 2.0 A.
  const std::array<std::uint16_t, 10> config{0x8000, 0x8000, 0, 100, 2048, 0, 1024, 50, 20, 0};
  std::array<std::uint16_t, 1> status{};
  ASSERT_EQ(modbus_write_and_read_registers(c.get(), 1024, 10, config.data(), 0, 1, status.data()), 1)
      << modbus_strerror(errno);
  EXPECT_EQ(status[0], 0x6408); // the unconfigured unit's word 0 (L2372): from before the write
  std::array<std::uint16_t, 2> next{};
  ASSERT_EQ(modbus_read_input_registers(c.get(), 0, 2, next.data()), 2);
  EXPECT_EQ(next[0], 0x8000); // the Control Word, mirrored once accepted (L2372)
  EXPECT_EQ(next[1], 0x8000); // the Config Word, mirrored (Table 9.4, L2358)
  // Output word 7 (idle current, holding register 1031) written 40 reads back 40 at once.
  const std::array<std::uint16_t, 1> idle{40};
  std::array<std::uint16_t, 1> read{};
  ASSERT_EQ(modbus_write_and_read_registers(c.get(), 1031, 1, idle.data(), 1031, 1, read.data()), 1)
      << modbus_strerror(errno);
  EXPECT_EQ(read[0], 40);
}

} // namespace
} // namespace hilrig::test
