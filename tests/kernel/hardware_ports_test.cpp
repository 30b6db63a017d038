// The hardware backend's real ports on a gpio-sim chip (rig/hardware/rig_ports.hpp), and a
// whole hardware run of a campaign through them. The lane gives the chip in HILRIG_GPIO_CHIP
// and its simulator directory in HILRIG_GPIO_SIM (sim_gpioN/value, sim_gpioN/pull).
#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <string>

#include "core/clock.hpp"
#include "drivers/socketcan/can_socket.hpp"
#include "rig/campaign/campaign_parser.hpp"
#include "rig/hardware/drive_plan.hpp"
#include "rig/hardware/edge_schedule.hpp"
#include "rig/hardware/hardware_run.hpp"
#include "rig/hardware/rig_ports.hpp"
#include "rig/rt/rt_loop.hpp"
#include "tests/hardware/loop_campaign.hpp"
#include "tests/kernel/gpio_sim_env.hpp"

using namespace hilrig;
using namespace hilrig::hardware;

namespace {

using hilrig::kernel_test::env;
using hilrig::kernel_test::sim_pull;
using hilrig::kernel_test::sim_value;

// The loop campaign's rig lines on the lane's chip: enc.A, enc.B, en at 0..2, ls1 at 8.
RigConfig lane_rig() {
  std::string text = test::kLoopRig;
  const std::string chip = "chip = \"gpiochip0\"";
  text.replace(text.find(chip), chip.size(), "chip = \"" + env("HILRIG_GPIO_CHIP") + "\"");
  return parse_rig_config(text, "lane-rig.toml");
}

} // namespace

TEST(RigPortsOnGpioSim, WritingOneLineKeepsTheOthersOfItsRequest) {
  const campaign::Campaign c = campaign::parse_campaign(test::kLoopCampaign, "loop.toml");
  const RigConfig rig = lane_rig();
  DrivePlan plan = plan_lines(c.file, c.points.at(0), rig);
  plan.outputs[2].initial = Level::High; // en starts high: requested, then set before the run
  sim_pull(8, "pull-down");
  const auto ports = open_rig_ports(rig, plan, c.points.at(0));
  EXPECT_EQ(sim_value(0), 0);
  EXPECT_EQ(sim_value(1), 0);
  EXPECT_EQ(sim_value(2), 1);
  // enc.A, enc.B and en share one bulk request: each write sets the whole request.
  ports->outputs().write(1, Level::High);
  EXPECT_EQ(sim_value(0), 0);
  EXPECT_EQ(sim_value(1), 1);
  EXPECT_EQ(sim_value(2), 1);
  ports->outputs().write(0, Level::High);
  ports->outputs().write(1, Level::Low);
  EXPECT_EQ(sim_value(0), 1);
  EXPECT_EQ(sim_value(1), 0);
  EXPECT_EQ(sim_value(2), 1);
  EXPECT_EQ(ports->input_level(0), Level::Low);
}

TEST(RigPortsOnGpioSim, InputEdgesComeOnTheMonotonicClockByPlanIndex) {
  const campaign::Campaign c = campaign::parse_campaign(test::kLoopCampaign, "loop.toml");
  const RigConfig rig = lane_rig();
  const DrivePlan plan = plan_lines(c.file, c.points.at(0), rig);
  sim_pull(8, "pull-down");
  const auto ports = open_rig_ports(rig, plan, c.points.at(0));
  const Nanos before = MonotonicClock{}.now();
  ports->begin(before);
  sim_pull(8, "pull-up");
  std::array<InputEdge, 4> edges{};
  std::size_t n = 0;
  // The simulator's interrupt may still be on its way (a kernel thread on PREEMPT_RT): bounded wait.
  for (int tries = 0; tries < 500 && n == 0; ++tries) {
    n = ports->inputs()->poll(edges);
    if (n == 0) (void)rig::sleep_until(MonotonicClock{}.now() + milliseconds(2));
  }
  const Nanos after = MonotonicClock{}.now();
  ASSERT_EQ(n, 1U);
  EXPECT_EQ(edges[0].line, 0U); // ls1: the plan's first input
  EXPECT_EQ(edges[0].level, Level::High);
  EXPECT_GE(edges[0].time, before);
  EXPECT_LE(edges[0].time, after);
}

TEST(HardwareRunOnGpioSim, PlaysTheScheduleOnTheChip) {
  const campaign::Campaign c = campaign::parse_campaign(test::kLoopCampaign, "loop.toml");
  const RigConfig rig = lane_rig(); // edge_tolerance 1 s: TCG timing is no reference
  const DrivePlan plan = plan_lines(c.file, c.points.at(0), rig);
  campaign::RunInputs in;
  in.scenario = &c.points.at(0);
  in.variant = "nominal";
  sim_pull(8, "pull-down");
  const auto ports = open_rig_ports(rig, plan, c.points.at(0));
  HardwareRunOptions o;
  o.rt = rig.rt;
  const campaign::VirtualRun v = run_hardware(in, plan, *ports, o);
  EXPECT_EQ(v.rig_fault, "");
  const std::vector<ScheduledEdge> schedule = build_schedule(in, plan).edges;
  for (std::size_t line = 0; line < plan.outputs.size(); ++line) {
    std::vector<Level> due;
    for (const ScheduledEdge& e : schedule)
      if (e.line == line) due.push_back(e.level);
    std::vector<Level> written;
    for (const Edge& e : v.trace->edges_of(plan.outputs[line].rig)) written.push_back(e.level);
    EXPECT_EQ(written, due) << plan.outputs[line].rig;
    // The chip holds the last level played.
    EXPECT_EQ(sim_value(plan.outputs[line].gpio->offset), is_high(due.back()) ? 1 : 0)
        << plan.outputs[line].rig;
  }
  EXPECT_TRUE(v.trace->edges_of("ls1").empty()); // nobody moved the board's output
}

// The resolver stream on the SJA1000 pair: the frames the run sent (can.log) crossed to can1 in
// order. Under QEMU a loaded guest may let can1's controller overrun (an SJA1000 has a 64-byte
// receive FIFO): a frame missing at can1 must then be accounted for by can1's overrun report
// or its socket's drop count, never lost silently.
TEST(HardwareRunOnCan, ResolverFramesReachTheBusAsRecorded) {
  const campaign::Campaign c = campaign::parse_campaign(test::kLoopCampaign, "loop.toml");
  RigConfig on_chip = lane_rig();
  on_chip.can_resolver = "can0";
  DrivePlan plan = plan_lines(c.file, c.points.at(0), on_chip);
  plan.resolver = true; // as if the campaign had a [resolver]
  campaign::RunInputs in;
  in.scenario = &c.points.at(0);
  socketcan::CanSocket rx("can1");
  const auto ports = open_rig_ports(on_chip, plan, c.points.at(0));
  HardwareRunOptions o;
  o.rt = on_chip.rt;
  const campaign::VirtualRun v = run_hardware(in, plan, *ports, o);
  EXPECT_EQ(v.rig_fault, "");
  const auto& sent = v.trace->can_frames();
  ASSERT_GE(sent.size(), 1U);
  EXPECT_EQ(sent[0].bus, "can0");
  std::size_t matched = 0; // frames of `sent` accounted for, in order
  std::size_t received = 0;
  socketcan::BusStateTracker can1;
  while (matched < sent.size()) {
    const auto got = rx.receive(seconds(2));
    if (!got) break;
    if (got->is_error) {
      can1.apply(got->error);
      continue;
    }
    while (matched < sent.size() && !(got->frame == sent[matched].frame)) ++matched; // skipped: lost
    ASSERT_LT(matched, sent.size()) << "can1 received a frame the run did not send, or out of order";
    ++matched;
    ++received;
  }
  const std::uint64_t reported = std::uint64_t{can1.rx_overflow_count()} + rx.rx_queue_drops();
  if (received < sent.size()) {
    EXPECT_GT(reported, 0U) << sent.size() - received << " frame(s) lost at can1 without an overrun report";
  }
  // On the sending side nothing was lost (the run's overrun figures are all 0, or it faulted).
  for (const char* name :
       {"rig.can.controller_rx_overflows", "rig.can.controller_tx_overflows", "rig.can.socket_rx_drops"}) {
    const auto m = std::find_if(v.rig_timing.begin(), v.rig_timing.end(),
                                [&](const rig::Measurement& x) { return x.name == name; });
    ASSERT_NE(m, v.rig_timing.end()) << name;
    EXPECT_EQ(m->value, 0.0) << name;
  }
}

// The interface going down is a named rig fault that stops the run.
TEST(HardwareRunOnCan, InterfaceDownIsARigFault) {
  const campaign::Campaign c = campaign::parse_campaign(test::kLoopCampaign, "loop.toml");
  RigConfig rig = lane_rig();
  rig.can_resolver = "can0";
  DrivePlan plan = plan_lines(c.file, c.points.at(0), rig);
  plan.resolver = true;
  campaign::RunInputs in;
  in.scenario = &c.points.at(0);
  const auto ports = open_rig_ports(rig, plan, c.points.at(0));
  ASSERT_EQ(std::system("ip link set can0 down"), 0);
  HardwareRunOptions o;
  o.rt = rig.rt;
  const campaign::VirtualRun v = run_hardware(in, plan, *ports, o);
  EXPECT_EQ(std::system("ip link set can0 up"), 0);
  EXPECT_EQ(v.rig_fault, "CAN can0: the interface is down or bus-off (ENETDOWN)");
  EXPECT_TRUE(v.trace->can_frames().empty());
}
