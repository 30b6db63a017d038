// A shaft_move check's expected profile (profile_of): the step rate a relative move
// programmed on the SMD23E is expected to follow, worked out from the manual's profile rules
// (smd23e manual seeds/003_7a93cebfafae55cd.txt:919-928: start at the Starting Speed, ramp at
// the Acceleration to the Programmed Speed, cruise, ramp at the Deceleration back to the
// Starting Speed at the target; a triangle when the ramps' steps exceed the move; L848-851:
// steps/ms/s x 1000 = steps/s²); the move found from the campaign's own [[host]] write, and
// every way a campaign can name a move without a profile refused at file:line:col: key.

#include <gtest/gtest.h>

#include <cmath>
#include <string>
#include <variant>

#include "rig/campaign/campaign_error.hpp"
#include "rig/campaign/campaign_parser.hpp"
#include "rig/checks/move_profile.hpp"
#include "rig/checks/shaft_move.hpp"

namespace hilrig::checks {
namespace {

using namespace hilrig::literals;

// v_s 1000, v_p 10000 steps/s, A = D = 100 steps/ms/s (a = d = 100,000 steps/s²): the
// campaign smd23e_profile's moves. n_acc = n_dec = (10000² - 1000²) / 2e5 = 495 steps.
MoveProfile planned(double steps, Nanos start = 10_ms) { return {start, 1000, 10000, 1e5, 1e5, steps}; }

void expect_knots(const std::vector<rig::RatePoint>& got, const std::vector<std::pair<Nanos, double>>& want) {
  ASSERT_EQ(got.size(), want.size());
  for (std::size_t i = 0; i < want.size(); ++i) {
    EXPECT_EQ(got[i].time, want[i].first) << "knot " << i;
    EXPECT_NEAR(got[i].rate, want[i].second, 1e-6) << "knot " << i;
  }
}

TEST(ExpectedStepRate, TrapezoidOfTheProfileCampaign) {
  // N = 4000 >= 990: t_acc = t_dec = 9000 / 1e5 = 90 ms; cruise (4000 - 990) / 10000 = 301 ms.
  expect_knots(expected_step_rate(planned(4000)),
               {{10_ms, 1000}, {100_ms, 10000}, {401_ms, 10000}, {491_ms, 1000}});
}

TEST(ExpectedStepRate, TriangleOfTheProfileCampaign) {
  // N = 600 < 990: v_peak = sqrt(1000² + 2·600·1e5·1e5 / 2e5) = sqrt(61e6) = 7810.2497 steps/s,
  // t_acc = t_dec = (7810.2497 - 1000) / 1e5 = 68.1025 ms, T = 136.205 ms.
  const double peak = std::sqrt(61e6);
  expect_knots(expected_step_rate(planned(600, 610_ms)),
               {{610_ms, 1000}, {678'102'497_ns, peak}, {746'204'994_ns, 1000}});
}

TEST(ExpectedStepRate, DifferentAccelerationAndDeceleration) {
  // L926: the rates may differ. D = 50 -> d = 50,000: n_dec = 99e6 / 1e5 = 990 steps, t_dec =
  // 180 ms; N = 4000: cruise (4000 - 495 - 990) / 10000 = 251.5 ms.
  MoveProfile p = planned(4000, 0_ms);
  p.decel = 5e4;
  expect_knots(expected_step_rate(p),
               {{0_ms, 1000}, {90_ms, 10000}, {341'500_us, 10000}, {521'500_us, 1000}});
}

TEST(ExpectedStepRate, SweepAcrossTheTrapezoidTriangleLimit) {
  // N = n_acc + n_dec = 990 exactly: a trapezoid with no cruise, peak v_p, T = 180 ms. One
  // step less: a triangle just below v_p, sqrt(1e6 + 989e5) = 9994.9987; one more: 0.1 ms of
  // cruise. Around the limit the peak and the end move smoothly (no jump at the switch).
  expect_knots(expected_step_rate(planned(990, 0_ms)), {{0_ms, 1000}, {90_ms, 10000}, {180_ms, 1000}});
  const auto below = expected_step_rate(planned(989, 0_ms));
  ASSERT_EQ(below.size(), 3U);
  EXPECT_NEAR(below[1].rate, std::sqrt(99.9e6), 1e-6);
  expect_knots(expected_step_rate(planned(991, 0_ms)),
               {{0_ms, 1000}, {90_ms, 10000}, {90'100_us, 10000}, {180'100_us, 1000}});
  std::vector<std::vector<rig::RatePoint>> sweep;
  for (int n = 980; n <= 1000; ++n) sweep.push_back(expected_step_rate(planned(n, 0_ms)));
  const auto peak_of = [](const std::vector<rig::RatePoint>& k) {
    double peak = 0.0;
    for (const auto& p : k) peak = std::max(peak, p.rate);
    return peak;
  };
  for (std::size_t i = 0; i < sweep.size(); ++i) {
    EXPECT_EQ(sweep[i].size(), 980 + i <= 990 ? 3U : 4U) << 980 + i; // a cruise from 991 on
    EXPECT_LE(peak_of(sweep[i]), 10000.0) << 980 + i;
    EXPECT_EQ(sweep[i].front().rate, 1000.0);
    EXPECT_EQ(sweep[i].back().rate, 1000.0);
    if (i == 0) continue;
    EXPECT_GE(peak_of(sweep[i]), peak_of(sweep[i - 1])) << 980 + i;
    // One step more takes about 1 / v_peak longer: 0.1 ms near 10000 steps/s.
    const Nanos longer = sweep[i].back().time - sweep[i - 1].back().time;
    EXPECT_GT(longer, 99_us) << 980 + i;
    EXPECT_LT(longer, 101_us) << 980 + i;
  }
}

TEST(ExpectedStepRate, NoRampsWhenTheProgrammedSpeedIsTheStartingSpeed) {
  // v_p = v_s: it runs N / v_s at v_s (docs/spec/smd23e.md §3.2 special cases): 500 / 1000 s.
  MoveProfile p = planned(500, 0_ms);
  p.speed = 1000;
  expect_knots(expected_step_rate(p), {{0_ms, 1000}, {500_ms, 1000}});
}

TEST(ExpectedStepRate, RidesAlongTheShaftMoveResultAndJudgesNothing) {
  // One step at 1 ms: the result carries the profile's knots and only the steps measurement.
  ShaftMoveSpec s;
  s.name = "m";
  s.steps = 1;
  s.profile = planned(4000);
  const std::vector<Edge> step = {{1_ms, Level::High}};
  const std::vector<Edge> dir = {{0_ms, Level::High}};
  const CheckResult r = check_shaft_move(step, dir, s);
  EXPECT_EQ(r.outcome(), rig::Outcome::Pass);
  ASSERT_EQ(r.measurements.size(), 1U);
  expect_knots(r.expected_rate, {{10_ms, 1000}, {100_ms, 10000}, {401_ms, 10000}, {491_ms, 1000}});
  s.profile.reset();
  EXPECT_TRUE(check_shaft_move(step, dir, s).expected_rate.empty());
}

// --- profile_of in a campaign ---------------------------------------------------------------

// A campaign: a configuration (v_s `vs`) unless `vs` is empty, then the [[host]] write "go"
// with `move_fields`, and a shaft_move check naming `of` on its last line.
std::string campaign(const std::string& move_fields, const std::string& of = "go",
                     const std::string& vs = "1000") {
  std::string t = "[campaign]\nname = \"p\"\nend = \"600ms\"\n"
                  "[dut]\nmodel = \"smd23e\"\n"
                  "[[wiring]]\nrig = \"shaft.step\"\nboard = \"STEP\"\n"
                  "[[wiring]]\nrig = \"shaft.dir\"\nboard = \"DIR\"\n";
  if (!vs.empty())
    t += "[[host]]\nat = \"0ms\"\nprogram = \"configuration\"\nstarting_speed = " + vs +
         "\nsteps_per_turn = 2048\nidle_current_percent = 50\nmotor_current_x10 = 20\n";
  else
    t += "[[host]]\nat = \"0ms\"\nprogram = \"command\"\ncommand = \"none\"\n";
  t += "[[host]]\nat = \"10ms\"\nname = \"go\"\n" + move_fields + "\n";
  t += "[[check]]\nkind = \"shaft_move\"\nname = \"m\"\nstep_line = \"shaft.step\"\ndir_line = "
       "\"shaft.dir\"\nfrom_ms = 10\nsteps = 4000\nprofile_of = \"" +
       of + "\"\n";
  return t;
}
const std::string kRelative = "program = \"move\"\nmove = \"relative\"\nsteps = 4000\nspeed = 10000\n"
                              "accel = 100\ndecel = 100";

std::string error_of(const std::string& text) {
  try {
    (void)campaign::parse_campaign(text, "t.toml");
    return "accepted";
  } catch (const campaign::CampaignError& e) {
    return e.what();
  }
}

// The line of profile_of in campaign(): the last line.
int profile_line(const std::string& text) {
  int lines = 0;
  for (const char c : text) lines += c == '\n';
  return lines;
}

::testing::AssertionResult refused(const std::string& text, const std::string& says) {
  const std::string got = error_of(text);
  const std::string where =
      "t.toml:" + std::to_string(profile_line(text)) + ":14: check[0].profile_of: "; // at its value
  if (got.rfind(where, 0) != 0 || got.find(says) == std::string::npos)
    return ::testing::AssertionFailure()
           << "expected \"" << where << "...\" naming \"" << says << "\", got \"" << got << "\"";
  return ::testing::AssertionSuccess();
}

TEST(ProfileOf, TheNamedWriteAndTheConfigurationBeforeItGiveTheProfile) {
  const campaign::Campaign c = campaign::parse_campaign(campaign(kRelative), "t.toml");
  const auto& p = std::get<ShaftMoveParams>(c.points.at(0).checks.at(0).params);
  ASSERT_TRUE(p.spec.profile.has_value());
  EXPECT_EQ(p.spec.profile->start, 10_ms); // the write's time: when the move was commanded
  EXPECT_EQ(p.spec.profile->starting_speed, 1000.0);
  EXPECT_EQ(p.spec.profile->speed, 10000.0);
  EXPECT_EQ(p.spec.profile->accel, 100'000.0); // 100 steps/ms/s (L848-851)
  EXPECT_EQ(p.spec.profile->decel, 100'000.0);
  EXPECT_EQ(p.spec.profile->steps, 4000.0);
  // A CCW move is as long; raw words (the two-word format, L2247-2253) read the same.
  const campaign::Campaign ccw = campaign::parse_campaign(
      campaign(
          "program = \"move\"\nmove = \"relative\"\nsteps = -1234567\nspeed = 10000\naccel = 7\ndecel = 9"),
      "t.toml");
  const auto& q = std::get<ShaftMoveParams>(ccw.points.at(0).checks.at(0).params);
  EXPECT_EQ(q.spec.profile->steps, 1'234'567.0);
  EXPECT_EQ(q.spec.profile->accel, 7000.0);
  EXPECT_EQ(q.spec.profile->decel, 9000.0);
  // MSW 0x0002, LSW 0x8000 (DriveEn), offset (4, 0), speed (10, 0), A 100, D 100, 0, J 0.
  const campaign::Campaign raw =
      campaign::parse_campaign(campaign("write = [2, 32768, 4, 0, 10, 0, 100, 100, 0, 0]"), "t.toml");
  const auto& w = std::get<ShaftMoveParams>(raw.points.at(0).checks.at(0).params);
  EXPECT_EQ(w.spec.profile->steps, 4000.0);
  EXPECT_EQ(w.spec.profile->speed, 10000.0);
}

TEST(ProfileOf, AMoveWithoutAKnownProfileIsBadInputAtTheKey) {
  EXPECT_TRUE(refused(campaign(kRelative, "nothing"), "names none"));
  EXPECT_TRUE(
      refused(campaign("program = \"move\"\nmove = \"absolute\"\nsteps = 4000\nspeed = 10000\naccel = "
                       "100\ndecel = 100"),
              "a relative move"));
  EXPECT_TRUE(
      refused(campaign("program = \"move\"\nmove = \"jog_cw\"\nspeed = 10000\naccel = 100\ndecel = 100"),
              "a relative move"));
  EXPECT_TRUE(refused(campaign(kRelative + "\njerk = 1"), "Acceleration Jerk 0"));
  EXPECT_TRUE(refused(campaign(kRelative + "\nencoder_move = true"), "not an encoder move"));
  EXPECT_TRUE(refused(campaign(kRelative, "go", ""), "after a configuration"));
  // The Programmed Speed at least the Starting Speed (L2510): 10000 passes at v_s 10000, not at 10001.
  EXPECT_EQ(error_of(campaign(kRelative, "go", "10000")), "accepted");
  EXPECT_TRUE(refused(campaign(kRelative, "go", "10001"), "Programmed Speed of the Starting Speed (10001)"));
  // Zero steps: no move to draw.
  EXPECT_TRUE(refused(campaign("program = \"move\"\nmove = \"relative\"\nsteps = 0\nspeed = 10000\naccel = "
                               "100\ndecel = 100"),
                      "a move of 1 .. 8388607 steps"));
  // Raw words out of the block's ranges: A 0 and 5001 (1 .. 5000, L2512), a lower word of 1000.
  EXPECT_TRUE(refused(campaign("write = [2, 32768, 4, 0, 10, 0, 0, 100, 0, 0]"), "1 .. 5000 steps/ms/s"));
  EXPECT_TRUE(refused(campaign("write = [2, 32768, 4, 0, 10, 0, 100, 5001, 0, 0]"), "1 .. 5000 steps/ms/s"));
  EXPECT_EQ(error_of(campaign("write = [2, 32768, 4, 0, 10, 0, 5000, 1, 0, 0]")), "accepted");
  EXPECT_TRUE(refused(campaign("write = [2, 32768, 4, 1000, 10, 0, 100, 100, 0, 0]"), "a move of 1 .. "));
}

TEST(ProfileOf, OnlyAShaftMoveCheckTakesIt) {
  const std::string text = campaign(kRelative);
  const std::string other =
      text.substr(0, text.find("[[check]]")) +
      "[[host]]\nat = \"500ms\"\nread = 0\nname = \"x\"\n"
      "[[check]]\nkind = \"word_equals\"\nname = \"w\"\nobservation = \"x\"\nvalue = 1\n"
      "profile_of = \"go\"\n";
  EXPECT_NE(error_of(other).find("check[0].profile_of"), std::string::npos) << error_of(other);
}

} // namespace
} // namespace hilrig::checks
