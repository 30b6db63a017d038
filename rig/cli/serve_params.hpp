#pragma once
// `hilrig serve DEVICE --param KEY=VALUE`: a device's [MODEL] choices from the command line,
// by the names and kinds of its campaign adapter (rig/duts, `hilrig list`), so everything a
// campaign's [dut.params] can set a served board can too.

#include <string>
#include <vector>

#include "rig/duts/dut.hpp"

namespace hilrig::cli {

// Every parameter of `device`: the defaults, overridden by the "KEY=VALUE" texts (the value
// in the parameter's kind: integer, number, duration with a unit such as "200ms", true/false,
// or text). Throws std::invalid_argument naming the key: for an unknown key its device's
// keys; for a value of the wrong kind or outside the parameter's range what a campaign's
// [dut.params] says of the same value (what the kind is written as, or the valid range).
[[nodiscard]] duts::DutParams serve_params(const duts::DutInfo& device,
                                           const std::vector<std::string>& key_values);

} // namespace hilrig::cli
