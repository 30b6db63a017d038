#pragma once
// A request to stop a campaign early (SIGINT/SIGTERM): set from a signal handler, read by the
// simulation between events. The first request wins; its signal names the stop. flag() is the
// same request as the plain stop flag the servers and RT loops poll.

#include <atomic>
#include <csignal>
#include <string>

namespace hilrig::campaign {

class StopRequest {
public:
  void request(int signal) {
    int none = 0;
    signal_.compare_exchange_strong(none, signal);
    stopped_.store(true);
  }
  [[nodiscard]] bool requested() const { return stopped_.load(std::memory_order_relaxed); }
  [[nodiscard]] const std::atomic<bool>& flag() const { return stopped_; }
  // "SIGTERM", "SIGINT", ... ("" before any request).
  [[nodiscard]] std::string reason() const {
    const int s = signal_.load();
    switch (s) {
    case 0:
      return {};
    case SIGTERM:
      return "SIGTERM";
    case SIGINT:
      return "SIGINT";
    case SIGHUP:
      return "SIGHUP";
    default:
      return "signal " + std::to_string(s);
    }
  }

private:
  std::atomic<int> signal_{0};
  std::atomic<bool> stopped_{false};
};

} // namespace hilrig::campaign
