#pragma once
// `hilrig serve DEVICE ... --far FAR.toml [--gpio-sim DIR] [--can IFACE]`: the served model's
// pins on real kernel interfaces (rig/far): board inputs read from gpio-sim's simulator side,
// board outputs pulled on it, the resolver stators from a resolver-emulator node on a CAN
// interface. tick(t) runs before each step of the model's clock to t.

#include <algorithm>
#include <memory>
#include <string>

#include "core/scheduler.hpp"
#include "rig/cli/serve_devices.hpp"

namespace hilrig::far {
class SocketCanPort;
} // namespace hilrig::far

namespace hilrig::cli {

struct FarSideOptions {
  std::string config;   // FAR.toml; empty: no far side
  std::string gpio_sim; // the gpio-sim chip's sysfs directory
  std::string can;      // the CAN interface of the resolver node
};

class ServedFarSide {
public:
  // Loads the config, opens the interfaces and attaches the model's pins. Throws
  // campaign::CampaignError (config), std::invalid_argument (a model without pins, a missing
  // interface option), gpiosim::GpioSimError or socketcan::CanError (cannot open).
  ServedFarSide(Scheduler& scheduler, const FarSideOptions& options, const ServedModel& model,
                const std::string& device);
  ServedFarSide(const ServedFarSide&) = delete;
  ServedFarSide& operator=(const ServedFarSide&) = delete;
  ~ServedFarSide();

  // Delivers the CAN frames and input edges that arrived, stamped t.
  void tick(Nanos t);
  // After the model ran to t: how long that took (it is that far behind real time).
  void note_lag(Nanos lag) { max_lag_ = std::max(max_lag_, lag); }
  [[nodiscard]] std::string describe() const; // what it carries, one line
  [[nodiscard]] std::string summary() const;  // what it counted, one line

private:
  std::unique_ptr<far::SocketCanPort> can_;
  std::unique_ptr<far::FarSide> far_;
  Nanos max_lag_{0};
};

} // namespace hilrig::cli
