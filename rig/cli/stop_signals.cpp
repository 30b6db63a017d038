#include "rig/cli/stop_signals.hpp"

#include <csignal>

namespace hilrig::cli {

StopSignals::StopSignals(campaign::StopRequest& stop) : stop_(stop), signals_(io_, SIGINT, SIGTERM) {
  wait();
  thread_ = std::thread([this] { io_.run(); });
}

StopSignals::~StopSignals() {
  io_.stop();
  if (thread_.joinable()) thread_.join();
}

void StopSignals::wait() {
  signals_.async_wait([this](const boost::system::error_code& ec, int signal) {
    if (ec) return;
    stop_.request(signal); // the first signal names the stop; later ones are absorbed
    wait();
  });
}

} // namespace hilrig::cli
