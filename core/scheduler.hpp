#pragma once
// Discrete-event scheduler that owns virtual time. Events at equal times run in the
// order they were scheduled (a sequence number breaks ties), so a run is deterministic;
// an event scheduled with Tie::Last runs after every ordinary event at its time.

#include <cstdint>
#include <functional>
#include <vector>

#include "core/clock.hpp"

namespace hilrig {

struct EventId {
  std::uint32_t slot = UINT32_MAX;
  std::uint32_t generation = 0;
  [[nodiscard]] bool valid() const { return slot != UINT32_MAX; }
};

// A place among events at equal times, taken before the event's time is known
// (Scheduler::reserve): an event scheduled later at that place runs where one scheduled at
// the reservation would have.
struct Reservation {
  std::uint64_t seq = 0;
};

// A run of ordinary events, each scheduled by the one before (the rig's encoder edges): the
// scheduler keeps its next event outside the heap (Scheduler::stream_at).
class EventStream {
public:
  virtual void fire() = 0;

protected:
  ~EventStream() = default;
};

class Scheduler {
public:
  using Action = std::function<void()>;

  enum class StopReason { ReachedTime, Idle, Stopped };
  // Where an event stands among others at the same time. A scanning model's scan is Last: it
  // sees every change at its instant, whenever that change was scheduled, so a scan scheduled
  // one period ahead and one scheduled later (after skipped scans) order alike.
  enum class Tie : std::uint8_t { InOrder, Last };

  explicit Scheduler(Nanos start = Nanos{0}) : clock_(start) {}
  // Destroys the pending actions first, while the scheduler is whole: an action may own the
  // last reference to a model whose destructor cancels its own events here.
  ~Scheduler();
  Scheduler(const Scheduler&) = delete;
  Scheduler& operator=(const Scheduler&) = delete;

  [[nodiscard]] Nanos now() const { return clock_.now(); }
  [[nodiscard]] const Clock& clock() const { return clock_; }

  // Schedules at an absolute time; a time before now() is a logic error and throws.
  EventId at(Nanos t, Action action, Tie tie = Tie::InOrder);
  EventId after(Nanos delay, Action action) { return at(now() + delay, std::move(action)); }

  // The place an ordinary event scheduled now would take among those at its time. An
  // at(t, action, place) later runs exactly where at(t, action) at the reservation would
  // have: after the events at t scheduled before the reservation, before those scheduled
  // after it. One pending event per reservation; a place already passed (t == now() and an
  // event after the place running) is a logic error and throws, as a past time does.
  [[nodiscard]] Reservation reserve() { return Reservation{next_seq_++}; }
  // n places in a row, as n reserve() calls would take them: place k is {first.seq + k}. A
  // train of events each scheduled by the one before takes its places up front, so one of
  // them is pending at a time and each runs where scheduling them all at once ran it.
  [[nodiscard]] Reservation reserve_places(std::uint64_t n) {
    const Reservation first{next_seq_};
    next_seq_ += n;
    return first;
  }
  EventId at(Nanos t, Action action, Reservation place);

  // The stream's next event at t: as at(t, [&] { stream.fire(); }) -- the same time and
  // sequence number, so it orders among the others exactly as that event would -- without a
  // heap entry, a slot or an Action. One stream per scheduler, at most one event of it pending;
  // a time before now() is a logic error and throws.
  void stream_at(EventStream& stream, Nanos t);

  // True when the event was still pending (and now never runs).
  bool cancel(EventId id);
  [[nodiscard]] bool pending(EventId id) const;
  [[nodiscard]] std::size_t pending_count() const { return live_; }
  [[nodiscard]] std::uint64_t executed() const { return executed_; }
  // Time of the next pending event, or Nanos::max() when idle.
  [[nodiscard]] Nanos next_time();

  // Runs every event with time <= t, then sets the clock to t.
  StopReason run_until(Nanos t);
  // Runs until no event is pending (or one at/after `limit` is next).
  StopReason run_until_idle(Nanos limit = Nanos::max());
  // Runs the next event, if any. False when idle.
  bool step();
  // From inside an event: the current run_* returns StopReason::Stopped after it.
  void stop() { stop_requested_ = true; }
  // True while an ordinary (Tie::InOrder) event runs: the Last events at now() have not run
  // yet. A model that skips its Last-tied scans tells from it whether the scan at now() would
  // already have run (docs/virtual-time.md).
  [[nodiscard]] bool ordinary_event_running() const { return ordinary_running_; }

private:
  struct Entry {
    std::int64_t time;
    std::uint64_t seq;
    std::uint32_t slot;
    std::uint32_t generation;
  };
  struct Slot {
    Action action;
    std::uint32_t generation = 0;
    bool live = false;
  };
  static bool later(const Entry& a, const Entry& b) {
    return a.time != b.time ? a.time > b.time : a.seq > b.seq;
  }
  EventId insert(Nanos t, Action action, std::uint64_t seq);
  void drop_dead_top();
  void release(std::uint32_t slot);
  // A 4-ary min-heap on (time, seq): half the depth of a binary heap, and the four children
  // of a node share a cache line or two, which is what bounds the hold benchmark.
  void heap_push(const Entry& e);
  void heap_pop();

  // True when the stream's pending event runs before the heap's top (drop_dead_top() first).
  [[nodiscard]] bool stream_first() const;

  VirtualClock clock_;
  EventStream* stream_ = nullptr;
  Entry stream_next_{}; // valid while stream_pending_; slot and generation unused
  bool stream_pending_ = false;
  std::vector<Entry> heap_;
  std::vector<Slot> slots_;
  std::vector<std::uint32_t> free_;
  std::uint64_t next_seq_ = 0;
  // The running (or last run) event's place: what a Reservation may no longer take.
  std::int64_t running_time_ = INT64_MIN;
  std::uint64_t running_seq_ = 0;
  std::uint64_t executed_ = 0;
  std::size_t live_ = 0;
  bool stop_requested_ = false;
  bool ordinary_running_ = false;
};

} // namespace hilrig
