#pragma once
// Each device's programming blocks in its manual's words (program_blocks.hpp), one file per
// device beside its adapter: what `[[host]] program = ...` accepts and the words it writes.

#include <string_view>
#include <vector>

#include "rig/duts/program_blocks.hpp"

namespace hilrig::duts {

// The blocks of a registered device by its name (dut_registry()'s), in declaration order;
// empty for a device that declares none (the reference PLS, an external board).
[[nodiscard]] const std::vector<ProgramBlockInfo>& device_programs(std::string_view device);
[[nodiscard]] const ProgramBlockInfo* find_program(std::string_view device, std::string_view block);

[[nodiscard]] std::vector<ProgramBlockInfo> ans1_programs();     // ans1_programs.cpp
[[nodiscard]] std::vector<ProgramBlockInfo> smd23e_programs();   // smd23e_programs.cpp
[[nodiscard]] std::vector<ProgramBlockInfo> amci4501_programs(); // amci4501_programs.cpp
[[nodiscard]] std::vector<ProgramBlockInfo> ssi7361_programs();  // ssi7361_programs.cpp
[[nodiscard]] std::vector<ProgramBlockInfo> pls2700_programs();  // pls2700_programs.cpp

} // namespace hilrig::duts
