// Resolver stator signals from the campaign's motion: the waveforms by hand, the parser's
// checks of [resolver], and the virtual ANS1 on its default resolver path (no CB2) end to end.

#include <gtest/gtest.h>

#include <cmath>
#include <memory>
#include <numbers>
#include <optional>
#include <random>
#include <string>

#include "campaign_text.hpp"
#include "models/ans1/position_resolver.hpp"
#include "models/pls2700/position.hpp"
#include "rig/campaign/campaign_parser.hpp"
#include "rig/campaign/executive.hpp"
#include "rig/campaign/plant_motion.hpp"
#include "rig/campaign/resolver_link.hpp"
#include "rig/campaign/resolver_stators.hpp"
#include "test_support.hpp"

namespace hilrig::campaign {
namespace {

using test::error_of;

using namespace hilrig::literals;
using rig::Outcome;

TEST(ResolverStators, CarryTheExcitationTimesSinAndCosOfTheShaftAngle) {
  // A shaft standing at 90 of 360 counts (a quarter turn): sin = 1, cos = 0. At t = 50 us the
  // 5 kHz excitation is at its positive peak, at 150 us its negative peak, at 100 us zero.
  const auto standing = std::make_shared<const signals::MotionProfile>(90.0);
  ResolverSpec r;
  r.amplitude = 2.0;
  r.ratio = 0.9;
  const Waveform s = stator_waveform(standing, 360.0, r, Stator::Sine);
  const Waveform c = stator_waveform(standing, 360.0, r, Stator::Cosine);
  EXPECT_NEAR(s(50_us), 1.8, 1e-12);
  EXPECT_NEAR(s(150_us), -1.8, 1e-12);
  EXPECT_NEAR(s(100_us), 0.0, 1e-12);
  EXPECT_NEAR(c(50_us), 0.0, 1e-12);
}

TEST(ResolverStators, APhaseShiftsTheExcitation) {
  // phase_deg 90: the carrier is amplitude * cos(2 pi f t) (a board with a cosine reference,
  // the Series 2700 model): at 5 kHz its peaks are at 0, 100 us (negative), 200 us, and it
  // is zero at 50 us. Shaft at 90 of 360 counts: the sine stator carries the whole carrier.
  const auto standing = std::make_shared<const signals::MotionProfile>(90.0);
  ResolverSpec r;
  r.phase_deg = 90.0;
  const Waveform s = stator_waveform(standing, 360.0, r, Stator::Sine);
  EXPECT_NEAR(s(0_us), 1.0, 1e-12);
  EXPECT_NEAR(s(100_us), -1.0, 1e-12);
  EXPECT_NEAR(s(200_us), 1.0, 1e-12);
  EXPECT_NEAR(s(50_us), 0.0, 1e-12);
}

TEST(ResolverStators, APairIsBothStatorsFromOneCarrierAndAngle) {
  // 1 kHz, amplitude 2, ratio 0.5, 4096 counts a turn; the shaft at 512 counts (an eighth of a
  // turn, sin = cos = sqrt(1/2)); t = 250 us is the carrier's positive peak (sin(pi/2) = 1):
  // both stators 0.5 * 2 * sqrt(1/2). A fault window sets the sine's ratio to 0.25 in 0.2 ..
  // 0.3 ms: there the sine is half. Each value is the one its own form gives, to the bit.
  ResolverSpec r;
  r.excitation_hz = 1000.0;
  r.amplitude = 2.0;
  r.ratio = 0.5;
  const StatorForm s(4096.0, r, Stator::Sine, {{200_us, 300_us, 0.25}});
  const StatorForm c(4096.0, r, Stator::Cosine);
  const double half_root = std::sqrt(0.5);
  const StatorForm::Pair at_peak = StatorForm::pair(s, c, 250_us, 512.0);
  EXPECT_NEAR(at_peak.sin, 0.25 * 2.0 * half_root, 1e-12);
  EXPECT_NEAR(at_peak.cos, 0.5 * 2.0 * half_root, 1e-12);
  const StatorForm::Pair after = StatorForm::pair(s, c, 1250_us, 512.0); // a period on, no fault
  EXPECT_NEAR(after.sin, 0.5 * 2.0 * half_root, 1e-12);
  EXPECT_NEAR(after.cos, 0.5 * 2.0 * half_root, 1e-12);
  std::mt19937_64 rng(1127);
  for (int k = 0; k < 1000; ++k) {
    const Nanos t{static_cast<std::int64_t>(rng() % 1'000'000)};
    const double position = static_cast<double>(rng() % 100'000) / 7.0;
    const StatorForm::Pair p = StatorForm::pair(s, c, t, position);
    ASSERT_EQ(p.sin, s(t, position)) << t.count() << " " << position;
    ASSERT_EQ(p.cos, c(t, position)) << t.count() << " " << position;
  }
}

TEST(ResolverStators, DemodulatedAtAPeakGiveBackTheAngle) {
  // Property: at any excitation peak, atan2(sin, cos) is the shaft angle (seeded positions).
  std::mt19937_64 rng(42);
  std::uniform_real_distribution<double> counts(-5000.0, 5000.0);
  ResolverSpec r;
  for (int i = 0; i < 200; ++i) {
    const double at = counts(rng);
    const auto p = std::make_shared<const signals::MotionProfile>(at);
    const double s = stator_waveform(p, 400.0, r, Stator::Sine)(250_us); // 5 kHz: a peak
    const double c = stator_waveform(p, 400.0, r, Stator::Cosine)(250_us);
    const double turns = std::atan2(s, c) / (2.0 * std::numbers::pi);
    const double expected = at / 400.0 - std::floor(at / 400.0 + 0.5);
    EXPECT_NEAR(turns, expected, 1e-9) << at;
  }
}

// The ANS1 on its power-up resolver path (CPC 4096, FSC 360: W-02, W-03), output 1 on
// [100, 200). The motion is in counts of a 90-line encoder, 360 per turn, so the rig's count
// is the GMP. 100 RPM: 600 counts/s. The board reads its stators at each excitation peak
// (every 100 us at 5 kHz) and truncates to 12 bits: GMP 100 is raw 1138 (1137.8 = 100/360 of
// 4096), 0.02 counts late, plus up to 100 us of R/D lag and 20 us of throughput: 0.072 counts
// at 600 counts/s. So each edge is within 0.5 counts of its setpoint; GMP 100 comes at 167 and
// 767 ms, GMP 200 at 333 and 933 ms.
const std::string kResolver = R"([campaign]
name = "resolver"
end = "1000ms"
host_poll = "100us"
[dut]
model = "ans1"
[[wiring]]
rig = "res.sin"
board = "SIN"
[[wiring]]
rig = "res.cos"
board = "COS"
[[wiring]]
rig = "ls1"
board = "OUT1"
[resolver]
sin = "res.sin"
cos = "res.cos"
[encoder]
lines = 90
[motion]
[[motion.move]]
kind = "constant"
speed_rpm = 100
duration = "1000ms"
[[host]]
at = "10ms"
write = [0x0403, 1, 0, 0, 100, 200, 0, 0]
name = "cb3"
[[check]]
kind = "edge_at_position"
name = "on"
output = "ls1"
position = 100
level = "high"
tolerance_counts = 0.5
modulus = 360
min_edges = 2
[[check]]
kind = "edge_at_position"
name = "off"
output = "ls1"
position = 200
level = "low"
tolerance_counts = 0.5
modulus = 360
min_edges = 2
)";

// The 2700's fault band [min_stator_ratio, max_stator_ratio] is closed (models/pls2700/README.md,
// "Decoder"): a transducer whose stators are exactly 0.5 or 1.5 of the reference is good at every
// angle, whatever the rounding of the sampled sinusoids; a millionth beyond either limit faults.
TEST(ResolverStators, The2700RatioBandIsClosedAtEveryAngle) {
  const double reference = 3.3;
  const auto reading = [&](double ratio, double angle) {
    return models::pls2700::decode_stators(reference * ratio * std::sin(angle),
                                           reference * ratio * std::cos(angle), reference, 0.5, 1.5);
  };
  int bad_at_limit = 0;
  int good_beyond = 0;
  for (int k = 0; k < 100'000; ++k) {
    const double angle = 2.0 * std::numbers::pi * k / 100'000.0;
    for (const double at : {0.5, 1.5})
      if (!reading(at, angle).valid) ++bad_at_limit;
    for (const double beyond : {0.5 * (1.0 - 1e-6), 1.5 * (1.0 + 1e-6)})
      if (reading(beyond, angle).valid) ++good_beyond;
  }
  EXPECT_EQ(bad_at_limit, 0);
  EXPECT_EQ(good_beyond, 0);
  // One coil open: the other alone, |cos| of 60 degrees is the limit (pls2700_open_coil.toml).
  EXPECT_TRUE(
      models::pls2700::decode_stators(0.0, reference * std::cos(std::numbers::pi / 3.0), reference, 0.5, 1.5)
          .valid);
  EXPECT_FALSE(models::pls2700::decode_stators(0.0, reference * std::cos(std::numbers::pi / 3.0 + 1e-6),
                                               reference, 0.5, 1.5)
                   .valid);
}

// The ANS1's fault band resolver_min_ratio .. resolver_max_ratio (0.75 .. 1.25, [MODEL],
// models/ans1/README.md "Device faults") is closed the same way (the routine the 2700 uses):
// stators exactly at 0.75 or 1.25 of the reference are no Resolver Fault (L2299) at any angle
// nor at any excitation peak, positive or negative; 0.749 and 1.251 are one at every angle,
// 0.751 and 1.249 at none; the relative 1e-9 around each limit counts as at it, 1e-6 beyond not.
TEST(ResolverStators, TheAns1RatioBandIsClosedAtEveryAngle) {
  namespace a = models::ans1;
  const a::ResolverExcitation excitation(5'000.0, 1.0); // the model's default reference
  int bad_inside = 0;
  int good_beyond = 0;
  Nanos peak = excitation.next_peak(Nanos{0});
  for (int k = 0; k < 100'000; ++k, peak = excitation.next_peak(peak)) {
    const double angle = 2.0 * std::numbers::pi * k / 100'000.0;
    const double reference = excitation.value(peak); // the rig's stators carry this wave
    const auto valid = [&](double ratio) {
      return a::decode_resolver(ratio * reference * std::sin(angle), ratio * reference * std::cos(angle),
                                reference, 0.75, 1.25)
          .valid;
    };
    for (const double inside : {0.75, 1.25, 0.751, 1.249, 0.75 * (1.0 - 0.5e-9), 1.25 * (1.0 + 0.5e-9)})
      if (!valid(inside)) ++bad_inside;
    for (const double beyond : {0.749, 1.251, 0.75 * (1.0 - 1e-6), 1.25 * (1.0 + 1e-6)})
      if (valid(beyond)) ++good_beyond;
  }
  EXPECT_EQ(bad_inside, 0);
  EXPECT_EQ(good_beyond, 0);
}

TEST(ResolverStators, TheAns1FollowsTheResolverToItsSetpoints) {
  const Campaign c = parse_campaign(kResolver, "t.toml");
  const rig::CampaignResult r = test::run_everything(c);
  ASSERT_EQ(r.runs.size(), 1U);
  ASSERT_TRUE(r.runs[0].error.empty()) << r.runs[0].error;
  std::string got;
  for (const auto& ch : r.runs[0].checks)
    for (const auto& m : ch.measurements) got += m.name + " " + m.detail + "\n";
  EXPECT_EQ(r.verdict, Outcome::Pass) << got;
  const auto* on = test::find(r.runs[0], "on.edge0");
  ASSERT_NE(on, nullptr);
  EXPECT_GE(on->value, 100.0); // never early: the board only lags
  EXPECT_LE(on->value, 100.1);
}

TEST(ResolverStators, AnOpenStatorIsAResolverFaultAndTheOutputsStayOff) {
  // Ratio 0.5 is below the 0.75 the model accepts (an open pair drops below it): the board
  // shows a resolver fault and, with HoldOuts = 0, holds every output off: no edges.
  std::string text = kResolver;
  text.replace(text.find("cos = \"res.cos\""), 15, "cos = \"res.cos\"\nratio = 0.5");
  const Campaign c = parse_campaign(text, "t.toml");
  const rig::CampaignResult r = test::run_everything(c);
  EXPECT_EQ(test::find(r.runs[0], "on.edges")->value, 0.0);
  EXPECT_EQ(r.verdict, Outcome::Fail);
}

TEST(ResolverStators, TheStatorsMustBeAnalogLines) {
  std::string text = kResolver;
  text.replace(text.find("sin = \"res.sin\""), 15, "sin = \"ls1\"");
  // [resolver] is line 16; sin is line 17, its value at column 7.
  EXPECT_EQ(error_of(text), "t.toml:17:7: resolver.sin: a rig line wired to an analog pin (\"ls1\" is not)");
}

TEST(ResolverStators, OneStatorLineMayFeedTwoChannelsButADigitalLineIsWiredOnce) {
  // A resolver jumpered into both channels of a two-channel Series 2700 (R-18-8, L1763):
  // res.sin and res.cos each go to two analog pins. A digital line wired twice is still an
  // error.
  const std::string head = R"([campaign]
name = "jumper"
end = "10ms"
[dut]
model = "pls2700"
[[wiring]]
rig = "res.sin"
board = "SIN1"
[[wiring]]
rig = "res.cos"
board = "COS1"
[[wiring]]
rig = "res.sin"
board = "SIN2"
[[wiring]]
rig = "res.cos"
board = "COS2"
[[wiring]]
rig = "ls1"
board = "OUT1"
)";
  // Every campaign judges something: a pulse_width check on the output.
  const std::string resolver = "[resolver]\nsin = \"res.sin\"\ncos = \"res.cos\"\nphase_deg = 90\n"
                               "[[check]]\nkind = \"pulse_width\"\nname = \"out\"\nline = \"ls1\"\n";
  const Campaign c = parse_campaign(head + resolver, "t.toml");
  EXPECT_EQ(c.points[0].wiring.size(), 5U);
  EXPECT_EQ(c.points[0].resolver.phase_deg, 90.0);
  const std::string twice = head + "[[wiring]]\nrig = \"ls1\"\nboard = \"OUT2\"\n" + resolver;
  EXPECT_NE(error_of(twice).find("wiring[5].rig: each rig line wired once; \"ls1\" is already wired"),
            std::string::npos)
      << error_of(twice);
  std::string wrong_phase = head + resolver;
  wrong_phase.replace(wrong_phase.find("phase_deg = 90"), 14, "phase_deg = 400");
  EXPECT_NE(error_of(wrong_phase).find("resolver.phase_deg: a phase in -360..360 degrees"), std::string::npos)
      << error_of(wrong_phase);
}

TEST(ResolverStators, AFrequencyOutsideTheRigsBandIsRejected) {
  // 400 Hz .. 10 kHz (rig/campaign/limits.hpp; the ANS1 accepts 2.2 .. 7 kHz, docs/spec/ans1.md L60).
  for (const char* bad : {"0", "399.99", "10000.01", "1e12", "nan", "inf"}) {
    std::string text = kResolver;
    text.replace(text.find("cos = \"res.cos\""), 15,
                 std::string("cos = \"res.cos\"\nexcitation_hz = ") + bad);
    EXPECT_NE(error_of(text).find("resolver.excitation_hz: a"), std::string::npos) << bad << error_of(text);
  }
}

// Round trip, plant angle -> stators -> decoded angle: a press crank at w0 = 20 pi rad/s whose
// valve drops at 125 ms (a closed-loop input: the plan is redone from then on) stops under a
// brake that engages d = 20 ms later and rises over r = 30 ms to T = 2000 N·m on J_c = 2 kg·m²
// (the clutch let go: the flywheel no longer counts). The angle in closed form:
//   t <= t_v + d:        w0 t
//   rise (tau = t - t_v - d <= r):  th_d + w0 tau - T tau³ / (6 J_c r)
//   then (u = tau - r):  th_r + w2 u - T u² / (2 J_c), w2 = w0 - T r / (2 J_c), to rest.
// At each 5 kHz excitation peak (the boards sample there) the stators, demodulated by the
// Series 2700's decoder (atan2, 8192 counts a turn, truncated), give that angle back to
// within one of its counts; the angles before the input come from the plant's history, the
// ones after from its plan, extended horizon by horizon as the shaft gets there.
TEST(ResolverStators, CarryThePlantsAngleAndDecodeBackToIt) {
  PlantSpec spec;
  spec.kind = PlantKind::Press;
  spec.press.flywheel_inertia = 20.0;
  spec.press.crank_inertia = 2.0;
  spec.press.ram_mass = 0.0;
  spec.press.brake_torque = 2000.0;
  spec.press.valve_delay = 0.020;
  spec.press.brake_rise = 0.030;
  spec.press_start.speed = 20.0 * std::numbers::pi;
  spec.press_start.motor = false;
  const double per_turn = 4096.0;
  const Nanos end{400'000'000};
  PlantMotion motion(spec, per_turn, end);
  motion.input(Nanos{125'000'000}, plants::PlantInput::Valve, false);

  const double w0 = 20.0 * std::numbers::pi, jc = 2.0, torque = 2000.0, d = 0.020, r = 0.030, tv = 0.125;
  const double w2 = w0 - torque * r / (2.0 * jc);
  const auto angle = [&](double t) {
    if (t <= tv + d) return w0 * t;
    const double tau = t - tv - d;
    const double th_d = w0 * (tv + d);
    if (tau <= r) return th_d + w0 * tau - torque * tau * tau * tau / (6.0 * jc * r);
    const double th_r = th_d + w0 * r - torque * r * r / (6.0 * jc);
    const double u = std::min(tau - r, w2 * jc / torque);
    return th_r + w2 * u - torque * u * u / (2.0 * jc);
  };
  ResolverSpec res;
  res.phase_deg = 90.0; // the 2700's cosine reference: peaks every 200 us from 0
  const ShaftPosition shaft = [&motion](Nanos t) { return motion.position(t); };
  const Waveform sin_w = stator_waveform(shaft, per_turn, res, Stator::Sine);
  const Waveform cos_w = stator_waveform(shaft, per_turn, res, Stator::Cosine);
  int compared = 0;
  for (std::int64_t ns = 0; ns <= end.count(); ns += 200'000) {
    const Nanos t{ns};
    // As the rig's drive does when the shaft reaches a plan's horizon.
    while (motion.plan_end() < t) motion.extend();
    const double reference = res.amplitude; // cos(0) at every peak
    const models::pls2700::StatorReading got =
        models::pls2700::decode_stators(sin_w(t), cos_w(t), reference, 0.5, 1.5);
    ASSERT_TRUE(got.valid) << ns;
    const double turns = angle(t.seconds()) / (2.0 * std::numbers::pi);
    const double expected = 8192.0 * (turns - std::floor(turns));
    // Truncation: the decoded count is the one the angle lies in (a hair either side of a
    // count boundary may read its neighbour; the circle wraps at 8192).
    const double diff = std::remainder(static_cast<double>(got.raw) - expected, 8192.0);
    EXPECT_GE(diff, -1.0 - 1e-6) << ns;
    EXPECT_LE(diff, 1e-6) << ns;
    ++compared;
  }
  EXPECT_EQ(compared, 2001);
  // The history holds the motion before the input exactly: 100 ms at w0.
  EXPECT_NEAR(motion.position(Nanos{100'000'000}), w0 * 0.1 * per_turn / (2.0 * std::numbers::pi), 1e-6);
  // At rest at the closed form's stop angle.
  EXPECT_NEAR(motion.position(end), angle(1.0) * per_turn / (2.0 * std::numbers::pi), 1e-5);
}

// The resolver front end's stators keep the values read since the node's last frame (the
// board reads each peak ahead, the trace again at the time): every read, ahead of the frames
// or after them, is the stator of the node's angle as the node holds it when read -- a frame
// that arrives between two reads of the same instant changes what the second one gives.
TEST(ResolverLink, StatorsReadAgainAfterAFrameFollowTheNodesNewAngle) {
  Scheduler sched;
  virt::VirtualBus bus(sched);
  constexpr double kPerTurn = 4096.0;
  ResolverLink link(
      sched, bus,
      [](Nanos t) {
        const double s = t.seconds();
        return models::resolver_emulator::ShaftSample{kPerTurn * (0.2 + 7.0 * s + 30.0 * s * s),
                                                      kPerTurn * (7.0 + 60.0 * s)};
      },
      kPerTurn);
  ResolverSpec spec;
  spec.excitation_hz = 5000.0;
  spec.phase_deg = 12.0;
  const Waveform sin = link.stator(spec, Stator::Sine, {{3_ms, 4_ms, 0.5}});
  const Waveform cos = link.stator(spec, Stator::Cosine, {});
  const StatorForm sin_form(kPerTurn, spec, Stator::Sine, {{3_ms, 4_ms, 0.5}});
  const StatorForm cos_form(kPerTurn, spec, Stator::Cosine);
  const auto want = [&](const StatorForm& form, Nanos t) {
    const std::optional<double> turns = link.node().angle_turns(t);
    return turns ? form(t, *turns * kPerTurn) : 0.0;
  };
  link.start(models::resolver_emulator::ShaftSample{kPerTurn * 0.2, kPerTurn * 7.0});
  for (Nanos now{0}; now < 8_ms; now += 50_us) {
    sched.run_until(now);
    for (Nanos t = now; t < now + 2_ms; t += 25_us) { // ahead, across the next frames
      const double s = sin(t);
      ASSERT_EQ(s, want(sin_form, t)) << now.count() << " " << t.count();
      ASSERT_EQ(cos(t), want(cos_form, t)) << now.count() << " " << t.count();
      ASSERT_EQ(sin(t), s); // read again with no frame between: the same
    }
  }
  EXPECT_GT(link.node().counters().frames, 6U);
}

// stators() gives both stators of one read (one node angle, one carrier) and keeps the other's
// value for its read: each is what its own form gives at the node's angle, whichever is read
// first, ahead of the frames or after them, each with its own fault window.
TEST(ResolverLink, BothStatorsFromOneReadAreEachFormsValue) {
  Scheduler sched;
  virt::VirtualBus bus(sched);
  constexpr double kPerTurn = 4096.0;
  ResolverLink link(
      sched, bus,
      [](Nanos t) {
        const double s = t.seconds();
        return models::resolver_emulator::ShaftSample{kPerTurn * (0.6 - 5.0 * s), kPerTurn * -5.0};
      },
      kPerTurn);
  ResolverSpec spec;
  spec.excitation_hz = 4000.0;
  spec.phase_deg = -30.0;
  const auto [sin, cos] = link.stators(spec, {{2_ms, 3_ms, 0.0}}, {{4_ms, 5_ms, 1.5}});
  const StatorForm sin_form(kPerTurn, spec, Stator::Sine, {{2_ms, 3_ms, 0.0}});
  const StatorForm cos_form(kPerTurn, spec, Stator::Cosine, {{4_ms, 5_ms, 1.5}});
  const auto want = [&](const StatorForm& form, Nanos t) {
    const std::optional<double> turns = link.node().angle_turns(t);
    return turns ? form(t, *turns * kPerTurn) : 0.0;
  };
  link.start(models::resolver_emulator::ShaftSample{kPerTurn * 0.6, kPerTurn * -5.0});
  bool cos_first = false;
  for (Nanos now{0}; now < 7_ms; now += 70_us) {
    sched.run_until(now);
    for (Nanos t = now; t < now + 1500_us; t += 30_us) {
      cos_first = !cos_first;
      if (cos_first) {
        ASSERT_EQ(cos(t), want(cos_form, t)) << now.count() << " " << t.count();
      }
      ASSERT_EQ(sin(t), want(sin_form, t)) << now.count() << " " << t.count();
      ASSERT_EQ(cos(t), want(cos_form, t)) << now.count() << " " << t.count();
    }
  }
  EXPECT_EQ(sin(2500_us), 0.0); // the open sine's window, read after its frames
  EXPECT_GT(link.node().counters().frames, 5U);
}

} // namespace
} // namespace hilrig::campaign
