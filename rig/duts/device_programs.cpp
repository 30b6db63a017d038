#include "rig/duts/device_programs.hpp"

#include <algorithm>
#include <map>
#include <string>

namespace hilrig::duts {

const std::vector<ProgramBlockInfo>& device_programs(std::string_view device) {
  static const std::map<std::string, std::vector<ProgramBlockInfo>, std::less<>> all = {
      {"ans1", ans1_programs()},       {"smd23e", smd23e_programs()},   {"amci4501", amci4501_programs()},
      {"ssi7361", ssi7361_programs()}, {"pls2700", pls2700_programs()},
  };
  static const std::vector<ProgramBlockInfo> none;
  const auto it = all.find(device);
  return it == all.end() ? none : it->second;
}

const ProgramBlockInfo* find_program(std::string_view device, std::string_view block) {
  const auto& blocks = device_programs(device);
  const auto it =
      std::find_if(blocks.begin(), blocks.end(), [&](const ProgramBlockInfo& b) { return b.name == block; });
  return it == blocks.end() ? nullptr : &*it;
}

PlannedMove planned_move(std::string_view device, std::span<const std::vector<std::uint16_t>> earlier,
                         std::span<const std::uint16_t> words) {
  if (device == "smd23e") return smd23e_planned_move(earlier, words);
  throw NoPlannedMove("a move of a board that plans its profile (smd23e)");
}

} // namespace hilrig::duts
