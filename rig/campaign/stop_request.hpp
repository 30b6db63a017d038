#pragma once
// A request to stop a campaign early (SIGINT/SIGTERM): set from the signal-handling thread,
// read by the simulation between events. The first request wins; its signal names the stop.

#include <atomic>
#include <csignal>
#include <string>

namespace hilrig::campaign {

class StopRequest {
public:
  void request(int signal) {
    int none = 0;
    signal_.compare_exchange_strong(none, signal);
  }
  [[nodiscard]] bool requested() const { return signal_.load(std::memory_order_relaxed) != 0; }
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
};

} // namespace hilrig::campaign
