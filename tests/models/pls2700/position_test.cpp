// Resolver decode, Scale Factor, Circular Offset and AutoZero (pls2700.md §2.3, §4.1, §4.2;
// examples W1-W3, W15, W16, W21), driven through the stator channels and host words.
#include <gtest/gtest.h>

#include <cmath>
#include <random>
#include <stdexcept>

#include "models/pls2700/bcd.hpp"
#include "models/pls2700/error_codes.hpp"
#include "models/pls2700/register_map.hpp"
#include "pls2700_bench.hpp"

namespace hilrig::models::pls2700 {
namespace {

using testing::Bench;
using namespace hilrig::literals;

TEST(Pls2700Offset, W1DesiredAboveCurrent) {
  // W1 (L348-L352): SF 4096, Cur 1234, Des 2000 -> CO = 766.
  EXPECT_EQ(offset_for(0, 1234, 2000, 4096), 766);
  EXPECT_EQ(machine_position(1234, 766, 4096), 2000);
}

TEST(Pls2700Offset, W2DesiredBelowCurrent) {
  // W2 (L354-L358): SF 1024, Cur 987, Des 123 -> 1024 - 864 = 160; (987 + 160) mod 1024 = 123.
  EXPECT_EQ(offset_for(0, 987, 123, 1024), 160);
  EXPECT_EQ(machine_position(987, 160, 1024), 123);
}

TEST(Pls2700Offset, W3ExistingOffsetUsesCorrectedSum) {
  // W3 (L360-L364): CO_old 983 + d 160 = 1143 (manual prints 1142) -> 1143 - 1024 = 119.
  EXPECT_EQ(offset_for(983, 987, 123, 1024), 119);
  // Absolute position (987 - 983) = 4; (4 + 119) = 123.
  EXPECT_EQ(machine_position(4, 119, 1024), 123);
  EXPECT_EQ(offset_for(0, 500, 500, 1024), 0); // Des == Cur: no change [I]
}

TEST(Pls2700Position, ReadsTheShaftThroughTheStatorsAtCountCentres) {
  // §2.3: SF 360 (default) -> count k at theta = (k + 0.5) / 360 turn reads k.
  Bench b(ModelVariant::M2741);
  for (int k : {0, 1, 90, 179, 359}) {
    b.hold(1, k, 360);
    b.run_for(1_ms);
    EXPECT_EQ(b.device().machine_position(1), k);
    EXPECT_EQ(b.btr()[0], k); // BTR word 1 = position, binary (L1316)
  }
}

TEST(Pls2700Position, RawCountIs8192PerTurn) {
  // L453: internal 1/8192 turn; SF 1024 = raw >> 3, SF 4096 = raw >> 1 (§2.3).
  Bench b(ModelVariant::M2741);
  EXPECT_EQ(b.btw({0x8801, 0x4096}), error::kNone);
  b.shaft(1, [](Nanos) { return 5001.5 / 8192.0; });
  b.run_for(1_ms);
  EXPECT_EQ(b.device().raw_position(1), 5001);
  EXPECT_EQ(b.device().machine_position(1), 5001 / 2);
}

TEST(Pls2700Position, PropertyMatchesTheDigestFormula) {
  // MP = (floor(floor(theta * 8192) * SF / 8192) + CO) mod SF for random angles, SF, CO;
  // angles kept 0.3 raw count away from a boundary so the truncation is unambiguous.
  std::mt19937 rng(2700);
  std::uniform_int_distribution<int> sf_dist(2, 4096);
  std::uniform_int_distribution<int> raw_dist(0, 8191);
  Bench b(ModelVariant::M2741);
  for (int trial = 0; trial < 60; ++trial) {
    const int sf = sf_dist(rng);
    const int co = std::uniform_int_distribution<int>(0, sf - 1)(rng);
    const int raw = raw_dist(rng);
    ASSERT_EQ(b.btw({0x8803, to_bcd(sf), to_bcd(co)}), error::kNone);
    b.shaft(1, [raw](Nanos) { return (raw + 0.3) / 8192.0; });
    b.run_for(1_ms);
    const int expected = static_cast<int>((static_cast<long>(raw) * sf / 8192 + co) % sf);
    EXPECT_EQ(b.device().machine_position(1), expected) << "sf " << sf << " co " << co << " raw " << raw;
  }
}

TEST(Pls2700Position, ScaleFactorProgrammingResetsTheOffset) {
  // R-SF-2 (L340, L653): programming SF sets CO := 0.
  Bench b(ModelVariant::M2741);
  b.hold(1, 100, 360);
  EXPECT_EQ(b.btw({0x8802, 0x0050}), error::kNone); // CO 50
  b.run_for(1_ms);
  EXPECT_EQ(b.device().machine_position(1), 150);
  EXPECT_EQ(b.btw({0x8801, 0x0360}), error::kNone); // same SF again: CO back to 0
  b.run_for(1_ms);
  EXPECT_EQ(b.device().setup().channels[0].circular_offset, 0);
  EXPECT_EQ(b.device().machine_position(1), 100);
}

TEST(Pls2700Position, HostOffsetFromW2MakesTheReadingTheDesiredOne) {
  // W2 through the module: SF 1024, shaft at count 987, host writes CO 160 -> reads 123.
  Bench b(ModelVariant::M2731);
  EXPECT_EQ(b.btw({0x8801, 0x1024}), error::kNone);
  b.hold(1, 987, 1024);
  b.run_for(1_ms);
  EXPECT_EQ(b.device().machine_position(1), 987);
  EXPECT_EQ(b.btw({0x8802, 0x0160}), error::kNone);
  b.run_for(1_ms);
  EXPECT_EQ(b.device().machine_position(1), 123);
}

TEST(Pls2700Position, AutoZeroMakesThePresentPositionZero) {
  // R-CO-3 (L366-L368): CO := (CO_old - Cur) mod SF. SF 360, CO 10, abs 200 -> MP 210;
  // AutoZero: CO = (10 - 210) mod 360 = 160 -> MP (200 + 160) mod 360 = 0.
  Bench b(ModelVariant::M2741);
  b.hold(1, 200, 360);
  EXPECT_EQ(b.btw({0x8802, 0x0010}), error::kNone);
  b.run_for(1_ms);
  ASSERT_EQ(b.device().machine_position(1), 210);
  EXPECT_TRUE(b.device().autozero(1));
  b.run_for(1_ms);
  EXPECT_EQ(b.device().setup().channels[0].circular_offset, 160);
  EXPECT_EQ(b.device().machine_position(1), 0);
  // 8100h disables keyboard programming (L1356): AutoZero refused until 8200h.
  EXPECT_EQ(b.btw({0x8100}), error::kNone);
  EXPECT_FALSE(b.device().autozero(1));
  EXPECT_EQ(b.btw({0x8200}), error::kNone);
  EXPECT_TRUE(b.device().autozero(1));
}

// The Program switch (seeds/002_46e90574ec92805f.txt:543-545, :534-537): CLEAR resets the
// position in Program Mode only; Display Mode, a removed jumper or the host's Disable Keyboard
// (8100h, "locked into display mode from the processor", L543, L1356) make it a no-op.
TEST(Pls2700Position, AutoZeroOnlyInProgramMode) {
  Bench b(ModelVariant::M2741);
  b.hold(1, 200, 360);
  b.run_for(1_ms);
  ASSERT_EQ(b.device().machine_position(1), 200);
  b.device().set_program_switch(false); // Display Mode (L535)
  EXPECT_FALSE(b.device().program_mode());
  EXPECT_FALSE(b.device().autozero(1));
  EXPECT_FALSE(b.device().keyboard_delete_pair(1, 1));
  b.run_for(1_ms);
  EXPECT_EQ(b.device().machine_position(1), 200);
  b.device().set_program_switch(true); // Program Mode, PRG LED on (L534, L543)
  EXPECT_TRUE(b.device().program_mode());
  EXPECT_EQ(b.btw({0x8100}), error::kNone); // Disable Keyboard: locked in Display Mode
  EXPECT_FALSE(b.device().program_mode());
  EXPECT_FALSE(b.device().autozero(1));
  EXPECT_EQ(b.btw({0x8200}), error::kNone);
  EXPECT_TRUE(b.device().program_mode());
  EXPECT_TRUE(b.device().autozero(1));
  b.run_for(1_ms);
  EXPECT_EQ(b.device().machine_position(1), 0);
}

TEST(Pls2700Position, WithoutTheJumperTheModuleIsLockedInDisplayMode) {
  Params p;
  p.program_jumper_fitted = false; // L545
  Bench b(ModelVariant::M2741, p);
  b.hold(1, 200, 360);
  b.run_for(1_ms);
  b.device().set_program_switch(true);
  EXPECT_FALSE(b.device().program_mode());
  EXPECT_FALSE(b.device().autozero(1));
  b.run_for(1_ms);
  EXPECT_EQ(b.device().machine_position(1), 200);
}

TEST(Pls2700Position, W15SampleBtrReadsPositionTachStatus) {
  // W15 (L1456, L1476): 1-channel BTR of length 3 = 155, 0, 0 for a shaft at 155 at rest,
  // no error, outputs off.
  Bench b(ModelVariant::M2731);
  b.hold(1, 155, 360);
  b.run_for(300_ms);
  EXPECT_EQ(b.btr(), (std::vector<std::uint16_t>{155, 0, 0}));
}

TEST(Pls2700Position, W16SingleTransferWordOfThe2731_04) {
  // W16 (L1184-L1216): the 2731-04 publishes its position also as a single-transfer input
  // word (I:011 with 1-slot, I:023 with 1/2-slot addressing; rack addressing is the PLC's).
  // What the module puts there (§5.2, L1320): the 16-bit binary position, at most 1023;
  // 8000h on a transducer fault. The host link serves it at input register 16.
  Bench b(ModelVariant::M2731_04);
  EXPECT_EQ(b.btw({0x8801, 0x1024}), error::kNone); // SF 1024, the 273x maximum
  b.hold(1, 1023, 1024);
  b.run_for(1_ms);
  EXPECT_EQ(b.device().single_transfer_word(), 1023);
  Pls2700Registers regs(b.device());
  std::array<std::uint16_t, 1> word{};
  ASSERT_EQ(regs.read_input_registers(16, word), RegisterStatus::Ok);
  EXPECT_EQ(word[0], 1023);
  auto& r = b.hold(1, 1023, 1024);
  signals::ResolverFaults open;
  open.sin_open = true;
  open.cos_open = true;
  r.set_faults(open);
  b.run_for(1_ms);
  EXPECT_EQ(b.device().single_transfer_word(), 0x8000);
  ASSERT_EQ(regs.read_input_registers(16, word), RegisterStatus::Ok);
  EXPECT_EQ(word[0], 0x8000);
}

TEST(Pls2700Fault, W21OpenStatorGives8000hAndOutputsOff) {
  // W21 (L1315): a transducer fault sets that channel's position and tach words to 8000h;
  // limit outputs off (L1437); programming answered 24h while it lasts (L1763); Clear Errors
  // clears it once the transducer is good again (L1359).
  Bench b(ModelVariant::M2742);
  b.hold(1, 15, 360);
  b.hold(2, 40, 360);
  EXPECT_EQ(b.btw({0xC011, 0x0000, 0x0010, 0x0020}), error::kNone); // output 1 on 10..19
  b.run_for(1_ms);
  EXPECT_TRUE(b.pin(1));
  auto& r = b.hold(1, 15, 360);
  signals::ResolverFaults open;
  open.sin_open = true;
  open.cos_open = true;
  r.set_faults(open);
  b.run_for(1_ms);
  EXPECT_EQ(b.btr()[0], 0x8000);
  EXPECT_EQ(b.btr()[1], 0x8000);
  EXPECT_EQ(b.btr()[2], 40); // the healthy channel keeps reporting (L1315)
  EXPECT_FALSE(b.pin(1));
  EXPECT_EQ(b.btw({0x8301}), error::kMessageIgnored);
  EXPECT_EQ(b.btw({0x8400}), error::kMessageIgnored); // still open: the fault stays
  EXPECT_EQ(b.btr()[0], 0x8000);
  r.set_faults({});
  b.run_for(1_ms);
  EXPECT_EQ(b.btr()[0], 0x8000); // latched until cleared
  EXPECT_EQ(b.btw({0x8400}), error::kNone);
  b.run_for(1_ms);
  EXPECT_EQ(b.btr()[0], 15);
  EXPECT_TRUE(b.pin(1));
}

TEST(Pls2700Fault, UnwiredSecondChannelIsAFaultOnlyOnTwoChannelModels) {
  Bench one(ModelVariant::M2741);
  one.hold(1, 5, 360);
  one.run_for(1_ms);
  EXPECT_FALSE(one.device().transducer_fault(1));
  Bench two(ModelVariant::M2732);
  two.hold(1, 5, 360);
  two.run_for(1_ms);
  EXPECT_TRUE(two.device().transducer_fault(2));
  EXPECT_EQ(two.btr()[2], 0x8000);
}

// The reference's peaks fall at k / (2f) (README "Decoder"): at 7.5 kHz every 66,666 2/3 ns,
// so every third one exactly on the 200 us update grid (L377), however far in time; a peak
// between two nanoseconds is placed at the later one.
TEST(Pls2700Excitation, PeaksOfAWholeHertzReferenceAreExact) {
  const Excitation ref(7'500.0, 1.0);
  EXPECT_EQ(ref.latest_peak(Nanos{66'666}), Nanos{0});
  EXPECT_EQ(ref.latest_peak(Nanos{66'667}), Nanos{66'667}); // 66,666.67 rounded up
  EXPECT_EQ(ref.peak_at_or_after(Nanos{1}), Nanos{66'667});
  EXPECT_EQ(ref.peak_at_or_after(Nanos{66'668}), Nanos{133'334}); // 133,333.33 rounded up
  for (const std::int64_t k : {1LL, 2LL, 3LL, 1'000LL, 1'000'000'007LL, 40'000'000'000LL}) {
    const Nanos update = 200_us * k;
    EXPECT_EQ(ref.latest_peak(update), update) << k;
    EXPECT_EQ(ref.peak_at_or_after(update), update) << k;
    EXPECT_EQ(ref.latest_peak(update - Nanos{1}), update - Nanos{66'666}) << k; // peak 3k - 1
  }
  // A fraction of a hertz has no exact peaks here: refused (params_check.hpp takes whole hertz).
  EXPECT_THROW(Excitation(5'000.5, 1.0), std::invalid_argument);
}

} // namespace
} // namespace hilrig::models::pls2700
