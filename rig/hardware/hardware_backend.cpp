#include "rig/hardware/hardware_backend.hpp"

#include <exception>
#include <memory>
#include <utility>

#include <fmt/format.h>

#include "rig/hardware/drive_plan.hpp"

namespace hilrig::hardware {

namespace {
void check_virtual_only(const std::string& file, const campaign::Scenario& s) {
  if (!s.device_faults.empty())
    throw campaign::CampaignError(
        file, s.device_faults.front().where, "device_fault[0].fault",
        fmt::format("no [[device_fault]] on a hardware backend: \"{}\" is made by a virtual board's model "
                    "or its stator signals; run it with --backend virtual (a real board's faults are its "
                    "own: a rig would need a fault switch into the board, which it has not)",
                    s.device_faults.front().name));
  if (!s.power_cycles.empty())
    throw campaign::CampaignError(file, s.power_cycles.front().where, "power_cycle[0].at",
                                  "no [[power_cycle]] on a hardware backend: the rig switches no supply of a "
                                  "real board; run it with --backend virtual");
  if (!s.panel.empty())
    throw campaign::CampaignError(
        file, s.panel.front().where, "panel[0].action",
        "no [[panel]] on a hardware backend: the rig presses no key of a real board; "
        "run it with --backend virtual");
}
} // namespace

void check_virtual_only(const campaign::Campaign& c) {
  for (const campaign::Scenario& s : c.points) check_virtual_only(c.file, s);
  for (const auto& points : c.fault_points)
    for (const campaign::Scenario& s : points) check_virtual_only(c.file, s);
}

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
