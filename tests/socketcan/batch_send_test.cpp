// send_in_batches against scripted stand-ins for sendmmsg(2) and poll(2): what the kernel may
// answer (man 2 sendmmsg: the number of messages queued, possibly fewer than asked; -1 with
// errno when none was; EAGAIN/ENOBUFS when the transmit queue is full) and what must follow.
#include "drivers/socketcan/batch_send.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cerrno>
#include <cstddef>
#include <deque>
#include <vector>

#include "tests/rt/allocation_counter.hpp"

using namespace hilrig::socketcan;

namespace {

// A transmit queue that takes what its script says per call (a count, or -errno), then
// everything it is offered; records the frame indices in the order they were queued.
struct ScriptedQueue {
  std::deque<long> script;
  std::vector<std::size_t> queued;
  std::vector<std::size_t> call_sizes;
  std::size_t waits = 0;
  std::size_t waits_allowed = 1'000'000;

  long send_many(std::size_t first, std::size_t count) {
    call_sizes.push_back(count);
    long take = static_cast<long>(count);
    if (!script.empty()) {
      take = std::min(script.front(), take); // the kernel never queues more than it is given
      script.pop_front();
    }
    if (take <= 0) return take;
    for (std::size_t k = 0; k < static_cast<std::size_t>(take); ++k) queued.push_back(first + k);
    return take;
  }
  bool wait_for_room() { return ++waits <= waits_allowed; }

  BatchSent run(std::size_t total, std::size_t batch) {
    return send_in_batches(
        total, batch, [this](std::size_t f, std::size_t c) { return send_many(f, c); },
        [this] { return wait_for_room(); });
  }
};

std::vector<std::size_t> first_n(std::size_t n) {
  std::vector<std::size_t> v(n);
  for (std::size_t k = 0; k < n; ++k) v[k] = k;
  return v;
}

} // namespace

TEST(SendInBatches, AQueueWithRoomTakesABatchPerCall) {
  ScriptedQueue q;
  const BatchSent r = q.run(130, 64);
  EXPECT_EQ(r.sent, 130U);
  EXPECT_EQ(r.status, SendStatus::Sent);
  EXPECT_EQ(r.error, 0);
  EXPECT_EQ(q.call_sizes, (std::vector<std::size_t>{64, 64, 2}));
  EXPECT_EQ(q.queued, first_n(130));
  EXPECT_EQ(q.waits, 0U);
}

TEST(SendInBatches, NothingToSendMakesNoCall) {
  ScriptedQueue q;
  const BatchSent r = q.run(0, 64);
  EXPECT_EQ(r.sent, 0U);
  EXPECT_EQ(r.status, SendStatus::Sent);
  EXPECT_TRUE(q.call_sizes.empty());
}

TEST(SendInBatches, APartialSendResumesAtTheFirstFrameNotTaken) {
  ScriptedQueue q;
  q.script = {10, 1, 63};
  const BatchSent r = q.run(100, 64);
  EXPECT_EQ(r.sent, 100U);
  EXPECT_EQ(r.status, SendStatus::Sent);
  // 0..9, then 10, then 11..73, then the 26 left.
  EXPECT_EQ(q.call_sizes, (std::vector<std::size_t>{64, 64, 64, 26}));
  EXPECT_EQ(q.queued, first_n(100)); // each frame once, in order
  EXPECT_EQ(q.waits, 0U);
}

TEST(SendInBatches, AFullQueueIsWaitedOutThenTheRestGoes) {
  for (const int full : {EAGAIN, ENOBUFS}) {
    ScriptedQueue q;
    q.script = {20, -full, -full, 64};
    const BatchSent r = q.run(90, 64);
    EXPECT_EQ(r.sent, 90U) << full;
    EXPECT_EQ(r.status, SendStatus::Sent) << full;
    EXPECT_EQ(r.error, 0) << full;
    EXPECT_EQ(q.waits, 2U) << full; // one wait per refusal, none after a send
    EXPECT_EQ(q.queued, first_n(90)) << full;
  }
}

TEST(SendInBatches, DeadlinePassedKeepsTheQueuedPrefix) {
  ScriptedQueue q;
  q.script = {5, -EAGAIN, -EAGAIN, -EAGAIN};
  q.waits_allowed = 2; // the third wait finds the deadline gone
  const BatchSent r = q.run(64, 64);
  EXPECT_EQ(r.sent, 5U);
  EXPECT_EQ(r.status, SendStatus::DeadlineMissed);
  EXPECT_EQ(r.error, EAGAIN);
  EXPECT_EQ(q.queued, first_n(5));
}

TEST(SendInBatches, NoProgressAndNoErrorCountsAsAFullQueue) {
  ScriptedQueue q;
  q.script = {0, 0};
  q.waits_allowed = 1;
  const BatchSent r = q.run(3, 64);
  EXPECT_EQ(r.sent, 0U);
  EXPECT_EQ(r.status, SendStatus::DeadlineMissed);
  EXPECT_EQ(q.waits, 2U);
}

TEST(SendInBatches, BusOffStopsAtOnce) {
  ScriptedQueue q;
  q.script = {7, -ENETDOWN};
  const BatchSent r = q.run(64, 64);
  EXPECT_EQ(r.sent, 7U);
  EXPECT_EQ(r.status, SendStatus::BusOff);
  EXPECT_EQ(r.error, ENETDOWN);
  EXPECT_EQ(q.waits, 0U);
}

TEST(SendInBatches, AnyOtherErrorFailsWithoutWaiting) {
  ScriptedQueue q;
  q.script = {-EINVAL};
  const BatchSent r = q.run(8, 64);
  EXPECT_EQ(r.sent, 0U);
  EXPECT_EQ(r.status, SendStatus::Failed);
  EXPECT_EQ(r.error, EINVAL);
  EXPECT_EQ(q.waits, 0U);
}

TEST(SendInBatches, AnInterruptedCallIsRepeatedWithoutWaiting) {
  ScriptedQueue q;
  q.script = {-EINTR, 8};
  const BatchSent r = q.run(8, 64);
  EXPECT_EQ(r.sent, 8U);
  EXPECT_EQ(r.status, SendStatus::Sent);
  EXPECT_EQ(q.waits, 0U);
  EXPECT_EQ(q.call_sizes, (std::vector<std::size_t>{8, 8}));
}

// Property: whatever prefix the queue takes per call, every frame is queued exactly once and
// in order, and no call asks for more than a batch.
TEST(SendInBatches, EveryFrameOnceInOrderForAnyBatchAndAnyPartialTake) {
  for (std::size_t total = 0; total <= 150; total += 7) {
    for (std::size_t batch = 1; batch <= 70; batch += 3) {
      for (long take = 1; take <= 5; ++take) {
        ScriptedQueue q;
        // Take `take` frames (or what was offered, if fewer) per call, a refusal every 4th.
        for (int k = 0; k < 400; ++k) q.script.push_back(k % 4 == 3 ? -EAGAIN : take);
        const BatchSent r = q.run(total, batch);
        ASSERT_EQ(r.sent, total) << total << " " << batch << " " << take;
        ASSERT_EQ(q.queued, first_n(total)) << total << " " << batch << " " << take;
        for (const std::size_t c : q.call_sizes) ASSERT_LE(c, batch);
      }
    }
  }
}

// The RT rule: sending a run of frames allocates nothing (the callables here do not either).
TEST(SendInBatches, DoesNotAllocate) {
  std::size_t queued = 0;
  int calls = 0;
  hilrig::test::arm_allocation_counter();
  const BatchSent r = send_in_batches(
      1000, 64,
      [&](std::size_t, std::size_t c) -> long {
        if (++calls % 3 == 0) return -EAGAIN;
        const std::size_t take = c > 9 ? c - 9 : c;
        queued += take;
        return static_cast<long>(take);
      },
      [] { return true; });
  const std::uint64_t allocations = hilrig::test::disarm_allocation_counter();
  EXPECT_EQ(allocations, 0U);
  EXPECT_EQ(r.sent, 1000U);
  EXPECT_EQ(queued, 1000U);
}
