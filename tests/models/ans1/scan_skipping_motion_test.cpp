// Exact scan skipping while the encoder moves (docs/virtual-time.md, "Motion"): property tests
// against the scan-every-period oracle. Random programs (setpoint pairs with advances and
// stitches, LS offsets, timers, speed/simple/pulse/window enabling, the shift register, the
// brake monitor, die protection, production counters) under random motion (speeds from
// standstill to one count per 3 us, reversals, pauses, steps on grid points) and random input
// edges: every output edge at the same time on both engines, and every host-visible value
// (the 20 status words, GMP, LS positions, time of rotation, shift register, counters) the same
// when read from an event at any instant, on a grid point or between.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <memory>
#include <numbers>
#include <random>

#include "ans1_bench.hpp"
#include "tests/signals/random_motion.hpp"

namespace hilrig::models::ans1 {
namespace {

using namespace hilrig::literals;
using testing::Bench;
using testing::every_period;

// Everything a host or the rig reads, at one instant.
struct Reading {
  Nanos at{};
  HostWords status{};
  std::uint16_t gmp = 0;
  std::array<std::uint16_t, kOutputCount> ls{};
  std::uint16_t time_of_rotation = 0;
  std::array<std::uint16_t, 16> shift_register{};
  std::uint32_t part_cycle = 0;
  std::uint32_t revolutions = 0;
  std::uint16_t outputs = 0;
  // Die protection and the inputs (DA16 w5/w7/w8, DA18): what input edges change.
  std::uint16_t inputs = 0;
  std::array<std::uint8_t, 16> fault_counts{};
  std::array<std::uint16_t, 16> rising{};
  std::array<std::uint16_t, 16> falling{};
  std::uint16_t first_to_fault = 0;
  std::uint16_t faulted_in_cycle = 0;
  friend bool operator==(const Reading&, const Reading&) = default;
};

Reading read(Ans1& d, Nanos at) {
  Reading r;
  r.at = at;
  r.status = d.host().status();
  r.gmp = d.gmp();
  for (int n = 1; n <= kOutputCount; ++n) {
    r.ls[static_cast<std::size_t>(n - 1)] = d.ls_position(n);
  }
  r.time_of_rotation = d.time_of_rotation();
  r.shift_register = d.shift_register().words();
  r.part_cycle = d.monitors().counters().value(CounterId::PartCycle);
  r.revolutions = d.monitors().counters().value(CounterId::Revolutions);
  r.outputs = d.output_states();
  r.inputs = d.input_states();
  const Monitors& m = d.monitors();
  for (int n = 1; n <= 16; ++n) {
    const auto i = static_cast<std::size_t>(n - 1);
    r.fault_counts[i] = m.die().fault_count(n);
    r.rising[i] = m.rising_position(n);
    r.falling[i] = m.falling_position(n);
  }
  r.first_to_fault = m.die().first_to_fault();
  r.faulted_in_cycle = m.die().faulted_in_cycle();
  return r;
}

void PrintTo(const Reading& r, std::ostream* os) {
  *os << "at " << r.at.count() << " ns: gmp " << r.gmp << ", outputs " << r.outputs << ", rotation "
      << r.time_of_rotation << ", part cycle " << r.part_cycle;
}

// A random program and stimulus, the same for both engines (one generator per bench, same seed).
class Scenario {
public:
  // steps: the motion as steps of constant period (else the caller plays a motion profile or
  // drives the stators); sensor: the transducer the program selects.
  explicit Scenario(std::uint64_t seed, bool steps = true, SensorType sensor = SensorType::Quadrature)
      : seed_(seed), steps_(steps), sensor_(sensor) {}

  void apply(Bench& b, Nanos end) const {
    std::mt19937_64 rng(seed_);
    const auto pick = [&rng](int lo, int hi) { return std::uniform_int_distribution<int>(lo, hi)(rng); };
    Ans1& d = b.device();

    PositionSetup position = d.position_setup();
    position.sensor = sensor_;
    const std::array<std::uint16_t, 3> cpcs{4096, 1000, 360};
    position.counts_per_cycle = cpcs[static_cast<std::size_t>(pick(0, 2))];
    const std::array<std::uint16_t, 3> fscs{position.counts_per_cycle, 360, 100};
    position.full_scale_count =
        std::min(position.counts_per_cycle, fscs[static_cast<std::size_t>(pick(0, 2))]);
    d.configure_position(position);
    const int fsc = position.full_scale_count;

    for (int n = 1; n <= kOutputCount; ++n) {
      OutputSetup o;
      const int pairs = pick(0, 3) == 0 ? pick(1, 3) : pick(0, 1); // few boundaries: long quiet stretches
      for (int k = 0; k < pairs; ++k) {
        SetpointPair& p = o.pairs[static_cast<std::size_t>(k)];
        p.from = static_cast<std::uint16_t>(pick(0, fsc - 1));
        p.to = static_cast<std::uint16_t>(pick(0, fsc - 1));
        if (seed_ % 4 == 0 && pick(0, 5) == 0) { // a stitched pair wakes at every GMP change
          p.on_stitch = static_cast<std::uint16_t>(pick(1, 5));
          p.off_stitch = static_cast<std::uint16_t>(pick(1, 5));
        }
      }
      o.ls_offset = pick(0, 1) == 0 ? 0 : pick(-(fsc - 1), fsc - 1);
      if (pick(0, 1) == 0) {
        o.advance_mode = AdvanceMode::Fixed;
        o.lead_ms = static_cast<std::uint16_t>(pick(0, 4));
        o.trail_ms = static_cast<std::uint16_t>(pick(0, 2));
      }
      if (pick(0, 7) == 0) {
        o.timer_type = pick(0, 1) == 0 ? TimerType::TimeOrPosition : TimerType::TimeOnly;
        o.timer_ms = static_cast<std::uint16_t>(pick(1, 5));
      }
      if (pick(0, 5) == 0) {
        o.rpm_low = static_cast<std::int16_t>(pick(-50, 200));
        o.rpm_high = static_cast<std::int16_t>(pick(-50, 2000));
      }
      const int anding = pick(0, 8);
      if (anding <= 2) {
        o.anding[static_cast<std::size_t>(pick(1, 3))] = static_cast<AndingMode>(anding + 1);
        o.window_low = static_cast<std::uint16_t>(pick(0, fsc - 1));
        o.window_high = static_cast<std::uint16_t>(pick(0, fsc - 1));
      }
      if (pick(0, 4) == 0) {
        o.sr_bit = static_cast<std::uint16_t>(pick(1, 4));
      }
      d.configure_output(n, o);
    }
    if (pick(0, 1) == 0) {
      ShiftRegisterSetup sr;
      sr.input = 5;
      sr.window_from = static_cast<std::uint16_t>(pick(0, fsc - 1));
      sr.window_to = static_cast<std::uint16_t>(pick(0, fsc - 1));
      sr.shift_position = static_cast<std::uint16_t>(pick(0, fsc - 1));
      d.configure_shift_register(sr);
    }
    MonitorSetup m;
    if (pick(0, 1) == 0) {
      m.brake.input = 6;
      m.brake.complete_stop_count = static_cast<std::uint8_t>(pick(0, 20));
      m.brake.start_time_limit_ms = static_cast<std::uint16_t>(pick(0, 30));
      m.brake.stop_time_limit_ms = static_cast<std::uint16_t>(pick(0, 200));
      m.brake.stop_overrun_output = 16;
    }
    if (pick(0, 2) == 0) {
      DieMonitorSetup& die = m.die.monitors[6];
      die.mode = static_cast<DieCheckMode>(pick(1, 5));
      die.fault_output = 15;
      die.windows[0] = DieWindow{static_cast<std::uint16_t>(pick(0, fsc - 1)),
                                 static_cast<std::uint16_t>(pick(0, fsc - 1))};
    }
    m.production.increment_position = static_cast<std::uint16_t>(pick(0, fsc - 1));
    m.production.counters[0] = CounterSetup{14, OverflowMode::Toggle, false, 3};
    d.configure_monitors(m);

    // Motion: segments of constant step period, reversals and pauses.
    Nanos t = microseconds(pick(0, 50));
    int direction = 1;
    const std::array<Nanos, 7> periods{3_us, 8_us, 10_us, 25_us, 100_us, 1_ms, 7_us};
    while (t < end) {
      if (pick(0, 3) == 0) {
        direction = -direction;
      }
      const Nanos period = periods[static_cast<std::size_t>(pick(0, 6))];
      const int steps = pick(1, static_cast<int>(40_ms / period));
      if (pick(0, 1) == 0) {
        t = (t / 10_us) * 10_us; // steps on grid points
      }
      if (steps_) {
        b.quadrature_run(t, period, steps, direction);
      }
      t += period * steps + microseconds(pick(0, 1) == 0 ? 0 : pick(1, 20'000));
    }
    // Input edges (inputs 1..7: enabling, shift register, brake, die protection).
    for (Nanos at = microseconds(pick(0, 2000)); at < end; at += microseconds(pick(1, 8000))) {
      b.input_at(at, pick(1, 7), pick(0, 1) == 1);
    }
  }

private:
  std::uint64_t seed_;
  bool steps_;
  SensorType sensor_;
};

// Readings from ordinary events: at random instants and exactly on grid points, where the
// scan at that instant has not run yet.
void sample(Bench& b, std::vector<Reading>& out, std::uint64_t seed, Nanos end) {
  std::mt19937_64 rng(seed ^ 0x5eedU);
  for (Nanos at = 0_us; at < end; at += microseconds(std::uniform_int_distribution<int>(1, 300)(rng))) {
    const Nanos when = std::uniform_int_distribution<int>(0, 1)(rng) == 0 ? at : (at / 10_us) * 10_us;
    b.scheduler().at(when, [&b, &out, when] { out.push_back(read(b.device(), when)); });
  }
}

TEST(ScanSkippingMotion, RandomProgramsAndMotionGiveTheOraclesEdgesAndWords) {
  constexpr Nanos kEnd = 400_ms;
  std::uint64_t skipped_scans = 0;
  std::uint64_t oracle_scans = 0;
  for (std::uint64_t seed = 1; seed <= 24; ++seed) {
    SCOPED_TRACE(seed);
    Bench oracle(every_period());
    Bench skipping;
    std::vector<Reading> oracle_readings;
    std::vector<Reading> skipping_readings;
    Scenario(seed).apply(oracle, kEnd);
    Scenario(seed).apply(skipping, kEnd);
    sample(oracle, oracle_readings, seed, kEnd);
    sample(skipping, skipping_readings, seed, kEnd);
    for (Nanos t = 0_ms; t <= kEnd; t += 7_ms) { // and from outside events, between runs
      oracle.run_until(t);
      skipping.run_until(t);
      ASSERT_EQ(read(oracle.device(), t), read(skipping.device(), t));
    }
    ASSERT_EQ(oracle_readings.size(), skipping_readings.size());
    for (std::size_t i = 0; i < oracle_readings.size(); ++i) {
      ASSERT_EQ(oracle_readings[i], skipping_readings[i]) << i;
    }
    for (int n = 1; n <= kOutputCount; ++n) {
      ASSERT_EQ(oracle.edges(n), skipping.edges(n)) << "output " << n;
    }
    oracle_scans += oracle.device().scans();
    skipped_scans += skipping.device().scans();
  }
  EXPECT_LT(skipped_scans, oracle_scans); // the comparison ran on a skipping engine
}

// Input edges that no output channel reads (docs/virtual-time.md, "Input edges"): the random
// programs above with die-protection monitors (random mode, action, windows and fault outputs)
// on inputs 7..12 and dense pulse trains on them (half periods 1..60 us: several edges
// between two scans, an edge every scan, or a level held over a few scans), now and then on a
// channel's ANDing input (1..3) or the shift register's (5), under the random motion: every
// output edge and every value read (die counts, first to fault, edge positions, inputs) is the
// oracle's, and the skipping engine left the channels alone in some of its scans.
TEST(ScanSkippingMotion, DieProtectionTrainsGiveTheOraclesEdgesAndWords) {
  constexpr Nanos kEnd = 300_ms;
  std::uint64_t held = 0;
  for (std::uint64_t seed = 1; seed <= 16; ++seed) {
    SCOPED_TRACE(seed);
    Bench oracle(every_period());
    Bench skipping;
    std::array<std::vector<Reading>, 2> readings;
    const std::array<Bench*, 2> benches{&oracle, &skipping};
    for (std::size_t k = 0; k < benches.size(); ++k) {
      Bench& b = *benches[k];
      Scenario(seed, seed % 3 != 0).apply(b, kEnd); // every third at standstill
      std::mt19937_64 rng(seed * 7919U);
      const auto pick = [&rng](int lo, int hi) { return std::uniform_int_distribution<int>(lo, hi)(rng); };
      const int fsc = b.device().position_setup().full_scale_count;
      MonitorSetup m = b.device().monitors().setup();
      for (int input = 7; input <= 12; ++input) {
        DieMonitorSetup& die = m.die.monitors[static_cast<std::size_t>(input - 1)];
        die.mode = static_cast<DieCheckMode>(pick(1, 5));
        die.action = static_cast<DieActionMode>(pick(0, 3));
        die.fault_output = static_cast<std::uint8_t>(pick(0, 1) == 0 ? 0 : pick(8, 13));
        if (pick(0, 1) == 0) {
          die.windows[0] = DieWindow{static_cast<std::uint16_t>(pick(0, fsc - 1)),
                                     static_cast<std::uint16_t>(pick(0, fsc - 1))};
        }
      }
      b.device().configure_monitors(m);
      for (int train = 0; train < 12; ++train) {
        const int r = pick(0, 9);
        const int input = r == 0 ? pick(1, 3) : (r == 1 ? 5 : pick(7, 12));
        const Nanos half = Nanos{pick(1'000, 60'000)};
        Nanos at = microseconds(pick(0, static_cast<int>(kEnd / 1_us) - 1));
        bool level = true;
        for (int e = pick(2, 3000); e > 0 && at < kEnd; --e, at += half) {
          b.input_at(at, input, level);
          level = !level;
        }
        b.input_at(at, input, false);
      }
      sample(b, readings[k], seed, kEnd);
    }
    for (Nanos t = 0_ms; t <= kEnd; t += 7_ms) {
      oracle.run_until(t);
      skipping.run_until(t);
      ASSERT_EQ(read(oracle.device(), t), read(skipping.device(), t));
    }
    ASSERT_EQ(readings[0].size(), readings[1].size());
    for (std::size_t i = 0; i < readings[0].size(); ++i) {
      ASSERT_EQ(readings[0][i], readings[1][i]) << i;
    }
    for (int n = 1; n <= kOutputCount; ++n) {
      ASSERT_EQ(oracle.edges(n), skipping.edges(n)) << "output " << n;
    }
    EXPECT_EQ(oracle.device().scans_channels_held(), 0U);
    held += skipping.device().scans_channels_held();
  }
  EXPECT_GT(held, 0U); // the channels were left alone in some scans
}

// A sampled encoder (docs/virtual-time.md, "Lines carry waveforms"): the device takes no edge,
// it asks the waveform for the count and for the time the count leaves its quiet interval. Under
// random programs and random motion profiles (trapezoids, ramps through zero, pauses,
// reversals) and a power cycle, every output edge and every value read is the oracle's, and
// the skipping engine's that takes every edge.
TEST(ScanSkippingMotion, SampledEncoderGivesTheOraclesEdgesAndWords) {
  constexpr Nanos kEnd = 250_ms;
  for (std::uint64_t seed = 1; seed <= 16; ++seed) {
    SCOPED_TRACE(seed);
    const signals::MotionProfile motion = signals::testing::random_motion(seed, kEnd);
    signals::QuadratureEncoder encoder;
    encoder.units_per_turn = static_cast<double>(encoder.counts_per_turn()); // a profile in counts
    encoder.placement = signals::EdgePlacement::WholeCount;
    const signals::QuadratureTrace edges = signals::solve_quadrature(motion, encoder, kEnd);
    signals::QuadratureWaveform waveform(motion, encoder, kEnd);
    Bench oracle(every_period());
    Bench skipping;
    Bench sampled({}, Variant::Correct, &waveform);
    std::array<std::vector<Reading>, 3> readings;
    const std::array<Bench*, 3> benches{&oracle, &skipping, &sampled};
    for (std::size_t k = 0; k < benches.size(); ++k) {
      Bench& b = *benches[k];
      Scenario(seed, false).apply(b, kEnd);
      b.play(edges);
      sample(b, readings[k], seed, kEnd);
      if (seed % 2 == 0) { // the count starts again at 0 from the lines' state at power-up (A36)
        b.scheduler().at(150_ms, [&b] { b.device().power_off(); });
        b.scheduler().at(150_ms + microseconds(static_cast<int>(seed) * 37), [&b] { b.device().power_on(); });
      }
    }
    for (Nanos t = 0_ms; t <= kEnd; t += 7_ms) {
      for (Bench* b : benches) {
        b->run_until(t);
      }
      ASSERT_EQ(read(oracle.device(), t), read(sampled.device(), t));
      ASSERT_EQ(read(skipping.device(), t), read(sampled.device(), t));
      ASSERT_EQ(oracle.device().transducer_count(), sampled.device().transducer_count());
    }
    for (std::size_t k = 1; k < benches.size(); ++k) {
      ASSERT_EQ(readings[0].size(), readings[k].size());
      for (std::size_t i = 0; i < readings[0].size(); ++i) {
        ASSERT_EQ(readings[0][i], readings[k][i]) << "bench " << k << ", reading " << i;
      }
    }
    for (int n = 1; n <= kOutputCount; ++n) {
      ASSERT_EQ(oracle.edges(n), sampled.edges(n)) << "output " << n;
      ASSERT_EQ(skipping.edges(n), sampled.edges(n)) << "output " << n;
    }
    EXPECT_LT(sampled.device().scans(), oracle.device().scans()); // it skipped
  }
}

// A quadrature master of 4,096 counts a turn, programmed by `program`, turned 3 turns at 1,800
// RPM (a 1,024-line encoder: one count per 8.14 us, more than one per 10 us scan) from 1 ms on,
// 100 ms, and run to 102 ms.
template <class Program> void three_turns_at_1800_rpm(Bench& b, const Program& program) {
  PositionSetup p = b.device().position_setup();
  p.sensor = SensorType::Quadrature;
  p.counts_per_cycle = 4096;
  p.full_scale_count = 4096;
  b.device().configure_position(p);
  program(b.device());
  b.quadrature_run(1_ms, 8'138_ns, 12'288, 1);
  b.run_until(102_ms);
}

TEST(ScanSkippingMotion, SteadyMotionScansAtOutputChangesNotEveryPeriod) {
  // 16 outputs each on for 200 of every 4,096 counts, no advance: 32 output changes per turn.
  Bench oracle(every_period());
  Bench skipping;
  for (Bench* b : {&oracle, &skipping}) {
    three_turns_at_1800_rpm(*b, [](auto& device) {
      for (int n = 1; n <= kOutputCount; ++n) {
        OutputSetup o;
        o.pairs[0] = SetpointPair{static_cast<std::uint16_t>(256 * (n - 1) + 1),
                                  static_cast<std::uint16_t>(256 * (n - 1) + 201), 0, 0};
        o.ls_offset = n % 2 == 1 ? 4000 : 0; // odd outputs 96 counts late: LS = GMP + 4000 mod 4096
        device.configure_output(n, o);
      }
    });
  }
  for (int n = 1; n <= kOutputCount; ++n) {
    ASSERT_EQ(oracle.edges(n), skipping.edges(n)) << "output " << n;
    EXPECT_EQ(oracle.edges(n).size(), 6U) << "output " << n; // on and off once per turn
  }
  // ans1 manual (seeds/000_08a2edf5547d4d1e.txt L572-L576, docs/spec/ans1.md L187): a master
  // scans every 10 us: t = 0, 10 us, ..., 102 ms.
  EXPECT_EQ(oracle.device().scans(), 10'201U);
  // About one scan per output change and per roll-over, not one per 10 us.
  EXPECT_LT(skipping.device().scans(), 16U * 2U * 3U + 3U + 40U);
}

// A stitched pair (L862-L873) narrows the quiet interval to the On or Off of its pattern the GMP
// is in, not to the GMP itself: a scan per stitch edge, not per count. 1,800 RPM on a 1,024-line
// encoder (one count per 8.14 us), output 1 stitched On 40 Off 24 over [1000, 1640): 10 Ons
// (L866: L = 64 * 10 = 640) and 20 edges per turn, plus its span's ends; output 2 stitched with a
// half On left over (On 40 Off 24, L 660: r = 20 >= On/2, on to the end, L872) and an LS offset.
TEST(ScanSkippingMotion, StitchedPairsScanAtStitchEdgesNotEveryCount) {
  Bench oracle(every_period());
  Bench skipping;
  for (Bench* b : {&oracle, &skipping}) {
    three_turns_at_1800_rpm(*b, [](auto& device) {
      OutputSetup one;
      one.pairs[0] = SetpointPair{1000, 1640, 40, 24};
      device.configure_output(1, one);
      OutputSetup two;
      two.pairs[0] = SetpointPair{3000, 3660, 40, 24};
      two.ls_offset = 100;
      device.configure_output(2, two);
    });
  }
  for (int n = 1; n <= 2; ++n) {
    ASSERT_EQ(oracle.edges(n), skipping.edges(n)) << "output " << n;
  }
  EXPECT_EQ(oracle.edges(1).size(), 3U * 20U); // 10 Ons a turn, 3 turns
  EXPECT_EQ(oracle.edges(2).size(), 3U * 22U); // 10 full Ons and the half On on to the end
  EXPECT_EQ(oracle.device().scans(), 10'201U);
  // About one scan per output change and per roll-over: 126 changes, 3 roll-overs. Pinned to
  // the GMP it scanned at every count: 12,288.
  EXPECT_LT(skipping.device().scans(), 3U * (20U + 22U) + 3U + 60U);
}

// Stators as the rig's resolver node drives them (rig/campaign/resolver_link.hpp): each frame
// holds the shaft's angle and speed at its arrival, the stators carry that angle extrapolated at
// that speed until the next frame, and nothing once no frame came for the timeout. Each frame
// revises both channels from its arrival on (AnalogChannel::Future::Revised). Fault windows set
// a stator's transformation ratio (an open coil 0, a ratio out of range).
class FramedStators {
public:
  FramedStators(Bench& b, std::uint64_t seed, const signals::MotionProfile& motion, Nanos end) {
    std::mt19937_64 rng(seed ^ 0xf4a3e5U);
    const auto pick = [&rng](int lo, int hi) { return std::uniform_int_distribution<int>(lo, hi)(rng); };
    for (int k = pick(0, 3); k > 0; --k) {
      const Nanos at = microseconds(pick(0, static_cast<int>(end / 1_us)));
      const std::array<double, 4> ratios{0.0, 0.5, 0.7, 1.4}; // the model's band is 0.75 .. 1.25
      windows_.push_back({at, at + microseconds(pick(50, 30'000)), pick(0, 2),
                          ratios[static_cast<std::size_t>(pick(0, 3))]});
    }
    const ResolverExcitation& ex = b.device().excitation();
    virt::AnalogChannel& sin = b.bus().analog("ans1.SIN");
    virt::AnalogChannel& cos = b.bus().analog("ans1.COS");
    sin.set_waveform([this, &ex](Nanos t) { return stator(ex, t, 0); }, virt::AnalogChannel::Future::Revised);
    cos.set_waveform([this, &ex](Nanos t) { return stator(ex, t, 1); }, virt::AnalogChannel::Future::Revised);
    for (Nanos t = 0_us; t < end;) {
      b.scheduler().at(t, [this, &motion, &sin, &cos, t] {
        // The speed rounded as a frame carries it: the extrapolation drifts from the shaft.
        frames_.push_back({t, motion.position(t), std::round(motion.velocity(t) / 64.0) * 64.0});
        sin.revise();
        cos.revise();
      });
      t += pick(0, 20) == 0 ? microseconds(pick(5'000, 9'000)) : microseconds(pick(1, 3'000));
    }
  }

private:
  struct Frame {
    Nanos at;
    double counts;
    double counts_per_s;
  };
  struct Window {
    Nanos at;
    Nanos until;
    int stators; // 0 sine, 1 cosine, 2 both
    double ratio;
  };
  static constexpr Nanos kTimeout = 5_ms;

  [[nodiscard]] double stator(const ResolverExcitation& ex, Nanos t, int which) const {
    const auto after = std::upper_bound(frames_.begin(), frames_.end(), t,
                                        [](Nanos at, const Frame& f) { return at < f.at; });
    if (after == frames_.begin() || t - std::prev(after)->at >= kTimeout) {
      return 0.0;
    }
    const Frame& f = *std::prev(after);
    double ratio = 0.95;
    for (const Window& w : windows_) {
      if (t >= w.at && t < w.until && (w.stators == 2 || w.stators == which)) {
        ratio = w.ratio;
      }
    }
    const double turns = (f.counts + f.counts_per_s * (t - f.at).seconds()) / 4096.0;
    const double angle = 2.0 * std::numbers::pi * turns;
    return ratio * ex.value(t) * (which == 0 ? std::sin(angle) : std::cos(angle));
  }

  std::vector<Frame> frames_;
  std::vector<Window> windows_;
};

// A resolver read ahead (docs/virtual-time.md, "Lines carry waveforms"): the device reads the
// excitation peaks before their scans and wakes at the first whose reading changes the fault
// flags or takes the GMP out of its quiet interval. Under random programs (count direction,
// HoldOuts, fault latching, Clear Errors), random motion profiles, frames at random intervals
// (and gaps beyond the timeout), open and out-of-range stators and a power cycle, every output
// edge, every value read and the transducer count are the per-peak oracle's: a wake one peak
// late differs.
TEST(ScanSkippingMotion, ResolverReadAheadGivesTheOraclesEdgesAndWords) {
  constexpr Nanos kEnd = 250_ms;
  std::uint64_t oracle_scans = 0;
  std::uint64_t skipped_scans = 0;
  for (std::uint64_t seed = 1; seed <= 16; ++seed) {
    SCOPED_TRACE(seed);
    const signals::MotionProfile motion = signals::testing::random_motion(seed, kEnd);
    Bench oracle(every_period());
    Bench skipping;
    std::array<std::vector<Reading>, 2> readings;
    const std::array<Bench*, 2> benches{&oracle, &skipping};
    std::vector<std::unique_ptr<FramedStators>> stators;
    for (std::size_t k = 0; k < benches.size(); ++k) {
      Bench& b = *benches[k];
      Scenario(seed, false, SensorType::Resolver).apply(b, kEnd);
      std::mt19937_64 rng(seed);
      PositionSetup p = b.device().position_setup();
      p.count_ccw = (rng() & 1U) != 0;
      p.hold_outputs_on_fault = (rng() & 2U) != 0;
      p.fault_auto_clear = (rng() & 4U) != 0;
      b.device().configure_position(p);
      stators.push_back(std::make_unique<FramedStators>(b, seed, motion, kEnd));
      for (Nanos at = microseconds(static_cast<int>(rng() % 40'000)); at < kEnd;
           at += microseconds(static_cast<int>(1 + rng() % 40'000))) {
        b.scheduler().at(at, [&b] { b.device().clear_errors(); });
      }
      sample(b, readings[k], seed, kEnd);
      if (seed % 2 == 0) { // the resolver is read afresh after power-up (L768)
        b.scheduler().at(150_ms, [&b] { b.device().power_off(); });
        b.scheduler().at(150_ms + microseconds(static_cast<int>(seed) * 37), [&b] { b.device().power_on(); });
      }
    }
    for (Nanos t = 0_ms; t <= kEnd; t += 7_ms) {
      for (Bench* b : benches) {
        b->run_until(t);
      }
      ASSERT_EQ(read(oracle.device(), t), read(skipping.device(), t));
      ASSERT_EQ(oracle.device().transducer_count(), skipping.device().transducer_count());
      ASSERT_EQ(oracle.device().resolver_fault(), skipping.device().resolver_fault());
    }
    ASSERT_EQ(readings[0].size(), readings[1].size());
    for (std::size_t i = 0; i < readings[0].size(); ++i) {
      ASSERT_EQ(readings[0][i], readings[1][i]) << "reading " << i;
    }
    for (int n = 1; n <= kOutputCount; ++n) {
      ASSERT_EQ(oracle.edges(n), skipping.edges(n)) << "output " << n;
    }
    oracle_scans += oracle.device().scans();
    skipped_scans += skipping.device().scans();
  }
  // It read ahead: far fewer scans than one per excitation peak (5 kHz: 2,500 peaks a run).
  EXPECT_LT(skipped_scans, oracle_scans / 10);
}

// The walk reads through the first peak at or after the next revision expected (a gap between
// the last two after the last one), so a revision drops one or two peaks read beyond it. A
// standing shaft, frames 990 us and 1010 us apart by turns (as a frame's stuff bits move its
// arrival) for 100 ms: 1,000 peaks (5 kHz, two a period). Per frame at most 2 peaks are read
// again -- the peak at or after the expected revision when the frame comes before it, or the
// 2 of the walk on when it comes after -- and 16 before the second frame: at most
// 1,000 + 2 * 100 + 16 sine reads. (Walking as many peaks as came between the last two frames
// plus one, a 990 us gap walked 10 peaks and stopped short of the next frame, then read 10 more
// that the frame dropped: ~1,500.)
TEST(ScanSkippingMotion, AResolverWalkReadsPeaksOnceAndOneOrTwoAgainAFrame) {
  Bench b;
  const ResolverExcitation& ex = b.device().excitation();
  std::uint64_t sine_reads = 0;
  constexpr double kAngle = 0.3; // rad
  virt::AnalogChannel& sin = b.bus().analog("ans1.SIN");
  virt::AnalogChannel& cos = b.bus().analog("ans1.COS");
  sin.set_waveform(
      [&](Nanos t) {
        ++sine_reads;
        return 0.95 * ex.value(t) * std::sin(kAngle);
      },
      virt::AnalogChannel::Future::Revised);
  cos.set_waveform([&](Nanos t) { return 0.95 * ex.value(t) * std::cos(kAngle); },
                   virt::AnalogChannel::Future::Revised);
  int frames = 0;
  for (Nanos t = 230_us; t < 100_ms; t += (frames % 2 == 0 ? 990_us : 1010_us)) {
    ++frames;
    b.scheduler().at(t, [&sin, &cos] {
      sin.revise();
      cos.revise();
    });
  }
  b.run_until(100_ms);
  ASSERT_EQ(frames, 100);
  EXPECT_GT(b.device().transducer_count(), 0); // read: 0.3 rad is count 195
  EXPECT_FALSE(b.device().resolver_fault());
  EXPECT_LT(b.device().scans(), 100U); // skipping: the walk did the reading
  EXPECT_GE(sine_reads, 1'000U);
  EXPECT_LE(sine_reads, 1'000U + 2U * 100U + 16U);
}

} // namespace
} // namespace hilrig::models::ans1
