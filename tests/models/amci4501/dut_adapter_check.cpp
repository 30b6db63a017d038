// The campaign adapter (rig/duts/amci4501_dut.hpp): pins by name, parameters with the
// model's defaults, variants by name, and the host words with the programming handshake,
// used the way the executive uses it.
#include "amci4501_rig.hpp"
#include "rig/duts/amci4501_dut.hpp"

namespace hilrig::models::amci4501::test {
namespace {

TEST(Amci4501Dut, DescribesPinsParamsAndVariants) {
  const duts::DutInfo info = duts::amci4501_info();
  EXPECT_EQ(info.name, "amci4501");
  ASSERT_NE(info.pin("CYCLE_OUT"), nullptr);
  EXPECT_EQ(info.pin("CYCLE_OUT")->direction, duts::PinDirection::Output);
  EXPECT_EQ(info.pin("LATCH")->direction, duts::PinDirection::Input);
  EXPECT_EQ(info.variants.front().name, "nominal");
  for (const auto& v : kVariantNames) EXPECT_TRUE(info.has_variant(v.name)) << v.name;
  EXPECT_EQ(info.host.output_words, 8u);
  EXPECT_EQ(info.host.input_words, 8u);
  const duts::DutParams p = info.with_defaults({});
  EXPECT_EQ(p.duration("throughput"), 125_us);
  EXPECT_EQ(p.integer("no_response_missed"), 4);
}

// Mode 3 through the adapter: W3, 12,345 us -> 12 / 345; the Cycle Output wired but unused.
TEST(Amci4501Dut, MeasuresThroughTheAdapter) {
  const duts::DutInfo info = duts::amci4501_info();
  Scheduler s;
  virt::VirtualBus bus{s};
  auto dut = info.make(s, info.with_defaults({}), "nominal", 1);
  dut->attach(bus,
              {{"A", "enc.A"}, {"B", "enc.B"}, {"START", "start"}, {"LATCH", "latch"}, {"CYCLE_OUT", "co"}});
  dut->host_write(1, 1000);
  dut->host_write(0, control::kMode3 | control::kTransmit);
  EXPECT_EQ(dut->host_read(0), status::kAcknowledge | mode_status_bit(3));
  dut->host_write(0, control::kMode3);
  s.at(1_ms, [&] { bus.line("start").driver().set(Level::High); });
  s.at(us(13345), [&] { bus.line("latch").driver().set(Level::High); });
  s.run_until(20_ms);
  EXPECT_EQ(dut->host_read(1), 12);
  EXPECT_EQ(dut->host_read(2), 345);
  EXPECT_EQ(bus.line("co").edge_count(), 0u);
}

TEST(Amci4501Dut, RejectsUnknownPinsVariantsAndJumpers) {
  const duts::DutInfo info = duts::amci4501_info();
  Scheduler s;
  virt::VirtualBus bus{s};
  EXPECT_THROW((void)info.make(s, info.with_defaults({}), "x8_counting", 1), std::invalid_argument);
  EXPECT_THROW((void)info.make(s, info.with_defaults({{"start_jumper", std::string("up")}}), "nominal", 1),
               std::invalid_argument);
  auto dut = info.make(s, info.with_defaults({}), "x2_counting", 1);
  EXPECT_THROW(dut->attach(bus, {{"OUT1", "x"}}), std::invalid_argument);
}

} // namespace
} // namespace hilrig::models::amci4501::test
