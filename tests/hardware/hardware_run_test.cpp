// The hardware run's orchestration over the RT ports, looped through a virtual DUT
// (virtual_dut_ports.hpp): the RT loop plays the precomputed schedule in real time, the
// board's edges come back with timestamps, and the trace holds what the virtual run's holds,
// shifted by the harness's wire delay. Rig faults stop the run and keep what was captured.

#include <gtest/gtest.h>

#include <algorithm>
#include <optional>
#include <span>
#include <stdexcept>
#include <string>
#include <utility>
#include <vector>

#include "rig/campaign/campaign_parser.hpp"
#include "rig/campaign/virtual_run.hpp"
#include "rig/hardware/edge_schedule.hpp"
#include "rig/hardware/hardware_run.hpp"
#include "tests/hardware/loop_campaign.hpp"
#include "tests/hardware/virtual_dut_ports.hpp"

namespace hilrig::hardware {
namespace {

// One scan period of the reference PLS: with the scan phase fixed by the seed, a DUT that
// sees every edge one scan later decides everything exactly one scan later.
constexpr Nanos kWireDelay{200'000};

struct Loop {
  campaign::Campaign c = campaign::parse_campaign(test::kLoopCampaign, "loop.toml");
  RigConfig rig = parse_rig_config(test::kLoopRig, "rig.toml");
  DrivePlan plan = plan_lines(c.file, c.points.at(0), rig);
  campaign::RunInputs in;
  HardwareRunOptions options;
  Loop() {
    in.scenario = &c.points.at(0);
    in.variant = "nominal";
    in.seed = 11;
    options.rt = rig.rt;
    options.realtime = false; // a unit test does not ask for SCHED_FIFO
    options.lead = Nanos{5'000'000};
  }
  [[nodiscard]] std::vector<ScheduledEdge> schedule() const { return build_schedule(in, plan).edges; }
};

const rig::Measurement* measurement(const campaign::VirtualRun& v, const std::string& name) {
  for (const rig::Measurement& m : v.rig_timing)
    if (m.name == name) return &m;
  return nullptr;
}

TEST(HardwareRun, LoopedThroughAVirtualDutCapturesWhatTheVirtualRunCaptures) {
  Loop f;
  const std::vector<ScheduledEdge> schedule = f.schedule();
  test::VirtualDutPorts ports(f.c.points[0], f.plan, schedule, kWireDelay, f.in.seed);
  const campaign::VirtualRun hw = run_hardware(f.in, f.plan, ports, f.options);
  ASSERT_EQ(hw.rig_fault, "");
  EXPECT_EQ(ports.written(), schedule.size());
  EXPECT_EQ(ports.mismatches(), 0U);

  // Every output edge went out, in order, never before it was due.
  for (std::size_t line = 0; line < f.plan.outputs.size(); ++line) {
    std::vector<ScheduledEdge> due;
    for (const ScheduledEdge& e : schedule)
      if (e.line == line) due.push_back(e);
    const std::vector<Edge> written = hw.trace->edges_of(f.plan.outputs[line].rig);
    ASSERT_EQ(written.size(), due.size()) << f.plan.outputs[line].rig;
    for (std::size_t i = 0; i < due.size(); ++i) {
      EXPECT_EQ(written[i].level, due[i].level);
      EXPECT_GE(written[i].time, due[i].time);
    }
  }

  // The board's output: the virtual run's edges, one wire delay later, to the nanosecond.
  const campaign::VirtualRun virt = campaign::run_virtual(f.in);
  const std::vector<Edge> expected = virt.trace->edges_of("ls1");
  ASSERT_GE(expected.size(), 2U); // OUT turns on at count 3 and off again
  const std::vector<Edge> captured = hw.trace->edges_of("ls1");
  ASSERT_EQ(captured.size(), expected.size());
  for (std::size_t i = 0; i < expected.size(); ++i) {
    EXPECT_EQ(captured[i].level, expected[i].level) << "edge " << i;
    EXPECT_EQ(captured[i].time, expected[i].time + kWireDelay) << "edge " << i;
  }

  // The rig's own timing is in the results.
  const rig::Measurement* edge_error = measurement(hw, "rig.edge_error.max");
  ASSERT_NE(edge_error, nullptr);
  EXPECT_EQ(edge_error->unit, "us");
  ASSERT_TRUE(edge_error->upper.has_value());
  EXPECT_EQ(*edge_error->upper, 1e6); // rt.edge_tolerance = "1s"
  EXPECT_NE(measurement(hw, "rig.wakeup.max"), nullptr);
  EXPECT_NE(measurement(hw, "rig.wakeup.p99"), nullptr);
  // The motion is the campaign's: count 10 at the end.
  EXPECT_EQ(hw.motion.back().time, f.c.points[0].end);
  EXPECT_EQ(hw.motion.back().position, 10.0);
}

TEST(HardwareRun, AnEdgeLaterThanTheToleranceIsARigFault) {
  Loop f;
  // No write returns within a nanosecond of the instant it was due.
  f.options.rt.edge_tolerance = Nanos{1};
  test::VirtualDutPorts ports(f.c.points[0], f.plan, f.schedule(), kWireDelay, f.in.seed);
  const campaign::VirtualRun hw = run_hardware(f.in, f.plan, ports, f.options);
  EXPECT_NE(hw.rig_fault.find("later than the edge tolerance"), std::string::npos) << hw.rig_fault;
  const rig::Measurement* edge_error = measurement(hw, "rig.edge_error.max");
  ASSERT_NE(edge_error, nullptr);
  EXPECT_EQ(edge_error->outcome, rig::Outcome::Fail);
}

// The campaign's [campaign] edge_tolerance wins over the rig config's: a campaign that needs
// nanosecond edges fails on a rig configured loosely, and the reported limit is its own.
TEST(HardwareRun, TheCampaignsEdgeToleranceOverridesTheRigs) {
  Loop f;
  f.options.rt.edge_tolerance = seconds(1);
  campaign::Scenario s = f.c.points[0];
  s.edge_tolerance = Nanos{1};
  f.in.scenario = &s;
  test::VirtualDutPorts ports(s, f.plan, f.schedule(), kWireDelay, f.in.seed);
  const campaign::VirtualRun hw = run_hardware(f.in, f.plan, ports, f.options);
  EXPECT_NE(hw.rig_fault.find("later than the edge tolerance (0.001 us)"), std::string::npos) << hw.rig_fault;
  const rig::Measurement* edge_error = measurement(hw, "rig.edge_error.max");
  ASSERT_NE(edge_error, nullptr);
  ASSERT_TRUE(edge_error->upper.has_value());
  EXPECT_EQ(*edge_error->upper, 0.001); // 1 ns in us
  EXPECT_EQ(edge_error->outcome, rig::Outcome::Fail);
}

// The resolver stream's CAN interface, reporting bus-off once three frames are out.
class BusOffAfterThree final : public ResolverCan {
public:
  std::string send(const CanFrame& /*frame*/) override {
    ++sent;
    return {};
  }
  std::string check() override { return sent >= 3 ? "CAN can9: bus-off (no ACK)" : ""; }
  const std::string& bus() const override { return name_; }
  CanOverruns overruns() const override { return {}; }
  int sent = 0;

private:
  std::string name_ = "can9";
};

TEST(HardwareRun, BusOffStopsTheRunAndKeepsWhatWasCaptured) {
  Loop f;
  f.plan.resolver = true; // as if the campaign had a [resolver]: the angle stream goes out
  BusOffAfterThree can;
  test::VirtualDutPorts ports(f.c.points[0], f.plan, f.schedule(), kWireDelay, f.in.seed);
  ports.set_resolver(&can);
  const campaign::VirtualRun hw = run_hardware(f.in, f.plan, ports, f.options);
  EXPECT_EQ(hw.rig_fault, "CAN can9: bus-off (no ACK)");
  EXPECT_FALSE(hw.interrupted);
  // Frames at 0, 1 and 2 ms went out before the controller said bus-off; they are in can.log.
  EXPECT_EQ(can.sent, 3);
  ASSERT_EQ(hw.trace->can_frames().size(), 3U);
  EXPECT_EQ(hw.trace->can_frames()[0].bus, "can9");
  EXPECT_EQ(hw.trace->can_frames()[0].frame.id, 0x120U); // ResolverAngle, channel 0
  // Stopped early: every rig-driven line ends at its inactive level.
  for (const PlannedLine& p : f.plan.outputs) {
    const std::vector<Edge> edges = hw.trace->edges_of(p.rig);
    if (!edges.empty()) {
      EXPECT_EQ(edges.back().level, Level::Low) << p.rig;
    }
  }
}

// Host words whose link fails on the first read.
class DeadLink final : public campaign::HostWords {
public:
  void write(std::size_t /*word*/, std::uint16_t /*value*/) override {}
  std::uint16_t read(std::size_t /*word*/) override {
    throw std::runtime_error("read input register 1: timeout");
  }
};

TEST(HardwareRun, ALostHostLinkIsARigFault) {
  Loop f;
  campaign::Scenario s = f.c.points[0];
  campaign::HostAction read;
  read.kind = campaign::HostAction::Kind::Read;
  read.at = Nanos{1'000'000};
  read.word = 1;
  read.name = "count";
  s.host.push_back(read);
  f.in.scenario = &s;
  f.plan.host = true;
  DeadLink link;
  test::VirtualDutPorts ports(s, f.plan, f.schedule(), kWireDelay, f.in.seed);
  ports.set_host(&link);
  const campaign::VirtualRun hw = run_hardware(f.in, f.plan, ports, f.options);
  EXPECT_EQ(hw.rig_fault, "host link: read input register 1: timeout");
  EXPECT_TRUE(hw.observations.empty());
}

// A resolver interface whose controller and socket report lost frames whenever check() reads
// them; check() itself never faults, so only the overrun count can stop the run. The report
// does not wait for a frame to have gone out: on a loaded machine every frame of this short
// run can be more than a period late (skipped as stale), and the overrun must still be the
// fault named (it outranks "sent no frame", hardware_run.cpp).
class Overrunning final : public ResolverCan {
public:
  explicit Overrunning(CanOverruns o) : reported_(o) {}
  std::string send(const CanFrame& /*frame*/) override {
    ++sent;
    return {};
  }
  std::string check() override {
    seen_ = reported_; // counted when check() reads the error frames
    return {};
  }
  const std::string& bus() const override { return name_; }
  CanOverruns overruns() const override { return seen_; }
  int sent = 0;

private:
  CanOverruns reported_;
  CanOverruns seen_;
  std::string name_ = "can9";
};

campaign::VirtualRun run_with_overruns(const CanOverruns& o) {
  Loop f;
  f.plan.resolver = true;
  Overrunning can(o);
  test::VirtualDutPorts ports(f.c.points[0], f.plan, f.schedule(), kWireDelay, f.in.seed);
  ports.set_resolver(&can);
  return run_hardware(f.in, f.plan, ports, f.options);
}

TEST(HardwareRun, CanOverrunsAreCountedAndNoOverrunPasses) {
  const campaign::VirtualRun clean = run_with_overruns({});
  EXPECT_EQ(clean.rig_fault, "");
  for (const char* name :
       {"rig.can.controller_rx_overflows", "rig.can.controller_tx_overflows", "rig.can.socket_rx_drops"}) {
    const rig::Measurement* m = measurement(clean, name);
    ASSERT_NE(m, nullptr) << name;
    EXPECT_EQ(m->value, 0.0) << name;
    EXPECT_EQ(m->upper, 0.0) << name; // at the limit: passes
    EXPECT_EQ(m->outcome, rig::Outcome::Pass) << name;
  }
}

TEST(HardwareRun, AnyCanOverrunIsARigFaultNamingEachKind) {
  // One of each kind alone (a hair beyond the limit of none), then all together.
  const campaign::VirtualRun rx = run_with_overruns({1, 0, 0});
  EXPECT_EQ(rx.rig_fault,
            "CAN can9: 1 frame(s) lost (controller RX overflow 1, TX overflow 0, socket receive "
            "queue drops 0): the run's bus evidence is incomplete");
  EXPECT_EQ(measurement(rx, "rig.can.controller_rx_overflows")->outcome, rig::Outcome::Fail);
  EXPECT_EQ(measurement(rx, "rig.can.controller_tx_overflows")->outcome, rig::Outcome::Pass);
  const campaign::VirtualRun tx = run_with_overruns({0, 1, 0});
  EXPECT_NE(tx.rig_fault.find("TX overflow 1,"), std::string::npos) << tx.rig_fault;
  EXPECT_EQ(measurement(tx, "rig.can.controller_tx_overflows")->outcome, rig::Outcome::Fail);
  const campaign::VirtualRun drops = run_with_overruns({0, 0, 1});
  EXPECT_NE(drops.rig_fault.find("socket receive queue drops 1)"), std::string::npos) << drops.rig_fault;
  EXPECT_EQ(measurement(drops, "rig.can.socket_rx_drops")->outcome, rig::Outcome::Fail);
  const campaign::VirtualRun all = run_with_overruns({2, 3, 4});
  EXPECT_NE(all.rig_fault.find("CAN can9: 9 frame(s) lost"), std::string::npos) << all.rig_fault;
  EXPECT_EQ(measurement(all, "rig.can.socket_rx_drops")->value, 4.0);
}

// A capture that reads its one line (ls1) high before the run, then reports the given edges at
// the run's start plus their offsets, once. The rig's writes go nowhere.
class ScriptedCapture final : public RigPorts {
public:
  explicit ScriptedCapture(std::vector<InputEdge> script) : script_(std::move(script)) {}
  RtOutputPort& outputs() override { return out_; }
  RtInputPort* inputs() override { return &in_; }
  campaign::HostWords* host() override { return nullptr; }
  ResolverCan* resolver() override { return nullptr; }
  std::optional<Level> input_level(std::size_t /*i*/) override { return Level::High; }
  void begin(Nanos start) override {
    for (InputEdge& e : script_) e.time += start;
  }

private:
  struct Out final : RtOutputPort {
    void write(std::uint16_t /*line*/, Level /*level*/) noexcept override {}
  };
  struct In final : RtInputPort {
    explicit In(ScriptedCapture& capture) : c(capture) {}
    std::size_t poll(std::span<InputEdge> out) noexcept override {
      std::size_t n = 0;
      while (c.next_ < c.script_.size() && n < out.size()) out[n++] = c.script_[c.next_++];
      return n;
    }
    ScriptedCapture& c;
  };
  std::vector<InputEdge> script_;
  std::size_t next_ = 0;
  Out out_;
  In in_{*this};
};

// The level a captured line is read at before the run is where it starts (trace.vcd's
// $dumpvars), and a sample at the level the line already has is no edge: the board driving
// the line high from power-up gives no edge at 0, and checks see only its real changes.
TEST(HardwareRun, ALineReadHighBeforeTheRunStartsHighWithNoEdge) {
  Loop f;
  ScriptedCapture ports({{Nanos{0}, 0, Level::High},
                         {Nanos{1'000'000}, 0, Level::Low},
                         {Nanos{2'000'000}, 0, Level::High},
                         {Nanos{3'000'000}, 0, Level::High}});
  const campaign::VirtualRun hw = run_hardware(f.in, f.plan, ports, f.options);
  ASSERT_EQ(hw.rig_fault, "");
  const std::int64_t ls1 = hw.trace->find("ls1");
  ASSERT_GE(ls1, 0);
  const SignalInfo& info = hw.trace->signals().at(static_cast<std::size_t>(ls1));
  ASSERT_TRUE(info.has_initial);
  EXPECT_EQ(info.initial, 1);
  EXPECT_EQ(hw.trace->edges_of("ls1"),
            (std::vector<Edge>{{Nanos{1'000'000}, Level::Low}, {Nanos{2'000'000}, Level::High}}));
}

} // namespace
} // namespace hilrig::hardware
