// SsiSlaveNode on scheduled lines: the same data edges as the pure state machine, and a
// master reads the values back. The lines are a small local stand-in (level + handlers,
// stamped with the scheduler's now), not the virtual bus.
#include <gtest/gtest.h>

#include <vector>

#include "core/scheduler.hpp"
#include "signals/ssi_master.hpp"
#include "signals/ssi_slave.hpp"
#include "signals/ssi_slave_node.hpp"

namespace hilrig::signals {
namespace {

using namespace hilrig::literals;

class StandInLine : public LineOutput, public LineInput {
public:
  explicit StandInLine(Scheduler& s) : scheduler_(s) {}
  void set(Level level) override {
    if (level == level_) return;
    level_ = level;
    const Edge e{scheduler_.now(), level};
    edges.push_back(e);
    for (auto& h : handlers_) h(e);
  }
  [[nodiscard]] Level driven() const override { return level_; }
  [[nodiscard]] Level level() const override { return level_; }
  void on_edge(EdgeHandler handler) override { handlers_.push_back(std::move(handler)); }
  std::vector<Edge> edges;

private:
  Scheduler& scheduler_;
  Level level_ = Level::High;
  std::vector<EdgeHandler> handlers_;
};

SsiSlave make_slave() {
  SsiSlaveParams sp; // 7361 default frame: 25 bits, 24-bit binary field at bit 1
  sp.output_delay = 300_ns;
  // Value = microseconds since start, so every frame carries a different number.
  return SsiSlave(sp, [](Nanos t) { return static_cast<std::uint32_t>(t.count() / 1000); });
}

TEST(SsiSlaveNode, MatchesThePureStateMachineAndReadsBack) {
  const SsiMaster master(ssi7361_master(true)); // 500 kHz, TINT 250 us
  const std::vector<Edge> clock_edges = master.clock_schedule(100_us, 8);

  Scheduler sched;
  StandInLine clock(sched);
  StandInLine data(sched);
  SsiSlave slave = make_slave();
  SsiSlaveNode node(sched, slave, clock, data);
  for (const Edge& e : clock_edges) sched.at(e.time, [&clock, e] { clock.set(e.level); });
  sched.run_until(2200_us);

  SsiSlave reference = make_slave();
  const std::vector<Edge> expected = respond(reference, clock_edges, 2200_us);
  EXPECT_EQ(data.edges, expected);

  const auto readings = master.read_frames(LineHistory(Level::High, data.edges), 100_us, 8);
  for (std::size_t i = 0; i < readings.size(); ++i) {
    // Frame i latches at F1 = 100 + 250 i us; the 24-bit field sits above one spare bit.
    EXPECT_EQ(readings[i].word >> 1, 100u + 250u * i) << i;
    EXPECT_TRUE(readings[i].ready);
    EXPECT_TRUE(readings[i].released);
  }
}

TEST(SsiSlaveNode, StuckLowFaultPullsTheLineAtOnce) {
  Scheduler sched;
  StandInLine clock(sched);
  StandInLine data(sched);
  SsiSlave slave = make_slave();
  SsiSlaveNode node(sched, slave, clock, data);
  sched.run_until(10_us);
  SsiSlaveFaults f;
  f.stuck = SsiStuck::Low;
  node.set_faults(f);
  ASSERT_EQ(data.edges.size(), 1u);
  EXPECT_EQ(data.edges[0], (Edge{10_us, Level::Low}));
}

} // namespace
} // namespace hilrig::signals
