// The host words as Modbus registers (README "Register map"): input registers 0..6 =
// %I, %AI1..6; holding registers 0..6 = %Q, %AQ1..6.

#include <gtest/gtest.h>

#include <array>
#include <stdexcept>

#include "models/ssi7361/registers.hpp"
#include "ssi7361_rig.hpp"

namespace hilrig::models::ssi7361::test {
namespace {

TEST(Ssi7361Registers, OneWriteProgramsAndTheInputsShowTheResult) {
  Rig rig; // no transducer: raw 0x1FFFFFF
  rig.run_for(1_ms);
  Ssi7361Registers regs(rig.module());
  // The checkout block with TRMT and AplyPst in one FC 16 write (M-04, M-05).
  const std::array<std::uint16_t, 7> block{0x803F, 266, 1000, 1024, 0xE9EC, 0x0001, 500};
  ASSERT_EQ(regs.write_holding_registers(0, block), RegisterStatus::Ok);
  std::array<std::uint16_t, 7> in{};
  ASSERT_EQ(regs.read_input_registers(0, in), RegisterStatus::Ok);
  EXPECT_EQ(in[0], 0x8000); // %I: ACK, no error
  EXPECT_EQ(in[1], 0xE9EC); // %AI1: DV 125,420 low
  EXPECT_EQ(in[2], 0x0001); // %AI2: DV high
  EXPECT_EQ(in[3], 0x0000); // %AI3/4: RoC 0
  EXPECT_EQ(in[4], 0x0000);
  EXPECT_EQ(in[5], 0xFFFF); // %AI5: raw low
  EXPECT_EQ(in[6], 0x01FF); // %AI6: raw high
  std::array<std::uint16_t, 7> back{};
  ASSERT_EQ(regs.read_holding_registers(0, back), RegisterStatus::Ok);
  EXPECT_EQ(back, block);
  // FC 6 on %Q alone: TRMT 1 -> 0 drops ACK.
  const std::array<std::uint16_t, 1> q{0x003F};
  ASSERT_EQ(regs.write_holding_registers(0, q), RegisterStatus::Ok);
  std::array<std::uint16_t, 1> i{};
  ASSERT_EQ(regs.read_input_registers(0, i), RegisterStatus::Ok);
  EXPECT_EQ(i[0], 0);
  // A part of the map: raw words only.
  std::array<std::uint16_t, 2> raw{};
  ASSERT_EQ(regs.read_input_registers(5, raw), RegisterStatus::Ok);
  EXPECT_EQ(raw, (std::array<std::uint16_t, 2>{0xFFFF, 0x01FF}));
}

TEST(Ssi7361Registers, OutsideTheMapIsIllegalDataAddress) {
  Rig rig;
  Ssi7361Registers regs(rig.module());
  std::array<std::uint16_t, 3> three{};
  std::array<std::uint16_t, 1> one{};
  EXPECT_EQ(regs.read_input_registers(5, three), RegisterStatus::IllegalDataAddress);
  EXPECT_EQ(regs.read_input_registers(7, one), RegisterStatus::IllegalDataAddress);
  EXPECT_EQ(regs.read_holding_registers(7, one), RegisterStatus::IllegalDataAddress);
  EXPECT_EQ(regs.write_holding_registers(6, std::span<const std::uint16_t>(three)),
            RegisterStatus::IllegalDataAddress);
  EXPECT_EQ(regs.read_input_registers(0, std::span<std::uint16_t>{}), RegisterStatus::IllegalDataValue);
  EXPECT_EQ(rig.module().command_words(), CommandWords{}); // the refused write left nothing
}

} // namespace
} // namespace hilrig::models::ssi7361::test

namespace hilrig::models::ssi7361::test {
namespace {

TEST(Ssi7361HostWords, WordsPastTheMapThrow) {
  Rig rig;
  const std::array<std::uint16_t, 2> two{1, 2};
  std::array<std::uint16_t, 2> out{};
  EXPECT_THROW(rig.module().write_command_words(6, two), std::out_of_range);
  EXPECT_THROW(rig.module().write_command(7, 0), std::out_of_range);
  EXPECT_THROW(rig.module().read_status_words(6, out), std::out_of_range);
  EXPECT_NO_THROW(rig.module().read_status_words(5, out));
}

} // namespace
} // namespace hilrig::models::ssi7361::test
