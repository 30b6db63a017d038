// The host words as a RegisterMap (registers.hpp, README "Register map"): the Modbus
// server's view of the module.
#include "amci4501_rig.hpp"
#include "models/amci4501/registers.hpp"

namespace hilrig::models::amci4501::test {
namespace {

// One FC 16 transaction programs mode 3 with a 500 ms timeout (Transmit in word 0 acts on
// word 1 written with it); input register 0 is the status word with Acknowledge.
TEST(Amci4501Registers, ProgramAndMeasureThroughRegisters) {
  Bench b;
  Amci4501Registers regs{*b.module};
  const std::array<std::uint16_t, 2> program{static_cast<std::uint16_t>(control::kMode3 | control::kTransmit),
                                             500};
  ASSERT_EQ(regs.write_holding_registers(0, program), RegisterStatus::Ok);
  std::array<std::uint16_t, 8> in{};
  ASSERT_EQ(regs.read_input_registers(0, in), RegisterStatus::Ok);
  EXPECT_EQ(in[0], status::kAcknowledge | mode_status_bit(3));
  const std::array<std::uint16_t, 1> done{control::kMode3};
  ASSERT_EQ(regs.write_holding_registers(0, done), RegisterStatus::Ok);
  std::array<std::uint16_t, 2> back{};
  ASSERT_EQ(regs.read_holding_registers(0, back), RegisterStatus::Ok);
  EXPECT_EQ(back, (std::array<std::uint16_t, 2>{control::kMode3, 500}));

  // W3 through the registers: 12,345 us -> input registers 1, 2 = 12, 345.
  b.start_pulse(us(1000), us(300));
  b.latch_pulse(us(13345), us(300));
  b.run_until(20_ms);
  std::array<std::uint16_t, 2> t{};
  ASSERT_EQ(regs.read_input_registers(1, t), RegisterStatus::Ok);
  EXPECT_EQ(t, (std::array<std::uint16_t, 2>{12, 345}));
  const std::array<std::uint16_t, 1> ack{control::kMode3 | control::kReceived};
  ASSERT_EQ(regs.write_holding_registers(0, ack), RegisterStatus::Ok);
  EXPECT_FALSE(b.bit(status::kNewValue));
}

// W21 (L243): ID code 3512 reserves 8 input and 8 output words: the image is words 0-7
// both ways, nothing beyond.
TEST(Amci4501Registers, W21EightInputAndEightOutputWords) {
  Bench b;
  Amci4501Registers regs{*b.module};
  std::array<std::uint16_t, 8> eight{};
  std::array<std::uint16_t, 9> nine{};
  EXPECT_EQ(regs.read_input_registers(0, eight), RegisterStatus::Ok);
  EXPECT_EQ(regs.read_holding_registers(0, eight), RegisterStatus::Ok);
  EXPECT_EQ(regs.read_input_registers(0, nine), RegisterStatus::IllegalDataAddress);
  EXPECT_EQ(regs.read_holding_registers(0, nine), RegisterStatus::IllegalDataAddress);
}

TEST(Amci4501Registers, AddressesOutsideTheImage) {
  Bench b;
  Amci4501Registers regs{*b.module};
  std::array<std::uint16_t, 8> eight{};
  std::array<std::uint16_t, 1> one{};
  EXPECT_EQ(regs.read_input_registers(0, eight), RegisterStatus::Ok);
  EXPECT_EQ(regs.read_input_registers(1, eight), RegisterStatus::IllegalDataAddress);
  EXPECT_EQ(regs.read_input_registers(8, one), RegisterStatus::IllegalDataAddress);
  EXPECT_EQ(regs.read_holding_registers(7, one), RegisterStatus::Ok);
  EXPECT_EQ(regs.read_holding_registers(65535, one), RegisterStatus::IllegalDataAddress);
  EXPECT_EQ(regs.write_holding_registers(8, one), RegisterStatus::IllegalDataAddress);
  EXPECT_EQ(regs.read_input_registers(0, std::span<std::uint16_t>{}), RegisterStatus::IllegalDataValue);
  EXPECT_EQ(regs.write_holding_registers(0, std::span<const std::uint16_t>{}),
            RegisterStatus::IllegalDataValue);
}

} // namespace
} // namespace hilrig::models::amci4501::test
