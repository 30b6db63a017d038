#include "rig/hardware/drive_plan.hpp"

#include <fmt/format.h>

#include "core/scheduler.hpp"
#include "rig/campaign/motion.hpp"
#include "rig/campaign/rig_drive.hpp"
#include "rig/hardware/host_words.hpp"

namespace hilrig::hardware {

namespace {

std::string rig_lines(const RigConfig& config) {
  std::string names;
  for (const GpioLine& l : config.lines) names += (names.empty() ? "" : ", ") + l.rig;
  return names.empty() ? "none" : names;
}

} // namespace

DrivePlan plan_lines(const std::string& campaign_file, const campaign::Scenario& s, const RigConfig& config) {
  using campaign::CampaignError;
  DrivePlan plan;
  // Initial levels as the drive computes them (encoder from the start count, brake released).
  Scheduler unused;
  const campaign::BuiltMotion motion = campaign::build_motion(campaign_file, s.motion, s.encoder);
  const campaign::RigDrive drive(unused, s, motion);
  for (std::size_t i = 0; i < s.wiring.size(); ++i) {
    const campaign::Wire& w = s.wiring[i];
    if (w.analog) continue; // a resolver stator: the CAN resolver front end drives it
    const GpioLine* g = config.line_for(w.rig);
    if (g == nullptr)
      throw CampaignError(campaign_file, w.where, fmt::format("wiring[{}].rig", i),
                          fmt::format("a rig line of {}: \"{}\" has no [[gpio.line]] there (it has: {})",
                                      config.file, w.rig, rig_lines(config)));
    if (w.direction == duts::PinDirection::Input)
      plan.outputs.push_back(PlannedLine{w.rig, g, drive.initial_level(w.rig)});
    else
      plan.inputs.push_back(PlannedLine{w.rig, g, Level::Low});
  }
  if (!s.resolver.sin_line.empty()) {
    if (config.can_resolver.empty())
      throw CampaignError(
          campaign_file, s.resolver.where, "resolver",
          fmt::format("a rig with a resolver front end: {} has no [can] resolver interface", config.file));
    plan.resolver = true;
  }
  if (!s.host.empty()) {
    const campaign::HostAction& first = s.host.front();
    if (config.host.link == HostLink::None)
      throw CampaignError(campaign_file, first.where, "host",
                          fmt::format("a rig with a host link: {} has no [host] table", config.file));
    if (host_words_of(s.dut.model) == nullptr)
      throw CampaignError(campaign_file, first.where, "host",
                          fmt::format("a device whose host words the rig can address over Modbus "
                                      "(\"{}\" is not one: {})",
                                      s.dut.model, host_device_names()));
    plan.host = true;
  }
  return plan;
}

} // namespace hilrig::hardware
