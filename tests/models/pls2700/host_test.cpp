// The BTW command set and the programming error byte (pls2700.md §5.3-§5.5; W10-W13, W22):
// every one of the 21 error codes, the rule that a bad instruction stops the rest of the BTW
// and that later BTWs are ignored (24h) until Clear Errors, and atomic instructions.
#include <gtest/gtest.h>

#include <initializer_list>
#include <vector>

#include "models/pls2700/error_codes.hpp"
#include "models/pls2700/register_map.hpp"
#include "pls2700_bench.hpp"

namespace hilrig::models::pls2700 {
namespace {

using namespace hilrig::literals;
using testing::Bench;

// The error byte a fresh module of `model` answers to one BTW.
std::uint8_t answer(ModelVariant model, std::initializer_list<std::uint16_t> words) {
  Bench b(model);
  return b.btw(words);
}

TEST(Pls2700Errors, AllTwentyOneCodes) {
  using M = ModelVariant;
  // 00h accepted.
  EXPECT_EQ(answer(M::M2741, {0x8801, 0x0360}), 0x00);
  // 21h: 0000h, unknown commands, channel 2 on a 1-channel module (L1350 [X] -> 21h),
  // the CL bit on a standard module, a non-zero X digit.
  EXPECT_EQ(answer(M::M2741, {0x0000}), 0x21);
  EXPECT_EQ(answer(M::M2741, {0x8500}), 0x21);
  EXPECT_EQ(answer(M::M2741, {0x8101}), 0x21);
  EXPECT_EQ(answer(M::M2741, {0x9801, 0x0360}), 0x21);
  EXPECT_EQ(answer(M::M2742, {0x8808, 0x0100}), 0x21);
  EXPECT_EQ(answer(M::M2742, {0x8811, 0x0360}), 0x21);
  // 22h: missing data words.
  EXPECT_EQ(answer(M::M2741, {0x8801}), 0x22);
  EXPECT_EQ(answer(M::M2741, {0xC012, 0x0000, 0x0010, 0x0020}), 0x22);
  // 24h: see StopsTheRestAndIgnoresLaterBtws.
  // 41h/42h/44h: ch1 SF 2..1024 (273x) / 2..4096 (274x), CO 0..SF-1, TR 0..4; bad BCD too.
  EXPECT_EQ(answer(M::M2731, {0x8801, 0x1025}), 0x41);
  EXPECT_EQ(answer(M::M2741, {0x8801, 0x1025}), 0x00);
  EXPECT_EQ(answer(M::M2741, {0x8801, 0x4096}), 0x00);
  EXPECT_EQ(answer(M::M2741, {0x8801, 0x4097}), 0x41);
  EXPECT_EQ(answer(M::M2741, {0x8801, 0x0001}), 0x41);
  EXPECT_EQ(answer(M::M2741, {0x8801, 0x036A}), 0x41);
  EXPECT_EQ(answer(M::M2741, {0x8802, 0x0360}), 0x42);
  EXPECT_EQ(answer(M::M2741, {0x8802, 0x0359}), 0x00);
  EXPECT_EQ(answer(M::M2741, {0x8804, 0x0005}), 0x44);
  // 48h: Output Allocation 0..8 in ch1's TR high byte.
  EXPECT_EQ(answer(M::M2742, {0x8804, 0x0903}), 0x48);
  // 51h/52h/54h: channel 2.
  EXPECT_EQ(answer(M::M2742, {0x9801, 0x0001}), 0x51);
  EXPECT_EQ(answer(M::M2742, {0x9802, 0x0360}), 0x52);
  EXPECT_EQ(answer(M::M2742, {0x9804, 0x0005}), 0x54);
  // 43h/45h/53h/55h: 2742-18 Cycle Length 1..SF and IP/OT 0..3.
  EXPECT_EQ(answer(M::M2742_18, {0x8808, 0x0000}), 0x43);
  EXPECT_EQ(answer(M::M2742_18, {0x8808, 0x0361}), 0x43);
  EXPECT_EQ(answer(M::M2742_18, {0x8808, 0x0360}), 0x00);
  EXPECT_EQ(answer(M::M2742_18, {0x8804, 0x0403}), 0x45);
  EXPECT_EQ(answer(M::M2742_18, {0x9808, 0x0000}), 0x53);
  EXPECT_EQ(answer(M::M2742_18, {0x9804, 0x0403}), 0x55);
  // 8nh: output digit not 1..8; Anh: pair digit not 1..8.
  EXPECT_EQ(answer(M::M2741, {0xC001, 0x0000, 0x0010, 0x0020}), 0x80);
  EXPECT_EQ(answer(M::M2741, {0xC091, 0x0000, 0x0010, 0x0020}), 0x89);
  EXPECT_EQ(answer(M::M2741, {0xC010}), 0xA0);
  EXPECT_EQ(answer(M::M2741, {0xC019}), 0xA9);
  // Cnh/Dnh: ON/OFF setpoint > SF - 1 (SF 360).
  EXPECT_EQ(answer(M::M2741, {0xC031, 0x0000, 0x0360, 0x0000}), 0xC3);
  EXPECT_EQ(answer(M::M2741, {0xC031, 0x0000, 0x0010, 0x0360}), 0xD3);
  EXPECT_EQ(answer(M::M2741, {0xC031, 0x0000, 0x0359, 0x0000}), 0x00);
  // Enh/Fnh: advances 0..99 (bad BCD), non-zero on outputs 6-8 of 27x1, OFF > ON.
  EXPECT_EQ(answer(M::M2741, {0xC051, 0xA000, 0x0010, 0x0020}), 0xE5);
  EXPECT_EQ(answer(M::M2741, {0xC061, 0x0100, 0x0010, 0x0020}), 0xE6);
  EXPECT_EQ(answer(M::M2741, {0xC051, 0x050A, 0x0010, 0x0020}), 0xF5);
  EXPECT_EQ(answer(M::M2741, {0xC051, 0x0506, 0x0010, 0x0020}), 0xF5);
  EXPECT_EQ(answer(M::M2741, {0xC071, 0x0001, 0x0010, 0x0020}), 0xF7);
}

TEST(Pls2700Errors, StopsTheRestAndIgnoresLaterBtws) {
  // L1340, L1438: earlier instructions stay applied; the failing one and all later ones are
  // discarded. L1413/L1435: until Clear Errors every BTW is Message Ignored (24h); a BTW that
  // starts with Clear Errors is processed (sample program, L1464/L1476).
  Bench b(ModelVariant::M2741);
  EXPECT_EQ(b.btw({0x8801, 0x0720, 0xC011, 0x0000, 0x0800, 0x0810, 0x83F0}), 0xC1);
  EXPECT_EQ(b.device().setup().channels[0].scale_factor, 720);
  EXPECT_EQ(b.device().setup().outputs[0].pair_count, 0);
  EXPECT_EQ(b.device().setup().mask, 0xFF);
  EXPECT_EQ(b.btw({0x83F0}), error::kMessageIgnored);
  EXPECT_EQ(b.device().setup().mask, 0xFF);
  EXPECT_EQ(b.device().status_word() >> 8, 0x24);
  EXPECT_EQ(b.btw({0x8400, 0x83F0}), error::kNone);
  EXPECT_EQ(b.device().setup().mask, 0xF0);
}

TEST(Pls2700Errors, RejectedInstructionChangesNothing) {
  // Atomicity (L1340): A807h with an invalid ch2 TR (5) keeps every earlier value.
  Bench b(ModelVariant::M2742);
  EXPECT_EQ(b.btw({0xA807, 0x0360, 0x0720, 0x0090, 0x0600, 0x0402, 0x0005}), 0x54);
  const pls2700::Setup& s = b.device().setup();
  EXPECT_EQ(s.channels[0].circular_offset, 0);
  EXPECT_EQ(s.channels[1].scale_factor, 360);
  EXPECT_EQ(s.channels[0].tach_code, 3);
  EXPECT_EQ(s.output_allocation, 8);
}

TEST(Pls2700Commands, W10W11StoreScaleFactorThenOffsetAndTach) {
  // W10 (L1367): 8801h takes exactly one data word. W11 (L1370): 8806h 0090h 0002h -> CO 90,
  // TR 2 (120 ms), SF unchanged.
  Bench b(ModelVariant::M2731);
  EXPECT_EQ(b.btw({0x8801, 0x0500}), error::kNone);
  EXPECT_EQ(b.btw({0x8806, 0x0090, 0x0002}), error::kNone);
  EXPECT_EQ(b.device().setup().channels[0].scale_factor, 500);
  EXPECT_EQ(b.device().setup().channels[0].circular_offset, 90);
  EXPECT_EQ(b.device().setup().channels[0].tach_code, 2);
}

TEST(Pls2700Commands, W13LimitHeaderCountsElevenDataWords) {
  // W13 (L1392): C065h = output 6, 5 pairs, 1 + 2 * 5 = 11 data words.
  std::vector<std::uint16_t> words{0xC065, 0x0000};
  for (std::uint16_t k = 0; k < 10; ++k) {
    words.push_back(to_bcd(10 * (k + 1)));
  }
  Bench b(ModelVariant::M2742);
  EXPECT_EQ(b.device().write_btw(std::span(words).first(11)), error::kInvalidLength);
  b.btw({0x8400});
  EXPECT_EQ(b.device().write_btw(words), error::kNone);
  EXPECT_EQ(b.device().setup().outputs[5].pair_count, 5);
  EXPECT_EQ(b.device().setup().outputs[5].pairs[4], (SetpointPair{90, 100}));
}

TEST(Pls2700Commands, W22SurplusDataWordIsACommand) {
  // W22 (L1411): 8807h then four data words: the first instruction is applied, the fourth
  // word (0001h) is decoded as a command -> 21h.
  Bench b(ModelVariant::M2741);
  EXPECT_EQ(b.btw({0x8807, 0x0720, 0x0100, 0x0001, 0x0001}), 0x21);
  EXPECT_EQ(b.device().setup().channels[0].scale_factor, 720);
  EXPECT_EQ(b.device().setup().channels[0].circular_offset, 100);
  EXPECT_EQ(b.device().setup().channels[0].tach_code, 1);
}

TEST(Pls2700Commands, SeveralInstructionsInOneBtw) {
  // §5.3: a BTW is a sequence of instructions; 64 words maximum.
  Bench b(ModelVariant::M2742);
  EXPECT_EQ(b.btw({0x8100, 0x83C3, 0x9801, 0x1000, 0xC081, 0x0000, 0x0001, 0x0002}), error::kNone);
  EXPECT_TRUE(b.device().setup().keyboard_disabled);
  EXPECT_EQ(b.device().setup().mask, 0xC3);
  EXPECT_EQ(b.device().setup().channels[1].scale_factor, 1000);
  EXPECT_EQ(b.device().setup().outputs[7].pair_count, 1);
}

TEST(Pls2700RegisterMap, BtwAndBtrWordByWord) {
  // README register map: holding 0.. = one BTW per write; input 0..2 = BTR (1-ch);
  // input 16 = 2731-04 single transfer; holding 64 = error byte.
  Bench b(ModelVariant::M2731_04);
  Pls2700Registers regs(b.device());
  const std::vector<std::uint16_t> btw{0x8400, 0x8801, 0x0360, 0xC011, 0x0000, 0x0010, 0x0020};
  EXPECT_EQ(regs.write_holding_registers(0, btw), RegisterStatus::Ok);
  b.hold(1, 15, 360);
  b.run_for(1_ms);
  std::vector<std::uint16_t> in(3);
  EXPECT_EQ(regs.read_input_registers(0, in), RegisterStatus::Ok);
  EXPECT_EQ(in, (std::vector<std::uint16_t>{15, 0, 0x0001}));
  std::vector<std::uint16_t> st(1);
  EXPECT_EQ(regs.read_input_registers(16, st), RegisterStatus::Ok);
  EXPECT_EQ(st[0], 15);
  std::vector<std::uint16_t> echo(7);
  EXPECT_EQ(regs.read_holding_registers(0, echo), RegisterStatus::Ok);
  EXPECT_EQ(echo, btw);
  EXPECT_EQ(regs.write_holding_registers(0, std::vector<std::uint16_t>{0x0000}), RegisterStatus::Ok);
  std::vector<std::uint16_t> err(1);
  EXPECT_EQ(regs.read_holding_registers(64, err), RegisterStatus::Ok);
  EXPECT_EQ(err[0], 0x21);
  // Out of the map.
  EXPECT_EQ(regs.read_input_registers(1, in), RegisterStatus::IllegalDataAddress);
  EXPECT_EQ(regs.write_holding_registers(5, btw), RegisterStatus::IllegalDataAddress);
  EXPECT_EQ(regs.write_holding_registers(0, std::vector<std::uint16_t>(65, 0x8400)),
            RegisterStatus::IllegalDataValue);
  Bench two(ModelVariant::M2742);
  Pls2700Registers regs2(two.device());
  std::vector<std::uint16_t> five(5);
  EXPECT_EQ(regs2.read_input_registers(0, five), RegisterStatus::Ok);
  EXPECT_EQ(regs2.read_input_registers(16, st), RegisterStatus::IllegalDataAddress);
}

} // namespace
} // namespace hilrig::models::pls2700
