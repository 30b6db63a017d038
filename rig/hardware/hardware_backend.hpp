#pragma once
// The hardware backend as the executive runs it: for each run, place the scenario's lines
// on the rig (drive_plan.hpp), open the rig's ports and play the run (hardware_run.hpp).
// check_campaign_on_rig() places every scenario of a campaign first, so a campaign the rig
// cannot carry is bad input before anything moves.

#include <string>

#include "rig/campaign/campaign.hpp"
#include "rig/campaign/executive.hpp"
#include "rig/hardware/hardware_run.hpp"
#include "rig/hardware/rig_config.hpp"
#include "rig/hardware/rig_ports.hpp"

namespace hilrig::hardware {

// Throws campaign::CampaignError for the first [[device_fault]], [[power_cycle]] or [[panel]]:
// the rig makes them only on a virtual board (a model raises the fault, switches the supply,
// presses the key), and a rig has no fault line into the board, switched supply or key pusher. Needs no rig
// config, so
// `--backend hardware` refuses such a campaign before anything else.
void check_virtual_only(const campaign::Campaign& campaign);

// Throws campaign::CampaignError for the first wire, resolver or host action the rig lacks.
void check_campaign_on_rig(const campaign::Campaign& campaign, const RigConfig& config);

// ports: how to open the rig's ports (default: open_rig_ports on the config). A port that
// cannot be opened is a rig fault of that run. The config outlives the backend.
[[nodiscard]] campaign::RunBackend hardware_backend(const RigConfig& config, std::string campaign_file,
                                                    RigPortsFactory ports = {},
                                                    HardwareRunOptions options = {});

} // namespace hilrig::hardware
