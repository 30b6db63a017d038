#include "rig/cli/serve_far_side.hpp"

#include <stdexcept>

#include <fmt/format.h>

#include "rig/far/far_config.hpp"
#include "rig/far/far_side.hpp"
#include "rig/far/socketcan_port.hpp"

namespace hilrig::cli {

ServedFarSide::ServedFarSide(Scheduler& scheduler, const FarSideOptions& options, const ServedModel& model,
                             const std::string& device) {
  if (!model.attach_far) throw std::invalid_argument(device + " has no pins a far side can carry");
  const far::FarConfig config = far::load_far_config(options.config);
  if (!config.pins.empty() && options.gpio_sim.empty())
    throw std::invalid_argument(options.config +
                                " puts pins on gpio-sim: give the chip's directory (--gpio-sim)");
  if (config.resolver && options.can.empty())
    throw std::invalid_argument(options.config + " has a [resolver] node: give its CAN interface (--can)");
  if (!options.can.empty()) {
    if (!config.resolver) throw std::invalid_argument("--can needs a [resolver] table in " + options.config);
    can_ = std::make_unique<far::SocketCanPort>(scheduler, options.can);
  }
  far_ = std::make_unique<far::FarSide>(scheduler, config, options.gpio_sim, can_.get());
  model.attach_far(*far_);
  far_->check_all_taken(device);
}

ServedFarSide::~ServedFarSide() = default;

void ServedFarSide::tick(Nanos t) {
  if (can_) (void)can_->poll(t);
  far_->poll(t);
}

std::string ServedFarSide::describe() const {
  std::string s = far_->describe();
  if (can_) s += " on " + can_->interface();
  return s;
}

std::string ServedFarSide::summary() const {
  const far::FarSideCounters c = far_->counters();
  std::string s =
      fmt::format("{} polls, {} input edge(s) read, {} output edge(s) pulled; model at most {:.3f} ms "
                  "behind real time",
                  c.polls, c.input_edges, c.output_edges, static_cast<double>(max_lag_.count()) / 1e6);
  if (const auto* node = far_->resolver()) {
    const auto& n = node->counters();
    s += fmt::format("; resolver node: {} frame(s), {} lost, {} timeout(s)", n.frames, n.lost_frames,
                     n.timeouts);
  }
  if (can_)
    s += fmt::format("; {}: {} error frame(s), {}", can_->interface(), can_->error_frames(),
                     socketcan::to_string(can_->state()));
  return s;
}

} // namespace hilrig::cli
