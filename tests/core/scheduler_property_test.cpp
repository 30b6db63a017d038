#include "core/scheduler.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <random>
#include <vector>

using namespace hilrig;

// Property (fixed seeds): with random times, many ties, random cancels and events that
// schedule more events, the run order is exactly the order of (time, scheduling order) among
// the events never cancelled -- what a stable sort of the schedule gives.
TEST(SchedulerProperty, RunOrderIsTimeThenSchedulingOrder) {
  for (std::uint32_t seed = 1; seed <= 25; ++seed) {
    std::mt19937 rng(seed);
    auto next = [&rng] { return static_cast<std::uint32_t>(rng()); };
    Scheduler s;
    struct Scheduled {
      std::int64_t time;
      int tag;
      bool cancelled;
    };
    std::vector<Scheduled> schedule; // in scheduling order
    std::vector<EventId> ids;
    std::vector<int> ran;
    std::function<void(std::int64_t)> add = [&](std::int64_t t) {
      const int tag = static_cast<int>(schedule.size());
      schedule.push_back({t, tag, false});
      ids.push_back(s.at(Nanos{t}, [&, tag] {
        ran.push_back(tag);
        if (next() % 4 == 0 && schedule.size() < 3000) add(s.now().count() + next() % 50);
      }));
    };
    for (int i = 0; i < 1000; ++i) add(next() % 200); // few distinct times: many ties
    for (int i = 0; i < 200; ++i) {
      const std::size_t k = next() % ids.size();
      if (s.cancel(ids[k])) schedule[k].cancelled = true;
    }
    s.run_until_idle();
    std::vector<Scheduled> expected;
    for (const auto& e : schedule) {
      if (!e.cancelled) expected.push_back(e);
    }
    std::stable_sort(expected.begin(), expected.end(),
                     [](const Scheduled& a, const Scheduled& b) { return a.time < b.time; });
    std::vector<int> expected_tags;
    expected_tags.reserve(expected.size());
    for (const auto& e : expected) expected_tags.push_back(e.tag);
    ASSERT_EQ(ran, expected_tags) << "seed " << seed;
    EXPECT_EQ(s.executed(), ran.size());
    EXPECT_EQ(s.pending_count(), 0U);
  }
}
