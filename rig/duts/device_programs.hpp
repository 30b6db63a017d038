#pragma once
// Each device's programming blocks in its manual's words (program_blocks.hpp), one file per
// device beside its adapter: what `[[host]] program = ...` accepts and the words it writes.

#include <cstdint>
#include <span>
#include <stdexcept>
#include <string_view>
#include <vector>

#include "rig/duts/program_blocks.hpp"

namespace hilrig::duts {

// The blocks of a registered device by its name (dut_registry()'s), in declaration order;
// empty for a device that declares none (the reference PLS, an external board).
[[nodiscard]] const std::vector<ProgramBlockInfo>& device_programs(std::string_view device);
[[nodiscard]] const ProgramBlockInfo* find_program(std::string_view device, std::string_view block);

// A move as the board plans it from the words a campaign writes (however written: a block
// or raw words): what a check needs to draw the move's profile.
struct PlannedMove {
  double starting_speed = 0; // steps/s
  double speed = 0;          // the Programmed Speed, steps/s
  double accel = 0;          // steps/s²
  double decel = 0;          // steps/s²
  double steps = 0;          // the move's length
};
// A write that starts no move with a known profile, or a board that plans none: what() says
// what is expected instead.
struct NoPlannedMove : std::invalid_argument {
  using std::invalid_argument::invalid_argument;
};
// The move `words` start on `device`, given the writes before them in the campaign (the
// configuration they run under). Throws NoPlannedMove.
[[nodiscard]] PlannedMove planned_move(std::string_view device,
                                       std::span<const std::vector<std::uint16_t>> earlier,
                                       std::span<const std::uint16_t> words);
[[nodiscard]] PlannedMove smd23e_planned_move(std::span<const std::vector<std::uint16_t>> earlier,
                                              std::span<const std::uint16_t> words); // smd23e_programs.cpp

[[nodiscard]] std::vector<ProgramBlockInfo> ans1_programs();     // ans1_programs.cpp
[[nodiscard]] std::vector<ProgramBlockInfo> smd23e_programs();   // smd23e_programs.cpp
[[nodiscard]] std::vector<ProgramBlockInfo> amci4501_programs(); // amci4501_programs.cpp
[[nodiscard]] std::vector<ProgramBlockInfo> ssi7361_programs();  // ssi7361_programs.cpp
[[nodiscard]] std::vector<ProgramBlockInfo> pls2700_programs();  // pls2700_programs.cpp

} // namespace hilrig::duts
