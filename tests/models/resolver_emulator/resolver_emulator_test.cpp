// The resolver-emulator node on a virtual CAN bus at 500 kbit/s, fed by the rig's angle
// streamer, its stators sampled as an ADC would and read back with an R/D converter.
//
// Frame latency, worked out from the frame's bits on the bus: a ResolverAngle frame is a
// classic base-ID data frame of 8 bytes: SOF 1 + ID 11 + RTR 1 + IDE 1 + r0 1 + DLC 4 + data
// 64 + CRC 15 = 98 stuffed-region bits, + CRC delimiter, ACK, ACK delimiter 3 + EOF 7 = 108
// bits up to the end of EOF, when receivers take it (ISO 11898-1; the intermission follows),
// plus the stuff bits the frame's own bit stream needs (counted by virt::can_frame_bits).
// With the bus idle, the frame sent at t reaches the node at t + (108 + stuff) * 2 us, and
// the node holds the frame's angle at that instant: its angle lags the profile by that time.

#include <gtest/gtest.h>

#include <cmath>
#include <cstdint>
#include <functional>
#include <numbers>
#include <optional>
#include <random>
#include <tuple>
#include <vector>

#include "core/scheduler.hpp"
#include "drivers/virtual/virtual_bus.hpp"
#include "models/resolver_emulator/angle_streamer.hpp"
#include "models/resolver_emulator/resolver_emulator.hpp"
#include "signals/move_builders.hpp"
#include "signals/rd_converter.hpp"
#include "signals/resolver_frames.hpp"

namespace hilrig::models::resolver_emulator {
namespace {

using namespace hilrig::literals;

constexpr double kQuarterCount = 0.25 / 4096.0; // 1/4 count at 12 bits, in turns
constexpr Nanos kBit = 2_us;                    // 500 kbit/s

double turn_error(double a, double b) {
  const double d = a - b;
  return d - std::round(d);
}

// The frame the streamer sends as its k-th (at k * period, from the profile at that time).
CanFrame frame_k(const signals::MotionProfile& p, std::int64_t k, Nanos period) {
  signals::ResolverAngleFrame f;
  const Nanos t = period * k;
  f.angle_turns = p.position(t);
  f.speed_turns_per_s = p.velocity(t);
  f.sequence = static_cast<std::uint8_t>(k & 0xF);
  return signals::encode(f);
}

// Send to receive time of a frame on an idle bus (see the top of the file).
Nanos latency(const CanFrame& frame) {
  const virt::CanFrameBits bits = virt::can_frame_bits(frame);
  return kBit * static_cast<std::int64_t>(108 + bits.stuff);
}

struct Rig {
  Scheduler scheduler;
  virt::VirtualBus bus{scheduler};
  virt::CanBus& can = bus.can("can0"); // 500 kbit/s by default
  CanPort& rig_port = can.attach("rig");
  CanPort& node_port = can.attach("resolver_emu");
  ResolverEmulator node;
  AngleStreamer streamer;

  Rig(const signals::MotionProfile& profile, ResolverEmulatorParams params = {})
      : node(scheduler, node_port, params), streamer(scheduler, rig_port, profile, {}) {
    bus.analog("res.ref").set_waveform(node.reference_waveform());
    bus.analog("res.sin").set_waveform(node.sin_waveform());
    bus.analog("res.cos").set_waveform(node.cos_waveform());
  }
  signals::ResolverSample adc(Nanos t) {
    return {t, bus.analog("res.ref").sample(t), bus.analog("res.sin").sample(t),
            bus.analog("res.cos").sample(t)};
  }
  // Peak |SIN| and |COS| over one 5 kHz carrier period from t, sampled every 1 us.
  std::pair<double, double> peaks(Nanos t) {
    double s = 0.0;
    double c = 0.0;
    for (Nanos u = t; u < t + 200_us; u += 1_us) {
      s = std::fmax(s, std::fabs(node.sin(u)));
      c = std::fmax(c, std::fabs(node.cos(u)));
    }
    return {s, c};
  }
};

signals::MotionProfile constant(double start_turns, double turns_per_s, Nanos duration) {
  signals::MotionProfile p(start_turns);
  signals::constant_speed(p, turns_per_s, duration);
  return p;
}

TEST(ResolverEmulator, RdConverterReadsTheProfileAngleAfterTheFrameLatency) {
  // 2 turn/s (120 rpm): the 216..264 us frame latency is 1.8..2.2 counts at 12 bits, well
  // beyond the 1/4-count tolerance, so the test also shows the latency is what the node adds.
  // (Faster, the stuff bits' frame-to-frame latency jitter shows: each frame steps the angle
  // by speed * (L_k+1 - L_k), up to 24 bits = 48 us, which the R/D loop smooths over; at
  // 5 turn/s that alone is ~0.2 count.)
  const double speed = 2.0;
  const signals::MotionProfile profile = constant(0.1, speed, 400_ms);
  Rig rig(profile);
  rig.streamer.start(Nanos{0});

  signals::RdParams rd_params; // 5 kHz, phase 0, TR 1: the node's defaults
  signals::RdConverter rd(rd_params);
  double worst = 0.0;
  double closest_undelayed = 1.0;
  std::size_t checks = 0;
  // An ADC at 200 kHz (40 samples a carrier period) from the scheduler, as a capture would.
  std::function<void(Nanos)> sample = [&](Nanos t) {
    const std::size_t before = rd.updates();
    rd.feed(rig.adc(t));
    if (t == 100_ms) rd.clear_faults(); // loss of signal before the first frame; settled since
    if (rd.updates() != before && t > 100_ms) {
      const Nanos at = rd.last_update();
      // The frame in force at `at`: the last one received by then.
      std::int64_t k = at.count() / 1'000'000;
      Nanos lag = latency(frame_k(profile, k, 1_ms));
      if (1_ms * k + lag > at) lag = latency(frame_k(profile, --k, 1_ms));
      worst = std::fmax(worst, std::fabs(turn_error(rd.angle_turns(), profile.position(at - lag))));
      closest_undelayed =
          std::fmin(closest_undelayed, std::fabs(turn_error(rd.angle_turns(), profile.position(at))));
      ++checks;
    }
    if (t + 5_us <= 300_ms) rig.scheduler.at(t + 5_us, [&sample, t] { sample(t + 5_us); });
  };
  rig.scheduler.at(Nanos{0}, [&sample] { sample(Nanos{0}); });
  rig.scheduler.run_until(300_ms);

  EXPECT_GT(checks, 900u); // 5 kHz windows for 200 ms
  EXPECT_LE(worst, kQuarterCount) << "worst " << worst * 4096.0 << " counts";
  // Without the latency the angle is never closer than 2 turn/s * 216 us (1.77 counts) less the
  // jitter, and at most 2.16 counts off (264 us): 2 turn/s * 216..264 us * 4096.
  EXPECT_GT(closest_undelayed, 1.7 / 4096.0);
  EXPECT_LT(closest_undelayed, 2.2 / 4096.0);
  EXPECT_FALSE(rd.latched().any());
  // The latency jitter's angle steps are a small speed ripple to the loop.
  EXPECT_NEAR(rd.velocity_turns_per_s(), speed, 1e-2);
  // Sent at 0, 1, ..., 300 ms; the one sent at 300 ms is still on the bus.
  EXPECT_EQ(rig.node.counters().frames, 300u);
  EXPECT_EQ(rig.node.counters().sequence_gaps, 0u);
  EXPECT_EQ(rig.node.counters().timeouts, 0u);
}

TEST(ResolverEmulator, FramesArriveAfterTheirBitsToEndOfFrame) {
  const signals::MotionProfile profile = constant(0.0, 2.0, 100_ms);
  Rig rig(profile);
  std::vector<Nanos> received;
  rig.can.attach("monitor").on_receive([&](const CanFrame&, Nanos at) { received.push_back(at); });
  rig.streamer.start(Nanos{0});
  rig.scheduler.run_until(10_ms + 500_us);
  ASSERT_EQ(received.size(), 11u);
  for (std::int64_t k = 0; k < 11; ++k) {
    const CanFrame f = frame_k(profile, k, 1_ms);
    EXPECT_EQ(received[static_cast<std::size_t>(k)], 1_ms * k + latency(f));
    // 108 + stuff bits: at least 216 us, and within the 8-byte worst case (24 stuff bits).
    EXPECT_GE(latency(f), 216_us);
    EXPECT_LE(latency(f), 264_us);
  }
  // The node holds frame k's angle at its receive time.
  const auto last = rig.node.last_frame();
  ASSERT_TRUE(last.has_value());
  EXPECT_EQ(last->received, received.back());
  EXPECT_NEAR(last->angle_turns, 0.02, 1.0 / 16'777'216.0); // 2 turn/s * 10 ms
  EXPECT_EQ(last->speed_turns_per_s, 2.0);
}

TEST(ResolverEmulator, NoFrameForThreePeriodsDropsTheStatorsAndIsReported) {
  const signals::MotionProfile profile = constant(0.125, 1.0, 100_ms);
  Rig rig(profile);
  std::vector<Nanos> timeouts;
  rig.node.on_timeout([&](Nanos at) { timeouts.push_back(at); });
  rig.streamer.start(Nanos{0});
  // Frames at 0..9 ms, then the rig stops streaming.
  rig.scheduler.at(9_ms + 500_us, [&] { rig.streamer.stop(); });
  const Nanos last_rx = 9_ms + latency(frame_k(profile, 9, 1_ms));
  const Nanos deadline = last_rx + 3_ms; // timeout_periods 3 of a 1 ms frame period
  rig.scheduler.run_until(deadline - 1_ns);
  EXPECT_FALSE(rig.node.timed_out());
  EXPECT_TRUE(rig.node.angle_turns(deadline - 1_ns).has_value());
  // Still driving: 0.125 turn + 1 turn/s is ~45 deg, both envelopes ~0.7.
  EXPECT_GT(rig.peaks(deadline - 300_us).first, 0.5);
  rig.scheduler.run_until(deadline + 5_ms);
  ASSERT_EQ(timeouts.size(), 1u);
  EXPECT_EQ(timeouts[0], deadline);
  EXPECT_TRUE(rig.node.timed_out());
  EXPECT_EQ(rig.node.counters().timeouts, 1u);
  EXPECT_FALSE(rig.node.angle_turns(deadline).has_value());
  const auto [sin_peak, cos_peak] = rig.peaks(deadline);
  EXPECT_EQ(sin_peak, 0.0);
  EXPECT_EQ(cos_peak, 0.0);
  EXPECT_NE(rig.node.reference(deadline + 50_us), 0.0); // the excitation itself runs on
  // Streaming again: the next frame restores the outputs and clears the timeout.
  const Nanos restart = deadline + 5_ms;
  rig.streamer.start(restart);
  rig.scheduler.run_until(restart + 1_ms);
  EXPECT_FALSE(rig.node.timed_out());
  EXPECT_GT(rig.peaks(restart + 500_us).first, 0.5);
  EXPECT_EQ(rig.node.counters().timeouts, 1u);
}

TEST(ResolverEmulator, FaultFlagsInTheFrameOpenTheWindings) {
  // Standing at 1/8 turn (45 deg): both envelopes sin 45 = cos 45 = 0.7071 (TR 1, 1 V).
  const signals::MotionProfile profile = constant(0.125, 0.0, 100_ms);
  Rig rig(profile);
  rig.streamer.start(Nanos{0});
  rig.scheduler.run_until(1_ms);
  auto [s, c] = rig.peaks(500_us);
  EXPECT_NEAR(s, std::sqrt(0.5), 1e-3);
  EXPECT_NEAR(c, std::sqrt(0.5), 1e-3);
  // SIN open from the frame sent at 2 ms (received ~2.22 ms).
  rig.scheduler.run_until(1_ms + 500_us);
  rig.streamer.set_open_windings(true, false);
  rig.scheduler.run_until(2_ms + 500_us);
  std::tie(s, c) = rig.peaks(2_ms + 500_us);
  EXPECT_EQ(s, 0.0);
  EXPECT_NEAR(c, std::sqrt(0.5), 1e-3);
  // Before that frame arrived SIN was still driven (the history holds the earlier frame).
  EXPECT_NEAR(rig.peaks(1_ms + 500_us).first, std::sqrt(0.5), 1e-3);
  rig.streamer.set_open_windings(false, true);
  rig.scheduler.run_until(3_ms + 500_us);
  std::tie(s, c) = rig.peaks(3_ms + 500_us);
  EXPECT_NEAR(s, std::sqrt(0.5), 1e-3);
  EXPECT_EQ(c, 0.0);
  // valid = 0: safe state, both stators zero, no angle.
  rig.streamer.set_open_windings(false, false);
  rig.streamer.set_valid(false);
  rig.scheduler.run_until(4_ms + 500_us);
  std::tie(s, c) = rig.peaks(4_ms + 500_us);
  EXPECT_EQ(s, 0.0);
  EXPECT_EQ(c, 0.0);
  EXPECT_FALSE(rig.node.angle_turns(4_ms + 500_us).has_value());
  EXPECT_EQ(rig.node.counters().frames, 5u);
}

TEST(ResolverEmulator, DroppedFramesAreCountedAsSequenceGaps) {
  const signals::MotionProfile profile = constant(0.0, 3.0, 100_ms);
  Rig rig(profile);
  // Lose frame 5 (sequence 5) and frame 20 (sequence 4 of the second round): each leaves a
  // 2 ms gap, inside the 3-period timeout, so the node keeps driving and counts the gaps.
  std::uint64_t seen = 0;
  rig.can.set_drop([&](const CanFrame&) {
    const auto k = seen++;
    return k == 5 || k == 20 || (k >= 30 && k <= 32);
  });
  rig.streamer.start(Nanos{0});
  rig.scheduler.run_until(29_ms + 500_us); // frames 0..29 received or dropped
  const ResolverEmulatorCounters& n = rig.node.counters();
  EXPECT_EQ(rig.can.frames_dropped(), 2u);
  EXPECT_EQ(n.frames, 28u);
  EXPECT_EQ(n.sequence_gaps, 2u);
  EXPECT_EQ(n.lost_frames, 2u);
  EXPECT_EQ(n.timeouts, 0u);
  // Frames 30..32 lost: a 4 ms silence is a timeout instead; the sequence starts afresh
  // with frame 33 (the loss is reported once, as the timeout).
  rig.scheduler.run_until(39_ms + 500_us);
  EXPECT_EQ(rig.can.frames_dropped(), 5u);
  EXPECT_EQ(n.frames, 35u);
  EXPECT_EQ(n.timeouts, 1u);
  EXPECT_EQ(n.sequence_gaps, 2u);
  EXPECT_FALSE(rig.node.timed_out());
}

TEST(ResolverEmulator, OtherFramesAreIgnoredAndBadOnesCounted) {
  const signals::MotionProfile profile = constant(0.0, 0.0, 100_ms);
  Rig rig(profile);
  CanPort& other = rig.can.attach("other");
  signals::ResolverAngleFrame f;
  f.channel = 1; // another node's channel
  other.send(signals::encode(f));
  CanFrame short_frame = signals::encode(signals::ResolverAngleFrame{});
  short_frame.len = 4; // 0x120 but not 8 bytes
  other.send(short_frame);
  CanFrame report = signals::encode(signals::EdgeReportFrame{});
  other.send(report);
  rig.scheduler.run_until(5_ms);
  const ResolverEmulatorCounters& n = rig.node.counters();
  EXPECT_EQ(n.other_channel, 1u);
  EXPECT_EQ(n.bad_frames, 1u);
  EXPECT_EQ(n.other_ids, 1u);
  EXPECT_EQ(n.frames, 0u);
  EXPECT_FALSE(rig.node.last_frame().has_value());
  EXPECT_EQ(rig.node.sin(1_ms + 50_us), 0.0); // never driven
  EXPECT_EQ(n.timeouts, 0u);                  // no timeout before the first frame
}

TEST(ResolverEmulator, RejectsBadParameters) {
  Scheduler scheduler;
  virt::VirtualBus bus{scheduler};
  CanPort& port = bus.can("can0").attach("n");
  ResolverEmulatorParams p;
  p.excitation_hz = 10'000.0;
  EXPECT_THROW(ResolverEmulator(scheduler, port, p), std::invalid_argument);
  p = {};
  p.channel = 16;
  EXPECT_THROW(ResolverEmulator(scheduler, port, p), std::invalid_argument);
  p = {};
  p.timeout_periods = 0;
  EXPECT_THROW(ResolverEmulator(scheduler, port, p), std::invalid_argument);
}

} // namespace
} // namespace hilrig::models::resolver_emulator

namespace hilrig::models::resolver_emulator {
namespace {

TEST(ResolverEmulator, StandingShaftAtAnyAngleAndUnit) {
  // Property, seeded: a profile in ANS1 counts (4096 a turn) standing at a random count; the
  // node's angle is count/4096 (to the frame's 2^-24 turn), and at the reference peak
  // (t = 50 us into a 5 kHz period) SIN = sin(2*pi*angle) and COS = cos(2*pi*angle) (TR 1, 1 V).
  std::mt19937 rng(20261122u);
  std::uniform_int_distribution<int> count(0, 4095);
  for (int trial = 0; trial < 20; ++trial) {
    const double c = static_cast<double>(count(rng));
    signals::MotionProfile profile(c);
    profile.dwell(50_ms);
    Scheduler scheduler;
    virt::VirtualBus bus{scheduler};
    virt::CanBus& can = bus.can("can0");
    CanPort& rig_port = can.attach("rig");
    ResolverEmulator node(scheduler, can.attach("node"), {});
    AngleStreamParams sp;
    sp.units_per_turn = 4096.0;
    AngleStreamer streamer(scheduler, rig_port, profile, sp);
    streamer.start(Nanos{0});
    scheduler.run_until(2_ms);
    const double turns = c / 4096.0;
    const Nanos peak = 1_ms + 50_us;
    ASSERT_TRUE(node.angle_turns(peak).has_value());
    EXPECT_NEAR(*node.angle_turns(peak), turns, 1.0 / 16'777'216.0);
    EXPECT_NEAR(node.reference(peak), 1.0, 1e-12);
    EXPECT_NEAR(node.sin(peak), std::sin(2.0 * std::numbers::pi * turns), 1e-6);
    EXPECT_NEAR(node.cos(peak), std::cos(2.0 * std::numbers::pi * turns), 1e-6);
  }
}

} // namespace
} // namespace hilrig::models::resolver_emulator

namespace hilrig::models::resolver_emulator {
namespace {

// With the bus's transport known to the streamer (as the virtual rig knows it: rig/campaign/
// resolver_link.cpp), each frame carries the shaft at the frame's own end of frame, so the
// node's angle is the shaft's with no lag: the frame's angle code at or above the shaft, at
// most 15 codes above (1/2^24 turn each: signals/resolver_frames.hpp), plus the speed field's
// rounding (half of 1/4096 turn/s) times the time since the frame (< 1 ms + one frame time).
// A frame whose stuff bits made it one bit time (2 us) longer or shorter than it was built for
// would be off by speed * 2 us: 1e-4 turn at 50 turn/s, far beyond that bound. Swept over
// speeds, both directions, exact and inexact in the speed field.
TEST(ResolverEmulator, WithTheTransportKnownTheNodeHoldsTheShaftAngleWithoutLag) {
  constexpr double kCode = 1.0 / 16'777'216.0;
  for (const double speed : {0.0, 2.0, 1000.0 / 60.0, 50.0, 2997.90146897172 / 60.0, -7.3}) {
    SCOPED_TRACE(speed);
    const signals::MotionProfile profile = constant(0.37, speed, 400_ms);
    Rig rig(profile);
    const virt::CanBitTiming timing = rig.can.timing();
    rig.streamer.lead_by_transport(
        [timing](const CanFrame& f) { return virt::can_end_of_frame(virt::can_frame_bits(f), timing); },
        virt::can_end_of_frame_range(signals::encode(signals::ResolverAngleFrame{}), timing));
    rig.streamer.start(Nanos{0});
    const double speed_rounding = 0.5 / 4096.0 * (1_ms + 300_us).seconds();
    double lowest = 1.0;
    double highest = -1.0;
    for (Nanos t = 2_ms; t < 300_ms; t += 7_us) {
      rig.scheduler.run_until(t); // the node keeps the last 16 frames: read as the run goes
      const std::optional<double> a = rig.node.angle_turns(t);
      ASSERT_TRUE(a.has_value());
      const double d = turn_error(*a, profile.position(t));
      lowest = std::fmin(lowest, d);
      highest = std::fmax(highest, d);
    }
    EXPECT_GE(lowest, -speed_rounding);
    EXPECT_LT(highest, 16 * kCode + speed_rounding);
    EXPECT_EQ(rig.node.counters().sequence_gaps, 0U);
  }
}

// The range of a ResolverAngle frame's end of frame at 500 kbit/s: 108 bits with no stuff bit
// (the file's top) up to the worst case's stuff bits, one bit time (2 us) apart.
TEST(ResolverEmulator, EndOfFrameRangeOfAnAngleFrame) {
  const CanFrame frame = signals::encode(signals::ResolverAngleFrame{});
  const std::vector<Nanos> range = virt::can_end_of_frame_range(frame, virt::CanBitTiming{});
  ASSERT_GE(range.size(), 2U);
  EXPECT_EQ(range.front(), kBit * 108);
  for (std::size_t i = 1; i < range.size(); ++i) EXPECT_EQ(range[i] - range[i - 1], kBit);
  EXPECT_EQ(range.back(), kBit * static_cast<std::int64_t>(108 + virt::can_frame_bits_worst(frame).stuff));
  EXPECT_GE(range.back(), latency(frame));
}

} // namespace
} // namespace hilrig::models::resolver_emulator
