#include "drivers/virtual/virtual_bus.hpp"

#include <gtest/gtest.h>

#include <sstream>
#include <vector>

using namespace hilrig;
using namespace hilrig::literals;
using hilrig::virt::VirtualBus;

TEST(VirtualBus, NamedThingsAreCreatedOnceAndShared) {
  Scheduler s;
  VirtualBus bus(s);
  EXPECT_EQ(&bus.line("enc.A"), &bus.line("enc.A"));
  EXPECT_NE(&bus.line("enc.A"), &bus.line("enc.B"));
  EXPECT_EQ(&bus.can("can0"), &bus.can("can0"));
  EXPECT_EQ(&bus.serial("host"), &bus.serial("host"));
  EXPECT_EQ(&bus.analog("res.sin"), &bus.analog("res.sin"));
  EXPECT_EQ(&bus.scheduler(), &s);
}

TEST(VirtualBus, EverythingLandsInOneTrace) {
  Scheduler s;
  TraceRecorder trace;
  VirtualBus bus(s, &trace);
  auto& a = bus.line("rig.enc.A", Level::Low);
  auto& z = bus.line("rig.enc.Z", Level::High);
  CanPort& tx = bus.can("can0").attach("rig");
  (void)bus.can("can0").attach("dut");
  s.at(1_us, [&] { a.driver().set(Level::High); });
  s.at(2_us, [&] { z.driver().set(Level::Low); });
  s.at(3_us, [&] {
    CanFrame f;
    f.id = 0x100;
    tx.send(f);
  });
  s.run_until_idle();
  EXPECT_EQ(trace.edges_of("rig.enc.A"), (std::vector<Edge>{{1_us, Level::High}}));
  EXPECT_EQ(trace.edges_of("rig.enc.Z"), (std::vector<Edge>{{2_us, Level::Low}}));
  ASSERT_EQ(trace.can_frames().size(), 1U);
  std::ostringstream vcd;
  write_vcd(trace, vcd);
  // Z starts high (initial value), A low: both in $dumpvars.
  EXPECT_NE(vcd.str().find("$dumpvars\n0!\n1\"\n$end\n"), std::string::npos);
}

TEST(VirtualBus, SameScenarioTwiceGivesTheSameHash) {
  auto run = [] {
    Scheduler s;
    TraceRecorder trace;
    VirtualBus bus(s, &trace);
    auto& a = bus.line("a");
    a.set_propagation_delay(7_ns);
    auto& link = bus.serial("host");
    for (int k = 1; k <= 50; ++k) {
      s.at(Nanos{k * std::int64_t{1000}}, [&, k] { a.driver().set(level_of(k % 2 == 1)); });
    }
    const std::array<std::uint8_t, 3> bytes{1, 2, 3};
    link.end_a().write(bytes);
    s.run_until_idle();
    return trace.content_hash();
  };
  EXPECT_EQ(run(), run());
}

// A board drives its outputs' idle levels as it powers up: while the bus powers up, a level
// driven is where the line starts (readers' level, the trace's initial value in $dumpvars),
// with no edge and no reader called, on a line made before power-up and on one made during it.
// After power-up every change is an edge again, at time 0 too.
TEST(VirtualBus, LevelsDrivenWhilePoweringUpAreWhereTheLinesStart) {
  Scheduler s;
  TraceRecorder trace;
  VirtualBus bus(s, &trace);
  auto& co = bus.line("co", Level::Low); // the rig's wiring, made before the board
  LineInput& in = co.reader();
  std::vector<Edge> seen;
  in.on_edge([&](const Edge& e) { seen.push_back(e); });
  bus.set_powering_up(true);
  co.driver().set(Level::High); // the board's idle level
  auto& clk = bus.line("clk");  // made while the board powers up
  clk.driver().set(Level::High);
  clk.driver().set(Level::Low);
  clk.driver().set(Level::High);
  bus.set_powering_up(false);
  EXPECT_EQ(in.level(), Level::High);
  EXPECT_TRUE(seen.empty());
  EXPECT_EQ(co.edge_count(), 0U);
  EXPECT_EQ(clk.edge_count(), 0U);

  co.driver().set(Level::Low); // at time 0, after power-up: an edge
  s.at(1_us, [&] { co.driver().set(Level::High); });
  s.run_until_idle();
  const std::vector<Edge> edges{{0_us, Level::Low}, {1_us, Level::High}};
  EXPECT_EQ(seen, edges);
  EXPECT_EQ(trace.edges_of("co"), edges);
  EXPECT_TRUE(trace.edges_of("clk").empty());
  std::ostringstream vcd;
  write_vcd(trace, vcd);
  // Both start high in $dumpvars; the first change of co is the edge at 0 after power-up.
  EXPECT_NE(vcd.str().find("$dumpvars\n1!\n1\"\n$end\n0!\n#1000\n1!\n"), std::string::npos) << vcd.str();
}
