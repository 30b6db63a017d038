// The seven models as a parameter (pls2700.md §1 table) and the fault variants: each wrong
// model differs from the correct one on some input.
#include <gtest/gtest.h>

#include "models/pls2700/error_codes.hpp"
#include "pls2700_bench.hpp"

namespace hilrig::models::pls2700 {
namespace {

using namespace hilrig::literals;
using testing::Bench;

constexpr double kTurnsPerSecondAt200us = 32.0 / 8192.0 / 0.0002; // 16 MP counts per 200 us at SF 4096

TEST(Pls2700Models, NamesRoundTrip) {
  EXPECT_EQ(kModels.size(), 7u);
  for (const ModelTraits& m : kModels) {
    ASSERT_TRUE(model_from_name(m.name).has_value());
    EXPECT_EQ(*model_from_name(m.name), m.variant);
    EXPECT_EQ(traits(m.variant).name, m.name);
  }
  EXPECT_FALSE(model_from_name("2733").has_value());
  for (const FaultName& f : kFaultNames) {
    EXPECT_EQ(fault_from_name(f.name), f.fault);
    EXPECT_EQ(fault_name(f.fault), f.name);
  }
  EXPECT_FALSE(fault_from_name("nonsense").has_value());
}

TEST(Pls2700Models, UpdatePeriodBtrLengthAndScaleFactorCeiling) {
  // L377/L457: 200 us on 2731/2731-04/2741 (50 updates per 10 ms), 400 us on the two-channel
  // modules (25). L1260: BTR 3 / 5 words. L273-L280: SF max 1024 (273x) / 4096 (274x).
  struct Expect {
    ModelVariant model;
    std::uint64_t updates;
    std::size_t btr;
    int max_sf;
  };
  const Expect table[] = {{ModelVariant::M2731, 50, 3, 1024},   {ModelVariant::M2731_04, 50, 3, 1024},
                          {ModelVariant::M2732, 25, 5, 1024},   {ModelVariant::M2732_04, 25, 5, 1024},
                          {ModelVariant::M2741, 50, 3, 4096},   {ModelVariant::M2742, 25, 5, 4096},
                          {ModelVariant::M2742_18, 25, 5, 4096}};
  for (const Expect& e : table) {
    Bench b(e.model);
    b.hold(1, 0, 360);
    b.hold(2, 0, 360);
    b.run_until(10_ms);
    const auto before = b.device().updates();
    b.run_until(20_ms);
    EXPECT_EQ(b.device().updates() - before, e.updates) << traits(e.model).name;
    EXPECT_EQ(b.btr().size(), e.btr);
    EXPECT_EQ(b.btw({0x8801, to_bcd(e.max_sf)}), error::kNone);
    EXPECT_EQ(b.btw({0x8801, to_bcd(e.max_sf + 1)}), error::kInvalidSf1);
  }
}

// Output 1 on 2000..2999 of SF 4096 with advances `adv`, on a 2741 spinning at 80 counts/ms.
std::vector<Edge> run_window(Fault fault, std::uint16_t adv) {
  Bench b(ModelVariant::M2741, {}, fault);
  EXPECT_EQ(b.btw({0x8801, 0x4096, 0xC011, adv, 0x2000, 0x3000}), error::kNone);
  b.shaft(1, signals::angle_at_constant_speed(0.5 / 8192.0, kTurnsPerSecondAt200us));
  b.run_until(50_ms);
  return b.edges(1);
}

TEST(Pls2700Faults, LateOutputsUpdateAtTwiceThePeriod) {
  // Correct: on at 25 ms (MP 2000 at update 125). Late: updates every 400 us; the first at or
  // after the crossing is 25.2 ms.
  ASSERT_FALSE(run_window(Fault::Nominal, 0x0000).empty());
  EXPECT_EQ(run_window(Fault::Nominal, 0x0000)[0].time, 25_ms);
  EXPECT_EQ(run_window(Fault::LateOutputs, 0x0000)[0].time, 25'200_us);
}

TEST(Pls2700Faults, AdvanceWrongSignFiresLate) {
  // Correct: ON point 2000 - 800 = 1200 -> 15 ms. Wrong sign: 2000 + 800 = 2800 -> 35 ms.
  EXPECT_EQ(run_window(Fault::Nominal, 0x1000)[0].time, 15_ms);
  EXPECT_EQ(run_window(Fault::AdvanceWrongSign, 0x1000)[0].time, 35_ms);
}

TEST(Pls2700Faults, OffLeOnNotEnforcedAcceptsALargerOffAdvance) {
  Bench good(ModelVariant::M2741);
  Bench bad(ModelVariant::M2741, {}, Fault::OffLeOnNotEnforced);
  EXPECT_EQ(good.btw({0xC011, 0x0510, 0x0010, 0x0020}), 0xF1);
  EXPECT_EQ(bad.btw({0xC011, 0x0510, 0x0010, 0x0020}), error::kNone);
}

TEST(Pls2700Faults, TachWindowWrongDoublesThe30msReading) {
  // 1000 RPM, code 0: correct 1000 at 30 ms; the faulty module sums 60 ms (8192 counts) but
  // scales as 30 ms: 0 at 30 ms, 2000 at 60 ms.
  for (Fault f : {Fault::Nominal, Fault::TachWindowWrong}) {
    Bench b(ModelVariant::M2741, {}, f);
    EXPECT_EQ(b.btw({0x8804, 0x0000}), error::kNone);
    b.shaft(1, signals::angle_at_constant_speed(0.5 / 8192.0, 1000.0 / 60.0));
    b.run_until(30_ms);
    EXPECT_EQ(b.device().tach(1), f == Fault::Nominal ? 1000 : 0);
    b.run_until(60_ms);
    EXPECT_EQ(b.device().tach(1), f == Fault::Nominal ? 1000 : 2000);
  }
}

TEST(Pls2700Faults, ErrorLatchMissingRunsTheRest) {
  // Correct: C1h stops the BTW (mask stays FFh) and the next BTW is ignored (24h).
  // Faulty: the mask after the bad instruction is applied and the next BTW is accepted.
  Bench good(ModelVariant::M2741);
  Bench bad(ModelVariant::M2741, {}, Fault::ErrorLatchMissing);
  for (Bench* b : {&good, &bad}) {
    EXPECT_EQ(b->btw({0xC011, 0x0000, 0x0800, 0x0810, 0x83F0}), 0xC1);
  }
  EXPECT_EQ(good.device().setup().mask, 0xFF);
  EXPECT_EQ(bad.device().setup().mask, 0xF0);
  EXPECT_EQ(good.btw({0x830F}), error::kMessageIgnored);
  EXPECT_EQ(bad.btw({0x830F}), error::kNone);
}

} // namespace
} // namespace hilrig::models::pls2700
