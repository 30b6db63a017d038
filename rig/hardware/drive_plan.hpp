#pragma once
// A scenario's rig lines placed on this rig: the lines the RT loop writes (board inputs,
// in output-index order), the lines it captures (board outputs, in input-index order), and
// the other links the scenario needs (the resolver stream on CAN, the host link). A rig
// line with no [[gpio.line]], or a link the rig config lacks, is bad input naming both files.

#include <string>
#include <vector>

#include "core/line.hpp"
#include "rig/campaign/campaign.hpp"
#include "rig/hardware/rig_config.hpp"

namespace hilrig::hardware {

struct PlannedLine {
  std::string rig;
  const GpioLine* gpio = nullptr; // into the rig config
  Level initial = Level::Low;     // outputs: the level the line is requested at
};

struct DrivePlan {
  std::vector<PlannedLine> outputs;
  std::vector<PlannedLine> inputs;
  bool resolver = false; // the scenario's resolver goes out as the CAN angle stream
  bool host = false;     // the scenario has host actions (over the host link)
};

// campaign_file: the campaign's file name, for messages. Throws campaign::CampaignError at
// the campaign's entry (file:line:column) naming the rig config it could not find it in.
[[nodiscard]] DrivePlan plan_lines(const std::string& campaign_file, const campaign::Scenario& scenario,
                                   const RigConfig& config);

} // namespace hilrig::hardware
