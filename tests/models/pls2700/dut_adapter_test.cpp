// The campaign adapter (rig/duts/pls2700_dut.hpp): made from its DutInfo with defaults,
// wired by pin name, programmed and read through host words as a campaign does.
#include <gtest/gtest.h>

#include "drivers/virtual/virtual_bus.hpp"
#include "models/pls2700/position.hpp"
#include "rig/duts/pls2700_dut.hpp"
#include "signals/resolver.hpp"

namespace hilrig::duts {
namespace {

using namespace hilrig::literals;

TEST(Pls2700Dut, InfoListsPinsParamsAndVariants) {
  const DutInfo info = pls2700_info();
  EXPECT_EQ(info.name, "pls2700");
  ASSERT_NE(info.pin("SIN1"), nullptr);
  EXPECT_TRUE(info.pin("SIN1")->analog);
  ASSERT_NE(info.pin("OUT8"), nullptr);
  EXPECT_EQ(info.pin("OUT8")->direction, PinDirection::Output);
  EXPECT_EQ(info.pin("OUT9"), nullptr);
  EXPECT_EQ(info.variants.front().name, "nominal");
  for (const char* v : {"late_outputs", "advance_wrong_sign", "off_le_on_not_enforced", "tach_window_wrong",
                        "error_latch_missing"}) {
    EXPECT_TRUE(info.has_variant(v)) << v;
  }
  ASSERT_NE(info.param("model"), nullptr);
}

TEST(Pls2700Dut, HostWordsProgramAndReadTheModule) {
  // W14 through the adapter on a 2741: BTW 8400h 8801h 0360h C011h 0000h 0010h 0020h in
  // words 1..7, sent by writing its length (7) to word 0 last, as a campaign's host write
  // does; shaft at 15 -> output 1 on, BTR 15, 0, 0001h.
  const DutInfo info = pls2700_info();
  Scheduler scheduler;
  virt::VirtualBus bus(scheduler);
  auto dut = info.make(scheduler, info.with_defaults({{"model", std::string("2741")}}), "nominal", 1);
  dut->attach(bus, {{"SIN1", "res.sin"}, {"COS1", "res.cos"}, {"OUT1", "ls1"}});
  const models::pls2700::Excitation ex(5'000.0, 1.0); // the default reference
  signals::Resolver r(ex.resolver_params(), [](Nanos) { return 15.5 / 360.0; });
  bus.analog("res.sin").set_waveform(r.sin_waveform());
  bus.analog("res.cos").set_waveform(r.cos_waveform());
  const std::uint16_t btw[] = {0x8400, 0x8801, 0x0360, 0xC011, 0x0000, 0x0010, 0x0020};
  for (std::size_t k = 0; k < 7; ++k) {
    dut->host_write(k + 1, btw[k]);
  }
  dut->host_write(kPls2700BtwSendWord, 7);
  scheduler.run_until(1_ms);
  EXPECT_EQ(dut->host_read(0), 15);
  EXPECT_EQ(dut->host_read(1), 0);
  EXPECT_EQ(dut->host_read(2), 0x0001);
  EXPECT_EQ(dut->host_read(kPls2700ErrorWord), 0x00);
  EXPECT_EQ(bus.line("ls1").level(), Level::High);
  EXPECT_THROW(info.make(scheduler, info.with_defaults({{"model", std::string("2799")}}), "nominal", 1),
               std::invalid_argument);
}

} // namespace
} // namespace hilrig::duts
