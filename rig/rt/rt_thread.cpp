#include "rig/rt/rt_thread.hpp"

#include <pthread.h>
#include <sched.h>
#include <sys/mman.h>
#include <sys/prctl.h>

#include <cerrno>
#include <cstring>

namespace hilrig::rig {

namespace {

// Touches a stack region once so its pages are resident before the loop runs.
void prefault_stack(std::size_t bytes) {
  constexpr std::size_t kChunk = 4096;
  volatile unsigned char probe[kChunk];
  probe[0] = 0;
  if (bytes > kChunk) prefault_stack(bytes - kChunk);
  probe[kChunk - 1] = probe[0];
}

void note(std::string& problems, const char* what, int err) {
  if (!problems.empty()) problems += "; ";
  problems += what;
  problems += ": ";
  problems += std::strerror(err);
}

} // namespace

RtSetupReport make_current_thread_realtime(const RtSettings& settings) {
  RtSetupReport report;
  if (settings.lock_memory) {
    if (mlockall(MCL_CURRENT | MCL_FUTURE) == 0) {
      report.locked = true;
    } else {
      note(report.problems, "mlockall", errno);
    }
  }
  if (settings.prefault_stack > 0) prefault_stack(settings.prefault_stack);
  if (settings.timer_slack_ns > 0 && ::prctl(PR_SET_TIMERSLACK, settings.timer_slack_ns, 0, 0, 0) != 0) {
    note(report.problems, "PR_SET_TIMERSLACK", errno);
  }
  report.timer_slack_ns = ::prctl(PR_GET_TIMERSLACK, 0, 0, 0, 0);
  if (settings.cpu) {
    cpu_set_t set;
    CPU_ZERO(&set);
    CPU_SET(static_cast<std::size_t>(*settings.cpu), &set);
    const int err = pthread_setaffinity_np(pthread_self(), sizeof(set), &set);
    if (err == 0) {
      report.pinned = true;
    } else {
      note(report.problems, "pthread_setaffinity_np", err);
    }
  }
  if (settings.priority > 0) {
    sched_param param{};
    param.sched_priority = settings.priority;
    const int err = pthread_setschedparam(pthread_self(), SCHED_FIFO, &param);
    if (err == 0) {
      report.scheduled = true;
    } else {
      note(report.problems, "SCHED_FIFO", err);
    }
  }
  return report;
}

} // namespace hilrig::rig
