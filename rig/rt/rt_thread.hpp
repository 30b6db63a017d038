#pragma once
// What makes a thread real-time on a PREEMPT_RT box: SCHED_FIFO at a priority, pinned to
// one CPU, all memory locked and the stack prefaulted so no page fault lands in the loop.
// Each step reports what failed by name; the caller decides whether that is fatal.

#include <optional>
#include <string>

namespace hilrig::rig {

struct RtSettings {
  int priority = 80;       // SCHED_FIFO 1..99; 0 = leave the thread SCHED_OTHER
  std::optional<int> cpu;  // pin to this CPU (an isolated one on a rig)
  bool lock_memory = true; // mlockall(MCL_CURRENT | MCL_FUTURE)
  std::size_t prefault_stack = 256 * 1024;
  // PR_SET_TIMERSLACK: how late the kernel may fire the thread's sleeps to batch timers
  // (default 50 us). 1 ns is the least (0 means "back to the default"); the kernel already
  // ignores the slack of a SCHED_FIFO thread, so this matters when FIFO is refused.
  unsigned long timer_slack_ns = 1;
};

struct RtSetupReport {
  bool scheduled = false; // SCHED_FIFO applied
  bool pinned = false;
  bool locked = false;
  long timer_slack_ns = -1; // as read back (PR_GET_TIMERSLACK); -1 if unreadable
  std::string problems;     // empty when everything asked for was applied
};

// Applies the settings to the calling thread. Never throws.
RtSetupReport make_current_thread_realtime(const RtSettings& settings);

} // namespace hilrig::rig
