#include "rig/hardware/hardware_backend.hpp"

#include <exception>
#include <memory>
#include <utility>

#include <fmt/format.h>

#include "rig/hardware/drive_plan.hpp"

namespace hilrig::hardware {

void check_campaign_on_rig(const campaign::Campaign& c, const RigConfig& config) {
  for (const campaign::Scenario& s : c.points) (void)plan_lines(c.file, s, config);
  for (const auto& points : c.fault_points)
    for (const campaign::Scenario& s : points) (void)plan_lines(c.file, s, config);
}

campaign::RunBackend hardware_backend(const RigConfig& config, std::string campaign_file,
                                      RigPortsFactory ports, HardwareRunOptions options) {
  options.rt = config.rt;
  return [&config, file = std::move(campaign_file), ports = std::move(ports),
          options](const campaign::RunInputs& in) -> campaign::VirtualRun {
    if (in.scenario == nullptr) throw campaign::RigFault("no scenario");
    const DrivePlan plan = plan_lines(file, *in.scenario, config);
    std::unique_ptr<RigPorts> opened;
    try {
      opened = ports ? ports(plan, in) : open_rig_ports(config, plan, *in.scenario);
    } catch (const campaign::RigFault&) {
      throw;
    } catch (const std::exception& e) {
      throw campaign::RigFault(fmt::format("opening the rig ({}): {}", config.file, e.what()));
    }
    return run_hardware(in, plan, *opened, options);
  };
}

} // namespace hilrig::hardware
