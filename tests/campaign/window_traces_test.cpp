// The trace cut around a judged window for the report's timing diagram
// (rig/campaign/window_traces.hpp): each lane's value at the span's start, its changes inside,
// repeated values dropped, and a lane denser than the figure thinned to the first and last
// change of each pixel column, so every level it held there is still drawn.

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>
#include <string>
#include <vector>

#include "core/scheduler.hpp"
#include "core/trace.hpp"
#include "rig/campaign/resolver_stators.hpp"
#include "rig/campaign/run_trace.hpp"
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

void expect_same(const std::vector<rig::WindowTrace>& a, const std::vector<rig::WindowTrace>& b,
                 const std::string& what) {
  ASSERT_EQ(a.size(), b.size()) << what;
  for (std::size_t w = 0; w < a.size(); ++w) {
    EXPECT_EQ(a[w].span.begin, b[w].span.begin) << what;
    EXPECT_EQ(a[w].span.end, b[w].span.end) << what;
    EXPECT_EQ(a[w].around.begin, b[w].around.begin) << what;
    ASSERT_EQ(a[w].lanes.size(), b[w].lanes.size()) << what;
    for (std::size_t l = 0; l < a[w].lanes.size(); ++l) {
      const rig::TraceLane& x = a[w].lanes[l];
      const rig::TraceLane& y = b[w].lanes[l];
      EXPECT_EQ(x.name, y.name) << what;
      EXPECT_EQ(x.real, y.real) << what;
      EXPECT_EQ(x.thinned, y.thinned) << what;
      ASSERT_EQ(x.changes.size(), y.changes.size()) << what << " " << x.name;
      for (std::size_t i = 0; i < x.changes.size(); ++i) {
        EXPECT_EQ(x.changes[i].time, y.changes[i].time) << what << " " << x.name << " " << i;
        EXPECT_EQ(x.changes[i].value, y.changes[i].value) << what << " " << x.name << " " << i;
        EXPECT_EQ(x.changes[i].real, y.changes[i].real) << what << " " << x.name << " " << i;
      }
    }
  }
}

// A run's checks are cut in one pass over the recording (the executive's): each check's
// windows come out as when it is cut alone, whatever the other checks' windows and lanes --
// overlapping windows, a check with two windows, one with none, one with no lanes, a rate
// lane, a real lane, a dense lane that is thinned, samples recorded out of time order.
TEST(WindowTraces, ChecksCutTogetherAreEachCutAlone) {
  TraceRecorder trace;
  const auto a = trace.declare("enc.A");
  trace.set_initial(a, 0);
  const auto count = trace.declare("shaft.count", SignalKind::Integer, 64);
  const auto out = trace.declare("ls1");
  const auto step = trace.declare("shaft.step");
  const auto sine = trace.declare("resolver.sin", SignalKind::Real, 64);
  Level level = Level::Low;
  for (std::int64_t t = 1'000; t < 4'000'000; t += 1'000) { // 4,000 counts: the lanes are thinned
    level = level == Level::Low ? Level::High : Level::Low;
    trace.edge(a, Edge{Nanos{t}, level});
    trace.value(count, Nanos{t}, t / 1'000);
    if (t % 7'000 == 0) trace.edge(step, Edge{Nanos{t}, level});
    if (t % 50'000 == 0) trace.real(sine, Nanos{t}, std::sin(static_cast<double>(t) * 1e-6));
    if (t % 300'000 == 0) trace.edge(out, Edge{Nanos{t}, level});
  }
  trace.edge(out, Edge{Nanos{150'000}, Level::High}); // out of time order
  rig::CheckResult two = one_window(Nanos{200'000}, Nanos{1'200'000});
  two.measurements.push_back(one_window(Nanos{1'000'000}, Nanos{3'000'000}).measurements[0]);
  const rig::CheckResult none; // no window
  const Lanes shaft{{"enc.A", rig::LaneRole::Stimulus},
                    {"resolver.sin", rig::LaneRole::Stimulus},
                    {"shaft.count", rig::LaneRole::Count},
                    {"ls1", rig::LaneRole::Output}};
  const Lanes steps{{"shaft.step", rig::LaneRole::Output},
                    {std::string("shaft.step") + kRateSuffix, rig::LaneRole::Rate}};
  const rig::CheckResult late = one_window(Nanos{2'500'000}, Nanos{2'600'000});
  const std::vector<WindowCut> cuts{
      {&two, shaft}, {&none, shaft}, {&late, steps}, {&two, {}}, {&late, shaft}};
  const auto together = cut_window_traces(cuts, trace);
  ASSERT_EQ(together.size(), cuts.size());
  EXPECT_EQ(together[0].size(), 2U);
  EXPECT_TRUE(together[1].empty());
  EXPECT_GT(together[0][1].lanes[0].thinned, 0U); // the dense lane was thinned
  EXPECT_TRUE(together[0][0].lanes[1].real);
  for (std::size_t k = 0; k < cuts.size(); ++k)
    expect_same(together[k], cut_window_traces(*cuts[k].check, trace, cuts[k].lanes),
                "cut " + std::to_string(k));
}

// One recording made twice, spilled beyond 1,000 samples: an encoder lane and its count every
// 1 us from 5 us to 3 ms, ls1 every 170 us and `other` every 10 us; `general` also has one
// sample on `other` out of time order (a signal no lane shows), which sends it to the general
// pass. `rich` adds an initial level, a count written twice at one time every 3 us and a real
// lane every 40 us.
void record_twice(TraceRecorder& ordered, TraceRecorder& general, bool rich) {
  const auto record = [rich](TraceRecorder& trace, bool out_of_order) {
    trace.spill_beyond(1'000);
    const auto a = trace.declare("enc.A");
    if (rich) trace.set_initial(a, 1);
    const auto count = trace.declare("shaft.count", SignalKind::Integer, 64);
    const auto out = trace.declare("ls1");
    const auto sine = rich ? trace.declare("resolver.sin", SignalKind::Real, 64) : 0U;
    const auto other = trace.declare("other");
    Level level = Level::Low;
    for (std::int64_t t = 5'000; t < 3'000'000; t += 1'000) {
      level = level == Level::Low ? Level::High : Level::Low;
      trace.edge(a, Edge{Nanos{t}, level});
      trace.value(count, Nanos{t}, t / 1'000);
      if (rich && t % 3'000 == 0) trace.value(count, Nanos{t}, t / 1'000 + 1); // twice at one time
      if (rich && t % 40'000 == 0) trace.real(sine, Nanos{t}, std::sin(static_cast<double>(t) * 1e-6));
      if (t % 170'000 == 0) trace.edge(out, Edge{Nanos{t}, level});
      if (t % 10'000 == 0) trace.edge(other, Edge{Nanos{t}, level});
    }
    if (out_of_order) trace.edge(other, Edge{Nanos{2'000}, Level::High});
  };
  record(ordered, false);
  record(general, true);
  ASSERT_TRUE(ordered.in_time_order());
  ASSERT_FALSE(general.in_time_order());
}

// A trace recorded in time order (a scheduler's) is cut by a pass that keeps each signal's
// last sample once, not once a window, and drops a window once its span has ended: the same
// cuts as the general pass, which the same samples and one more, out of time order on a
// signal no lane shows, take. Windows overlapping, nested, sharing a begin, beginning and
// ending on a sample's time, before every sample and after the last; samples at equal times;
// a spilled recording read back.
TEST(WindowTraces, ATraceInTimeOrderIsCutAsTheGeneralPassCutsIt) {
  TraceRecorder ordered;
  TraceRecorder general;
  ASSERT_NO_FATAL_FAILURE(record_twice(ordered, general, true));
  ASSERT_GT(ordered.sample_count(), 1'000U); // spilled: read back from the file
  rig::CheckResult many = one_window(Nanos{200'000}, Nanos{1'200'000});
  for (const auto& [b, e] : std::vector<std::pair<std::int64_t, std::int64_t>>{
           {1'000'000, 2'000'000}, {200'000, 250'000}, {0, 1'000}})
    many.measurements.push_back(one_window(Nanos{b}, Nanos{e}).measurements[0]);
  rig::CheckResult more = one_window(Nanos{2'990'000}, Nanos{3'500'000});
  for (const auto& [b, e] : std::vector<std::pair<std::int64_t, std::int64_t>>{
           {4'000'000, 4'100'000}, {500'000, 510'000}, {1'500'000, 1'500'000}})
    more.measurements.push_back(one_window(Nanos{b}, Nanos{e}).measurements[0]);
  const Lanes shaft{{"enc.A", rig::LaneRole::Stimulus},
                    {"resolver.sin", rig::LaneRole::Stimulus},
                    {"shaft.count", rig::LaneRole::Count},
                    {"ls1", rig::LaneRole::Output}};
  const std::vector<WindowCut> cuts{
      {&many, shaft}, {&more, shaft}, {&many, {{"ls1", rig::LaneRole::Output}}}};
  const auto fast = cut_window_traces(cuts, ordered);
  const auto slow = cut_window_traces(cuts, general);
  ASSERT_EQ(fast.size(), cuts.size());
  EXPECT_EQ(fast[0].size(), 4U);
  EXPECT_GE(fast[1].size(), 3U); // the windows timing_figures draws
  for (std::size_t k = 0; k < cuts.size(); ++k)
    EXPECT_EQ(fast[k].size(), rig::timing_figures(*cuts[k].check).size()) << k;
  for (std::size_t k = 0; k < cuts.size(); ++k) expect_same(fast[k], slow[k], "cut " + std::to_string(k));
}

// Windows that all end long before the recording does: the time-ordered pass stops at the
// first sample past every window (the rest is not read back) and gives the general pass's
// cuts. ls1 changes every 170 us, so its window at 1.21-1.24 ms (its last change before it at
// 1.19 ms, the next at 1.36 ms, after the pass stopped) begins only in the loop after the pass.
TEST(WindowTraces, APassThatStopsAfterTheLastWindowCutsAsTheGeneralPass) {
  TraceRecorder ordered;
  TraceRecorder general;
  ASSERT_NO_FATAL_FAILURE(record_twice(ordered, general, false));
  rig::CheckResult early = one_window(Nanos{1'210'000}, Nanos{1'240'000});
  for (const auto& [b, e] : std::vector<std::pair<std::int64_t, std::int64_t>>{
           {200'000, 250'000}, {1'250'000, 1'250'000}, {0, 1'000}, {1'000'000, 1'189'000}})
    early.measurements.push_back(one_window(Nanos{b}, Nanos{e}).measurements[0]);
  const Lanes shaft{{"enc.A", rig::LaneRole::Stimulus},
                    {"shaft.count", rig::LaneRole::Count},
                    {"ls1", rig::LaneRole::Output}};
  const std::vector<WindowCut> cuts{{&early, shaft}, {&early, {{"ls1", rig::LaneRole::Output}}}};
  const auto fast = cut_window_traces(cuts, ordered);
  const auto slow = cut_window_traces(cuts, general);
  ASSERT_EQ(fast.size(), cuts.size());
  for (std::size_t k = 0; k < cuts.size(); ++k) expect_same(fast[k], slow[k], "cut " + std::to_string(k));
  // The 1.21-1.24 ms window is drawn over 1.204-1.246 ms (padded by a fifth of its width,
  // figure_span). ls1 there holds the level of its change at 1.19 ms, no change inside: the
  // level toggles every 1 us from High at 5 us, so at 1.19 ms, (1,190 - 5) toggles later, Low.
  bool found = false;
  for (const rig::WindowTrace& w : fast[1]) {
    if (w.span.begin != Nanos{1'204'000}) continue;
    found = true;
    ASSERT_EQ(w.lanes.size(), 1U);
    ASSERT_EQ(w.lanes[0].changes.size(), 1U);
    EXPECT_EQ(w.lanes[0].changes[0].value, 0);
  }
  EXPECT_TRUE(found);
}

// A resolver board's stimulus in its diagram: the stators as the run recorded them, real
// lanes. The stator model (rig/campaign/resolver_stators.hpp, after the ANS1 and Series 2700
// resolver inputs): the rotor is excited with amplitude * sin(2 pi f t + phase) and each
// stator carries it times the ratio and sin / cos of the shaft angle; the trace samples them
// at each excitation peak (run_trace.hpp), where the carrier is +1. So at the k-th peak
// t_k = (1/4 - phase/360 + k) / f the sine lane reads ratio * amplitude * sin(angle(t_k)).
TEST(Figure, AResolverWindowHasItsStatorsAsRealLanesAtEachExcitationPeak) {
  ResolverSpec r;
  r.excitation_hz = 5000.0; // peaks every 200 us, the first at 50 us
  r.amplitude = 2.0;
  r.ratio = 0.5;
  constexpr double kPerTurn = 4096.0;
  const ShaftPosition shaft = [](Nanos t) { return 1000.0 * t.seconds(); }; // 1000 counts/s
  Scheduler sched;
  TraceRecorder trace;
  const auto sampler = trace_stators(sched, trace, r, stator_waveform(shaft, kPerTurn, r, Stator::Sine),
                                     stator_waveform(shaft, kPerTurn, r, Stator::Cosine), Nanos{5'000'000});
  sched.run_until_idle();
  const checks::CheckParams params = checks::ThroughputParams{};
  const auto lanes = lanes_of(params, trace);
  ASSERT_EQ(lanes.size(), 2U); // no encoder, count or output declared in this trace
  EXPECT_EQ(lanes[0], (std::pair<std::string, rig::LaneRole>{"resolver.sin", rig::LaneRole::Stimulus}));
  EXPECT_EQ(lanes[1], (std::pair<std::string, rig::LaneRole>{"resolver.cos", rig::LaneRole::Stimulus}));
  const rig::CheckResult c = one_window(Nanos{2'000'000}, Nanos{3'000'000});
  const auto span = rig::figure_span(c.measurements[0]);
  const auto cut = cut_window_traces(c, trace, lanes);
  ASSERT_EQ(cut.size(), 1U);
  const auto expected = [&](Nanos t, bool sine) {
    const double angle = 2.0 * std::numbers::pi * 1000.0 * t.seconds() / kPerTurn;
    return r.ratio * r.amplitude * (sine ? std::sin(angle) : std::cos(angle));
  };
  const auto peak = [](std::int64_t k) { return Nanos{50'000 + k * 200'000}; };
  for (const bool sine : {true, false}) {
    const rig::TraceLane& lane = cut[0].lanes[sine ? 0 : 1];
    EXPECT_TRUE(lane.real);
    EXPECT_EQ(lane.thinned, 0U);
    // Every peak inside the span and nothing else: the first is the first peak at or after
    // the span's start (a sampled signal has no value between its peaks), each to 1 uV.
    const std::int64_t first = (span.begin.count() - 50'000 + 199'999) / 200'000;
    const std::int64_t last = (span.end.count() - 50'000) / 200'000;
    ASSERT_EQ(lane.changes.size(), static_cast<std::size_t>(last - first + 1));
    EXPECT_GE(lane.changes[0].time, span.begin);
    EXPECT_LT(lane.changes[0].time, span.begin + Nanos{200'000});
    for (std::size_t i = 0; i < lane.changes.size(); ++i) {
      const Nanos at = peak(first + static_cast<std::int64_t>(i));
      EXPECT_EQ(lane.changes[i].time, at);
      EXPECT_NEAR(lane.changes[i].real, expected(at, sine), 0.5e-6) << "peak at " << at.count() << " ns";
      EXPECT_DOUBLE_EQ(lane.changes[i].real, std::round(lane.changes[i].real * 1e6) / 1e6);
      EXPECT_EQ(lane.changes[i].value, 0);
    }
  }
}

// A window shorter than an excitation period, between two peaks: no sample inside, so the
// lane shows the last peak before it at that peak's own time, not moved to the span's start.
TEST(Figure, AStatorLaneWithNoPeakInsideItsSpanShowsTheLastPeakAtItsOwnTime) {
  ResolverSpec r;
  r.excitation_hz = 2000.0;                                 // peaks every 500 us, the first at 125 us
  const ShaftPosition shaft = [](Nanos) { return 1024.0; }; // a quarter turn: sin 1, cos 0
  Scheduler sched;
  TraceRecorder trace;
  const auto sampler = trace_stators(sched, trace, r, stator_waveform(shaft, 4096.0, r, Stator::Sine),
                                     stator_waveform(shaft, 4096.0, r, Stator::Cosine), Nanos{5'000'000});
  sched.run_until_idle();
  const auto lanes = lanes_of(checks::ThroughputParams{}, trace);
  // Window 1.150 .. 1.160 ms: its span (a fifth either side, 1.148 .. 1.162 ms) lies between
  // the peaks at 1.125 and 1.625 ms.
  const auto cut = cut_window_traces(one_window(Nanos{1'150'000}, Nanos{1'160'000}), trace, lanes);
  ASSERT_EQ(cut.size(), 1U);
  ASSERT_LT(cut[0].span.end, Nanos{1'625'000});
  for (const rig::TraceLane& lane : cut[0].lanes) {
    ASSERT_EQ(lane.changes.size(), 1U) << lane.name;
    EXPECT_EQ(lane.changes[0].time, Nanos{1'125'000}) << lane.name;
    EXPECT_NEAR(lane.changes[0].real, lane.name == "resolver.sin" ? 1.0 : 0.0, 1e-12) << lane.name;
  }
}

// Stator volts to 1 uV (kRealLaneResolution): the nearest multiple, either side of a half,
// and exactly the double nearest that decimal (0.936613, not 0.9366129999999999), over a
// sweep of a stator's range.
TEST(Figure, RealLaneValuesAreRoundedToOneMicrovolt) {
  EXPECT_EQ(kRealLaneResolution, 1e-6);
  EXPECT_EQ(real_lane_value(0.1234564999), 0.123456);
  EXPECT_EQ(real_lane_value(0.1234565001), 0.123457);
  EXPECT_EQ(real_lane_value(-0.7071067811865476), -0.707107);
  EXPECT_EQ(real_lane_value(0.936612999), 0.936613);
  EXPECT_EQ(real_lane_value(0.0000004), 0.0);
  EXPECT_EQ(real_lane_value(2.5), 2.5);
  for (int i = -20000; i <= 20000; ++i) {
    const double v = std::sin(i * 1e-4) * 2.0 + 1e-9; // off the grid by a nanovolt
    const double r = real_lane_value(v);
    EXPECT_LE(std::abs(r - v), 0.5e-6 + 1e-15) << v;
    // On the grid: the double nearest a whole number of microvolts.
    EXPECT_EQ(r, std::round(r * 1e6) / 1e6) << v;
  }
}

} // namespace
} // namespace hilrig::campaign
