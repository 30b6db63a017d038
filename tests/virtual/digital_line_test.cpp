#include "drivers/virtual/digital_line.hpp"

#include <gtest/gtest.h>

#include <vector>

using namespace hilrig;
using namespace hilrig::literals;
using hilrig::virt::DigitalLine;

TEST(DigitalLine, ReaderSeesTimestampedEdgesAndLevel) {
  Scheduler s;
  DigitalLine line(s, "enc.A", Level::Low, nullptr);
  LineInput& in = line.reader();
  std::vector<Edge> seen;
  in.on_edge([&](const Edge& e) { seen.push_back(e); });
  s.at(1_us, [&] { line.driver().set(Level::High); });
  s.at(3_us, [&] { line.driver().set(Level::Low); });
  s.run_until(2_us);
  EXPECT_EQ(in.level(), Level::High);
  s.run_until_idle();
  EXPECT_EQ(seen, (std::vector<Edge>{{1_us, Level::High}, {3_us, Level::Low}}));
  EXPECT_EQ(line.edge_count(), 2U);
}

TEST(DigitalLine, SameLevelAgainIsNotAnEdge) {
  Scheduler s;
  DigitalLine line(s, "x", Level::High, nullptr);
  int edges = 0;
  line.reader().on_edge([&](const Edge&) { ++edges; });
  line.driver().set(Level::High); // already high
  s.at(1_us, [&] {
    line.driver().set(Level::Low);
    line.driver().set(Level::Low);
  });
  s.run_until_idle();
  EXPECT_EQ(edges, 1);
  EXPECT_EQ(line.driver().driven(), Level::Low);
}

TEST(DigitalLine, PropagationDelayShiftsEveryEdge) {
  Scheduler s;
  DigitalLine line(s, "x", Level::Low, nullptr);
  line.set_propagation_delay(250_ns);
  LineInput& in = line.reader();
  std::vector<Edge> seen;
  in.on_edge([&](const Edge& e) { seen.push_back(e); });
  // A 100 ns pulse at 1 us, shorter than the delay: a transport delay keeps it whole,
  // arriving at 1.25 us and 1.35 us (1000 + 250, 1100 + 250 ns).
  s.at(1_us, [&] { line.driver().set(Level::High); });
  s.at(1100_ns, [&] { line.driver().set(Level::Low); });
  s.run_until(1200_ns);
  EXPECT_EQ(line.driver().driven(), Level::Low); // the driver's side changes at once
  EXPECT_EQ(in.level(), Level::Low);             // readers have seen nothing yet
  s.run_until(1300_ns);
  EXPECT_EQ(in.level(), Level::High);
  s.run_until_idle();
  EXPECT_EQ(seen, (std::vector<Edge>{{1250_ns, Level::High}, {1350_ns, Level::Low}}));
}

TEST(DigitalLine, ShorterDelayNeverReordersEdges) {
  Scheduler s;
  DigitalLine line(s, "x", Level::Low, nullptr);
  line.set_propagation_delay(1_us);
  std::vector<Edge> seen;
  line.reader().on_edge([&](const Edge& e) { seen.push_back(e); });
  line.driver().set(Level::High); // due at 1 us
  line.set_propagation_delay(0_ns);
  s.at(100_ns, [&] { line.driver().set(Level::Low); }); // held back behind the first edge
  s.run_until_idle();
  EXPECT_EQ(seen, (std::vector<Edge>{{1_us, Level::High}, {1_us, Level::Low}}));
  EXPECT_THROW(line.set_propagation_delay(-1_ns), std::invalid_argument);
}

TEST(DigitalLine, ManyReadersEachSeeEveryEdgeInOrder) {
  Scheduler s;
  DigitalLine line(s, "x", Level::Low, nullptr);
  line.set_propagation_delay(10_ns);
  constexpr int kReaders = 8;
  std::vector<std::vector<Edge>> seen(kReaders);
  std::vector<int> call_order;
  for (int r = 0; r < kReaders; ++r) {
    LineInput& in = line.reader();
    in.on_edge([&, r](const Edge& e) {
      seen[static_cast<std::size_t>(r)].push_back(e);
      call_order.push_back(r);
    });
  }
  for (int k = 1; k <= 5; ++k) {
    s.at(Nanos{k * std::int64_t{100}}, [&, k] { line.driver().set(level_of(k % 2 == 1)); });
  }
  s.run_until_idle();
  // Edges at 110, 210, ..., 510 ns, alternating from High.
  std::vector<Edge> expected;
  for (int k = 1; k <= 5; ++k) expected.push_back(Edge{Nanos{k * 100 + 10}, level_of(k % 2 == 1)});
  for (const auto& v : seen) EXPECT_EQ(v, expected);
  // Readers are called in the order they were created, for each edge.
  ASSERT_EQ(call_order.size(), 5U * kReaders);
  for (std::size_t i = 0; i < call_order.size(); ++i)
    EXPECT_EQ(call_order[i], static_cast<int>(i % kReaders));
}

TEST(DigitalLine, EdgesAreTracedWhenReadersSeeThem) {
  Scheduler s;
  TraceRecorder trace;
  DigitalLine line(s, "rig.enc.A", Level::High, &trace);
  line.set_propagation_delay(40_ns);
  s.at(1_us, [&] { line.driver().set(Level::Low); });
  s.at(2_us, [&] { line.driver().set(Level::High); });
  s.run_until_idle();
  EXPECT_EQ(trace.edges_of("rig.enc.A"), (std::vector<Edge>{{1040_ns, Level::Low}, {2040_ns, Level::High}}));
  const SignalInfo& info = trace.signals().at(static_cast<std::size_t>(trace.find("rig.enc.A")));
  EXPECT_TRUE(info.has_initial);
  EXPECT_EQ(info.initial, 1);
}
