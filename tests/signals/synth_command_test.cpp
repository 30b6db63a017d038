// `hilrig synth`: the command writes the solved quadrature / discrete edges to a VCD file.
// Expected edge counts are worked out by hand from the options.

#include "rig/cli/synth_command.hpp"
#include "tests/signals/run_synth.hpp"
#include "tests/tools/vcd_reader.hpp"

#include <CLI/CLI.hpp>
#include <gtest/gtest.h>

#include <cstddef>
#include <string>

using namespace hilrig;
using namespace hilrig::literals;

namespace {

using test::synth;

// How often a variable changes after its initial value (each a "0<id>" or "1<id>" line).
std::size_t change_count(const test::Vcd& vcd, const char* leaf) { return vcd.leaf(leaf).changes.size(); }

} // namespace

TEST(SynthCommand, ParsesDurations) {
  EXPECT_EQ(cli::parse_instant("10ms", "--t"), 10_ms);
  EXPECT_EQ(cli::parse_instant("24.414us", "--t"), 24'414_ns);
  EXPECT_EQ(cli::parse_instant("250ns", "--t"), 250_ns);
  EXPECT_EQ(cli::parse_instant("1.5s", "--t"), 1'500_ms);
  EXPECT_EQ(cli::parse_instant("2", "--t"), 2_s);
  EXPECT_THROW(static_cast<void>(cli::parse_instant("fast", "--t")), CLI::ValidationError);
}

// One parser, each option's own range in its refusal: both ends are in, a nanosecond (or any
// amount) beyond either is out, and so are NaN and infinities; a time that rounds below the
// 1 ns minimum is refused by that minimum, not rounded to 0 and then called "not > 0". Times
// are judged as they round to whole ns (docs/synth.md "Ranges"): 0.9ns and 0.5ns are 1 ns.
TEST(SynthCommand, DurationsOutsideTheirRangeNameIt) {
  const auto refusal = [](const std::string& text, Nanos lo, Nanos hi) -> std::string {
    try {
      static_cast<void>(cli::parse_duration(text, "--first", lo, hi));
    } catch (const CLI::ValidationError& e) {
      return e.what();
    }
    return "accepted";
  };
  EXPECT_EQ(cli::parse_positive_duration("1ns", "--first"), 1_ns);
  EXPECT_EQ(cli::parse_positive_duration("3600s", "--first"), 3'600_s);
  EXPECT_EQ(cli::parse_instant("0", "--late"), 0_ns);
  EXPECT_EQ(cli::parse_positive_duration("0.9ns", "--first"), 1_ns);
  EXPECT_EQ(cli::parse_positive_duration("0.5ns", "--first"), 1_ns);
  EXPECT_EQ(cli::parse_positive_duration("3600.0000000004s", "--first"), 3'600_s);
  for (const char* text : {"0", "1e-10", "0.4ns", "-1ns", "3600.000000001s", "3601s", "nan", "inf", "-inf"})
    EXPECT_EQ(refusal(text, 1_ns, 3'600_s), std::string("--first: 1ns .. 3600s (got ") + text + ")") << text;
  for (const char* text : {"-1ns", "3601s", "nan"})
    EXPECT_EQ(refusal(text, 0_ns, 3'600_s), std::string("--first: 0s .. 3600s (got ") + text + ")") << text;
}

TEST(SynthCommand, QuadratureAt600RpmWritesEveryEdge) {
  // 1,024 lines at 600 RPM for 1 ms: 4,096 counts/turn x 10 turns/s = 40,960 counts/s, 40.96
  // counts. The rig's placement (docs/campaigns.md "[encoder]": count = floor(position), count
  // n entered when the motion reaches n): edges at 1 ... 40 counts = 40 edges, alternating A
  // (states 1, 3, ...: 00 -> 10 -> 11 -> 01) and B: 20 on each. The first at 1 / 40,960 s =
  // 24,414.06 ns, to the nearest ns.
  const std::string path = test::kSynthDir + "/synth_quadrature_test.vcd";
  synth({"quadrature", "--lines", "1024", "--rpm", "600", "--duration", "1ms", "--out", path});
  const test::Vcd vcd = test::read_vcd_file(path);
  ASSERT_TRUE(vcd.has_leaf("A") && vcd.has_leaf("B"));
  EXPECT_EQ(change_count(vcd, "A"), 20U);
  EXPECT_EQ(change_count(vcd, "B"), 20U);
  ASSERT_GE(vcd.times.size(), 2U);
  EXPECT_EQ(vcd.times[1], 24'414);
}

// The count signal carries the count, however far from 0: 600,000 lines (2,400,000 counts a
// turn) from 1,000 turns start at 2,400,000,000 (past 2^31) and from -1,000 turns at
// -2,400,000,000; at 1 RPM (40,000 counts/s: one count per 25 us) 90 us take it 3 counts up.
TEST(SynthCommand, CountPast2To31IsNotWrapped) {
  for (const std::int64_t sign : {1, -1}) {
    SCOPED_TRACE(sign);
    const std::string path = test::kSynthDir + "/synth_quadrature_count_test.vcd";
    synth({"quadrature", "--lines", "600000", "--rpm", "1", "--start", sign > 0 ? "1000" : "-1000",
           "--duration", "90us", "--count", "--out", path});
    const test::Vcd vcd = test::read_vcd_file(path);
    ASSERT_TRUE(vcd.has_leaf("count"));
    const test::VcdVar& count = vcd.leaf("count");
    EXPECT_EQ(count.width, 64);
    ASSERT_TRUE(count.initial.has_value());
    EXPECT_EQ(static_cast<std::int64_t>(count.initial->bits()), sign * 2'400'000'000LL);
    ASSERT_FALSE(count.changes.empty());
    EXPECT_EQ(count.changes.size(), 3U);
    EXPECT_EQ(static_cast<std::int64_t>(count.changes.back().bits()), sign * 2'400'000'000LL + 3);
  }
}

TEST(SynthCommand, GlitchFaultAddsTwoEdgesOnItsChannel) {
  // As above (A edges at counts 1, 3, 5 ...: 24.4, 73.2, 122.1 us ...), plus a 50 ns glitch on
  // A at 100 us, between two A edges: 20 + 2 A changes, B untouched.
  const std::string path = test::kSynthDir + "/synth_glitch_test.vcd";
  synth({"quadrature", "--lines", "1024", "--rpm", "600", "--duration", "1ms", "--glitch", "A,100us,50ns",
         "--out", path});
  const test::Vcd vcd = test::read_vcd_file(path);
  EXPECT_EQ(change_count(vcd, "A"), 22U);
  EXPECT_EQ(change_count(vcd, "B"), 20U);
}

TEST(SynthCommand, TrapezoidWithGatedIndex) {
  // 2 turns of a 100-line encoder (400 counts/turn) as a trapezoid: states 1 ... 800, so
  // 800 A/B edges. Z gated to line 0 is high in states 2 and 402 (802 is never reached):
  // 2 pulses, 4 Z edges.
  const std::string path = test::kSynthDir + "/synth_trapezoid_test.vcd";
  synth({"quadrature", "--profile", "trapezoid", "--lines", "100", "--turns", "2", "--rpm", "600", "--accel",
         "100", "--index-line", "0", "--out", path});
  const test::Vcd vcd = test::read_vcd_file(path);
  EXPECT_EQ(change_count(vcd, "A") + change_count(vcd, "B"), 800U);
  EXPECT_EQ(change_count(vcd, "Z"), 4U);
}

TEST(SynthCommand, RateLimitFailIsACheckFailure) {
  // 1,024 lines at 14,000 RPM = 238.9 kHz per channel, above 200 kHz: exit status 1. (Within the
  // rig's 1,000,000 counts/s, 14648 rpm on 1,024 lines: beyond it the command refuses --rpm.)
  const std::string path = test::kSynthDir + "/synth_rate_test.vcd";
  try {
    synth({"quadrature", "--rpm", "14000", "--duration", "1ms", "--max-input-hz", "200e3", "--rate-action",
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
  const test::Vcd vcd = test::read_vcd_file(path);
  EXPECT_EQ(change_count(vcd, "start"), 11U);
}
