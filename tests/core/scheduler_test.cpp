#include "core/scheduler.hpp"

#include <gtest/gtest.h>

#include <memory>
#include <stdexcept>
#include <string>
#include <vector>

using namespace hilrig;
using namespace hilrig::literals;

TEST(Scheduler, RunsEventsInTimeOrder) {
  Scheduler s;
  std::vector<int> order;
  s.at(3_us, [&] { order.push_back(3); });
  s.at(1_us, [&] { order.push_back(1); });
  s.at(2_us, [&] { order.push_back(2); });
  EXPECT_EQ(s.run_until_idle(), Scheduler::StopReason::Idle);
  EXPECT_EQ(order, (std::vector<int>{1, 2, 3}));
  EXPECT_EQ(s.now(), 3_us);
}

TEST(Scheduler, EqualTimesRunInSchedulingOrder) {
  Scheduler s;
  std::string order;
  for (char c : std::string("abcdefghij")) {
    s.at(5_us, [&order, c] { order.push_back(c); });
  }
  // An event scheduled from inside another at the same time runs after those already queued.
  s.at(5_us, [&] { s.at(5_us, [&] { order.push_back('z'); }); });
  s.at(5_us, [&] { order.push_back('k'); });
  s.run_until_idle();
  EXPECT_EQ(order, "abcdefghijkz");
}

TEST(Scheduler, CancelledEventNeverRuns) {
  Scheduler s;
  int ran = 0;
  EventId a = s.at(1_us, [&] { ran += 1; });
  EventId b = s.at(2_us, [&] { ran += 10; });
  EXPECT_TRUE(s.pending(a));
  EXPECT_TRUE(s.cancel(a));
  EXPECT_FALSE(s.pending(a));
  EXPECT_FALSE(s.cancel(a)); // twice is a no-op
  EXPECT_EQ(s.pending_count(), 1U);
  s.run_until_idle();
  EXPECT_EQ(ran, 10);
  EXPECT_FALSE(s.cancel(b)); // already ran
}

TEST(Scheduler, StaleIdDoesNotCancelReusedSlot) {
  Scheduler s;
  int ran = 0;
  EventId a = s.at(1_us, [&] { ran += 1; });
  s.cancel(a);
  s.at(2_us, [&] { ran += 10; }); // reuses a's slot
  EXPECT_FALSE(s.cancel(a));
  s.run_until_idle();
  EXPECT_EQ(ran, 10);
}

TEST(Scheduler, RunUntilStopsAtTimeAndAdvancesClock) {
  Scheduler s;
  int ran = 0;
  s.at(10_us, [&] { ++ran; });
  s.at(20_us, [&] { ++ran; });
  EXPECT_EQ(s.run_until(15_us), Scheduler::StopReason::ReachedTime);
  EXPECT_EQ(ran, 1);
  EXPECT_EQ(s.now(), 15_us);
  s.run_until(20_us); // inclusive
  EXPECT_EQ(ran, 2);
}

TEST(Scheduler, StopFromInsideAnEvent) {
  Scheduler s;
  int ran = 0;
  s.at(1_us, [&] {
    ++ran;
    s.stop();
  });
  s.at(2_us, [&] { ++ran; });
  EXPECT_EQ(s.run_until_idle(), Scheduler::StopReason::Stopped);
  EXPECT_EQ(ran, 1);
  EXPECT_EQ(s.run_until_idle(), Scheduler::StopReason::Idle);
  EXPECT_EQ(ran, 2);
}

TEST(Scheduler, RejectsEventsInThePast) {
  Scheduler s;
  s.run_until(5_us);
  EXPECT_THROW(s.at(4_us, [] {}), std::logic_error);
}

TEST(Scheduler, PeriodicEventReschedulesItself) {
  Scheduler s;
  std::vector<Nanos> ticks;
  std::function<void()> tick = [&] {
    ticks.push_back(s.now());
    if (ticks.size() < 4) s.after(200_us, tick);
  };
  s.at(0_ns, tick);
  s.run_until_idle();
  EXPECT_EQ(ticks, (std::vector<Nanos>{0_us, 200_us, 400_us, 600_us}));
}

TEST(Scheduler, TellsWhetherTheLastEventsAtNowHaveRunYet) {
  // A model that skips its Last-tied scans asks this (docs/virtual-time.md): during an
  // ordinary event the Last ones at its instant are still to come; during a Last event, and
  // outside events after run_until(t), they are not.
  Scheduler s;
  std::vector<bool> seen;
  s.at(
      5_us, [&] { seen.push_back(s.ordinary_event_running()); }, Scheduler::Tie::Last);
  s.at(5_us, [&] { seen.push_back(s.ordinary_event_running()); });
  EXPECT_FALSE(s.ordinary_event_running());
  s.run_until(5_us);
  EXPECT_EQ(seen, (std::vector<bool>{true, false}));
  EXPECT_FALSE(s.ordinary_event_running());
}

// A reservation holds the place an event scheduled at it would have had: an event scheduled
// later at that place, at a time only known then, runs after the events at its time scheduled
// before the reservation and before those scheduled after it, and a place can be taken again
// (a look ahead that found nothing yet moves on in the same place).
TEST(Scheduler, ReservedPlaceOrdersAsAtTheReservation) {
  Scheduler s;
  std::string order;
  s.at(5_us, [&] { order.push_back('a'); });
  const Reservation place = s.reserve();
  s.at(5_us, [&] { order.push_back('c'); });
  s.at(1_us, [&] {
    s.at(5_us, [&] { order.push_back('d'); }); // scheduled after the reservation, before its use
    // Taken at 2 us, then again at 5 us from there: still between a and c.
    s.at(
        2_us,
        [&] {
          s.at(
              5_us, [&] { order.push_back('b'); }, place);
        },
        place);
  });
  s.at(
      5_us, [&] { order.push_back('e'); }, Scheduler::Tie::Last);
  s.run_until_idle();
  EXPECT_EQ(order, "abcde");
}

TEST(Scheduler, ReservedPlaceAlreadyPassedIsRefused) {
  Scheduler s;
  const Reservation early = s.reserve();
  bool refused = false;
  bool now_at_own_place = false;
  s.at(5_us, [&] {
    // The place before this event's, at its instant, has passed; a later instant has not.
    try {
      s.at(
          5_us, [] {}, early);
    } catch (const std::logic_error&) {
      refused = true;
    }
    s.at(
        6_us, [] {}, early);
  });
  const Reservation own = s.reserve();
  s.at(
      7_us,
      [&] {
        s.at(
            7_us, [&] { now_at_own_place = true; }, own);
      },
      own);
  s.run_until_idle();
  EXPECT_TRUE(refused);
  EXPECT_TRUE(now_at_own_place); // an event may hand its own place on at its instant
  // After run_until() moved the clock past the last event, a reservation is good at now().
  Scheduler t;
  const Reservation first = t.reserve();
  t.at(1_us, [] {});
  t.run_until(3_us);
  bool ran = false;
  t.at(
      3_us, [&] { ran = true; }, first);
  t.run_until_idle();
  EXPECT_TRUE(ran);
}

// A run stopped by a rig fault leaves events pending; one may own the last reference to a
// model whose destructor cancels its own event (a resolver emulator kept by a stator sampler's
// next sample). Destroying the scheduler then runs that destructor, which must find the
// scheduler whole: the cancel succeeds (under ASan, no use after free).
TEST(Scheduler, DestroyedWithAPendingActionWhoseOwnedModelCancelsItsEvent) {
  struct Model {
    Scheduler* s = nullptr;
    EventId own;
    bool* cancelled = nullptr;
    ~Model() { *cancelled = s->cancel(own); }
  };
  bool cancelled = false;
  {
    Scheduler s;
    auto model = std::make_shared<Model>();
    model->s = &s;
    model->cancelled = &cancelled;
    model->own = s.at(Nanos{20}, [] {});
    s.at(Nanos{10}, [model] {}); // the only owner once `model` goes
    model.reset();
    // Freed slots: the cancel at destruction appends to that list (under ASan, to freed memory
    // if the list went first).
    std::vector<EventId> gone;
    for (int i = 0; i < 3; ++i) gone.push_back(s.at(Nanos{30 + i}, [] {}));
    for (const EventId id : gone) EXPECT_TRUE(s.cancel(id));
  }
  EXPECT_TRUE(cancelled);
}
