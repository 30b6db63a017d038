// `hilrig synth`: the command writes the solved quadrature / discrete edges to a VCD file.
// Expected edge counts are worked out by hand from the options.

#include "rig/cli/synth_command.hpp"
#include "tests/signals/run_synth.hpp"

#include <CLI/CLI.hpp>
#include <gtest/gtest.h>

#include <fstream>
#include <map>
#include <sstream>
#include <string>
#include <vector>

using namespace hilrig;
using namespace hilrig::literals;

namespace {

using test::synth;

// Value changes per VCD identifier after $dumpvars (each change is one "0<id>"/"1<id>" line),
// with the names the header gives the identifiers.
struct VcdCounts {
  std::map<std::string, std::string> id_of; // leaf name -> id
  std::map<std::string, int> changes;       // id -> count
  std::vector<long long> times;
};

VcdCounts count_changes(const std::string& path) {
  std::ifstream in(path);
  VcdCounts vcd;
  std::string line;
  bool in_dumpvars = false;
  bool body = false;
  while (std::getline(in, line)) {
    std::istringstream words(line);
    std::string w;
    words >> w;
    if (w == "$var") {
      std::string type, width, id, name;
      words >> type >> width >> id >> name;
      vcd.id_of[name] = id;
    } else if (w == "$enddefinitions") {
      body = true;
    } else if (body && w == "$dumpvars") {
      in_dumpvars = true;
    } else if (body && w == "$end") {
      in_dumpvars = false;
    } else if (body && !w.empty() && w[0] == '#') {
      vcd.times.push_back(std::stoll(w.substr(1)));
    } else if (body && !in_dumpvars && !w.empty() && (w[0] == '0' || w[0] == '1')) {
      ++vcd.changes[w.substr(1)];
    }
  }
  return vcd;
}

} // namespace

TEST(SynthCommand, ParsesDurations) {
  EXPECT_EQ(cli::parse_duration("10ms"), 10_ms);
  EXPECT_EQ(cli::parse_duration("24.414us"), 24'414_ns);
  EXPECT_EQ(cli::parse_duration("250ns"), 250_ns);
  EXPECT_EQ(cli::parse_duration("1.5s"), 1'500_ms);
  EXPECT_EQ(cli::parse_duration("2"), 2_s);
  EXPECT_THROW(static_cast<void>(cli::parse_duration("fast")), CLI::ValidationError);
}

TEST(SynthCommand, QuadratureAt600RpmWritesEveryEdge) {
  // 1,024 lines at 600 RPM for 1 ms: 40.96 counts, edges at 0.5 ... 40.5 counts = 41
  // edges, alternating A, B: 21 on A, 20 on B. The first at 12,207 ns (0.5 / 40,960 s).
  const std::string path = test::kSynthDir + "/synth_quadrature_test.vcd";
  synth({"quadrature", "--lines", "1024", "--rpm", "600", "--duration", "1ms", "--out", path});
  const VcdCounts vcd = count_changes(path);
  ASSERT_TRUE(vcd.id_of.count("A") && vcd.id_of.count("B"));
  EXPECT_EQ(vcd.changes.at(vcd.id_of.at("A")), 21);
  EXPECT_EQ(vcd.changes.at(vcd.id_of.at("B")), 20);
  ASSERT_GE(vcd.times.size(), 2U);
  EXPECT_EQ(vcd.times[1], 12'207);
}

TEST(SynthCommand, GlitchFaultAddsTwoEdgesOnItsChannel) {
  // As above (A edges at 12.2, 61.0, 109.9 us ...), plus a 50 ns glitch on A at 100 us,
  // between two A edges: 21 + 2 A changes, B untouched.
  const std::string path = test::kSynthDir + "/synth_glitch_test.vcd";
  synth({"quadrature", "--lines", "1024", "--rpm", "600", "--duration", "1ms", "--glitch", "A,100us,50ns",
         "--out", path});
  const VcdCounts vcd = count_changes(path);
  EXPECT_EQ(vcd.changes.at(vcd.id_of.at("A")), 23);
  EXPECT_EQ(vcd.changes.at(vcd.id_of.at("B")), 20);
}

TEST(SynthCommand, TrapezoidWithGatedIndex) {
  // 2 turns of a 100-line encoder (400 counts/turn) as a trapezoid: states 1 ... 800, so
  // 800 A/B edges. Z gated to line 0 is high in states 2 and 402 (802 is never reached):
  // 2 pulses, 4 Z edges.
  const std::string path = test::kSynthDir + "/synth_trapezoid_test.vcd";
  synth({"quadrature", "--profile", "trapezoid", "--lines", "100", "--turns", "2", "--rpm", "600", "--accel",
         "100", "--index-line", "0", "--out", path});
  const VcdCounts vcd = count_changes(path);
  EXPECT_EQ(vcd.changes.at(vcd.id_of.at("A")) + vcd.changes.at(vcd.id_of.at("B")), 800);
  EXPECT_EQ(vcd.changes.at(vcd.id_of.at("Z")), 4);
}

TEST(SynthCommand, RateLimitFailIsACheckFailure) {
  // 1,024 lines at 20,000 RPM = 341.3 kHz per channel, above 250 kHz: exit status 1.
  const std::string path = test::kSynthDir + "/synth_rate_test.vcd";
  try {
    synth({"quadrature", "--rpm", "20000", "--duration", "1ms", "--max-input-hz", "250e3", "--rate-action",
           "fail", "--out", path});
    FAIL() << "expected a check failure";
  } catch (const CLI::RuntimeError& e) {
    EXPECT_EQ(e.get_exit_code(), 1);
  }
}

TEST(SynthCommand, DiscreteBounceAndTrain) {
  // A 3-pulse train (6 edges) and a 2-bounce closing (5 edges): 11 edges.
  const std::string path = test::kSynthDir + "/synth_discrete_test.vcd";
  synth({"discrete", "--name", "rig.start", "--train", "1ms,100us,10us,3", "--bounce", "2ms,1,1ms,2,7",
         "--out", path});
  const VcdCounts vcd = count_changes(path);
  EXPECT_EQ(vcd.changes.at(vcd.id_of.at("start")), 11);
}
