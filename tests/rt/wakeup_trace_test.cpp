// The per-wake-up breakdown of `hilrig latency --breakdown`: the percentile rule on known
// samples, the summary of hand-made stamps, and the measuring loop with a trace attached
// (no allocation; every wake-up stamped on the loop's grid). No timing threshold: the loop
// runs on the real clock, so only orderings and the grid are checked.
#include "rig/rt/wakeup_trace.hpp"

#include <gtest/gtest.h>

#include <atomic>
#include <memory>
#include <vector>

#include "allocation_counter.hpp"
#include "core/clock.hpp"
#include "rig/rt/rt_loop.hpp"

using namespace hilrig;
using namespace hilrig::rig;

namespace {
std::vector<Nanos> one_to(std::int64_t n, std::int64_t step = 1) {
  std::vector<Nanos> v;
  for (std::int64_t k = n; k >= 1; --k) v.push_back(Nanos{k * step}); // unsorted on purpose
  return v;
}
} // namespace

// Nearest rank: the smallest sample with at least q of the samples at or below it.
TEST(WakeupSpread, NearestRankOnOneToAHundred) {
  const Spread s = spread_of(one_to(100));
  EXPECT_EQ(s.p50, Nanos{50});
  EXPECT_EQ(s.p99, Nanos{99});
  EXPECT_EQ(s.max, Nanos{100});
}

TEST(WakeupSpread, RankRoundsUpBetweenSamples) {
  // 1,001 samples: 99 % is rank 990.99 -> 991; 50 % is rank 500.5 -> 501.
  const Spread s = spread_of(one_to(1001, 10));
  EXPECT_EQ(s.p99, Nanos{9910});
  EXPECT_EQ(s.p50, Nanos{5010});
  EXPECT_EQ(s.max, Nanos{10010});
}

TEST(WakeupSpread, OneSampleIsEveryPercentileAndNoneIsZero) {
  const Spread one = spread_of({Nanos{7}});
  EXPECT_EQ(one.p50, Nanos{7});
  EXPECT_EQ(one.p99, Nanos{7});
  EXPECT_EQ(one.max, Nanos{7});
  const Spread none = spread_of({});
  EXPECT_EQ(none.max, Nanos{0});
}

TEST(WakeupBreakdownSummary, SeparatesLatencyWorkAndLead) {
  std::vector<WakeupStamps> stamps;
  for (std::int64_t k = 1; k <= 100; ++k) {
    const Nanos due{k * 1'000'000};
    // back asleep 900 us ahead, woke k us late, work 100 + k ns
    stamps.push_back(
        WakeupStamps{due, due - Nanos{900'000}, due + Nanos{k * 1000}, due + Nanos{k * 1000 + 100 + k}});
  }
  const WakeupBreakdown b = summarize(stamps);
  EXPECT_EQ(b.wakeups, 100U);
  EXPECT_EQ(b.latency.p99, Nanos{99'000});
  EXPECT_EQ(b.latency.max, Nanos{100'000});
  EXPECT_EQ(b.work.p50, Nanos{150});
  EXPECT_EQ(b.work.max, Nanos{200});
  EXPECT_EQ(b.ahead.p50, Nanos{900'000});
}

TEST(WakeupTrace, KeepsItsCapacityAndCountsTheRest) {
  WakeupTrace t(3);
  for (int k = 0; k < 5; ++k) t.add(WakeupStamps{Nanos{k}, Nanos{k}, Nanos{k}, Nanos{k}});
  ASSERT_EQ(t.stamps().size(), 3U);
  EXPECT_EQ(t.stamps()[2].due, Nanos{2});
  EXPECT_EQ(t.dropped(), 2U);
}

// The measuring loop with the trace attached allocates nothing, stamps every wake-up, and
// every deadline is a point of its grid (a stall skips points, never shifts the phase).
TEST(WakeupTrace, MeasuringLoopStampsEveryWakeupOnItsGridWithoutAllocating) {
  constexpr std::uint64_t kLoops = 200;
  const Nanos interval = microseconds(20);
  auto histogram = std::make_unique<LatencyHistogram>();
  WakeupTrace trace(kLoops);
  std::atomic<bool> stop{false};
  const Nanos start = MonotonicClock{}.now();
  hilrig::test::arm_allocation_counter();
  measure_wakeups(start, interval, kLoops, stop, *histogram, &trace);
  const std::uint64_t allocations = hilrig::test::disarm_allocation_counter();
  EXPECT_EQ(allocations, 0U);
  ASSERT_EQ(trace.stamps().size(), kLoops);
  EXPECT_EQ(histogram->count(), kLoops);
  Nanos previous = start;
  for (const WakeupStamps& s : trace.stamps()) {
    EXPECT_GT(s.due, previous);
    EXPECT_EQ((s.due - start).count() % interval.count(), 0);
    EXPECT_LE(s.asleep, s.woke);
    EXPECT_GE(s.woke, s.due); // an absolute sleep never returns early
    EXPECT_GE(s.done, s.woke);
    previous = s.due;
  }
}
