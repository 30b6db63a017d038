#pragma once
// Reads a [[host]] entry written in the board's own words, `program = "<block>"` with the
// block's fields (rig/duts/program_blocks.hpp), into the output words it compiles to. Every
// field is checked against the device's declaration: a field of another block, a value out of
// its range or not one of its words is bad input at that key. Internal to the parser.

#include <cstdint>
#include <vector>

#include "rig/campaign/toml_reader.hpp"
#include "rig/duts/dut.hpp"
#include "rig/duts/program_blocks.hpp"

namespace hilrig::campaign {

// The words of the block `program` names. info: the DUT (nullptr: an external board, which
// has no declared blocks: bad input). earlier: the words the campaign wrote before it, in order
// (a setting the block leaves as it is, on a board that cannot read it back: duts::EarlierWrites).
[[nodiscard]] std::vector<std::uint16_t> read_program(TableReader& r, const duts::DutInfo* info,
                                                      duts::EarlierWrites earlier = {});

} // namespace hilrig::campaign
