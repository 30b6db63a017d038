// The SMD23E pulling an inertia through a stepper-load plant
// (campaigns/smd23e/smd23e_load_too_fast.toml): the board's steps drive the plant, the plant
// turns the encoder the board's stall detection watches (docs/spec/smd23e.md §2.3, manual L1255,
// L2885). The verdicts and the acceleration thresholds are the file's hand calculation (the
// undamped pendulum of the rotor's electrical lag).

#include <cmath>
#include <cstdint>
#include <fstream>
#include <numbers>
#include <sstream>
#include <string>

#include <fmt/format.h>
#include <gtest/gtest.h>

#include "rig/campaign/campaign_parser.hpp"
#include "rig/campaign/executive.hpp"
#include "test_support.hpp"

namespace hilrig::campaign {
namespace {

using rig::Outcome;

const std::string kLoadTooFastFile = test::campaign_dir("smd23e") + "/smd23e_load_too_fast.toml";

constexpr double kJ = 4.8e-5 + 1.0e-2; // kg·m²: rotor + load
constexpr double kT = 1.69477;         // N·m: 240 oz-in (spec §1)

// The shaft's acceleration (rad/s²) for A steps/ms/s (L2496: x 1000 steps/s²), 12,800 steps
// a turn, and f = J alpha / T.
double alpha(double a) { return a * 1000.0 * 2.0 * std::numbers::pi / 12800.0; }
double load_ratio(double a) { return kJ * alpha(a) / kT; }

// With f > 1 the lag passes pi (a pole slipped) by sqrt(2 pi / (50 (alpha - T / J))): lost
// within the ramp (25,600 steps/s at A x 1000 steps/s²) when that comes first.
bool loses_within_ramp(double a) {
  if (load_ratio(a) <= 1.0) return false;
  return std::sqrt(2.0 * std::numbers::pi / (50.0 * (alpha(a) - kT / kJ))) <= 25.6 / a;
}

// Bisection on [lo, hi] for the root of a function that changes sign there.
template <class F> double root(F f, double lo, double hi) {
  for (int i = 0; i < 200; ++i) {
    const double mid = 0.5 * (lo + hi);
    if ((f(lo) > 0.0) == (f(mid) > 0.0))
      lo = mid;
    else
      hi = mid;
  }
  return 0.5 * (lo + hi);
}

// The separatrix from rest: slips iff f (pi - asin f) >= 1 + sqrt(1 - f²).
double f_slip() {
  return root([](double f) { return f * (std::numbers::pi - std::asin(f)) - 1.0 - std::sqrt(1.0 - f * f); },
              0.3, 0.99);
}

// Follows whatever the ring's phase at the deceleration: T (1 - 2 cos d_max) under the
// saddle -f (pi - asin f) + sqrt(1 - f²), d_max from f d = 1 - cos d.
double f_safe() {
  const auto d_max = [](double f) {
    return root([f](double d) { return f * d - (1.0 - std::cos(d)); }, 1e-6, 3.14);
  };
  return root(
      [&](double f) {
        return -f * (std::numbers::pi - std::asin(f)) + std::sqrt(1.0 - f * f) -
               (1.0 - 2.0 * std::cos(d_max(f)));
      },
      0.05, 0.72);
}

std::string with_acceleration(int a) {
  std::string t = test::read_file(kLoadTooFastFile);
  const std::string nominal = "accel = 50\ndecel = 50"; // the move's A and D, steps/ms/s
  const std::size_t at = t.find(nominal);
  EXPECT_NE(at, std::string::npos);
  t.replace(at, nominal.size(), fmt::format("accel = {}\ndecel = {}", a, a));
  return t;
}

TEST(Smd23eLoadTooFast, TheNominalRampFollowsAndTheFastOneStalls) {
  EXPECT_NEAR(f_slip(), 0.72461, 1e-5);
  EXPECT_NEAR(f_safe(), 0.42227, 1e-5);
  EXPECT_LT(load_ratio(50), f_safe());
  EXPECT_TRUE(loses_within_ramp(500));
  const Campaign c = load_campaign(kLoadTooFastFile);
  const rig::CampaignResult r = test::run_everything(c);
  ASSERT_EQ(r.runs.size(), 2U);
  EXPECT_EQ(r.verdict, Outcome::Pass) << test::failures(r);
  EXPECT_EQ(r.totals.faults_caught, 1U);
  const rig::Observation* sw2 = test::find_observation(r.runs[0], "sw2");
  const rig::Observation* lower = test::find_observation(r.runs[0], "encoder_lower");
  ASSERT_NE(sw2, nullptr);
  ASSERT_NE(lower, nullptr);
  EXPECT_EQ(static_cast<int>(sw2->value) & 0x4000, 0);
  EXPECT_NEAR(lower->value, 48.0, 3.0); // 2048 +- 3 counts of ringing
  const rig::Observation* stalled = test::find_observation(r.runs[1], "sw2");
  ASSERT_NE(stalled, nullptr);
  EXPECT_EQ(static_cast<int>(stalled->value) & 0x4000, 0x4000); // SW2 bit 14 (L2885)
}

// Either side of the predicted band: follows at A <= 145.09 (f <= f_safe), stalls at
// A >= 408.93 (f > 1 and the lag passes pi within the ramp).
TEST(Smd23eLoadTooFast, StallsAtTheAccelerationThePhysicsPredicts) {
  EXPECT_GT(f_slip(), f_safe()); // the separatrix from rest lies inside the open band
  for (const int a : {130, 140, 450, 480}) {
    const bool follows = load_ratio(a) <= f_safe();
    ASSERT_TRUE(follows || loses_within_ramp(a)) << a << " lies in the band the ring's phase decides";
    const Campaign c = parse_campaign(with_acceleration(a), "accel.toml");
    const RunOutput out = Executive(c).run(c.runs[0]);
    const rig::Observation* sw2 = test::find_observation(out.result, "sw2");
    ASSERT_NE(sw2, nullptr) << a;
    EXPECT_EQ((static_cast<int>(sw2->value) & 0x4000) == 0, follows) << a << " sw2 " << sw2->value;
    ASSERT_EQ(out.result.checks.size(), 3U);
    for (const auto& check : out.result.checks) {
      if (follows || check.check == "no_stall") {
        EXPECT_EQ(check.outcome(), follows ? Outcome::Pass : Outcome::Fail) << a << " " << check.check;
      }
    }
  }
}

// After the fast move has stalled (10 ms, A = D = 500, the fault run above), Reset Errors,
// Preset Position 0 and Preset Encoder 0, a slow move follows: the unit watches the encoder
// "while a move is in progress" (L1255), so what the stall left between the steps and the
// counts is no disagreement of the next move. The slow move: 12,800 steps (one turn) at
// v_p 6400, A = D = 10 (f = 0.029, far below f_safe), from v_s 1 (L2496: 10,000 steps/s²):
// ramps of 0.6399 s, the end at 1.5 s + 2.6398 s; at 4.0 s, 0.1398 s before it,
// 0.1398 + 10,000 x 0.1398² / 2 = 97.86 steps are left: position 12,702, the encoder
// 12,702 x 1024 / 12,800 = 1016 counts. The undamped rotor keeps ringing after the stall, within
// a pole (pi electrical, +-10.24 counts) of where it is held, at the preset as at the reading:
// the encoder reads 1016 +- 20.48 counts (+- 3 of the move's own ring).
std::string after_a_stall() {
  std::string t = test::read_file(kLoadTooFastFile);
  t.replace(t.find("end = \"1610ms\""), 14, "end = \"4010ms\"");
  const std::size_t moves = t.find("# Relative move (MSW 0x0002)");
  EXPECT_NE(moves, std::string::npos);
  t.resize(moves);
  t += R"(
[[host]]
at = "10ms"
name = "too_fast"
program = "move"
move = "relative"
steps = 25600
speed = 25600
accel = 500
decel = 500

[[host]]
at = "1000ms"
read = 1
name = "sw2_stalled"

[[host]]
at = "1002ms"
name = "reset"
program = "command"
command = "reset_errors"

[[host]]
at = "1004ms"
name = "preset_position"
program = "command"
command = "preset_position"
position = 0

[[host]]
at = "1006ms"
name = "preset_encoder"
program = "command"
command = "preset_encoder"
position = 0

[[host]]
at = "1500ms"
name = "slow"
program = "move"
move = "relative"
steps = 12800
speed = 6400
accel = 10
decel = 10
)";
  for (const int word : {1, 2, 3, 4, 5}) {
    t += fmt::format("\n[[host]]\nat = \"4000ms\"\nread = {}\nname = \"w{}\"\n", word, word);
  }
  t += R"(
[[check]]
kind = "word_bits"
name = "no_stall"
observation = "w1"
mask = 0x4000 # SW2 bit 14, Stall (L2885)
value = 0
)";
  return t;
}

TEST(Smd23eLoadTooFast, AfterAStallResetAndPresetsTheNextMoveIsWatchedOnItsOwn) {
  const Campaign c = parse_campaign(after_a_stall(), "after_a_stall.toml");
  const RunOutput out = Executive(c).run(c.runs[0]);
  const auto word = [&](const std::string& name) {
    const rig::Observation* o = test::find_observation(out.result, name);
    EXPECT_NE(o, nullptr) << name;
    return o == nullptr ? 0 : static_cast<std::int16_t>(static_cast<std::uint16_t>(o->value));
  };
  EXPECT_EQ(word("sw2_stalled") & 0x4000, 0x4000); // the first move did stall
  EXPECT_EQ(word("w1") & 0x4000, 0);               // the second one runs its steps
  EXPECT_EQ(word("w2") * 1000 + word("w3"), 12702);
  EXPECT_NEAR(word("w4") * 1000 + word("w5"), 1016, 20.48 + 3.0);
  ASSERT_EQ(out.result.checks.size(), 1U);
  EXPECT_EQ(out.result.checks[0].outcome(), Outcome::Pass);
}

} // namespace
} // namespace hilrig::campaign
