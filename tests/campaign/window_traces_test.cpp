// The trace cut around a judged window for the report's timing diagram
// (rig/campaign/window_traces.hpp): each lane's value at the span's start, its changes inside,
// repeated values dropped, and a lane denser than the figure thinned to the first and last
// change of each pixel column, so every level it held there is still drawn.

#include <gtest/gtest.h>

#include "core/trace.hpp"
#include "rig/campaign/window_traces.hpp"
#include "rig/results/timing_figures.hpp"

namespace hilrig::campaign {
namespace {

rig::CheckResult one_window(Nanos begin, Nanos end) {
  rig::CheckResult c;
  rig::Measurement m;
  m.name = "x.edge0";
  m.unit = "counts";
  m.lower = 9.5;
  m.upper = 10.5;
  m.outcome = rig::Outcome::Fail;
  m.window = rig::TraceWindow{begin, end};
  m.at = end;
  c.measurements.push_back(m);
  return c;
}

TEST(WindowTraces, ValueAtTheStartThenTheChangesInside) {
  TraceRecorder trace;
  const auto a = trace.declare("enc.A");
  trace.set_initial(a, 0);
  const auto count = trace.declare("shaft.count", SignalKind::Integer, 64);
  const auto out = trace.declare("ls1");
  trace.set_initial(out, 1);
  trace.edge(a, Edge{Nanos{1'000}, Level::High});
  trace.value(count, Nanos{1'000}, 7);
  trace.value(count, Nanos{200'000}, 7); // the same value again: no change
  trace.value(count, Nanos{210'000}, 8);
  trace.edge(a, Edge{Nanos{210'000}, Level::Low});
  trace.edge(a, Edge{Nanos{900'000}, Level::High}); // after the span
  const rig::CheckResult c = one_window(Nanos{200'000}, Nanos{250'000});
  const auto span = rig::figure_span(c.measurements[0]); // 50 us + 10 us either side
  ASSERT_EQ(span.begin, Nanos{190'000});
  ASSERT_EQ(span.end, Nanos{260'000});
  const auto cut = cut_window_traces(c, trace,
                                     {{"enc.A", rig::LaneRole::Stimulus},
                                      {"shaft.count", rig::LaneRole::Count},
                                      {"ls1", rig::LaneRole::Output}});
  ASSERT_EQ(cut.size(), 1U);
  ASSERT_EQ(cut[0].lanes.size(), 3U);
  const auto& la = cut[0].lanes[0].changes;
  ASSERT_EQ(la.size(), 2U);
  EXPECT_EQ(la[0].time, Nanos{190'000});
  EXPECT_EQ(la[0].value, 1);
  EXPECT_EQ(la[1].time, Nanos{210'000});
  EXPECT_EQ(la[1].value, 0);
  const auto& lc = cut[0].lanes[1].changes;
  ASSERT_EQ(lc.size(), 2U);
  EXPECT_EQ(lc[0].value, 7);
  EXPECT_EQ(lc[1].value, 8);
  // A line that never changed: its initial level, alone.
  ASSERT_EQ(cut[0].lanes[2].changes.size(), 1U);
  EXPECT_EQ(cut[0].lanes[2].changes[0].value, 1);
}

TEST(WindowTraces, ADenseLaneIsThinnedPerPixelColumnKeepingItsLevels) {
  TraceRecorder trace;
  const auto a = trace.declare("enc.A");
  trace.set_initial(a, 0);
  // 10 ms of a 1 MHz square wave: 20000 changes, 40 per column of a 500-column figure.
  for (std::int64_t i = 1; i <= 20'000; ++i)
    trace.edge(a, Edge{Nanos{i * 500}, i % 2 == 1 ? Level::High : Level::Low});
  const rig::CheckResult c = one_window(Nanos{2'000'000}, Nanos{8'000'000});
  const auto cut = cut_window_traces(c, trace, {{"enc.A", rig::LaneRole::Stimulus}});
  ASSERT_EQ(cut.size(), 1U);
  const rig::TraceLane& lane = cut[0].lanes[0];
  const auto span = cut[0].span; // 800 us .. 9.2 ms: the edges 1600 .. 18400 inside
  ASSERT_EQ(span.begin, Nanos{800'000});
  ASSERT_EQ(span.end, Nanos{9'200'000});
  EXPECT_LE(lane.changes.size(), 2 * kLaneColumns + 1);
  EXPECT_GT(lane.thinned, 0U);
  EXPECT_EQ(lane.changes.size() - 1 + lane.thinned, 16'801U);
  // Both levels survive in every column (the first change of a column is the opposite of its last).
  EXPECT_EQ(lane.changes.front().value, 1); // high from the edge at 799.5 us
  EXPECT_EQ(lane.changes[1].time, Nanos{800'000});
  EXPECT_EQ(lane.changes.back().time, Nanos{9'200'000});
  for (std::size_t i = 2; i < lane.changes.size(); ++i)
    EXPECT_LT(lane.changes[i - 1].time, lane.changes[i].time);
}

// shaft_move's step rate against time: each step's rate is 1 / the time since the step
// before (every edge of the step line a step); the rate drops to 0 once the next step is
// overdue (twice the last interval without one).
TEST(WindowTraces, StepRateFromTheStepLineBeforeThinning) {
  TraceRecorder trace;
  const auto step = trace.declare("shaft.step");
  trace.set_initial(step, 0);
  // Steps every 1 ms from 1 ms to 5 ms (1000 steps/s), then every 0.5 ms to 8 ms (2000/s),
  // then none.
  std::vector<Nanos> steps;
  for (std::int64_t t = 1'000'000; t <= 5'000'000; t += 1'000'000) steps.push_back(Nanos{t});
  for (std::int64_t t = 5'500'000; t <= 8'000'000; t += 500'000) steps.push_back(Nanos{t});
  Level l = Level::Low;
  for (const Nanos t : steps) {
    l = l == Level::Low ? Level::High : Level::Low;
    trace.edge(step, Edge{t, l});
  }
  const rig::CheckResult c = one_window(Nanos{2'500'000}, Nanos{8'000'000});
  const auto span = rig::figure_span(c.measurements[0]); // 5.5 ms + 1.1 ms either side
  ASSERT_EQ(span.begin, Nanos{1'400'000});
  ASSERT_EQ(span.end, Nanos{9'100'000});
  const auto cut = cut_window_traces(c, trace,
                                     {{"shaft.step", rig::LaneRole::Output},
                                      {std::string("shaft.step") + kRateSuffix, rig::LaneRole::Rate}});
  ASSERT_EQ(cut.size(), 1U);
  const rig::TraceLane& rate = cut[0].lanes[1];
  EXPECT_EQ(rate.name, "shaft.step rate");
  const std::vector<std::pair<std::int64_t, std::int64_t>> want{
      {1'400'000, 0},    {2'000'000, 1000}, {3'000'000, 1000}, {4'000'000, 1000},
      {5'000'000, 1000}, {5'500'000, 2000}, {6'000'000, 2000}, {6'500'000, 2000},
      {7'000'000, 2000}, {7'500'000, 2000}, {8'000'000, 2000}, {9'000'000, 0}};
  ASSERT_EQ(rate.changes.size(), want.size());
  for (std::size_t i = 0; i < want.size(); ++i) {
    EXPECT_EQ(rate.changes[i].time.count(), want[i].first) << i;
    EXPECT_EQ(rate.changes[i].value, want[i].second) << i;
  }
}

} // namespace
} // namespace hilrig::campaign
