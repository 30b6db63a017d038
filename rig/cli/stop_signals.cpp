#include "rig/cli/stop_signals.hpp"

#include <atomic>

namespace hilrig::cli {

namespace {

std::atomic<campaign::StopRequest*> current{nullptr};
static_assert(std::atomic<campaign::StopRequest*>::is_always_lock_free);
static_assert(std::atomic<int>::is_always_lock_free);

void on_stop_signal(int signal) {
  // The first signal names the stop; later ones are absorbed (StopRequest::request).
  if (campaign::StopRequest* stop = current.load()) stop->request(signal);
}

} // namespace

StopSignals::StopSignals(campaign::StopRequest& stop) : outer_(current.exchange(&stop)) {
  struct sigaction action {};
  action.sa_handler = on_stop_signal;
  sigfillset(&action.sa_mask);
  action.sa_flags = SA_RESTART;
  sigaction(SIGINT, &action, &old_int_);
  sigaction(SIGTERM, &action, &old_term_);
}

StopSignals::~StopSignals() {
  sigaction(SIGINT, &old_int_, nullptr);
  sigaction(SIGTERM, &old_term_, nullptr);
  current.store(outer_);
}

} // namespace hilrig::cli
