#include "core/trace.hpp"
#include "core/vcd_stream.hpp"
#include "tests/tools/vcd_reader.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <random>
#include <sstream>
#include <string>
#include <vector>

using namespace hilrig;
using namespace hilrig::literals;

namespace {

// rig.enc.A/B (wires), dut.count (8-bit integer), dut.volt (real), top (wire, no scope).
TraceRecorder small_trace() {
  TraceRecorder t;
  const std::uint32_t a = t.declare("rig.enc.A");
  const std::uint32_t b = t.declare("rig.enc.B");
  const std::uint32_t n = t.declare("dut.count", SignalKind::Integer, 8);
  const std::uint32_t v = t.declare("dut.volt", SignalKind::Real);
  t.declare("top");
  t.set_initial(a, 0);
  t.set_initial(n, 5);
  t.set_initial_real(v, 0.5);
  t.edge(a, Edge{100_ns, Level::High});
  t.value(n, 100_ns, 6);
  t.edge(b, Edge{250_ns, Level::High});
  t.real(v, 250_ns, 1.25);
  t.value(n, 300_ns, -1); // two's complement within 8 bits: 11111111
  return t;
}

// Written by hand from IEEE 1364 §18.2: identifiers '!' '"' '#' '$' '%' in declaration order,
// scopes per dotted component, $dumpvars with the initial values (x where none), then
// the value changes under ascending #times.
const char* const kSmallVcd = "$version\n"
                              "  hilrig trace\n"
                              "$end\n"
                              "$timescale 1ns $end\n"
                              "$scope module rig $end\n"
                              "$scope module enc $end\n"
                              "$var wire 1 ! A $end\n"
                              "$var wire 1 \" B $end\n"
                              "$upscope $end\n"
                              "$upscope $end\n"
                              "$scope module dut $end\n"
                              "$var integer 8 # count $end\n"
                              "$var real 64 $ volt $end\n"
                              "$upscope $end\n"
                              "$var wire 1 % top $end\n"
                              "$enddefinitions $end\n"
                              "#0\n"
                              "$dumpvars\n"
                              "0!\n"
                              "x\"\n"
                              "b101 #\n"
                              "r0.5 $\n"
                              "x%\n"
                              "$end\n"
                              "#100\n"
                              "1!\n"
                              "b110 #\n"
                              "#250\n"
                              "1\"\n"
                              "r1.25 $\n"
                              "#300\n"
                              "b11111111 #\n";

} // namespace

TEST(Vcd, WritesTheHandWrittenFile) {
  std::ostringstream out;
  write_vcd(small_trace(), out);
  EXPECT_EQ(out.str(), kSmallVcd);
}

// The body's formatting by hand: times across decimal lengths (1, 2, 3, 10, 11 and 19 digits,
// each side of a power of ten), integers across byte boundaries of their binary digits (1, 7, 8,
// 9, 16, 17 and 64 digits, zero as one digit, two's complement masked to the width), and
// two-character identifiers (signal 94 is "!\"": 94 = 0 + 1 * 94; signal 95 is "\"\"").
TEST(Vcd, WritesTimesIntegersAndLongIdentifiersByHand) {
  TraceRecorder t;
  const std::uint32_t w = t.declare("w0");
  for (int i = 1; i < 94; ++i) t.declare("w" + std::to_string(i));
  const std::uint32_t n = t.declare("n", SignalKind::Integer, 64);
  const std::uint32_t m = t.declare("m", SignalKind::Integer, 12);
  ASSERT_EQ(n, 94U);
  ASSERT_EQ(m, 95U);
  t.value(n, 7_ns, 0);
  t.value(n, 10_ns, 1);
  t.value(n, 99_ns, 0x7F);
  t.value(n, 100_ns, 0x80);
  t.value(n, 1000_ns, 0x1FF);
  t.value(n, Nanos{123456789}, 0xA5A5);
  t.value(m, Nanos{123456789}, 0x10001); // 12 bits of it: 1
  t.value(n, Nanos{9999999999}, 0x10001);
  t.value(n, Nanos{10000000000}, -1);
  t.value(n, Nanos{99999999999}, std::numeric_limits<std::int64_t>::min());
  t.value(m, Nanos{std::numeric_limits<std::int64_t>::max()}, -2);
  t.edge(w, Edge{Nanos{std::numeric_limits<std::int64_t>::max()}, Level::High});
  std::ostringstream out;
  write_vcd(t, out);
  const std::string s = out.str();
  const std::size_t dumped = s.find("$end\n", s.find("$dumpvars"));
  ASSERT_NE(dumped, std::string::npos);
  EXPECT_EQ(s.substr(dumped + 5), "#7\n"
                                  "b0 !\"\n"
                                  "#10\n"
                                  "b1 !\"\n"
                                  "#99\n"
                                  "b1111111 !\"\n"
                                  "#100\n"
                                  "b10000000 !\"\n"
                                  "#1000\n"
                                  "b111111111 !\"\n"
                                  "#123456789\n"
                                  "b1010010110100101 !\"\n"
                                  "b1 \"\"\n"
                                  "#9999999999\n"
                                  "b10000000000000001 !\"\n"
                                  "#10000000000\n"
                                  "b" +
                                      std::string(64, '1') +
                                      " !\"\n"
                                      "#99999999999\n"
                                      "b1" +
                                      std::string(63, '0') +
                                      " !\"\n"
                                      "#9223372036854775807\n"
                                      "b111111111110 \"\"\n"
                                      "1!\n");
}

TEST(Vcd, DateCommentIsOptionalHeader) {
  std::ostringstream out;
  write_vcd(small_trace(), out, "run 42");
  EXPECT_EQ(out.str().rfind("$date\n  run 42\n$end\n$version", 0), 0U);
}

TEST(Vcd, SamplesOutOfOrderAreWrittenInTimeOrder) {
  TraceRecorder t;
  const std::uint32_t a = t.declare("a");
  t.edge(a, Edge{300_ns, Level::Low});
  t.edge(a, Edge{200_ns, Level::High});
  std::ostringstream out;
  write_vcd(t, out);
  const std::string s = out.str();
  EXPECT_LT(s.find("#200\n1!"), s.find("#300\n0!"));
}

TEST(Vcd, OverlayIsMergedInTimeOrderAfterTheTracesOwnSamplesOfTheSameTime) {
  TraceRecorder t;
  const std::uint32_t a = t.declare("a");
  const std::uint32_t mark = t.declare("check.on");
  t.edge(a, Edge{100_ns, Level::High});
  t.edge(a, Edge{300_ns, Level::Low});
  // Given out of order, and one at a time of the trace's own, one after its last sample.
  const std::vector<TraceSample> overlay{{400_ns, mark, 0, 0.0}, {100_ns, mark, 1, 0.0}};
  std::ostringstream out;
  write_vcd(t, out, "", overlay);
  const std::string s = out.str();
  EXPECT_NE(s.find("#100\n1!\n1\"\n#300\n0!\n#400\n0\"\n"), std::string::npos) << s;
  // Of a signal the trace does not declare: refused, not written under another's id.
  const std::vector<TraceSample> stranger{{100_ns, 7, 1, 0.0}};
  std::ostringstream none;
  EXPECT_THROW(write_vcd(t, none, "", stranger), std::invalid_argument);
}
TEST(Vcd, NegativeTimeIsRejected) {
  TraceRecorder t;
  t.declare("a");
  t.edge(0, Edge{-1_ns, Level::High});
  std::ostringstream out;
  EXPECT_THROW(write_vcd(t, out), std::invalid_argument);
}

TEST(VcdStream, AppendsAsTheRunGoesAndEndsEqualToWriteVcd) {
  TraceRecorder t = small_trace();
  // Rebuild the same trace in two halves, updating the stream in between.
  TraceRecorder live;
  for (const SignalInfo& s : t.signals()) live.declare(s.name, s.kind, s.width);
  live.set_initial(0, 0);
  live.set_initial(2, 5);
  live.set_initial_real(3, 0.5);
  std::ostringstream out;
  VcdStream stream(out);
  stream.update(live); // header only: already a readable file
  EXPECT_NE(out.str().find("$enddefinitions $end\n#0\n$dumpvars\n"), std::string::npos);
  live.edge(0, Edge{100_ns, Level::High});
  live.value(2, 100_ns, 6);
  stream.update(live);
  const std::string half = out.str();
  EXPECT_TRUE(half.ends_with("$end\n#100\n1!\nb110 #\n"));
  live.edge(1, Edge{250_ns, Level::High});
  live.real(3, 250_ns, 1.25);
  live.value(2, 300_ns, -1);
  stream.update(live);
  EXPECT_EQ(out.str(), kSmallVcd);
  EXPECT_EQ(stream.skipped(), 0U);
}

TEST(VcdStream, SignalsDeclaredAfterTheHeaderAreSkipped) {
  TraceRecorder t;
  t.declare("a");
  std::ostringstream out;
  VcdStream stream(out);
  stream.update(t);
  const std::uint32_t late = t.declare("b");
  t.edge(late, Edge{5_ns, Level::High});
  t.edge(0, Edge{6_ns, Level::High});
  stream.update(t);
  EXPECT_EQ(stream.skipped(), 1U);
  EXPECT_TRUE(out.str().ends_with("$end\n#6\n1!\n"));
}

namespace {

// A value change as a VCD reader sees it: the signal's declaration index, its time, and the
// value (wires and integers: the bits as written; reals: the number).
struct Change {
  std::int64_t time;
  std::size_t signal;
  std::uint64_t bits;
  double real;
  friend bool operator==(const Change&, const Change&) = default;
};

// The changes after $dumpvars as the tests' VCD reader (tests/tools/vcd_reader.hpp) reads them,
// in file order. Each variable's identifier code must be its declaration index in base 94 over
// '!'..'~', least significant digit first (the writer's documented scheme).
std::vector<Change> read_vcd(const std::string& text) {
  const hilrig::test::Vcd vcd = hilrig::test::parse_vcd_text(text);
  for (const hilrig::test::VcdVar& v : vcd.vars) {
    std::size_t index = 0;
    for (auto c = v.id.rbegin(); c != v.id.rend(); ++c)
      index = index * 94 + static_cast<std::size_t>(*c - '!');
    EXPECT_EQ(index, v.index) << v.name << " has identifier code " << v.id;
  }
  std::vector<Change> changes;
  std::vector<std::size_t> next(vcd.vars.size(), 0); // per var: its next change
  for (const std::size_t var : vcd.change_of) {
    const hilrig::test::VcdChange& c = vcd.vars[var].changes[next[var]++];
    const bool real = c.value[0] == 'r';
    changes.push_back(Change{c.time, var, real ? 0U : c.bits(), real ? c.number() : 0.0});
  }
  return changes;
}

} // namespace

// Round trip: a seeded random trace of wires, integers of every width 1..64 (negative values,
// the extremes of int64) and reals, written as VCD and read back by the reader above, gives
// the recorded changes: each integer as its two's complement within its width, each real the
// same double (shortest round-trip decimal), in time order.
TEST(Vcd, RoundTripGivesTheRecordedChanges) {
  for (const std::uint32_t seed : {1U, 2U, 3U, 4U}) {
    std::mt19937_64 rng(seed);
    TraceRecorder t;
    std::vector<std::uint32_t> signals;
    signals.push_back(t.declare("w.a"));
    signals.push_back(t.declare("w.b"));
    for (unsigned width = 1; width <= 64; ++width)
      signals.push_back(
          t.declare("int.n" + std::to_string(width), SignalKind::Integer, static_cast<std::uint8_t>(width)));
    signals.push_back(t.declare("an.v", SignalKind::Real));
    std::vector<Change> expected;
    std::int64_t now = 0;
    const std::int64_t extremes[] = {
        0,   -1,  1,   std::numeric_limits<std::int64_t>::min(), std::numeric_limits<std::int64_t>::max(),
        255, 256, -256};
    for (int i = 0; i < 3000; ++i) {
      if (rng() % 3 == 0) now += static_cast<std::int64_t>(rng() % 100000);
      const std::uint32_t s = signals[rng() % signals.size()];
      const SignalInfo& info = t.signals()[s];
      if (info.kind == SignalKind::Wire) {
        const bool high = rng() % 2 == 0;
        t.edge(s, Edge{Nanos{now}, level_of(high)});
        expected.push_back({now, s, high ? 1U : 0U, 0.0});
      } else if (info.kind == SignalKind::Integer) {
        const std::int64_t v =
            rng() % 4 == 0 ? extremes[rng() % std::size(extremes)] : static_cast<std::int64_t>(rng());
        t.value(s, Nanos{now}, v);
        const std::uint64_t mask =
            info.width == 64 ? ~std::uint64_t{0} : (std::uint64_t{1} << info.width) - 1U;
        expected.push_back({now, s, static_cast<std::uint64_t>(v) & mask, 0.0});
      } else {
        const double v =
            std::ldexp(static_cast<double>(rng() % 2000001) - 1e6, static_cast<int>(rng() % 40) - 20);
        t.real(s, Nanos{now}, v);
        expected.push_back({now, s, 0U, v});
      }
    }
    std::ostringstream out;
    write_vcd(t, out);
    EXPECT_EQ(read_vcd(out.str()), expected) << "seed " << seed;
  }
}
