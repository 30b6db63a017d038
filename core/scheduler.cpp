#include "core/scheduler.hpp"

#include <algorithm>
#include <stdexcept>
#include <utility>

namespace hilrig {

EventId Scheduler::at(Nanos t, Action action) {
  if (t < now()) {
    throw std::logic_error("Scheduler: event scheduled in the past");
  }
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
  heap_.push_back(Entry{t.count(), next_seq_++, slot, s.generation});
  std::push_heap(heap_.begin(), heap_.end(), later);
  ++live_;
  return EventId{slot, s.generation};
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
    std::pop_heap(heap_.begin(), heap_.end(), later);
    heap_.pop_back();
  }
}

Nanos Scheduler::next_time() {
  drop_dead_top();
  return heap_.empty() ? Nanos::max() : Nanos{heap_.front().time};
}

bool Scheduler::step() {
  drop_dead_top();
  if (heap_.empty()) {
    return false;
  }
  std::pop_heap(heap_.begin(), heap_.end(), later);
  const Entry e = heap_.back();
  heap_.pop_back();
  // Move the action out first: it may schedule events that grow slots_.
  Action action = std::move(slots_[e.slot].action);
  release(e.slot);
  clock_.advance_to(Nanos{e.time});
  ++executed_;
  action();
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
