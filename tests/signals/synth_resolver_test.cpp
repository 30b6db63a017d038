// `hilrig synth resolver`: run in-process, read the VCD back and check the stator signals
// against the resolver equations worked out by hand: V_sin = TR*Vref*sin(theta),
// V_cos = TR*Vref*cos(theta), Vref = A*sin(2*pi*f*t); and the angle frames against the
// ResolverAngle layout (0x120: angle 1/2^24 turn, speed 1/4096 turn/s, sequence, valid).

#include <gtest/gtest.h>

#include <cmath>
#include <fstream>
#include <numbers>
#include <string>
#include <vector>

#include "tests/signals/run_synth.hpp"
#include "tests/tools/vcd_reader.hpp"

using namespace hilrig;

namespace {

using test::synth;

std::vector<std::string> lines_of(const std::string& path) {
  std::ifstream in(path);
  std::vector<std::string> lines;
  for (std::string l; std::getline(in, l);) lines.push_back(l);
  return lines;
}

const double kTan30 = 1.0 / std::sqrt(3.0);

} // namespace

TEST(SynthResolver, At30DegreesSinOverCosIsTan30) {
  const std::string out = test::kSynthDir + "/synth_resolver_30.vcd";
  synth({"resolver", "--out", out, "--start", "30", "--rate", "1e6", "--duration", "1ms"});
  const test::Vcd vcd = test::read_vcd_file(out);
  const auto& ref = vcd.leaf("ref").changes;
  const auto& sin = vcd.leaf("sin").changes;
  const auto& cos = vcd.leaf("cos").changes;
  // 1 MHz for 1 ms, both ends included: 1001 samples a signal.
  ASSERT_EQ(ref.size(), 1001u);
  ASSERT_EQ(sin.size(), 1001u);
  ASSERT_EQ(cos.size(), 1001u);
  // Vref = sin(2*pi*5 kHz*t): peak at 50 us, zero at 100 us, trough at 150 us.
  EXPECT_EQ(ref[50].time, 50'000);
  EXPECT_NEAR(ref[50].number(), 1.0, 1e-12);
  EXPECT_NEAR(ref[100].number(), 0.0, 1e-12);
  EXPECT_NEAR(ref[150].number(), -1.0, 1e-12);
  // Envelope ratio: the largest |SIN| over the largest |COS| is tan 30 deg; and at every
  // sample SIN = sin 30 * Vref = Vref/2, COS = cos 30 * Vref (TR 1, carrier in phase).
  double max_sin = 0.0;
  double max_cos = 0.0;
  for (std::size_t i = 0; i < ref.size(); ++i) {
    max_sin = std::fmax(max_sin, std::fabs(sin[i].number()));
    max_cos = std::fmax(max_cos, std::fabs(cos[i].number()));
    EXPECT_NEAR(sin[i].number(), 0.5 * ref[i].number(), 1e-12);
    EXPECT_NEAR(cos[i].number(), std::sqrt(3.0) / 2.0 * ref[i].number(), 1e-12);
  }
  EXPECT_NEAR(max_sin / max_cos, kTan30, 1e-9);
}

TEST(SynthResolver, TurningShaftEnvelopeFollowsTheAngle) {
  // 600 rpm = 10 turn/s from 0: theta(t) = 2*pi*10*t; TR 0.5, 2 V reference at 4 kHz.
  const std::string out = test::kSynthDir + "/synth_resolver_turning.vcd";
  synth({"resolver", "--out", out, "--rpm", "600", "--rate", "100e3", "--duration", "30ms", "--tr", "0.5",
         "--amplitude", "2", "--excitation-hz", "4000"});
  const test::Vcd vcd = test::read_vcd_file(out);
  const auto& ref = vcd.leaf("ref").changes;
  const auto& sin = vcd.leaf("sin").changes;
  const auto& cos = vcd.leaf("cos").changes;
  ASSERT_EQ(ref.size(), 3001u);
  std::size_t checked = 0;
  for (std::size_t i = 0; i < ref.size(); ++i) {
    const double t = static_cast<double>(ref[i].time) * 1e-9;
    const double vref = 2.0 * std::sin(2.0 * std::numbers::pi * 4000.0 * t);
    EXPECT_NEAR(ref[i].number(), vref, 1e-9);
    if (std::fabs(vref) < 0.2) continue;
    const double theta = 2.0 * std::numbers::pi * 10.0 * t;
    EXPECT_NEAR(sin[i].number() / ref[i].number(), 0.5 * std::sin(theta), 1e-9);
    EXPECT_NEAR(cos[i].number() / ref[i].number(), 0.5 * std::cos(theta), 1e-9);
    ++checked;
  }
  EXPECT_GT(checked, 2000u);
}

TEST(SynthResolver, WindingFaults) {
  const std::string out = test::kSynthDir + "/synth_resolver_fault.vcd";
  auto peak = [](const std::vector<test::VcdChange>& s) {
    double m = 0.0;
    for (const test::VcdChange& c : s) m = std::fmax(m, std::fabs(c.number()));
    return m;
  };
  // Open SIN coil: SIN reads zero, COS is untouched (cos 30 deg of a 1 V reference).
  synth({"resolver", "--out", out, "--start", "30", "--rate", "1e6", "--duration", "1ms", "--sin-open"});
  test::Vcd vcd = test::read_vcd_file(out);
  EXPECT_EQ(peak(vcd.leaf("sin").changes), 0.0);
  EXPECT_NEAR(peak(vcd.leaf("cos").changes), std::sqrt(3.0) / 2.0, 1e-9);
  // Excitation loss: both windings zero, the board's reference still there.
  synth(
      {"resolver", "--out", out, "--start", "30", "--rate", "1e6", "--duration", "1ms", "--excitation-loss"});
  vcd = test::read_vcd_file(out);
  EXPECT_EQ(peak(vcd.leaf("sin").changes), 0.0);
  EXPECT_EQ(peak(vcd.leaf("cos").changes), 0.0);
  EXPECT_NEAR(peak(vcd.leaf("ref").changes), 1.0, 1e-12);
  // Imbalance: SIN gain 0.9 makes the envelope ratio 0.9 * tan 30.
  synth(
      {"resolver", "--out", out, "--start", "30", "--rate", "1e6", "--duration", "1ms", "--sin-gain", "0.9"});
  vcd = test::read_vcd_file(out);
  EXPECT_NEAR(peak(vcd.leaf("sin").changes) / peak(vcd.leaf("cos").changes), 0.9 * kTan30, 1e-9);
  // Carrier phase shift of 90 deg on SIN: at the reference peak (50 us) SIN's carrier
  // sin(pi/2 + pi/2) = 0, at the reference zero (100 us) it is sin(pi + pi/2) = -1, times sin 30.
  synth(
      {"resolver", "--out", out, "--start", "30", "--rate", "1e6", "--duration", "1ms", "--sin-phase", "90"});
  vcd = test::read_vcd_file(out);
  EXPECT_NEAR(vcd.leaf("sin").changes[50].number(), 0.0, 1e-9);
  EXPECT_NEAR(vcd.leaf("sin").changes[100].number(), -0.5, 1e-9);
}

TEST(SynthResolver, EmulatorFramesInTraceAndCandumpLog) {
  const std::string out = test::kSynthDir + "/synth_resolver_frames.vcd";
  const std::string log = test::kSynthDir + "/synth_resolver_frames.log";
  synth({"resolver", "--out", out, "--rpm", "600", "--duration", "10ms", "--can-frames", "--frame-period",
         "1ms", "--can-log", log});
  // Frames at 0, 1, ..., 10 ms: 11 frames.
  const test::Vcd vcd = test::read_vcd_file(out);
  const auto& angle = vcd.leaf("angle").changes;
  const auto& sequence = vcd.leaf("sequence").changes;
  ASSERT_EQ(angle.size(), 11u);
  ASSERT_EQ(sequence.size(), 11u);
  for (std::size_t k = 0; k < 11; ++k) {
    // 10 turn/s: frame k at k ms holds 0.01*k turn = round(0.01*k * 2^24) LSB.
    EXPECT_EQ(angle[k].time, static_cast<long long>(k) * 1'000'000);
    EXPECT_EQ(angle[k].number(), std::round(0.01 * static_cast<double>(k) * 16'777'216.0));
    EXPECT_EQ(sequence[k].number(), static_cast<double>(k % 16));
  }
  const auto lines = lines_of(log);
  ASSERT_EQ(lines.size(), 11u);
  // Frame 0: angle 0; speed 10*4096 = 40960 = 0x00A000 (bytes 3..5, LE: 00 A0 00);
  // byte 6 = valid (bit 52 -> 0x10) | sequence 0; byte 7 = channel 0.
  EXPECT_EQ(lines[0], "(0000000000.000000) can0 120#00000000A0001000");
  // Frame 1 at 1 ms: angle round(0.01 * 2^24) = 167772 = 0x028F5C (LE 5C 8F 02); sequence 1.
  EXPECT_EQ(lines[1], "(0000000000.001000) can0 120#5C8F0200A0001100");
}
