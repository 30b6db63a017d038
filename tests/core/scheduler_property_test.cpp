#include "core/scheduler.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cstdint>
#include <functional>
#include <random>
#include <stdexcept>
#include <utility>
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

namespace {

// A chain of events each scheduling the next (the rig's encoder edges), either as the
// scheduler's stream or as ordinary events.
class Chain final : public EventStream {
public:
  Chain(Scheduler& s, bool as_stream, std::function<void()> body)
      : s_(s), stream_(as_stream), body_(std::move(body)) {}
  void next_at(Nanos t) {
    if (stream_)
      s_.stream_at(*this, t);
    else
      s_.at(t, [this] { fire(); });
  }
  void fire() override { body_(); }

private:
  Scheduler& s_;
  bool stream_;
  std::function<void()> body_;
};

// Random ordinary and Last events at few instants, each of which may schedule another (up to
// `cap` events in all): the mix the chains and trains below run in. The log: each event's tag,
// instant and ordinary_event_running(), then the executed count.
class RandomEvents {
public:
  RandomEvents(Scheduler& s, std::uint32_t seed, int cap) : s_(s), rng_(seed), cap_(cap) {}
  std::int64_t next() { return static_cast<std::int64_t>(rng_() % 1000); }
  void record(std::int64_t tag) {
    log_.insert(log_.end(), {tag, s_.now().count(), s_.ordinary_event_running() ? 1 : 0});
  }
  // An event within `span` ns of now, Last one time in four; one time in three it schedules
  // another 0-6 ns after itself.
  void add_within(std::int64_t span) {
    const std::int64_t t = s_.now().count() + next() % span;
    const bool last = next() % 4 == 0;
    const int tag = tags_++;
    s_.at(
        Nanos{t},
        [this, tag] {
          record(tag);
          if (next() % 3 == 0 && tags_ < cap_) add_within(7);
        },
        last ? Scheduler::Tie::Last : Scheduler::Tie::InOrder);
  }
  [[nodiscard]] bool room() const { return tags_ < cap_; }
  std::vector<std::int64_t> run() {
    s_.run_until_idle();
    log_.push_back(static_cast<std::int64_t>(s_.executed()));
    return log_;
  }

private:
  Scheduler& s_;
  std::mt19937 rng_;
  int cap_;
  int tags_ = 0;
  std::vector<std::int64_t> log_;
};

// What ran, when, and whether Last events at that time had run, for one seed and engine.
std::vector<std::int64_t> run_chain_program(std::uint32_t seed, bool as_stream) {
  Scheduler s;
  RandomEvents events(s, seed, 4000);
  int links = 0;
  Chain* chain = nullptr;
  Chain c(s, as_stream, [&] {
    events.record(-1);
    if (events.next() % 2 == 0 && events.room()) events.add_within(5);
    if (++links < 3000) chain->next_at(s.now() + Nanos{events.next() % 4}); // 0: two links at one instant
  });
  chain = &c;
  for (int i = 0; i < 300; ++i) events.add_within(100);
  chain->next_at(Nanos{events.next() % 10});
  for (int i = 0; i < 300; ++i) events.add_within(100);
  return events.run();
}

} // namespace

// The stream's events run exactly where the same chain of ordinary events runs: same instants,
// same order among ties (ordinary events before and after it by scheduling order, Last events
// after), under many ties and events that schedule more events (fixed seeds).
TEST(SchedulerProperty, StreamRunsWhereTheSameOrdinaryEventsRun) {
  for (std::uint32_t seed = 1; seed <= 30; ++seed) {
    const std::vector<std::int64_t> heap = run_chain_program(seed, false);
    const std::vector<std::int64_t> stream = run_chain_program(seed, true);
    ASSERT_GT(heap.size(), 3000u * 3);
    ASSERT_EQ(stream, heap) << "seed " << seed;
  }
}

TEST(SchedulerProperty, StreamEventInThePastOrASecondPendingOneThrows) {
  Scheduler s;
  Chain c(s, true, [] {});
  s.run_until(Nanos{10});
  EXPECT_THROW(c.next_at(Nanos{9}), std::logic_error);
  c.next_at(Nanos{12});
  EXPECT_THROW(c.next_at(Nanos{13}), std::logic_error);
  EXPECT_EQ(s.pending_count(), 1u);
  EXPECT_EQ(s.next_time(), Nanos{12});
  s.run_until_idle();
  EXPECT_EQ(s.pending_count(), 0u);
  EXPECT_EQ(s.now(), Nanos{12});
}

namespace {

// Random ordinary and Last events at few instants, with trains of events every `period`
// (0-3 ns: links share instants with each other and with the rest) interleaved in their
// scheduling, each train scheduled whole up front or one link at a time from the link before
// in places reserved up front (reserve_places). The log: each event's tag, instant and
// ordinary_event_running(), then the executed count.
std::vector<std::int64_t> run_train_program(std::uint32_t seed, bool one_at_a_time) {
  Scheduler s;
  RandomEvents events(s, seed, 3000);
  struct Train {
    std::int64_t start, period, links, tag;
    Reservation first;
    std::int64_t next = 0;
  };
  std::vector<Train> trains;
  trains.reserve(20);
  std::function<void(Train&)> link = [&](Train& tr) {
    const std::int64_t k = tr.next;
    s.at(
        Nanos{tr.start + tr.period * k},
        [&, &tr = tr] {
          events.record(tr.tag - tr.next);
          if (++tr.next < tr.links) link(tr);
        },
        Reservation{tr.first.seq + static_cast<std::uint64_t>(k)});
  };
  for (int i = 0; i < 20; ++i) {
    events.add_within(100);
    const std::int64_t start = events.next() % 50;
    const std::int64_t period = events.next() % 4;
    const std::int64_t links = 1 + events.next() % 200;
    const std::int64_t tag = -1000 * (i + 1);
    if (one_at_a_time) {
      trains.push_back(Train{start, period, links, tag, s.reserve_places(static_cast<std::uint64_t>(links))});
      link(trains.back());
    } else {
      for (std::int64_t k = 0; k < links; ++k)
        s.at(Nanos{start + period * k}, [&events, tag, k] { events.record(tag - k); });
    }
    events.add_within(100);
  }
  return events.run();
}

} // namespace

// A train scheduled a link at a time in places reserved up front (the rig's bounce stimuli)
// runs exactly where the same train scheduled whole runs (fixed seeds).
TEST(SchedulerProperty, TrainInReservedPlacesRunsWhereTheWholeTrainRuns) {
  for (std::uint32_t seed = 1; seed <= 30; ++seed) {
    const std::vector<std::int64_t> whole = run_train_program(seed, false);
    const std::vector<std::int64_t> linked = run_train_program(seed, true);
    ASSERT_GT(whole.size(), 20u * 3);
    ASSERT_EQ(linked, whole) << "seed " << seed;
  }
}
