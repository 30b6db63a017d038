// Signal faults on the lines the rig synthesizes from a source other than its own encoder: the
// [ssi] transducer's DATA and a plant's encoder and valve monitor. The fault overrides the
// source for its span (docs/campaigns.md: "stuck overrides whatever else drives the line", "a
// glitch inverts a line for its width"); a stimulus that drives levels there is refused.

#include <string>
#include <vector>

#include <fmt/format.h>
#include <gtest/gtest.h>

#include "rig/campaign/campaign_error.hpp"
#include "rig/campaign/campaign_parser.hpp"
#include "rig/campaign/executive.hpp"
#include "test_support.hpp"

namespace hilrig::campaign {
namespace {

using rig::Outcome;

// A 16-bit transducer (65,536 counts a turn) at 60 rpm: 65,536 counts/s from 0. The 7361
// clocks it at 125 kHz with F1 at 0.1 ms + k x 0.5 ms (L1090, L1096; first_frame fixed) and has
// the 25 bits 25 T = 200 us later (T = 8 us, L1123); Format M = 1, N = 16 makes the Data Value
// the 16-bit field (L2012-2013). A read at a whole ms R sees the frame latched at R - 0.4 ms:
//   4 ms: latched 3.6 ms, 65,536 x 0.0036 = 235.93 -> 235
//   6 ms: latched 5.6 ms, 367.00 -> 367
//   8 ms: latched 7.6 ms, 498.07 -> 498
// Each read takes the status word (0), the Data Value (1) and the raw words (5: stream bits
// 10..25; 6: stream bits 1..9 in bits 09..01).
std::string ssi_campaign(const std::string& fault) {
  std::string text = R"([campaign]
name = "ssi-data-faults"
end = "10ms"
seed = 1
host_poll = "500us"
[dut]
model = "ssi7361"
[dut.params]
first_frame = "100us"
frame_phase_from_seed = false
[[wiring]]
rig = "ssi.clk"
board = "CLK"
[[wiring]]
rig = "ssi.data"
board = "DATA"
[encoder]
lines = 1000
[motion]
[[motion.move]]
kind = "constant"
speed_rpm = 60
duration = "20ms"
[ssi]
clock = "ssi.clk"
data = "ssi.data"
data_bits = 16
counts_per_turn = 65536
)" + fault + R"(
[[host]]
at = "2ms"
program = "setup"
bits = 16
first_bit = 1
name = "setup"
)";
  for (const int ms : {4, 6, 8})
    for (const int word : {0, 1, 5, 6})
      text += fmt::format("[[host]]\nat = \"{}ms\"\nread = {}\nname = \"w{}_{}ms\"\n", ms, word, word, ms);
  text += R"([[check]]
kind = "word_within"
name = "dv_6ms"
observation = "w1_6ms"
lower = 300
upper = 400
)";
  return text;
}

// The words each read saw.
struct Reads {
  rig::RunResult run;
  double word(int w, int ms) const {
    const rig::Observation* o = test::find_observation(run, fmt::format("w{}_{}ms", w, ms));
    EXPECT_NE(o, nullptr) << w << " at " << ms;
    return o != nullptr ? o->value : -1.0;
  }
};

Reads run_ssi(const std::string& fault) {
  const Campaign c = parse_campaign(ssi_campaign(fault), "ssi_faults.toml");
  Reads r{Executive(c).run(c.runs.at(0)).result};
  EXPECT_EQ(r.run.error, "");
  return r;
}

TEST(SsiDataFaults, WithNoFaultTheDataValueIsTheShaft) {
  const Reads r = run_ssi("");
  EXPECT_EQ(r.word(1, 4), 235);
  EXPECT_EQ(r.word(1, 6), 367);
  EXPECT_EQ(r.word(1, 8), 498);
}

// A DATA line stuck high reads as no transducer: every bit 1, raw 33,554,431 (L683-684,
// L2173-2180), so the 16-bit field is 65,535; the module flags nothing (L260-264). When the
// fault ends the transducer's data is back.
TEST(SsiDataFaults, DataStuckHighReadsAllOnesUnflagged) {
  const Reads r = run_ssi(R"([[stimulus]]
kind = "stuck"
line = "ssi.data"
at = "5ms"
level = "high"
until = "7ms"
)");
  EXPECT_EQ(r.word(1, 4), 235);
  EXPECT_EQ(r.word(1, 6), 65535);
  EXPECT_EQ(r.word(5, 6), 0xFFFF); // stream bits 10..25
  EXPECT_EQ(r.word(6, 6), 0x01FF); // stream bits 1..9
  EXPECT_EQ(r.word(0, 6), 0);      // no status bit
  EXPECT_EQ(r.word(1, 8), 498);
}

// Stuck low: raw 0 (digest docs/spec/ssi7361.md §4), Data Value 0, unflagged.
TEST(SsiDataFaults, DataStuckLowReadsZeroUnflagged) {
  const Reads r = run_ssi(R"([[stimulus]]
kind = "stuck"
line = "ssi.data"
at = "5ms"
level = "low"
until = "7ms"
)");
  EXPECT_EQ(r.word(1, 6), 0);
  EXPECT_EQ(r.word(5, 6), 0);
  EXPECT_EQ(r.word(6, 6), 0);
  EXPECT_EQ(r.word(0, 6), 0);
  EXPECT_EQ(r.word(1, 8), 498);
}

// A glitch over the whole frame latched at 5.6 ms (5.55 .. 5.85 ms; its bits sampled by 5.8 ms)
// inverts every bit the transducer sends in it, not only the level it had when the glitch began:
// the field reads 65,535 - 367 = 65,168.
TEST(SsiDataFaults, AGlitchInvertsEveryBitInsideIt) {
  const Reads r = run_ssi(R"([[stimulus]]
kind = "glitch"
line = "ssi.data"
at = "5.55ms"
width = "300us"
)");
  EXPECT_EQ(r.word(1, 4), 235);
  EXPECT_EQ(r.word(1, 6), 65535 - 367);
  EXPECT_EQ(r.word(1, 8), 498);
}

// As a [[fault]] (the audit's f1_stuck_on_ssi.toml): the fault run is judged, and caught.
TEST(SsiDataFaults, AFaultOnTheTransducersDataIsCaught) {
  const Campaign c = parse_campaign(ssi_campaign("") + R"([[fault]]
name = "data-stuck-high"
caught_by = "dv_6ms"
signal = { kind = "stuck", line = "ssi.data", at = "5ms", level = "high" }
)",
                                    "ssi_fault.toml");
  const rig::CampaignResult r = test::run_everything(c);
  ASSERT_EQ(r.runs.size(), 2U);
  EXPECT_EQ(r.runs[0].outcome, Outcome::Pass) << test::failures(r);
  EXPECT_EQ(r.runs[1].error, "");
  EXPECT_TRUE(rig::caught(r.runs[1])) << test::failures(r);
  EXPECT_EQ(r.verdict, Outcome::Pass) << test::failures(r);
}

// The press plant of campaigns/ans1/ans1_press_plant.toml turns enc.A/enc.B and drives the
// valve monitor "brake" (valve drops at 125 ms, the crank stands still at 222.83 ms).
RunOutput run_press(const std::string& stimulus) {
  std::string text = test::read_file(test::campaign_dir("ans1") + "/ans1_press_plant.toml");
  text = text.substr(0, text.find("[[fault]]"));
  const Campaign c = parse_campaign(text + stimulus, "press.toml");
  return Executive(c).run(c.runs.at(0));
}

std::size_t edges_between(const RunOutput& out, const std::string& line, Nanos from, Nanos to) {
  std::size_t n = 0;
  for (const Edge& e : out.trace->edges_of(line))
    if (e.time >= from && e.time < to) ++n;
  return n;
}

TEST(PlantLineFaults, EncoderAndValveFaultsOverrideThePlant) {
  const Nanos t50{50'000'000}, t100{100'000'000}, t150{150'000'000};
  const RunOutput none = run_press("");
  ASSERT_EQ(none.result.error, "");
  EXPECT_GT(edges_between(none, "enc.A", t50, t100), 0U);
  EXPECT_EQ(none.trace->edges_of("brake").size(), 1U); // the valve drops at 125 ms

  const RunOutput stuck = run_press(R"([[stimulus]]
kind = "stuck"
line = "enc.A"
at = "50ms"
level = "high"
until = "100ms"
)");
  ASSERT_EQ(stuck.result.error, "");
  EXPECT_EQ(edges_between(stuck, "enc.A", Nanos{50'000'001}, t100), 0U);
  EXPECT_GT(edges_between(stuck, "enc.A", t100, t150), 0U);

  const RunOutput lost = run_press(R"([[stimulus]]
kind = "missing_edges"
line = "enc.B"
at = "50ms"
until = "100ms"
)");
  ASSERT_EQ(lost.result.error, "");
  EXPECT_EQ(edges_between(lost, "enc.B", t50, t100), 0U);
  EXPECT_EQ(edges_between(lost, "enc.A", t50, t100), edges_between(none, "enc.A", t50, t100));

  const RunOutput held = run_press(R"([[stimulus]]
kind = "stuck"
line = "brake"
at = "100ms"
level = "high"
)");
  ASSERT_EQ(held.result.error, "");
  EXPECT_TRUE(held.trace->edges_of("brake").empty()); // held released over the valve's drop
}

// A stimulus that drives levels (level, pulse, bounce) would fight the source: refused before
// anything runs, naming the line and its source; so is a debounce probe there.
TEST(PlantLineFaults, DrivingStimuliOnSynthesizedLinesAreRefused) {
  const auto error_of = [](const std::string& text) {
    try {
      (void)parse_campaign(text, "t.toml");
      return std::string("accepted");
    } catch (const CampaignError& e) {
      return std::string(e.what());
    }
  };
  std::string press = test::read_file(test::campaign_dir("ans1") + "/ans1_press_plant.toml");
  press = press.substr(0, press.find("[[fault]]"));
  EXPECT_NE(error_of(press + "[[stimulus]]\nkind = \"level\"\nline = \"brake\"\nat = \"50ms\"\nlevel = "
                             "\"low\"\n")
                .find("brake is driven by the plant's valve"),
            std::string::npos);
  EXPECT_NE(error_of(ssi_campaign("[[stimulus]]\nkind = \"pulse\"\nline = \"ssi.data\"\nat = \"5ms\"\n"
                                  "width = \"10us\"\n"))
                .find("ssi.data is driven by the [ssi] transducer"),
            std::string::npos);
  EXPECT_NE(error_of(press + R"([[check]]
kind = "debounce"
name = "valve_probe"
input = "brake"
output = "stop_fault"
level = "low"
filter_us = 16000
tolerance_us = 1000
narrow_us = 1000
wide_us = 20000
probe_at = "10ms"
)")
                .find("brake is driven by the plant's valve"),
            std::string::npos);
}

} // namespace
} // namespace hilrig::campaign
