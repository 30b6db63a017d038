#pragma once
// Runs `hilrig serve`'s engine (run_serve) on a free loopback port in a background thread;
// the destructor always stops and joins it, whatever the test did.

#include <atomic>
#include <cstdint>
#include <exception>
#include <future>
#include <string>
#include <thread>

#include "rig/cli/serve_command.hpp"

namespace hilrig::test {

class ServerThread {
public:
  explicit ServerThread(std::string fault = "none") {
    std::promise<std::uint16_t> bound;
    std::future<std::uint16_t> port = bound.get_future();
    thread_ = std::thread([this, fault, p = std::move(bound)]() mutable {
      cli::ServeOptions o;
      o.bind = "127.0.0.1";
      o.port = 0; // the OS picks a free port
      o.fault = fault;
      try {
        cli::run_serve(o, stop_, [&p](std::uint16_t port_number) { p.set_value(port_number); });
      } catch (...) {
        try {
          p.set_exception(std::current_exception());
        } catch (...) { // already listening: the promise is satisfied
        }
      }
    });
    try {
      port_ = port.get();
    } catch (...) {
      stop();
      throw;
    }
  }
  ServerThread(const ServerThread&) = delete;
  ServerThread& operator=(const ServerThread&) = delete;
  ~ServerThread() { stop(); }

  [[nodiscard]] std::uint16_t port() const { return port_; }
  void stop() {
    stop_.store(true);
    if (thread_.joinable()) {
      thread_.join();
    }
  }

private:
  std::atomic<bool> stop_{false};
  std::thread thread_;
  std::uint16_t port_ = 0;
};

} // namespace hilrig::test
