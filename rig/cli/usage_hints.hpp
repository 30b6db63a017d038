#pragma once
// What CLI11 says of a mistyped command line is misleading: `hilrig rn` is "the following
// argument was not expected", `hilrig run x.toml --ot d` is "--out is required". Before CLI11
// parses, an unknown subcommand or option is named with the closest valid ones.

#include <optional>
#include <string>

#include "rig/cli/cli_fwd.hpp"

namespace hilrig::cli {

// "hilrig: rn: no such command (did you mean \"run\"?); commands: ..." or
// "hilrig run: --ot: no such option (did you mean \"--out\"?)"; nullopt when the words are
// all known (CLI11 then parses them and judges the rest). A command of a command is followed
// ("synth quadrature --lines": quadrature's options). A word after "-" and a digit or "." is a
// value ("-3", "-1ms"), not an option, and so is the word after an option that takes one
// ("--rpm -inf": CLI11 gives it to --rpm, whose own check refuses it).
[[nodiscard]] std::optional<std::string> unknown_word(const CLI::App& app, int argc, const char* const* argv);

} // namespace hilrig::cli
