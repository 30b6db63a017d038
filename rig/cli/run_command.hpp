#pragma once
// `hilrig run FILE.toml --out DIR [--seed S] [--shard K/N]`: runs a campaign (in virtual
// time by default) and writes DIR/results.json, junit.xml, report.html, trace.vcd (the
// shard's first run; also trace-run<i>.vcd for up to 20 runs that did not pass) and
// can.log when CAN was used. Exit: 0 all passed, 1 a check failed, 2 bad input, 3 a rig fault.

#include <cstddef>
#include <cstdint>
#include <filesystem>
#include <iosfwd>
#include <optional>
#include <string>

#include <CLI/CLI.hpp>

namespace hilrig::cli {

void add_run_command(CLI::App& app);

struct RunOptions {
  std::string file;
  std::filesystem::path out;
  std::optional<std::uint64_t> seed; // overrides [campaign] seed
  std::string shard = "0/1";         // K/N, K in 0..N-1: runs whose index mod N is K
  bool progress = false;             // a progress line on err
};

// Does the whole command and returns its exit status; messages go to err.
[[nodiscard]] int run_campaign(const RunOptions& options, std::ostream& err);

// "K/N" -> (K, N); nullopt unless 0 <= K < N.
[[nodiscard]] std::optional<std::pair<std::size_t, std::size_t>> parse_shard(const std::string& text);

} // namespace hilrig::cli
