// Device faults in time ([[device_fault]], issue 17): the parser's typed events and its errors
// (file:line:column: key: the valid fault names of the device), the rig's resolver faults on
// the stator waveforms, the models' detection of an open coil from the signal, and each
// shipped device-fault campaign end to end through the executive: it passes on the virtual
// board, and without its [[device_fault]] entries its checks fail (they judge the board's
// reaction to the fault, not something that happens anyway).

#include <gtest/gtest.h>

#include <cmath>
#include <memory>
#include <numbers>
#include <set>
#include <string>

#include "campaign_text.hpp"
#include "models/ans1/position_resolver.hpp"
#include "models/pls2700/position.hpp"
#include "rig/campaign/campaign_parser.hpp"
#include "rig/campaign/executive.hpp"
#include "rig/campaign/resolver_stators.hpp"
#include "test_support.hpp"

namespace hilrig::campaign {
namespace {

using test::error_of;
using test::rejected_at;
using test::replace_line;

using namespace hilrig::literals;
using rig::Outcome;

// A 7361 campaign with one EEPROM error, 18 lines; cases replace one line or append lines.
const std::string kSsi = R"([campaign]
name = "t"
end = "50ms"
[dut]
model = "ssi7361"
[[host]]
at = "1ms"
read = 0
name = "status"
[[check]]
kind = "word_bits"
name = "e2err"
observation = "status"
mask = 4096
value = 4096
[[device_fault]]
fault = "eeprom_error"
at = "0ms"
)";

TEST(DeviceFaultParser, BuildsTheTypedEventOnce) {
  const Campaign c = parse_campaign(kSsi, "t.toml");
  ASSERT_EQ(c.points.at(0).device_faults.size(), 1U);
  const DeviceFaultEvent& f = c.points[0].device_faults[0];
  EXPECT_EQ(f.name, "eeprom_error");
  EXPECT_EQ(f.fault, 0U);
  EXPECT_EQ(f.site, duts::FaultSite::Board);
  EXPECT_EQ(f.at, 0_ms);
  EXPECT_EQ(f.until, Nanos::max()); // only E2CLR clears it
}

TEST(DeviceFaultParser, AFaultTheDeviceLacksNamesTheValidOnes) {
  EXPECT_TRUE(rejected_at(replace_line(kSsi, 17, "fault = \"over_temperature\""),
                          "t.toml:17:9: device_fault[0].fault: a fault of ssi7361: one of eeprom_error"));
}

TEST(DeviceFaultParser, AFaultWithoutAnEndOfItsOwnTakesNoUntil) {
  EXPECT_TRUE(rejected_at(kSsi + "until = \"5ms\"\n",
                          "t.toml:19:9: device_fault[0].until: no `until`: eeprom_error"));
}

TEST(DeviceFaultParser, TheStartLiesWithinTheRun) {
  EXPECT_TRUE(
      rejected_at(replace_line(kSsi, 18, "at = \"51ms\""), "t.toml:18:6: device_fault[0].at: a time within"));
  EXPECT_EQ(error_of(replace_line(kSsi, 18, "at = \"50ms\"")), "accepted"); // at the end: inclusive
}

TEST(DeviceFaultParser, UnknownKeysAndAMissingFaultAreErrors) {
  EXPECT_TRUE(rejected_at(kSsi + "ratio = 0.5\n", "t.toml:19:1: device_fault[0].ratio"));
  EXPECT_TRUE(rejected_at(replace_line(kSsi, 17, "name = \"eeprom_error\""), "t.toml:16:1: device_fault[0]"));
}

TEST(DeviceFaultParser, ADeviceWithoutFaultsSaysSo) {
  const std::string text = test::kPlsCampaign + "[[device_fault]]\nfault = \"eeprom_error\"\nat = \"0ms\"\n";
  EXPECT_NE(error_of(text).find("device_fault[0].fault: none: reference_pls has no device faults"),
            std::string::npos)
      << error_of(text);
}

// An ANS1 on its resolver: 21 lines, then the fault.
const std::string kAns1 = R"([campaign]
name = "t"
end = "50ms"
[dut]
model = "ans1"
[[wiring]]
rig = "res.sin"
board = "SIN"
[[wiring]]
rig = "res.cos"
board = "COS"
[resolver]
sin = "res.sin"
cos = "res.cos"
[[host]]
at = "1ms"
read = 0
name = "status"
[[check]]
kind = "word_bits"
name = "fault"
observation = "status"
mask = 4096
value = 4096
[[device_fault]]
)";

TEST(DeviceFaultParser, AStatorRatioFaultNeedsItsRatioInRange) {
  const std::string f = kAns1 + "fault = \"ratio_out_of_range\"\nat = \"0ms\"\n";
  EXPECT_TRUE(rejected_at(f, "t.toml:25:1: device_fault[0].ratio"));
  EXPECT_TRUE(rejected_at(f + "ratio = 10.5\n",
                          "t.toml:28:9: device_fault[0].ratio: a transformation ratio in 0 .. 10"));
  const Campaign c = parse_campaign(f + "ratio = 0.5\n", "t.toml");
  EXPECT_EQ(c.points[0].device_faults[0].site, duts::FaultSite::StatorRatio);
  EXPECT_DOUBLE_EQ(c.points[0].device_faults[0].ratio, 0.5);
}

TEST(DeviceFaultParser, AResolverFaultNeedsTheRigsStators) {
  std::string text = kAns1 + "fault = \"open_sin_coil\"\nat = \"0ms\"\n";
  for (int line : {6, 7, 8, 9, 10, 11, 12, 13, 14}) text = replace_line(text, line, "");
  EXPECT_NE(error_of(text).find("device_fault[0].fault: a [resolver] the rig drives"), std::string::npos)
      << error_of(text);
}

TEST(DeviceFaultParser, UntilComesAfterAt) {
  const std::string f = kAns1 + "fault = \"open_sin_coil\"\nat = \"10ms\"\n";
  EXPECT_TRUE(rejected_at(f + "until = \"10ms\"\n", "t.toml:28:9: device_fault[0].until: a time after `at`"));
  EXPECT_EQ(error_of(f + "until = \"10000001ns\"\n"), "accepted");
}

// ---- The rig's resolver faults on the stators

TEST(DeviceFaultStators, AnOpenCoilIsZeroForItsWindowOnly) {
  const Campaign c =
      parse_campaign(kAns1 + "fault = \"open_sin_coil\"\nat = \"10ms\"\nuntil = \"20ms\"\n", "t.toml");
  const Scenario& s = c.points[0];
  const auto at_90 = std::make_shared<const signals::MotionProfile>(1024.0); // a quarter turn of 4096
  const Waveform sin =
      stator_waveform(at_90, 4096.0, s.resolver, Stator::Sine, stator_fault_windows(s, Stator::Sine));
  const Waveform cos =
      stator_waveform(at_90, 4096.0, s.resolver, Stator::Cosine, stator_fault_windows(s, Stator::Cosine));
  // 5 kHz excitation, amplitude 1, ratio 1: positive peaks at 50 us + k * 200 us.
  EXPECT_NEAR(sin(9'850_us), 1.0, 1e-9);                        // before
  EXPECT_EQ(sin(10_ms), 0.0);                                   // from `at`, inclusive
  EXPECT_EQ(sin(19'850_us), 0.0);                               // inside
  EXPECT_NEAR(sin(20'050_us), 1.0, 1e-9);                       // from `until` the coil is back
  EXPECT_TRUE(stator_fault_windows(s, Stator::Cosine).empty()); // the other coil is untouched
  EXPECT_NEAR(cos(10'050_us), 0.0, 1e-9);                       // cos 90 deg
}

TEST(DeviceFaultStators, ARatioFaultScalesBothStators) {
  const Campaign c =
      parse_campaign(kAns1 + "fault = \"ratio_out_of_range\"\nat = \"10ms\"\nratio = 0.5\n", "t.toml");
  const Scenario& s = c.points[0];
  const auto at_45 = std::make_shared<const signals::MotionProfile>(512.0);
  for (Stator st : {Stator::Sine, Stator::Cosine}) {
    const Waveform w = stator_waveform(at_45, 4096.0, s.resolver, st, stator_fault_windows(s, st));
    EXPECT_NEAR(w(9'850_us), std::sqrt(0.5), 1e-9);
    EXPECT_NEAR(w(10'050_us), 0.5 * std::sqrt(0.5), 1e-9);
    EXPECT_NEAR(w(49'850_us), 0.5 * std::sqrt(0.5), 1e-9); // no until: to the end
  }
}

// ---- The boards detect an open coil from the signal

// ans1 manual (seeds/000_08a2edf5547d4d1e.txt:418-419, :2299; docs/spec/ans1.md L79): an open stator
// pair is a Resolver Fault. The model judges the stator amplitude sqrt(S^2 + C^2) against
// resolver_min_ratio 0.75 ([MODEL]): with the SIN coil open only the COS stator remains,
// TR * |cos theta|, a fault where that is below 0.75 (TR 0.95: |cos theta| < 0.789).
TEST(DeviceFaultModels, Ans1SeesAnOpenSinCoilWhereTheCosStatorAloneIsTooSmall) {
  namespace a = models::ans1;
  const double tr = 0.95;
  for (int deg = 0; deg < 360; deg += 5) {
    const double c = tr * std::cos(deg * std::numbers::pi / 180.0);
    const a::ResolverReading r = a::decode_resolver(0.0, c, 1.0, 0.75, 1.25);
    EXPECT_EQ(r.valid, std::abs(c) >= 0.75) << deg << " deg";
  }
  EXPECT_FALSE(a::decode_resolver(0.0, 0.0, 1.0, 0.75, 1.25).valid);              // both open
  EXPECT_FALSE(a::decode_resolver(0.5 * 0.6, 0.5 * 0.8, 1.0, 0.75, 1.25).valid);  // TR 0.5
  EXPECT_TRUE(a::decode_resolver(0.75 * 0.6, 0.75 * 0.8, 1.0, 0.75, 1.25).valid); // at the limit
}

// The same band on the running board: a stator ratio exactly at resolver_min_ratio 0.75 or
// resolver_max_ratio 1.25 ([MODEL], closed) through a whole turn at 100 RPM (600 ms; a peak
// every 100 us, 6,000 angles) leaves Resolver Fault (status bit 12, L2299) clear; the fault
// latches (XFltLatch 0, L1839), so a single peak judged bad would still show at 610 ms.
// 0.749 and 1.251 are a fault.
std::string ans1_turn_at_ratio(double ratio) {
  return R"([campaign]
name = "t"
end = "620ms"
[dut]
model = "ans1"
[[wiring]]
rig = "res.sin"
board = "SIN"
[[wiring]]
rig = "res.cos"
board = "COS"
[resolver]
sin = "res.sin"
cos = "res.cos"
[motion]
[[motion.move]]
kind = "constant"
speed_rpm = 100
duration = "620ms"
[[host]]
at = "610ms"
read = 0
name = "status"
[[check]]
kind = "word_bits"
name = "no_fault"
observation = "status"
mask = 4096
value = 0
[[device_fault]]
fault = "ratio_out_of_range"
at = "0ms"
ratio = )" +
         std::to_string(ratio) + "\n";
}

TEST(DeviceFaultModels, Ans1StatorsExactlyAtARatioLimitAreNoFaultThroughATurn) {
  for (const double at_limit : {0.75, 1.25}) {
    const rig::CampaignResult r =
        test::run_everything(parse_campaign(ans1_turn_at_ratio(at_limit), "t.toml"));
    EXPECT_EQ(r.verdict, Outcome::Pass) << at_limit << ": " << test::failures(r);
  }
  for (const double beyond : {0.749, 1.251}) {
    const rig::CampaignResult r = test::run_everything(parse_campaign(ans1_turn_at_ratio(beyond), "t.toml"));
    EXPECT_EQ(r.verdict, Outcome::Fail) << beyond;
  }
}

// pls2700 manual (seeds/002_46e90574ec92805f.txt:765-772, digest §4.9): a broken transducer cable is a
// transducer fault; with both stators lost the demodulated amplitude is 0 whatever the angle.
TEST(DeviceFaultModels, Pls2700SeesATransducerLossAtEveryAngle) {
  namespace p = models::pls2700;
  for (int deg = 0; deg < 360; deg += 15) {
    EXPECT_FALSE(p::decode_stators(0.0, 0.0, 1.0, 0.5, 1.5).valid) << deg;
    const double t = deg * std::numbers::pi / 180.0;
    EXPECT_TRUE(p::decode_stators(std::sin(t), std::cos(t), 1.0, 0.5, 1.5).valid) << deg;
  }
}

// ---- A device fault as a fault-injection run ([[fault]] with `set` and caught_by)

// The 7361 without a fault: %I read at 12 ms has no E2Err (seeds/004_2d8564fc60a2b9d4.txt:2043-2044,
// bit 13 = 0x1000) and no Acknowledge (bit 15, no host write). The fault run puts the EEPROM
// error in at 10 ms: E2Err set at once ([MODEL]), ACK still 0 (no programming cycle, L1298-1299).
const std::string kSsiChecks = R"([campaign]
name = "t"
end = "20ms"
[dut]
model = "ssi7361"
[[host]]
at = "12ms"
read = 0
name = "status"
[[check]]
kind = "word_bits"
name = "no_e2err"
observation = "status"
mask = 4096
value = 0
[[check]]
kind = "word_bits"
name = "no_ack"
observation = "status"
mask = 32768
value = 0
[[fault]]
name = "eeprom"
set = { device_fault = [ { fault = "eeprom_error", at = "10ms" } ] }
)";

TEST(DeviceFaultAsAFault, ACheckThatJudgesTheFaultCatchesIt) {
  const Campaign c = parse_campaign(kSsiChecks + "caught_by = \"no_e2err\"\n", "t.toml");
  ASSERT_EQ(c.runs.size(), 2U);
  EXPECT_TRUE(c.scenario_of(c.runs[0]).device_faults.empty());
  ASSERT_EQ(c.scenario_of(c.runs[1]).device_faults.size(), 1U);
  EXPECT_EQ(c.scenario_of(c.runs[1]).device_faults[0].at, 10_ms);
  const rig::CampaignResult r = test::run_everything(c);
  EXPECT_EQ(r.totals.faults, 1U);
  EXPECT_EQ(r.totals.faults_caught, 1U);
  EXPECT_EQ(r.verdict, Outcome::Pass) << test::failures(r);
}

TEST(DeviceFaultAsAFault, ACheckBlindToTheFaultLetsItThroughAndTheCampaignFails) {
  const rig::CampaignResult r =
      test::run_everything(parse_campaign(kSsiChecks + "caught_by = \"no_ack\"\n", "t.toml"));
  EXPECT_EQ(r.totals.faults, 1U);
  EXPECT_EQ(r.totals.faults_caught, 0U);
  EXPECT_EQ(r.verdict, Outcome::Fail);
}

TEST(DeviceFaultAsAFault, AFaultNamedAsAVariantIsPointedAtTheSetForm) {
  const std::string text =
      replace_line(kSsiChecks, 24, "variant = \"eeprom_error\"") + "caught_by = \"no_e2err\"\n";
  EXPECT_TRUE(rejected_at(text, "t.toml:24:11: fault[0].variant: a device variant: eeprom_error is a device "
                                "fault of ssi7361; a fault run puts it in with set = { device_fault = ["));
}

TEST(DeviceFaultAsAFault, AFaultTheDeviceLacksInASetIsAnError) {
  const std::string text =
      replace_line(kSsiChecks, 24, "set = { device_fault = [ { fault = \"overheat\", at = \"10ms\" } ] }") +
      "caught_by = \"no_e2err\"\n";
  EXPECT_NE(
      error_of(text).find("fault[0].set: device_fault[0].fault: a fault of ssi7361: one of eeprom_error"),
      std::string::npos)
      << error_of(text);
}

// ---- The shipped campaigns, end to end

struct Shipped {
  const char* device;
  const char* file;
  std::set<std::string> judge_the_fault; // checks that fail on a run without the fault
};

class DeviceFaultCampaign : public ::testing::TestWithParam<Shipped> {};

TEST_P(DeviceFaultCampaign, PassesAndItsChecksJudgeTheFault) {
  const Shipped& p = GetParam();
  Campaign c = load_campaign(test::campaign_dir(p.device) + "/" + p.file);
  ASSERT_FALSE(c.points.at(0).device_faults.empty());
  const rig::CampaignResult pass = test::run_everything(c);
  EXPECT_EQ(pass.verdict, Outcome::Pass) << test::failures(pass);
  for (Scenario& s : c.points) s.device_faults.clear();
  const rig::CampaignResult without = test::run_everything(c);
  EXPECT_EQ(without.verdict, Outcome::Fail);
  std::set<std::string> failed;
  for (const auto& run : without.runs)
    for (const auto& check : run.checks)
      if (check.judgement == rig::Judgement::Fail) failed.insert(check.check);
  EXPECT_EQ(failed, p.judge_the_fault);
}

INSTANTIATE_TEST_SUITE_P(
    Shipped, DeviceFaultCampaign,
    ::testing::Values(
        Shipped{"ssi7361",
                "ssi7361_eeprom.toml",
                // e2clr_clears too: E2CLR alone without E2Err has no effect,
                // CMDErr (L2031, L2120-2121).
                {"e2err_set", "programming_refused", "defaults_low", "defaults_high", "e2clr_clears"}},
        Shipped{"smd23e",
                "smd23e_drive_faults.toml",
                {"power_removed", "driver_fault_set", "no_current_in_fault", "fault_stays_while_hot",
                 "warning_set", "position_invalid"}},
        Shipped{"ans1",
                "ans1_resolver_faults.toml",
                {"open_coil_detected", "outputs_off", "fault_latched", "ratio_detected"}},
        Shipped{"pls2700",
                "pls2700_open_coil.toml",
                {"sin_open_detected", "sin_outputs_off", "sin_latched", "cos_open_detected", "cos_latched",
                 "cos_outputs_off"}},
        Shipped{"pls2700",
                "pls2700_transducer_loss.toml",
                {"fault_word", "outputs_off", "position_latched", "tach_latched", "programming_ignored"}}),
    [](const ::testing::TestParamInfo<Shipped>& p) {
      const std::string file = p.param.file;
      return file.substr(0, file.find('.')); // the campaign's file name without .toml
    });

} // namespace
} // namespace hilrig::campaign
