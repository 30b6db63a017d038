#pragma once
// --seed, one parser for every command that takes one (run, power): a seed is an unsigned 64-bit
// integer, 0..18446744073709551615, written in decimal. A sign, another base, a fraction or a
// number past the range is refused with the range in the message, never wrapped or clamped.

#include <cstdint>
#include <optional>
#include <string>
#include <string_view>

#include "rig/cli/cli_fwd.hpp"

namespace hilrig::cli {

// The seed `text` spells, or nullopt; seed_range_message() says what a seed is.
[[nodiscard]] std::optional<std::uint64_t> parse_seed(std::string_view text);
[[nodiscard]] std::string seed_range_message(std::string_view text);

// Adds --seed to cmd, parsed by parse_seed into seed (a bad one: CLI::ValidationError, exit 2).
CLI::Option* add_seed_option(CLI::App& cmd, std::optional<std::uint64_t>& seed, const std::string& what);

} // namespace hilrig::cli
