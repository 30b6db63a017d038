#pragma once
// SIGINT and SIGTERM stop a campaign instead of killing it mid-write: while a StopSignals
// lives, a Boost.Asio signal_set on a thread of its own (off the simulation's path) turns
// either signal into a stop request, which the executive checks before each event. When it
// is destroyed the signals' default actions are back.

#include <thread>

#include <boost/asio/io_context.hpp>
#include <boost/asio/signal_set.hpp>

#include "rig/campaign/stop_request.hpp"

namespace hilrig::cli {

class StopSignals {
public:
  explicit StopSignals(campaign::StopRequest& stop);
  ~StopSignals();
  StopSignals(const StopSignals&) = delete;
  StopSignals& operator=(const StopSignals&) = delete;

private:
  void wait();

  campaign::StopRequest& stop_;
  boost::asio::io_context io_;
  boost::asio::signal_set signals_;
  std::thread thread_;
};

} // namespace hilrig::cli
