#pragma once
// Runs `hilrig serve`'s engine (serve_device) for any device and link in a background thread;
// the destructor always stops and joins it, whatever the test did.

#include <atomic>
#include <cstdint>
#include <exception>
#include <future>
#include <string>
#include <thread>
#include <utility>

#include "rig/cli/serve_command.hpp"

namespace hilrig::test {

class ServeThread {
public:
  explicit ServeThread(cli::ServeOptions options) {
    std::promise<cli::ServeEndpoint> ready;
    std::future<cli::ServeEndpoint> endpoint = ready.get_future();
    thread_ = std::thread([this, options, p = std::move(ready)]() mutable {
      try {
        cli::serve_device(options, stop_, [&p](const cli::ServeEndpoint& e) { p.set_value(e); });
      } catch (...) {
        try {
          p.set_exception(std::current_exception());
        } catch (...) { // already serving: the promise is satisfied
        }
      }
    });
    try {
      endpoint_ = endpoint.get();
    } catch (...) {
      stop();
      throw;
    }
  }
  ServeThread(const ServeThread&) = delete;
  ServeThread& operator=(const ServeThread&) = delete;
  ~ServeThread() { stop(); }

  [[nodiscard]] const cli::ServeEndpoint& endpoint() const { return endpoint_; }
  [[nodiscard]] std::uint16_t port() const { return endpoint_.port; }
  void stop() {
    stop_.store(true);
    if (thread_.joinable()) {
      thread_.join();
    }
  }

private:
  std::atomic<bool> stop_{false};
  std::thread thread_;
  cli::ServeEndpoint endpoint_;
};

// ANS1 served on a new pty pair (Modbus RTU, 19200 8E1, unit 1) or on a free loopback port.
inline cli::ServeOptions ans1_on_pty(std::uint8_t unit = 1) {
  cli::ServeOptions o;
  o.device = "ans1";
  o.link = cli::ServeLink::Pty;
  o.unit = unit;
  return o;
}
// The SMD23E (the first served device) on a free loopback port, optionally a fault variant.
inline cli::ServeOptions smd23e_on_tcp(std::string fault = "none") {
  cli::ServeOptions o;
  o.device = "smd23e";
  o.link = cli::ServeLink::Tcp;
  o.port = 0;
  o.fault = std::move(fault);
  return o;
}
inline cli::ServeOptions ans1_on_tcp() {
  cli::ServeOptions o;
  o.device = "ans1";
  o.link = cli::ServeLink::Tcp;
  o.port = 0;
  return o;
}

} // namespace hilrig::test
