#pragma once
// SIGINT and SIGTERM stop hilrig instead of killing it mid-write: while a StopSignals lives, a
// handler turns either signal into a stop request (the executive checks it before each event;
// `serve` and `latency` poll its flag()). When it is destroyed the signals' earlier actions
// are back. Every command that stops on a signal installs it this way, and only this way.
//
// The handler only sets the request's atomic (lock-free, async-signal-safe): no thread of its
// own, so a short campaign stays a single-threaded process (a second thread, however idle, costs
// its start-up and a TLB shoot-down at each unmap and copy-on-write fault of the run).

#include <csignal>

#include "rig/campaign/stop_request.hpp"

namespace hilrig::cli {

class StopSignals {
public:
  explicit StopSignals(campaign::StopRequest& stop);
  ~StopSignals();
  StopSignals(const StopSignals&) = delete;
  StopSignals& operator=(const StopSignals&) = delete;

private:
  campaign::StopRequest* outer_; // the request of an enclosing StopSignals, if any
  struct sigaction old_int_ {};
  struct sigaction old_term_ {};
};

} // namespace hilrig::cli
