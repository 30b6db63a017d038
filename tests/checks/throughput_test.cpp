#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <random>
#include <vector>

#include "check_test_support.hpp"
#include "rig/checks/throughput.hpp"

namespace hilrig::checks {
namespace {

using namespace hilrig::literals;
using test::find;

// Crossings at 1, 2, 3 ms; the output goes high 15, 20, 12 us after each and low again
// 500 us later. Sorted latencies 12, 15, 20 us: min 12, median (nearest rank: ceil(1.5) =
// 2nd) 15, p99 (ceil(2.97) = 3rd) 20, max 20.
std::vector<Edge> outputs_after(const std::vector<Nanos>& crossings, const std::vector<Nanos>& latencies) {
  std::vector<Edge> e;
  for (std::size_t i = 0; i < latencies.size(); ++i) {
    e.push_back({crossings[i] + latencies[i], Level::High});
    e.push_back({crossings[i] + 500_us, Level::Low});
  }
  return e;
}

const std::vector<Nanos> kCrossings{1_ms, 2_ms, 3_ms};

TEST(Throughput, DistributionWorkedByHand) {
  const auto out = outputs_after(kCrossings, {15_us, 20_us, 12_us});
  const auto r = check_throughput(kCrossings, out, {.name = "ls1", .limit = 20_us});
  EXPECT_EQ(r.outcome(), rig::Outcome::Pass);
  EXPECT_EQ(find(r, "ls1.count").value, 3.0);
  EXPECT_EQ(find(r, "ls1.min").value, 12.0);
  EXPECT_EQ(find(r, "ls1.median").value, 15.0);
  EXPECT_EQ(find(r, "ls1.p99").value, 20.0);
  EXPECT_EQ(find(r, "ls1.max").value, 20.0);
  EXPECT_EQ(find(r, "ls1.max").unit, "us");
  EXPECT_EQ(find(r, "ls1.max").upper, 20.0);
  EXPECT_EQ(find(r, "ls1.missing").value, 0.0);
  // The max's window is the crossing at 2 ms to its edge at 2.020 ms.
  ASSERT_TRUE(find(r, "ls1.max").window);
  EXPECT_EQ(find(r, "ls1.max").window->begin, 2_ms);
  EXPECT_EQ(find(r, "ls1.max").window->end, 2_ms + 20_us);
  // The raw series keeps crossing order.
  ASSERT_EQ(r.series.size(), 1U);
  EXPECT_EQ(r.series[0].values, (std::vector<double>{15.0, 20.0, 12.0}));
}

TEST(Throughput, FailsOneNanosecondAndOneMicrosecondBeyondTheLimitAndPassesAtIt) {
  for (const Nanos worst : {20_us + 1_ns, 21_us}) {
    const auto out = outputs_after(kCrossings, {15_us, worst, 12_us});
    const auto r = check_throughput(kCrossings, out, {.name = "ls1", .limit = 20_us});
    EXPECT_EQ(r.outcome(), rig::Outcome::Fail) << worst.count();
    EXPECT_EQ(find(r, "ls1.max").outcome, rig::Outcome::Fail);
  }
  const auto out = outputs_after(kCrossings, {20_us, 20_us, 20_us});
  EXPECT_EQ(check_throughput(kCrossings, out, {.name = "ls1", .limit = 20_us}).outcome(), rig::Outcome::Pass);
}

TEST(Throughput, MissingEdgeIsANamedFailure) {
  // The second crossing's edge never comes before the third crossing.
  std::vector<Edge> out{
      {1_ms + 15_us, Level::High}, {1_ms + 500_us, Level::Low}, {3_ms + 12_us, Level::High}};
  const auto r = check_throughput(kCrossings, out, {.name = "ls1", .limit = 20_us});
  EXPECT_EQ(r.outcome(), rig::Outcome::Fail);
  const auto& missing = find(r, "ls1.missing");
  EXPECT_EQ(missing.value, 1.0);
  EXPECT_EQ(missing.outcome, rig::Outcome::Fail);
  EXPECT_NE(missing.detail.find("missing edge"), std::string::npos);
  ASSERT_TRUE(missing.window);
  EXPECT_EQ(missing.window->begin, 2_ms);
  EXPECT_EQ(missing.window->end, 3_ms);
  EXPECT_EQ(find(r, "ls1.count").value, 2.0);
}

TEST(Throughput, TimeoutBoundsTheSearchAndWrongLevelDoesNotCount) {
  // A low edge after the crossing is not the expected high edge; a high edge 60 us late is
  // beyond a 50 us timeout, so it is missing rather than slow.
  std::vector<Nanos> one{1_ms};
  std::vector<Edge> out{{1_ms + 5_us, Level::Low}, {1_ms + 60_us, Level::High}};
  const auto r = check_throughput(one, out, {.name = "t", .limit = 20_us, .timeout = 50_us});
  EXPECT_EQ(find(r, "t.missing").value, 1.0);
  EXPECT_EQ(find(r, "t.count").outcome, rig::Outcome::Fail);
}

TEST(Throughput, NearestRankP99OverAHundredCrossingsHasItsOwnLimit) {
  // Latencies 1..100 us: nearest-rank p99 is the 99th smallest = 99 us, max 100 us, median
  // the 50th = 50 us.
  std::vector<Nanos> crossings;
  std::vector<Nanos> lat;
  for (int i = 0; i < 100; ++i) {
    crossings.push_back(milliseconds(i + 1));
    lat.push_back(microseconds(100 - i)); // descending, so sorting matters
  }
  const auto out = outputs_after(crossings, lat);
  auto r = check_throughput(crossings, out, {.name = "t", .limit = 100_us, .p99_limit = 99_us});
  EXPECT_EQ(find(r, "t.median").value, 50.0);
  EXPECT_EQ(find(r, "t.p99").value, 99.0);
  EXPECT_EQ(find(r, "t.max").value, 100.0);
  EXPECT_EQ(r.outcome(), rig::Outcome::Pass);
  r = check_throughput(crossings, out, {.name = "t", .limit = 100_us, .p99_limit = 98_us});
  EXPECT_EQ(find(r, "t.p99").outcome, rig::Outcome::Fail);
  EXPECT_EQ(find(r, "t.max").outcome, rig::Outcome::Pass);
}

TEST(Throughput, PropertyStatisticsAreOrderStatisticsOfTheLatencies) {
  // Seeded random latencies in [1, 400] us, crossings 1 ms apart: count, min, max and the
  // nearest-rank median/p99 equal the order statistics of the generated latencies.
  std::mt19937_64 rng(7361);
  for (int trial = 0; trial < 50; ++trial) {
    std::uniform_int_distribution<int> n_pick(1, 300);
    std::uniform_int_distribution<std::int64_t> lat_pick(1'000, 400'000);
    const auto n = static_cast<std::size_t>(n_pick(rng));
    std::vector<Nanos> crossings;
    std::vector<Nanos> lat;
    for (std::size_t i = 0; i < n; ++i) {
      crossings.push_back(milliseconds(static_cast<std::int64_t>(i) + 1));
      lat.push_back(Nanos{lat_pick(rng)});
    }
    const auto r = check_throughput(crossings, outputs_after(crossings, lat), {.name = "t", .limit = 400_us});
    std::vector<Nanos> sorted = lat;
    std::sort(sorted.begin(), sorted.end());
    const auto rank = [&](double p) { // nearest rank, 1-based ceil(p/100 * n)
      const auto k = static_cast<std::size_t>(std::ceil(p / 100.0 * static_cast<double>(n)));
      return to_us(sorted[std::max<std::size_t>(k, 1) - 1]);
    };
    EXPECT_EQ(find(r, "t.count").value, static_cast<double>(n));
    EXPECT_EQ(find(r, "t.min").value, to_us(sorted.front()));
    EXPECT_EQ(find(r, "t.max").value, to_us(sorted.back()));
    EXPECT_EQ(find(r, "t.median").value, rank(50.0));
    EXPECT_EQ(find(r, "t.p99").value, rank(99.0));
    EXPECT_EQ(r.outcome(), rig::Outcome::Pass);
  }
}

// An SSI clock as the 7361 drives it (manual L1085-L1098): idle high, each frame 25 falling
// edges T = 8 us apart with a rising edge T/2 after each; frame k starts at starts[k].
std::vector<Edge> ssi_clock(const std::vector<Nanos>& starts) {
  std::vector<Edge> e;
  for (const Nanos s : starts)
    for (std::int64_t j = 0; j < 25; ++j) {
      e.push_back({s + 8_us * j, Level::Low});
      e.push_back({s + 8_us * j + 4_us, Level::High});
    }
  return e;
}

// Expected frame starts every TINT = 500 us (L1090, L1096) from 100 us.
const std::vector<Nanos> kFrameStarts{100_us, 600_us, 1100_us, 1600_us};

// The 7361 campaigns' frame_start check: the frame's first falling edge (after >= 20 us of
// clock high, TM L1091-L1092) within +- T/2 = 4 us of the expected start.
const ThroughputSpec kFrameStart{
    .name = "fs", .expected = Level::Low, .limit = 4_us, .quiet = 20_us, .early = 4_us, .min_count = 4};

std::vector<Nanos> shifted(std::size_t frame, Nanos by) {
  std::vector<Nanos> s = kFrameStarts;
  s[frame] += by;
  return s;
}

TEST(Throughput, AnyEdgeLetsAFrameAWholeClockPeriodEarlyPass) {
  // Why quiet exists: frame 2 starts 8 us (one T) early, its second falling edge is on the
  // expected start, and a check taking any falling edge reads 0 us.
  const auto out = ssi_clock(shifted(2, -8_us));
  const auto r = check_throughput(kFrameStarts, out, {.name = "fs", .expected = Level::Low, .limit = 4_us});
  EXPECT_EQ(r.outcome(), rig::Outcome::Pass);
}

TEST(Throughput, QuietJudgesTheBurstsFirstEdgeEarlyAndLateEachSideOfTheLimit) {
  const auto on_time = check_throughput(kFrameStarts, ssi_clock(kFrameStarts), kFrameStart);
  EXPECT_EQ(on_time.outcome(), rig::Outcome::Pass);
  EXPECT_EQ(find(on_time, "fs.min").value, 0.0);
  EXPECT_EQ(find(on_time, "fs.max").value, 0.0);
  EXPECT_EQ(find(on_time, "fs.min").lower, -4.0);
  // Exactly T/2 early or late passes; a nanosecond beyond fails, each side.
  for (const Nanos d : {-4_us, -1_ns, 1_ns, 4_us}) {
    const auto r = check_throughput(kFrameStarts, ssi_clock(shifted(2, d)), kFrameStart);
    EXPECT_EQ(r.outcome(), rig::Outcome::Pass) << d.count();
  }
  const auto early = check_throughput(kFrameStarts, ssi_clock(shifted(2, -4_us - 1_ns)), kFrameStart);
  EXPECT_EQ(early.outcome(), rig::Outcome::Fail);
  EXPECT_EQ(find(early, "fs.min").value, -4.001); // measured, not lost to the next frame
  EXPECT_EQ(find(early, "fs.min").outcome, rig::Outcome::Fail);
  const auto late = check_throughput(kFrameStarts, ssi_clock(shifted(2, 4_us + 1_ns)), kFrameStart);
  EXPECT_EQ(late.outcome(), rig::Outcome::Fail);
  EXPECT_EQ(find(late, "fs.max").value, 4.001);
  // Early by whole clock periods: the frame's inner edges do not stand in for its first one.
  for (const Nanos d : {-8_us, -16_us, -152_us}) {
    const auto r = check_throughput(kFrameStarts, ssi_clock(shifted(2, d)), kFrameStart);
    EXPECT_EQ(r.outcome(), rig::Outcome::Fail) << d.count();
    EXPECT_EQ(find(r, "fs.min").value, to_us(d)) << d.count();
  }
  // Late by a whole period: the expected start has no edge until the frame's first.
  const auto period_late = check_throughput(kFrameStarts, ssi_clock(shifted(2, 8_us)), kFrameStart);
  EXPECT_EQ(period_late.outcome(), rig::Outcome::Fail);
  EXPECT_EQ(find(period_late, "fs.max").value, 8.0);
}

TEST(Throughput, AnEarlyEdgeIsNegativeLatencyWithItsWindowInOrder) {
  const auto r = check_throughput(kFrameStarts, ssi_clock(shifted(1, -3_us)), kFrameStart);
  EXPECT_EQ(r.outcome(), rig::Outcome::Pass);
  EXPECT_EQ(find(r, "fs.min").value, -3.0);
  ASSERT_TRUE(find(r, "fs.min").window);
  EXPECT_EQ(find(r, "fs.min").window->begin, 597_us);
  EXPECT_EQ(find(r, "fs.min").window->end, 600_us);
}

// The capture ends 20 us after the last crossing (3 ms), the limit is 20 us: a board within the
// limit has had to answer by the end, so a missing edge there fails; 1 ns later and the end cuts
// the window short: that crossing is not judged (a board may answer after the run), never failed.
TEST(Throughput, ACrossingWhoseLimitReachesPastTheCaptureIsNotJudged) {
  const auto out = outputs_after({1_ms, 2_ms}, {15_us, 20_us}); // none after 3 ms
  const ThroughputSpec spec{.name = "ls1", .limit = 20_us, .min_count = 2};
  auto r = check_throughput(kCrossings, out, spec, 3_ms + 20_us);
  EXPECT_EQ(find(r, "ls1.missing").value, 1.0);
  EXPECT_EQ(r.outcome(), rig::Outcome::Fail);
  r = check_throughput(kCrossings, out, spec, 3_ms + 20_us - 1_ns);
  EXPECT_EQ(find(r, "ls1.missing").value, 0.0);
  EXPECT_EQ(find(r, "ls1.count").value, 2.0);
  EXPECT_NE(find(r, "ls1.count").detail.find("1 crossing(s) within limit_us of the capture's end"),
            std::string::npos);
  EXPECT_EQ(r.outcome(), rig::Outcome::Pass);
  // An edge that did come before the end is judged as ever, cut window or not.
  const auto all = outputs_after(kCrossings, {15_us, 20_us, 12_us});
  r = check_throughput(kCrossings, all, spec, 3_ms + 13_us);
  EXPECT_EQ(find(r, "ls1.count").value, 3.0);
  EXPECT_EQ(r.outcome(), rig::Outcome::Pass);
  const auto late = outputs_after(kCrossings, {15_us, 20_us, 21_us});
  r = check_throughput(kCrossings, late, {.name = "ls1", .limit = 20_us, .timeout = 30_us}, 3_ms + 25_us);
  EXPECT_EQ(find(r, "ls1.max").outcome, rig::Outcome::Fail);
  // Fewer judged crossings than min_count: the run's shortfall, an error; none judged, too.
  r = check_throughput(kCrossings, out, {.name = "ls1", .limit = 20_us, .min_count = 3}, 3_ms + 19_us);
  EXPECT_EQ(find(r, "ls1.count").outcome, rig::Outcome::Error);
  const std::vector<Nanos> last{3_ms};
  r = check_throughput(last, {}, {.name = "ls1", .limit = 20_us}, 3_ms + 5_us);
  EXPECT_EQ(find(r, "ls1.count").outcome, rig::Outcome::Error);
  EXPECT_EQ(r.outcome(), rig::Outcome::Error);
}

} // namespace
} // namespace hilrig::checks
