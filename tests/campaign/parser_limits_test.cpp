// Everything a campaign file can get wrong is refused at parse time (bad input, exit 2) with
// file:line:column, the key and the valid range: non-finite numbers, durations and periods
// outside what the device or the rig can honour, plans too big to hold, adversarial files.
// Line and column numbers are counted by hand in the text of each case.

#include <sys/stat.h>

#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <string>

#include <fmt/format.h>

#include "campaign_text.hpp"
#include "rig/campaign/campaign_parser.hpp"
#include "rig/campaign/duration.hpp"
#include "rig/campaign/limits.hpp"
#include "rig/campaign/toml_file.hpp"
#include "rig/duts/dut.hpp"
#include "tests/tools/scratch_files.hpp"

namespace hilrig::campaign {
namespace {

using test::error_of;
using test::rejected_at;
using test::replace_line;

namespace fs = std::filesystem;

::testing::AssertionResult accepted(const std::string& text) {
  const std::string got = error_of(text);
  if (got == "accepted") return ::testing::AssertionSuccess();
  return ::testing::AssertionFailure() << "refused: " << got;
}

std::string file_error_of(const std::string& path) {
  try {
    (void)load_campaign(path);
    return "accepted";
  } catch (const CampaignError& e) {
    return e.key() + ": " + e.expected();
  }
}

// ---- non-finite numbers (TOML's nan and inf) ------------------------------------------------

TEST(CampaignLimits, NanAndInfAreRefusedWhereverANumberIsExpected) {
  for (const char* v : {"nan", "+nan", "-nan", "inf", "+inf", "-inf"}) {
    // speed_rpm's value starts at column 13.
    EXPECT_TRUE(rejected_at(replace_line(test::kValidCampaign, 21, fmt::format("speed_rpm = {}", v)),
                            "t.toml:21:13: motion.move[0].speed_rpm: a finite number"))
        << v;
    EXPECT_TRUE(
        rejected_at(replace_line(test::kValidCampaign, 18, fmt::format("[motion]\nstart_turns = {}", v)),
                    "t.toml:19:15: motion.start_turns: a finite number"))
        << v;
    // A press stroke's brake angle passed the old [0, 360) test as nan (every comparison false).
    EXPECT_TRUE(rejected_at(replace_line(test::kValidCampaign, 20,
                                         fmt::format("kind = \"press_stroke\"\ndecel_rpm_s = 100\n"
                                                     "brake_at_deg = {}",
                                                     v)),
                            "t.toml:22:16: motion.move[0].brake_at_deg: a finite number"))
        << v;
  }
}

// ---- durations and periods outside the device's range -----------------------------------------

TEST(CampaignLimits, ScanSweptAcrossTheReferencePlsRange) {
  // reference_pls declares scan in 1us .. 100ms (rig/duts/reference_pls.cpp); line 7 col 8.
  const std::string want = "t.toml:7:8: dut.params.scan: a value in 1us .. 100ms";
  for (const char* bad : {"\"-1ms\"", "\"0ns\"", "\"1ns\"", "\"999ns\"", "\"100000001ns\"", "\"1s\""})
    EXPECT_TRUE(
        rejected_at(replace_line(test::kValidCampaign, 7, fmt::format("scan = {}\non = 10", bad)), want))
        << bad;
  for (const char* good : {"\"1us\"", "\"1001ns\"", "\"200us\"", "\"99999999ns\"", "\"100ms\""})
    EXPECT_TRUE(accepted(replace_line(test::kValidCampaign, 7, fmt::format("scan = {}\non = 10", good))))
        << good;
}

TEST(CampaignLimits, NegativeDelaysAreRefused) {
  EXPECT_TRUE(rejected_at(replace_line(test::kValidCampaign, 7, "delay = \"-1ns\"\non = 10"),
                          "t.toml:7:9: dut.params.delay: a value in 0s .. 1s"));
  EXPECT_TRUE(accepted(replace_line(test::kValidCampaign, 7, "delay = \"0ns\"\non = 10")));
  EXPECT_TRUE(rejected_at(replace_line(test::kValidCampaign, 7, "filter = \"-5ms\"\non = 10"),
                          "t.toml:7:10: dut.params.filter: a value in 0s .. 1s"));
}

TEST(CampaignLimits, CountsOutsideTheHostWordAreRefused) {
  // The reference PLS's counts travel in 16-bit host words: -32768 .. 32767.
  EXPECT_TRUE(accepted(replace_line(test::kValidCampaign, 8, "off = 32767")));
  EXPECT_TRUE(rejected_at(replace_line(test::kValidCampaign, 8, "off = 32768"),
                          "t.toml:8:7: dut.params.off: a value in -32768 .. 32767"));
  EXPECT_TRUE(accepted(replace_line(test::kValidCampaign, 7, "on = -32768")));
  EXPECT_TRUE(rejected_at(replace_line(test::kValidCampaign, 7, "on = -32769"),
                          "t.toml:7:6: dut.params.on: a value in -32768 .. 32767"));
}

TEST(CampaignLimits, CampaignTimesOutsideTheRigsRangeAreRefused) {
  // end: 1 ns .. 1 h (limits::kMaxEnd); line 3 col 7.
  EXPECT_TRUE(rejected_at(replace_line(test::kValidCampaign, 3, "end = \"3600000000001ns\""),
                          "t.toml:3:7: campaign.end: a duration in 1ns .. 3600s"));
  EXPECT_TRUE(accepted(replace_line(test::kValidCampaign, 3, "end = \"3600s\"")));
  EXPECT_TRUE(
      rejected_at(replace_line(test::kValidCampaign, 3, "end = \"-1s\""), "t.toml:3:7: campaign.end:"));
  // host_poll: 10 us .. 1 s (a 1 ns poll is 10^9 polls per virtual second).
  for (const char* bad : {"\"1ns\"", "\"9999ns\"", "\"0us\"", "\"-1ms\"", "\"1000000001ns\""})
    EXPECT_TRUE(rejected_at(
        replace_line(test::kValidCampaign, 3, fmt::format("end = \"100ms\"\nhost_poll = {}", bad)),
        "t.toml:4:13: campaign.host_poll: a duration in 10us .. 1s"))
        << bad;
  for (const char* good : {"\"10us\"", "\"10001ns\"", "\"1s\""})
    EXPECT_TRUE(
        accepted(replace_line(test::kValidCampaign, 3, fmt::format("end = \"100ms\"\nhost_poll = {}", good))))
        << good;
  EXPECT_TRUE(rejected_at(replace_line(test::kValidCampaign, 3, "end = \"100ms\"\nedge_tolerance = \"-1us\""),
                          "t.toml:4:18: campaign.edge_tolerance: a duration in 1ns .. 1s"));
}

// A duration too long for 64-bit nanoseconds is a duration out of range, not "a duration with a
// unit" missing: the key's range is named as for one just past it (docs/campaigns.md, "Ranges
// and limits"), either sign; one too short to hold is 0 ns, as 0.4ns rounds.
TEST(CampaignLimits, DurationsTooLongToHoldAreOutOfTheKeysRange) {
  for (const char* too_long : {"\"99999999999999999999s\"", "\"1e400s\"", "\"20000000000000000000000ns\"",
                               "\"9000000001s\"", "\"-1e400s\""})
    EXPECT_TRUE(rejected_at(replace_line(test::kValidCampaign, 3, fmt::format("end = {}", too_long)),
                            "t.toml:3:7: campaign.end: a duration in 1ns .. 3600s"))
        << too_long;
  EXPECT_TRUE(rejected_at(replace_line(test::kValidCampaign, 3, "end = \"1e-400s\""),
                          "t.toml:3:7: campaign.end: a duration in 1ns .. 3600s"));
  // A swept one and a device parameter name their own ranges.
  EXPECT_TRUE(
      rejected_at(test::kValidCampaign + "[[sweep]]\nkey = \"dut.params.scan\"\nvalues = [\"1e400s\"]\n",
                  "t.toml:33:11: dut.params.scan: a value in 1us .. 100ms"));
  // Still not a duration: no unit, or not a number.
  EXPECT_TRUE(rejected_at(replace_line(test::kValidCampaign, 3, "end = \"1e400\""),
                          "t.toml:3:7: campaign.end: expected a duration with a unit"));
  EXPECT_TRUE(rejected_at(replace_line(test::kValidCampaign, 3, "end = \"infs\""),
                          "t.toml:3:7: campaign.end: expected a duration with a unit"));
}

TEST(CampaignLimits, DurationTextIsClampedOnlyBeyondWhatItHolds) {
  EXPECT_EQ(parse_duration_clamped("9000000000s"), kMaxDurationText); // the longest held, exactly
  EXPECT_EQ(parse_duration("9000000000s"), kMaxDurationText);
  EXPECT_EQ(parse_duration_clamped("9000000001s"), kMaxDurationText); // one second beyond: clamped
  EXPECT_EQ(parse_duration("9000000001s"), std::nullopt);             // and refused unclamped
  EXPECT_EQ(parse_duration_clamped("-1e400s"), Nanos{-kMaxDurationText.count()});
  EXPECT_EQ(parse_duration_clamped("1e-400s"), Nanos{0});
  EXPECT_EQ(parse_duration_clamped("1e400"), std::nullopt); // no unit
  EXPECT_EQ(parse_duration_clamped("nans"), std::nullopt);
}

// What is wrong with a text that is no duration is said: a word that is not a unit is named.
TEST(CampaignLimits, TextThatIsNoDurationSaysWhy) {
  EXPECT_EQ(duration_text_problem("100h"), "\"h\" is not a unit (one of ns, us, ms or s)");
  EXPECT_EQ(duration_text_problem("60min"), "\"min\" is not a unit (one of ns, us, ms or s)");
  EXPECT_EQ(duration_text_problem("60"), "no unit (one of ns, us, ms or s)");
  EXPECT_EQ(duration_text_problem("ms"), "no number before a unit (ns, us, ms or s)");
  EXPECT_EQ(duration_text_problem("6x0s"), "\"6x0\" is not a finite number");
  // A duration, or one too long to hold (a range check names that), has nothing wrong as text.
  for (const char* text : {"60s", "1ns", "9000000000s", "9000000001s", "1e400s"})
    EXPECT_EQ(duration_text_problem(text), "") << text;
}

// ---- speeds the rig cannot make ------------------------------------------------------------

TEST(CampaignLimits, SpeedsBeyondTheSpeedWordAreRefused) {
  // +-32767 rpm: the boards' signed rpm word (docs/spec/ans1.md L1024). 100 lines make 218,447
  // counts/s at that speed, under the 10^6 counts/s bound.
  const std::string want = "t.toml:21:13: motion.move[0].speed_rpm: a speed in rpm in -32767 .. 32767";
  for (const char* bad : {"9.2e18", "1e12", "32767.01", "-32767.01", "32768"})
    EXPECT_TRUE(rejected_at(replace_line(test::kValidCampaign, 21, fmt::format("speed_rpm = {}", bad)), want))
        << bad;
  for (const char* good : {"32767", "-32767", "32766.99", "0"})
    EXPECT_TRUE(accepted(replace_line(test::kValidCampaign, 21, fmt::format("speed_rpm = {}", good))))
        << good;
  EXPECT_TRUE(rejected_at(replace_line(test::kValidCampaign, 20, "kind = \"accelerate\"\nto_rpm = 1e12"),
                          "t.toml:21:10: motion.move[0].to_rpm: a speed in rpm in -32767 .. 32767"));
}

TEST(CampaignLimits, EncoderCountRateBoundsTheSpeed) {
  // 1000 lines = 4000 counts/turn; 10^6 counts/s (docs/spec/amci4501.md L292) is 15000 rpm.
  const std::string lines1000 = replace_line(test::kValidCampaign, 30, "lines = 1000");
  EXPECT_TRUE(accepted(replace_line(lines1000, 21, "speed_rpm = 15000")));
  EXPECT_TRUE(accepted(replace_line(lines1000, 21, "speed_rpm = -15000")));
  EXPECT_TRUE(rejected_at(replace_line(lines1000, 21, "speed_rpm = 15000.01"),
                          "t.toml:21:13: motion.move[0].speed_rpm: a speed in rpm in -15000 .. 15000 "
                          "(1000000 counts/s at most from the 1000-line encoder)"));
}

TEST(CampaignLimits, TrapezoidAndPressBoundsAreRefused) {
  const std::string trap =
      replace_line(test::kValidCampaign, 20, "kind = \"trapezoid\"\naccel_rpm_s = 100\nturns = 1");
  // Lines 20..24 now: kind, accel, turns, speed_rpm = 60, duration (unknown for a trapezoid).
  const std::string t = replace_line(trap, 24, "");
  EXPECT_TRUE(accepted(t));
  EXPECT_TRUE(rejected_at(replace_line(t, 23, "speed_rpm = 0.001"),
                          "t.toml:23:13: motion.move[0].speed_rpm: a cruise speed in rpm in 0.01 .. 32767"));
  EXPECT_TRUE(
      rejected_at(replace_line(t, 21, "accel_rpm_s = 1e300"),
                  "t.toml:21:15: motion.move[0].accel_rpm_s: a rate in rpm/s above 0, at most 1000000"));
  EXPECT_TRUE(rejected_at(replace_line(t, 22, "turns = 1e9"),
                          "t.toml:22:9: motion.move[0].turns: a distance in turns in -10000 .. 10000"));
  // 10000 turns at 600 rpm (10 turns/s) take 1000 s; at 60 rpm 10000 s, more than a run's hour.
  EXPECT_TRUE(accepted(replace_line(replace_line(t, 23, "speed_rpm = 600"), 22, "turns = -10000")));
  EXPECT_TRUE(rejected_at(replace_line(t, 22, "turns = -10000"),
                          "t.toml:23:13: motion.move[0].speed_rpm: a move that ends within 3600 s"));
}

// ---- values only a run found before: now the parser ------------------------------------------

const std::string kPls2700 = R"([campaign]
name = "t"
end = "10ms"
[dut]
model = "pls2700"
[dut.params]
model = "2742"
[[wiring]]
rig = "ls1"
board = "OUT1"
[[check]]
kind = "pulse_width"
name = "out"
line = "ls1"
)";

TEST(CampaignLimits, UnknownSeries2700ModelIsBadInputNotARigFault) {
  EXPECT_TRUE(accepted(kPls2700));
  // 2731 .. 2742-18: the seven models of docs/spec/pls2700.md; line 7 col 9.
  EXPECT_TRUE(rejected_at(replace_line(kPls2700, 7, "model = \"2799\""),
                          "t.toml:7:9: dut.params.model: one of 2731, 2731-04, 2732, 2732-04, 2741, 2742, "
                          "2742-18"));
  EXPECT_TRUE(rejected_at(replace_line(kPls2700, 7, "reverse_advance = \"sideways\""),
                          "t.toml:7:19: dut.params.reverse_advance: one of signed, disabled"));
  EXPECT_TRUE(rejected_at(replace_line(kPls2700, 7, "excitation_hz = 1e12"),
                          "t.toml:7:17: dut.params.excitation_hz: a value in 1250 .. 10000"));
  EXPECT_TRUE(rejected_at(replace_line(kPls2700, 7, "excitation_hz = nan"),
                          "t.toml:7:17: dut.params.excitation_hz: a finite number"));
}

// The module's update period is "always 200 microseconds for single channel units and 400
// microseconds for two channel units" (L377, L455-L457), and the model samples at a reference
// peak at each update (models/pls2700/README.md "Decoder"): a reference is taken only where
// its half period 1/(2f) divides that period, f a multiple of 1/(2 * 200 us) = 2,500 Hz on a
// 2741, of 1/(2 * 400 us) = 1,250 Hz on a 2742, up to 10 kHz. One hertz beside each is refused
// at the key's line (line 8, col 17: "excitation_hz = " is 16 characters).
TEST(CampaignLimits, Series2700ReferenceMustFallOnTheUpdateGrid) {
  const auto with = [](const char* model, const std::string& hz) {
    return replace_line(kPls2700, 7, fmt::format("model = \"{}\"\nexcitation_hz = {}", model, hz));
  };
  const std::string on_2741 =
      "t.toml:8:17: dut.params.excitation_hz: a reference whose half period 1/(2f) "
      "divides the 2741's 200 us update, so every update samples at a peak "
      "(models/pls2700/README.md \"Decoder\", L377): a multiple of 2500 Hz up to 10000: 2500, "
      "5000, 7500, 10000 (got ";
  for (const int hz : {2500, 5000, 7500, 10000}) {
    EXPECT_TRUE(accepted(with("2741", std::to_string(hz)))) << hz;
    EXPECT_TRUE(rejected_at(with("2741", std::to_string(hz - 1)), on_2741 + std::to_string(hz - 1) + " Hz)"))
        << hz - 1;
    if (hz < 10000) {
      EXPECT_TRUE(
          rejected_at(with("2741", std::to_string(hz + 1)), on_2741 + std::to_string(hz + 1) + " Hz)"))
          << hz + 1;
    }
  }
  // A hair off a valid frequency is off the grid too (exact, not a float that rounds to it).
  EXPECT_TRUE(rejected_at(with("2741", "5000.000000001"), on_2741 + "5000.000000001 Hz)"));
  EXPECT_TRUE(rejected_at(with("2741", "3000"), on_2741 + "3000 Hz)")); // the examiner's 359 us case
  EXPECT_TRUE(rejected_at(with("2741", "1250"), on_2741 + "1250 Hz)")); // a two-channel module's only
  EXPECT_TRUE(
      rejected_at(with("2741", "10001"), "t.toml:8:17: dut.params.excitation_hz: a value in 1250 .. 10000"));
  const std::string on_2742 =
      "t.toml:8:17: dut.params.excitation_hz: a reference whose half period 1/(2f) "
      "divides the 2742's 400 us update, so every update samples at a peak "
      "(models/pls2700/README.md \"Decoder\", L377): a multiple of 1250 Hz up to 10000: 1250, "
      "2500, 3750, 5000, 6250, 7500, 8750, 10000 (got ";
  for (const int hz : {1250, 3750, 8750}) {
    EXPECT_TRUE(accepted(with("2742", std::to_string(hz)))) << hz;
    EXPECT_TRUE(rejected_at(with("2742", std::to_string(hz + 1)), on_2742 + std::to_string(hz + 1) + " Hz)"))
        << hz + 1;
  }
  EXPECT_TRUE(
      rejected_at(with("2742", "1249"), "t.toml:8:17: dut.params.excitation_hz: a value in 1250 .. 10000"));
  EXPECT_TRUE(rejected_at(with("2742", "3749"), on_2742 + "3749 Hz)"));
  // A swept frequency is checked at each point, pointed at in the sweep's values (line 17).
  EXPECT_TRUE(
      rejected_at(replace_line(kPls2700, 7, "model = \"2741\"") +
                      "[[sweep]]\nkey = \"dut.params.excitation_hz\"\nvalues = [5000, 3000]\n",
                  on_2741.substr(0, 7) + "17:17: dut.params.excitation_hz: a reference whose half period"));
  // Written before the model, the frequency is still the key pointed at (line 7).
  EXPECT_TRUE(rejected_at(replace_line(kPls2700, 7, "excitation_hz = 3000\nmodel = \"2741\""),
                          "t.toml:7:17: dut.params.excitation_hz: a reference whose half period"));
}

// The transducer-fault band [min_stator_ratio, max_stator_ratio] is closed (models/pls2700/
// README.md "Decoder"): equal ends are a band of one ratio, accepted; a minimum above the
// maximum holds no ratio (a fault whatever the signal) and is refused, naming both keys, at the
// line of the one given (the minimum when both are).
TEST(CampaignLimits, Series2700FaultBandMinimumIsAtMostItsMaximum) {
  const auto band = [](const std::string& lines) { return replace_line(kPls2700, 7, lines); };
  const std::string says = "dut.params.min_stator_ratio: min_stator_ratio at most max_stator_ratio: the "
                           "transducer-fault band [min_stator_ratio, max_stator_ratio] is empty with ";
  EXPECT_TRUE(accepted(band("min_stator_ratio = 1.0\nmax_stator_ratio = 1.0")));
  EXPECT_TRUE(accepted(band("min_stator_ratio = 0.999999999999\nmax_stator_ratio = 1.0")));
  EXPECT_TRUE(rejected_at(band("min_stator_ratio = 1.000000000001\nmax_stator_ratio = 1.0"),
                          "t.toml:7:20: " + says + "1.000000000001 > 1, a fault whatever the signal"));
  EXPECT_TRUE(rejected_at(band("max_stator_ratio = 0.5\nmin_stator_ratio = 0.6"),
                          "t.toml:8:20: " + says + "0.6 > 0.5"));
  // One end given against the other's default (0.5 .. 1.5, README "Parameters"): that end.
  EXPECT_TRUE(accepted(band("min_stator_ratio = 1.5")));
  EXPECT_TRUE(rejected_at(band("min_stator_ratio = 1.6"), "t.toml:7:20: " + says + "1.6 > 1.5"));
  EXPECT_TRUE(accepted(band("max_stator_ratio = 0.5")));
  EXPECT_TRUE(
      rejected_at(band("max_stator_ratio = 0.4"),
                  "t.toml:7:20: dut.params.max_stator_ratio: min_stator_ratio at most max_stator_ratio: "
                  "the transducer-fault band [min_stator_ratio, max_stator_ratio] is empty with 0.5 > 0.4"));
}

TEST(CampaignLimits, SweptValuesAreCheckedAgainstTheSameRanges) {
  // The second value of the axis (line 33, col 20) is out of reference_pls's scan range.
  const std::string text =
      test::kValidCampaign + "[[sweep]]\nkey = \"dut.params.scan\"\nvalues = [\"200us\", \"1ns\"]\n";
  EXPECT_TRUE(rejected_at(text, "t.toml:33:20: dut.params.scan: a value in 1us .. 100ms"));
}

// Every device declares a finite range for each numeric parameter and the words of each text
// parameter, and its defaults lie inside them (a device cannot forget one).
TEST(CampaignLimits, EveryDeviceParameterDeclaresARangeHoldingItsDefault) {
  for (const duts::DutInfo& d : duts::dut_registry()) {
    for (const duts::ParamInfo& p : d.params) {
      SCOPED_TRACE(d.name + "." + p.name);
      EXPECT_TRUE(duts::in_range(p.range, p.default_value));
      if (p.kind == duts::ParamKind::Text) {
        EXPECT_FALSE(p.range.choices.empty());
      }
      if (p.kind == duts::ParamKind::Integer || p.kind == duts::ParamKind::Number ||
          p.kind == duts::ParamKind::Duration) {
        EXPECT_TRUE(std::isfinite(p.range.min) && std::isfinite(p.range.max));
        EXPECT_LE(p.range.min, p.range.max);
      }
      // A duration never below 0: a negative delay or period is not a time the rig can wait.
      // A detection-power knob ("[KNOB]", docs/power.md) is a signed error added to a time the
      // board keeps: it may be negative, and its default is the manual's timing, an error of 0.
      if (p.kind == duts::ParamKind::Duration) {
        if (p.description.rfind("[KNOB]", 0) == 0) {
          EXPECT_EQ(std::get<Nanos>(p.default_value), Nanos{0});
          EXPECT_LE(p.range.min, 0.0);
          EXPECT_GE(p.range.max, 0.0);
        } else {
          EXPECT_GE(p.range.min, 0.0);
        }
      }
    }
  }
}

// ---- plans too big to hold -----------------------------------------------------------------

TEST(CampaignLimits, RepeatIsBoundedNotAnOutOfMemory) {
  // repeat = 100000000 died with bad_alloc (exit 3); now line 4 col 10 names the bound.
  EXPECT_TRUE(rejected_at(replace_line(test::kValidCampaign, 3, "end = \"100ms\"\nrepeat = 100000000"),
                          "t.toml:4:10: campaign.repeat: a repetition count in 1 .. 10000"));
  EXPECT_TRUE(rejected_at(replace_line(test::kValidCampaign, 3, "end = \"100ms\"\nrepeat = 10001"),
                          "t.toml:4:10: campaign.repeat: a repetition count in 1 .. 10000"));
  const Campaign c =
      parse_campaign(replace_line(test::kValidCampaign, 3, "end = \"100ms\"\nrepeat = 10000"), "t.toml");
  EXPECT_EQ(c.runs.size(), 10'000U);
}

TEST(CampaignLimits, PlanOfMoreThanTenThousandRunsIsRefused) {
  // 2 sweep points x 5000 repeats = 10,000 runs: the bound; 5001 repeats is 10,002.
  const std::string sweep = "[[sweep]]\nkey = \"dut.params.delay\"\nvalues = [\"50us\", \"60us\"]\n";
  const Campaign c = parse_campaign(
      replace_line(test::kValidCampaign, 3, "end = \"100ms\"\nrepeat = 5000") + sweep, "t.toml");
  EXPECT_EQ(c.runs.size(), 10'000U);
  EXPECT_TRUE(rejected_at(replace_line(test::kValidCampaign, 3, "end = \"100ms\"\nrepeat = 5001") + sweep,
                          "t.toml:4:10: campaign.repeat: a plan of at most 10000 runs (2 sweep point(s) x "
                          "(5001 repeat + 0 fault(s)) is 10002)"));
}

TEST(CampaignLimits, SweepOfMoreThanAThousandPointsIsRefusedBeforeItIsBuilt) {
  // Two axes of 40 values are 1600 points; eleven axes of 100 values would overflow a size_t
  // product if it were computed first. Axis 1's key (line 35) is where the bound is crossed.
  std::string values;
  for (int i = 0; i < 40; ++i) values += fmt::format("{}\"{}us\"", i == 0 ? "" : ", ", 50 + i);
  const std::string text = test::kValidCampaign + "[[sweep]]\nkey = \"dut.params.delay\"\nvalues = [" +
                           values + "]\n[[sweep]]\nkey = \"dut.params.filter\"\nvalues = [" + values + "]\n";
  EXPECT_TRUE(rejected_at(text, "t.toml:35:7: sweep: at most 1000 sweep points"));
  std::string many;
  for (int a = 0; a < 11; ++a) {
    std::string v;
    for (int i = 0; i < 100; ++i) v += fmt::format("{}{}", i == 0 ? "" : ", ", i);
    many += fmt::format("[[sweep]]\nkey = \"motion.move[0].x{}\"\nvalues = [{}]\n", a, v);
  }
  EXPECT_TRUE(rejected_at(test::kValidCampaign + many, "t.toml:35:7: sweep: at most 1000 sweep points"));
}

TEST(CampaignLimits, HugeArrayIndexInASweepKeyIsBadInputNotAnUncaughtException) {
  // std::stoull threw std::out_of_range for a 30-digit index, past every catch of `hilrig run`.
  EXPECT_TRUE(rejected_at(test::kValidCampaign +
                              "[[sweep]]\nkey = \"motion.move[999999999999999999999999999999].speed_rpm\"\n"
                              "values = [1, 2]\n",
                          "t.toml:32:7: sweep[0].key: a key path in this file"));
  EXPECT_TRUE(rejected_at(test::kValidCampaign +
                              "[[sweep]]\nkey = \"motion.move[1000000000].speed_rpm\"\nvalues = [1]\n",
                          "t.toml:32:7: sweep[0].key: a key path in this file"));
}

// ---- adversarial files ----------------------------------------------------------------------

std::string dotted(std::size_t parts) {
  std::string key = "a";
  for (std::size_t i = 1; i < parts; ++i) key += ".a";
  return key;
}

TEST(CampaignLimits, FiftyThousandPartDottedKeyIsRefusedNotACrash) {
  // It overflowed the stack inside toml++ (a table nested per part).
  EXPECT_TRUE(rejected_at(test::kValidCampaign + dotted(50'000) + " = 1\n",
                          "t.toml:31:2: toml: a dotted key or table name of at most 64 parts"));
  EXPECT_TRUE(rejected_at(test::kValidCampaign + "[" + dotted(50'000) + "]\n",
                          "t.toml:31:3: toml: a dotted key or table name of at most 64 parts"));
  EXPECT_TRUE(rejected_at(test::kValidCampaign + "[[" + dotted(50'000) + "]]\n",
                          "t.toml:31:4: toml: a dotted key or table name of at most 64 parts"));
  // Quoted parts count as parts; blanks around the dots do not hide them.
  std::string quoted = "\"a\"";
  for (int i = 1; i < 65; ++i) quoted += " . \"a\"";
  EXPECT_TRUE(rejected_at(test::kValidCampaign + quoted + " = 1\n", "t.toml:31:"));
}

TEST(CampaignLimits, KeyPartBoundIsExactAndIgnoresDotsInValues) {
  // 64 parts pass the bound (and are then an unknown key of [encoder]); 65 do not.
  EXPECT_TRUE(
      rejected_at(test::kValidCampaign + dotted(64) + " = 1\n", "t.toml:31:1: encoder.a: unknown key"));
  EXPECT_TRUE(rejected_at(test::kValidCampaign + dotted(65) + " = 1\n", "t.toml:31:2: toml: a dotted key"));
  // Dots inside strings, comments and a row of floats are no key parts.
  std::string dots(1000, '.');
  std::string floats;
  for (int i = 0; i < 200; ++i) floats += fmt::format("{}{}.5", i == 0 ? "" : ", ", i);
  EXPECT_EQ(error_of(replace_line(test::kValidCampaign, 2,
                                  "name = \"t\"\ndescription = \"t" + dots + "\" # " + dots)),
            "accepted");
  EXPECT_EQ(error_of(replace_line(test::kValidCampaign, 2,
                                  "description = '''" + dots + "\n" + dots + "'''\nname = \"t\"")),
            "accepted");
  EXPECT_EQ(
      error_of(test::kValidCampaign + "[[sweep]]\nkey = \"motion.start_turns\"\nvalues = [" + floats + "]\n"),
      "accepted");
}

TEST(CampaignLimits, DeeplyNestedValuesAreRefusedNotACrash) {
  std::string arrays = "x = " + std::string(10'000, '[') + std::string(10'000, ']') + "\n";
  EXPECT_TRUE(rejected_at(test::kValidCampaign + arrays, "t.toml:31:"));
  std::string tables = "x = ";
  for (int i = 0; i < 10'000; ++i) tables += "{a = ";
  tables += "1" + std::string(10'000, '}') + "\n";
  EXPECT_TRUE(rejected_at(test::kValidCampaign + tables, "t.toml:31:"));
}

TEST(CampaignLimits, OnlyARegularFileOfAtMostOneMebibyteIsRead) {
  const fs::path dir = hilrig::test::scratch_dir("campaign", "file_kinds");
  EXPECT_EQ(file_error_of(dir.string()),
            "file: a regular campaign file (" + dir.string() + " is a directory)");
  const fs::path fifo = dir / "fifo.toml";
  ASSERT_EQ(mkfifo(fifo.c_str(), 0600), 0);
  EXPECT_EQ(file_error_of(fifo.string()), "file: a regular campaign file (" + fifo.string() + " is a FIFO)");
  EXPECT_EQ(file_error_of("/dev/zero"), "file: a regular campaign file (/dev/zero is a device)");
  // Exactly the cap is read; one byte more is refused (a comment pads the valid campaign).
  const std::size_t cap = limits::kMaxFileBytes;
  std::string text = test::kValidCampaign + "#";
  text += std::string(cap - text.size() - 1, 'x') + "\n";
  ASSERT_EQ(text.size(), cap);
  EXPECT_EQ(file_error_of(hilrig::test::write_file(dir, "cap.toml", text).string()), "accepted");
  EXPECT_EQ(file_error_of(hilrig::test::write_file(dir, "over.toml", text + "\n").string()),
            "file: a campaign file of at most 1048576 bytes");
}

// A campaign file's path is written into results.json, junit.xml and report.html (UTF-8): a
// path that is not UTF-8 (a Latin-1 name, a cut sequence, an overlong form, a surrogate) is bad
// input before anything runs, not a rig fault after; a UTF-8 name of 2, 3 and 4 bytes is read.
TEST(CampaignLimits, APathThatIsNotUtf8IsBadInput) {
  const fs::path dir = hilrig::test::scratch_dir("campaign", "utf8_names");
  for (const char* bad : {"caf\xe9.toml", "cut\xc3.toml", "over\xc0\xaf.toml", "sur\xed\xa0\x80.toml"}) {
    const fs::path path = hilrig::test::write_file(dir, bad, test::kValidCampaign);
    EXPECT_EQ(file_error_of(path.string()),
              "file: a campaign file whose path is valid UTF-8 (the outputs name it): rename it")
        << bad;
  }
  for (const char* good : {"caf\xc3\xa9.toml", "\xe2\x82\xac.toml", "\xf0\x9f\x94\xa7.toml"})
    EXPECT_EQ(file_error_of(hilrig::test::write_file(dir, good, test::kValidCampaign).string()), "accepted")
        << good;
}

TEST(CampaignLimits, AFileOfSeveralReadChunksIsReadByteForByte) {
  // read_toml_text reads in 16 KiB chunks: a text of 2.5 chunks, every byte value but NUL,
  // comes back whole and in order.
  const fs::path dir = hilrig::test::scratch_dir("campaign", "chunks");
  std::string text;
  for (std::size_t i = 0; i < 40960; ++i) text += static_cast<char>(1 + i % 255);
  EXPECT_EQ(read_toml_text(hilrig::test::write_file(dir, "chunks.toml", text).string(), "campaign file"),
            text);
  EXPECT_EQ(read_toml_text(hilrig::test::write_file(dir, "empty.toml", "").string(), "campaign file"), "");
}

} // namespace
} // namespace hilrig::campaign
