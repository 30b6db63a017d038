#include "rig/rt/rt_loop.hpp"

#include <gtest/gtest.h>

#include <array>
#include <memory>
#include <vector>

#include "allocation_counter.hpp"
#include "core/clock.hpp"

using namespace hilrig;
using namespace hilrig::rig;

namespace {

// Records writes into fixed storage: an output port that itself never allocates.
class RecordingOutputs final : public RtOutputPort {
public:
  void write(std::uint16_t line, Level level) noexcept override {
    if (n < writes.size()) writes[n++] = {line, level};
  }
  std::array<std::pair<std::uint16_t, Level>, 4096> writes{};
  std::size_t n = 0;
};

// Holds `limit` input edges and hands over as many as fit per poll, like a gpiod edge-event
// queue that already holds them: what the loop sees does not depend on when it wakes.
class ScriptedInputs final : public RtInputPort {
public:
  std::size_t poll(std::span<InputEdge> out) noexcept override {
    std::size_t n = 0;
    while (given < limit && n < out.size()) {
      out[n++] = InputEdge{Nanos{static_cast<std::int64_t>(given) * 1000}, 7, level_of(given % 2 == 0)};
      ++given;
    }
    return n;
  }
  std::size_t given = 0;
  std::size_t limit = 100;
};

std::vector<ScheduledEdge> quadrature_like_schedule(std::size_t edges, Nanos spacing) {
  std::vector<ScheduledEdge> s;
  for (std::size_t i = 0; i < edges; ++i) {
    s.push_back(ScheduledEdge{spacing * static_cast<std::int64_t>(i + 1), static_cast<std::uint16_t>(i % 2),
                              level_of((i / 2) % 2 == 0)});
  }
  return s;
}

} // namespace

TEST(RtLoop, PlaysEveryEdgeInOrderAndHandsEachToTheRing) {
  const auto schedule = quadrature_like_schedule(500, microseconds(20));
  RecordingOutputs outputs;
  SpscRing<LoopSample> ring(1024);
  std::atomic<bool> stop{false};
  auto stats = std::make_unique<RtLoopStats>();
  play(schedule, MonotonicClock{}.now(), outputs, nullptr, ring, stop, RtLoopConfig{}, *stats);

  ASSERT_EQ(outputs.n, schedule.size());
  for (std::size_t i = 0; i < schedule.size(); ++i) {
    EXPECT_EQ(outputs.writes[i].first, schedule[i].line);
    EXPECT_EQ(outputs.writes[i].second, schedule[i].level);
  }
  EXPECT_EQ(stats->edges_played, schedule.size());
  LoopSample sample{};
  std::size_t popped = 0;
  Nanos previous{0};
  while (ring.pop(sample)) {
    EXPECT_EQ(sample.kind, LoopSample::Kind::Output);
    EXPECT_GE(sample.actual, sample.scheduled); // never early
    EXPECT_GE(sample.scheduled, previous);
    previous = sample.scheduled;
    ++popped;
  }
  EXPECT_EQ(popped, schedule.size());
}

TEST(RtLoop, DoesNotAllocateWhilePlaying) {
  const auto schedule = quadrature_like_schedule(2000, microseconds(10));
  RecordingOutputs outputs;
  ScriptedInputs inputs;
  SpscRing<LoopSample> ring(4096);
  std::atomic<bool> stop{false};
  auto stats = std::make_unique<RtLoopStats>();
  const Nanos start = MonotonicClock{}.now();

  hilrig::test::arm_allocation_counter();
  play(schedule, start, outputs, &inputs, ring, stop, RtLoopConfig{}, *stats);
  const std::uint64_t allocations = hilrig::test::disarm_allocation_counter();

  EXPECT_EQ(allocations, 0U);
  EXPECT_EQ(stats->edges_played, 2000U);
  EXPECT_EQ(stats->inputs_seen, inputs.limit);
}

// The capture tail after the last edge (a hardware run keeps listening to the board until
// the scenario's end) hands over every input edge and allocates nothing either.
TEST(RtLoop, CapturesInputsUntilTheEndWithoutAllocating) {
  ScriptedInputs inputs;
  SpscRing<LoopSample> ring(4096);
  std::atomic<bool> stop{false};
  auto stats = std::make_unique<RtLoopStats>();
  const Nanos end = MonotonicClock{}.now() + milliseconds(2);

  hilrig::test::arm_allocation_counter();
  capture_until(end, inputs, ring, stop, microseconds(200), *stats);
  const std::uint64_t allocations = hilrig::test::disarm_allocation_counter();

  EXPECT_EQ(allocations, 0U);
  EXPECT_EQ(stats->inputs_seen, inputs.limit);
  LoopSample sample{};
  std::size_t popped = 0;
  while (ring.pop(sample)) {
    EXPECT_EQ(sample.kind, LoopSample::Kind::Input);
    ++popped;
  }
  EXPECT_EQ(popped, inputs.limit);
}

TEST(RtLoop, AllocationCounterSeesAnAllocation) {
  // The proof above is only worth something if the counter can count.
  hilrig::test::arm_allocation_counter();
  auto p = std::make_unique<int>(42);
  const std::uint64_t allocations = hilrig::test::disarm_allocation_counter();
  EXPECT_EQ(allocations, 1U);
  EXPECT_EQ(*p, 42);
}

TEST(RtLoop, StopFlagEndsThePlayEarlyAndSaysSo) {
  const auto schedule = quadrature_like_schedule(10, milliseconds(100));
  RecordingOutputs outputs;
  SpscRing<LoopSample> ring(16);
  std::atomic<bool> stop{true};
  auto stats = std::make_unique<RtLoopStats>();
  play(schedule, MonotonicClock{}.now(), outputs, nullptr, ring, stop, RtLoopConfig{}, *stats);
  EXPECT_TRUE(stats->stopped_early);
  EXPECT_EQ(outputs.n, 0U);
}

TEST(RtLoop, EdgesAlreadyDueAreWrittenTogetherAndCountedLate) {
  // A schedule whose start lies 1 s in the past: every edge is overdue by far more than the
  // tolerance, so each is a missed deadline — reported, never silently dropped.
  const auto schedule = quadrature_like_schedule(8, microseconds(1));
  RecordingOutputs outputs;
  SpscRing<LoopSample> ring(16);
  std::atomic<bool> stop{false};
  auto stats = std::make_unique<RtLoopStats>();
  play(schedule, MonotonicClock{}.now() - seconds(1), outputs, nullptr, ring, stop, RtLoopConfig{}, *stats);
  EXPECT_EQ(outputs.n, 8U);
  EXPECT_EQ(stats->missed_deadlines, 8U);
  EXPECT_GE(stats->max_edge_error, seconds(1) - microseconds(8));
}
