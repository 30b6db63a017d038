#pragma once
// Shared by the campaign tests: the shipped campaigns' paths and a small campaign text
// for the reference PLS that each test extends.

#include <algorithm>
#include <filesystem>
#include <string>
#include <vector>

#include "rig/campaign/campaign.hpp"
#include "rig/campaign/executive.hpp"
#include "rig/results/campaign_result.hpp"
#include "tests/tools/scratch_files.hpp"

namespace hilrig::campaign::test {

inline std::string shipped(const std::string& name) {
  return std::string(HILRIG_SOURCE_DIR) + "/campaigns/reference/" + name;
}

// campaigns/DEVICE/ of the source tree.
inline std::string campaign_dir(const std::string& device) {
  return std::string(HILRIG_SOURCE_DIR) + "/campaigns/" + device;
}

// Every campaign file shipped for a device, in name order.
inline std::vector<std::string> campaigns_of(const std::string& device) {
  std::vector<std::string> files;
  for (const auto& e : std::filesystem::directory_iterator(campaign_dir(device)))
    if (e.path().extension() == ".toml") files.push_back(e.path().string());
  std::sort(files.begin(), files.end());
  return files;
}

// Every shipped campaign but the RT VM lane's (campaigns/lane/ needs the lane's rig), in
// path order.
inline std::vector<std::filesystem::path> shipped_campaigns() {
  std::vector<std::filesystem::path> out;
  const std::filesystem::path root = std::filesystem::path(HILRIG_SOURCE_DIR) / "campaigns";
  for (const auto& e : std::filesystem::recursive_directory_iterator(root)) {
    if (e.path().extension() != ".toml") continue;
    if (std::filesystem::relative(e.path(), root).begin()->string() == "lane") continue;
    out.push_back(e.path());
  }
  std::sort(out.begin(), out.end());
  return out;
}

// Reference PLS (on 100, off 300, scan 200 us, delay 50 us, preset -50), encoder 100 lines
// (400 counts/turn), the shaft at count -50 swinging forward and back at 600 rpm (250 us
// per count) in swings of 100.07 ms. The throughput check "on_latency" judges [50, 250] us.
inline const std::string kPlsCampaign = R"([campaign]
name = "inline"
end = "300ms"
seed = 5
[dut]
model = "reference_pls"
[dut.params]
on = 100
off = 300
preset = -50
[[wiring]]
rig = "enc.A"
board = "A"
[[wiring]]
rig = "enc.B"
board = "B"
[[wiring]]
rig = "ls1"
board = "OUT"
[encoder]
lines = 100
[motion]
start_turns = -0.125
[[motion.move]]
kind = "constant"
speed_rpm = 600
duration = "100.07ms"
[[motion.move]]
kind = "constant"
speed_rpm = -600
duration = "100.07ms"
[[motion.move]]
kind = "constant"
speed_rpm = 600
duration = "100.07ms"
[[check]]
kind = "throughput"
name = "on_latency"
output = "ls1"
setpoint = 100
direction = "rising"
level = "high"
limit_us = 250
min_count = 2
)";

// The measurement of that name in a run, or null.
inline const rig::Measurement* find(const rig::RunResult& run, const std::string& name) {
  for (const auto& c : run.checks)
    for (const auto& m : c.measurements)
      if (m.name == name) return &m;
  return nullptr;
}

// The observation (host read) of that name in a run, or null.
inline const rig::Observation* find_observation(const rig::RunResult& run, const std::string& name) {
  for (const auto& o : run.observations)
    if (o.name == name) return &o;
  return nullptr;
}

// A file's whole text (a shipped campaign a test edits).
using hilrig::test::read_file;

// Every failing measurement of a result, for a failure message.
inline std::string failures(const rig::CampaignResult& r) {
  std::string out;
  for (const auto& run : r.runs) {
    if (!run.error.empty()) out += run.name + ": rig error " + run.error + "\n";
    if (rig::run_outcome(run) == rig::Outcome::Pass) continue;
    out += run.name + " failed:\n";
    for (const auto& c : run.checks)
      for (const auto& m : c.measurements)
        out += "  " + m.name + " = " + std::to_string(m.value) + " " + rig::to_string(m.outcome) + " " +
               m.detail + "\n";
  }
  return out;
}

// Every run of the campaign, unsharded, with its own seed.
inline rig::CampaignResult run_everything(const Campaign& c) {
  return Executive(c).run_all(c.runs, c.seed, rig::Shard{0, 1});
}

} // namespace hilrig::campaign::test
