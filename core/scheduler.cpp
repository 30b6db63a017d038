#include "core/scheduler.hpp"

#include <algorithm>
#include <stdexcept>
#include <utility>

namespace hilrig {

// The top bit of the sequence number orders Last events after every InOrder one at a time.
constexpr std::uint64_t kLast = std::uint64_t{1} << 63;

Scheduler::~Scheduler() {
  // A run stopped early (a rig fault thrown out of an event) leaves events pending, and one may
  // hold the last reference to a model (a resolver emulator kept by a stator sampler's next
  // sample): its destructor cancels its events on this scheduler. Each action leaves its slot
  // before it is destroyed, so a cancel from it finds every member alive. By index: a
  // destructor may only cancel, which does not grow slots_.
  for (std::size_t i = 0; i < slots_.size(); ++i) {
    Action pending_action;
    std::swap(pending_action, slots_[i].action);
  }
}

EventId Scheduler::at(Nanos t, Action action, Tie tie) {
  if (t < now()) {
    throw std::logic_error("Scheduler: event scheduled in the past");
  }
  return insert(t, std::move(action), next_seq_++ | (tie == Tie::Last ? kLast : 0));
}

EventId Scheduler::at(Nanos t, Action action, Reservation place) {
  if (t < now() || (t.count() == running_time_ && place.seq < running_seq_))
    throw std::logic_error("Scheduler: event scheduled in the past (at a place already passed)");
  return insert(t, std::move(action), place.seq);
}

EventId Scheduler::insert(Nanos t, Action action, std::uint64_t seq) {
  std::uint32_t slot = 0;
  if (!free_.empty()) {
    slot = free_.back();
    free_.pop_back();
  } else {
    slot = static_cast<std::uint32_t>(slots_.size());
    slots_.emplace_back();
  }
  Slot& s = slots_[slot];
  s.action = std::move(action);
  s.live = true;
  heap_push(Entry{t.count(), seq, slot, s.generation});
  ++live_;
  return EventId{slot, s.generation};
}

void Scheduler::stream_at(EventStream& stream, Nanos t) {
  if (t < now()) throw std::logic_error("Scheduler: stream event scheduled in the past");
  if (stream_pending_ || (stream_ != nullptr && stream_ != &stream))
    throw std::logic_error("Scheduler: one stream, one pending event of it");
  stream_ = &stream;
  stream_next_ = Entry{t.count(), next_seq_++, 0, 0};
  stream_pending_ = true;
  ++live_;
}

bool Scheduler::stream_first() const {
  if (!stream_pending_) return false;
  if (heap_.empty()) return true;
  const Entry& top = heap_.front();
  return stream_next_.time != top.time ? stream_next_.time < top.time : stream_next_.seq < top.seq;
}

void Scheduler::heap_push(const Entry& e) {
  heap_.push_back(e);
  std::size_t i = heap_.size() - 1;
  while (i > 0) {
    const std::size_t parent = (i - 1) / 4;
    if (!later(heap_[parent], e)) break;
    heap_[i] = heap_[parent];
    i = parent;
  }
  heap_[i] = e;
}

// True when a runs before b. Bitwise, not short-circuit, so the compiler emits no branch:
// on random times the branch predictor would miss about half of these.
static inline bool earlier(std::int64_t at, std::uint64_t aseq, std::int64_t bt, std::uint64_t bseq) {
  return static_cast<bool>(static_cast<unsigned>(at < bt) |
                           (static_cast<unsigned>(at == bt) & static_cast<unsigned>(aseq < bseq)));
}

void Scheduler::heap_pop() {
  const Entry last = heap_.back();
  heap_.pop_back();
  const std::size_t n = heap_.size();
  if (n == 0) return;
  Entry* const h = heap_.data();
  std::size_t i = 0;
  for (;;) {
    const std::size_t first = 4 * i + 1;
    if (first >= n) break;
    std::size_t best = first;
    if (first + 4 <= n) {
      // All four children: a branch-free tournament.
      const std::size_t b01 =
          earlier(h[first + 1].time, h[first + 1].seq, h[first].time, h[first].seq) ? first + 1 : first;
      const std::size_t b23 =
          earlier(h[first + 3].time, h[first + 3].seq, h[first + 2].time, h[first + 2].seq) ? first + 3
                                                                                            : first + 2;
      best = earlier(h[b23].time, h[b23].seq, h[b01].time, h[b01].seq) ? b23 : b01;
    } else {
      for (std::size_t c = first + 1; c < n; ++c) {
        best = earlier(h[c].time, h[c].seq, h[best].time, h[best].seq) ? c : best;
      }
    }
    if (!earlier(h[best].time, h[best].seq, last.time, last.seq)) break;
    h[i] = h[best];
    i = best;
  }
  h[i] = last;
}

bool Scheduler::pending(EventId id) const {
  return id.valid() && id.slot < slots_.size() && slots_[id.slot].live &&
         slots_[id.slot].generation == id.generation;
}

bool Scheduler::cancel(EventId id) {
  if (!pending(id)) {
    return false;
  }
  release(id.slot); // its heap entry is now stale and is skipped when it surfaces
  return true;
}

void Scheduler::release(std::uint32_t slot) {
  Slot& s = slots_[slot];
  s.action = nullptr;
  s.live = false;
  ++s.generation;
  free_.push_back(slot);
  --live_;
}

void Scheduler::drop_dead_top() {
  while (!heap_.empty()) {
    const Entry& top = heap_.front();
    const Slot& s = slots_[top.slot];
    if (s.live && s.generation == top.generation) {
      return;
    }
    heap_pop();
  }
}

Nanos Scheduler::next_time() {
  drop_dead_top();
  if (stream_first()) return Nanos{stream_next_.time};
  return heap_.empty() ? Nanos::max() : Nanos{heap_.front().time};
}

bool Scheduler::step() {
  drop_dead_top();
  if (stream_first()) {
    stream_pending_ = false;
    --live_;
    clock_.advance_to(Nanos{stream_next_.time});
    ++executed_;
    running_time_ = stream_next_.time;
    running_seq_ = stream_next_.seq;
    ordinary_running_ = true;
    stream_->fire();
    ordinary_running_ = false;
    return true;
  }
  if (heap_.empty()) {
    return false;
  }
  const Entry e = heap_.front();
  heap_pop();
  // Move the action out first: it may schedule events that grow slots_.
  Action action = std::move(slots_[e.slot].action);
  release(e.slot);
  clock_.advance_to(Nanos{e.time});
  ++executed_;
  running_time_ = e.time;
  running_seq_ = e.seq;
  ordinary_running_ = (e.seq & kLast) == 0;
  action();
  ordinary_running_ = false;
  return true;
}

Scheduler::StopReason Scheduler::run_until(Nanos t) {
  stop_requested_ = false;
  while (next_time() <= t) {
    step();
    if (stop_requested_) {
      return StopReason::Stopped;
    }
  }
  if (t > now()) {
    clock_.advance_to(t);
  }
  return StopReason::ReachedTime;
}

Scheduler::StopReason Scheduler::run_until_idle(Nanos limit) {
  stop_requested_ = false;
  for (;;) {
    const Nanos next = next_time();
    if (next == Nanos::max()) {
      return StopReason::Idle;
    }
    if (next >= limit) {
      return StopReason::ReachedTime;
    }
    step();
    if (stop_requested_) {
      return StopReason::Stopped;
    }
  }
}

} // namespace hilrig
