#pragma once
// Shared by the campaign tests: the shipped campaigns' paths and a small campaign text
// for the reference PLS that each test extends.

#include <string>

#include "rig/campaign/campaign.hpp"
#include "rig/campaign/executive.hpp"
#include "rig/results/campaign_result.hpp"

namespace hilrig::campaign::test {

inline std::string shipped(const std::string& name) {
  return std::string(HILRIG_SOURCE_DIR) + "/campaigns/reference/" + name;
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

// Every run of the campaign, unsharded, with its own seed.
inline rig::CampaignResult run_everything(const Campaign& c) {
  return Executive(c).run_all(c.runs, c.seed, rig::Shard{0, 1});
}

} // namespace hilrig::campaign::test
