// A malformed or inconsistent campaign is rejected before anything runs, with
// "file:line:column: key: what was expected". Line and column numbers below are counted by
// hand in the text of each case (line 1 is the first line of the raw string).

#include <gtest/gtest.h>

#include <fmt/format.h>

#include <string>

#include "campaign_text.hpp"
#include "rig/campaign/campaign_parser.hpp"

namespace hilrig::campaign {
namespace {

using test::error_of;
using test::rejected_at;
using test::replace_line;

using namespace hilrig::literals;

TEST(CampaignParser, BaseCampaignIsAccepted) {
  const Campaign c = parse_campaign(test::kValidCampaign, "t.toml");
  EXPECT_EQ(c.name, "t");
  ASSERT_EQ(c.points.size(), 1U);
  EXPECT_EQ(c.points[0].end, 100_ms);
  EXPECT_EQ(c.points[0].wiring.size(), 3U);
  EXPECT_EQ(c.points[0].encoder.lines, 100);
  EXPECT_EQ(std::get<std::int64_t>(c.points[0].dut.params.at("on").value), 10);
  // Parameters not written take the model's defaults (reference_pls scan = 200 us).
  EXPECT_EQ(std::get<Nanos>(c.points[0].dut.params.at("scan").value), 200_us);
  ASSERT_EQ(c.runs.size(), 1U);
}

TEST(CampaignParser, EdgeToleranceIsTheCampaignsOwnWhenSet) {
  EXPECT_FALSE(parse_campaign(test::kValidCampaign, "t.toml").points[0].edge_tolerance.has_value());
  const Campaign c = parse_campaign(
      replace_line(test::kValidCampaign, 3, "end = \"100ms\"\nedge_tolerance = \"20us\""), "t.toml");
  EXPECT_EQ(c.points[0].edge_tolerance, 20_us);
  // Line 4 is the new key; its value starts at column 18.
  const std::string error =
      error_of(replace_line(test::kValidCampaign, 3, "end = \"100ms\"\nedge_tolerance = \"0us\""));
  EXPECT_EQ(error.rfind("t.toml:4:18: campaign.edge_tolerance: ", 0), 0U) << error;
}

// [dut] serial (issue 18, traceability): a string of 1..64 printable ASCII characters that the
// outputs carry; anything else is bad input at the value (line 6, column 10: `serial = `).
TEST(CampaignParser, DutSerialIsALabelOfAtMost64PrintableCharacters) {
  const auto with = [](const std::string& value) {
    return replace_line(test::kValidCampaign, 5, "model = \"reference_pls\"\nserial = " + value);
  };
  EXPECT_EQ(parse_campaign(test::kValidCampaign, "t.toml").points[0].dut.serial, ""); // not given
  EXPECT_EQ(parse_campaign(with("\"SN 0042/A\""), "t.toml").points[0].dut.serial, "SN 0042/A");
  const std::string range =
      "t.toml:6:10: dut.serial: the board's serial number: 1 .. 64 printable ASCII characters";
  for (std::size_t n : {1U, 2U, 63U, 64U})
    EXPECT_EQ(parse_campaign(with("\"" + std::string(n, 'x') + "\""), "t.toml").points[0].dut.serial.size(),
              n);
  for (std::size_t n : {0U, 65U, 66U})
    EXPECT_TRUE(rejected_at(with("\"" + std::string(n, 'x') + "\""), range)) << n;
  EXPECT_TRUE(rejected_at(with("\"a\\tb\""), range));     // a control character
  EXPECT_TRUE(rejected_at(with("\"\u00b5-42\""), range)); // not ASCII
  EXPECT_TRUE(rejected_at(with("42"), "t.toml:6:10: dut.serial: expected a string"));
}

TEST(CampaignParser, TomlSyntaxErrorGivesItsPosition) {
  // Line 7 "on = = 10": toml++ reports the second '=' at column 6.
  EXPECT_TRUE(rejected_at(replace_line(test::kValidCampaign, 7, "on = = 10"), "t.toml:7:"));
}

TEST(CampaignParser, UnknownTopLevelKeyIsAnError) {
  EXPECT_TRUE(rejected_at(test::kValidCampaign + "[motoin]\n", "t.toml:31:2: motoin: unknown key"));
}

TEST(CampaignParser, UnknownKeyInATableIsAnError) {
  // "lenes" instead of "lines" on line 30.
  EXPECT_TRUE(rejected_at(replace_line(test::kValidCampaign, 30, "lenes = 100"),
                          "t.toml:30:1: encoder.lenes: unknown key"));
}

TEST(CampaignParser, UnknownDutParameterIsAnError) {
  EXPECT_TRUE(rejected_at(replace_line(test::kValidCampaign, 8, "of = 20"),
                          "t.toml:8:1: dut.params.of: unknown key"));
}

TEST(CampaignParser, UnknownCheckParameterIsAnError) {
  // The check registry rejects "limit" (it takes limit_us); the error points at the key's value.
  EXPECT_TRUE(
      rejected_at(replace_line(test::kValidCampaign, 28, "limit = 250"), "t.toml:28:9: check[0].limit:"));
}

TEST(CampaignParser, MissingRequiredCheckParameterNamesIt) {
  EXPECT_TRUE(rejected_at(replace_line(test::kValidCampaign, 28, ""), "t.toml:23:1: check[0].limit_us:"));
}

TEST(CampaignParser, WrongTypeIsAnError) {
  EXPECT_TRUE(rejected_at(replace_line(test::kValidCampaign, 7, "on = \"ten\""),
                          "t.toml:7:6: dut.params.on: expected an integer"));
}

TEST(CampaignParser, DurationWithoutUnitIsAnError) {
  EXPECT_TRUE(rejected_at(replace_line(test::kValidCampaign, 3, "end = 100"),
                          "t.toml:3:7: campaign.end: expected a duration"));
  EXPECT_TRUE(rejected_at(replace_line(test::kValidCampaign, 3, "end = \"100\""),
                          "t.toml:3:7: campaign.end: expected a duration"));
}

TEST(CampaignParser, UnknownModelIsAnError) {
  EXPECT_TRUE(rejected_at(replace_line(test::kValidCampaign, 5, "model = \"pls9000\""),
                          "t.toml:5:9: dut.model: a device model"));
}

TEST(CampaignParser, UnknownVariantIsAnError) {
  EXPECT_TRUE(
      rejected_at(replace_line(test::kValidCampaign, 5, "model = \"reference_pls\"\nvariant = \"early\""),
                  "t.toml:6:11: dut.variant: a variant of reference_pls"));
}

TEST(CampaignParser, WiringToAPinTheDutLacksIsAnError) {
  EXPECT_TRUE(rejected_at(replace_line(test::kValidCampaign, 17, "board = \"OUT2\""),
                          "t.toml:17:9: wiring[2].board: a pin of"));
}

TEST(CampaignParser, PinWiredTwiceIsAnError) {
  EXPECT_TRUE(rejected_at(replace_line(test::kValidCampaign, 17, "board = \"A\""),
                          "t.toml:17:9: wiring[2].board: each board pin"));
}

TEST(CampaignParser, EncoderIntoABoardOutputIsAnError) {
  EXPECT_TRUE(rejected_at(replace_line(test::kValidCampaign, 11, "board = \"OUT\""),
                          "t.toml:11:9: wiring[0].board:"));
}

TEST(CampaignParser, CheckNamingAnUnwiredLineIsAnError) {
  EXPECT_TRUE(rejected_at(replace_line(test::kValidCampaign, 26, "output = \"ls2\""),
                          "t.toml:26:10: check[0].output: a wired rig line"));
}

// A check judges the board's response on a line the rig captures (a board output); timed on a
// line the rig drives itself it would pass whatever the board does.
TEST(CampaignParser, CheckWatchingALineTheRigDrivesIsAnError) {
  EXPECT_TRUE(
      rejected_at(replace_line(test::kValidCampaign, 26, "output = \"enc.A\""),
                  "t.toml:26:10: check[0].output: a line wired to a board output, which the rig captures; "
                  "\"enc.A\" is wired to board input A, which the rig drives"));
  // The same line as a pulse_width check's line.
  const std::string pulse =
      test::kValidCampaign + "[[check]]\nkind = \"pulse_width\"\nname = \"p\"\nline = \"enc.B\"\n";
  EXPECT_TRUE(rejected_at(pulse, "t.toml:34:8: check[1].line: a line wired to a board output"));
  EXPECT_EQ(error_of(replace_line(pulse, 34, "line = \"ls1\"")), "accepted");
}

// An observation a check names is a [[host]] read's name: a typo would judge a missing word
// (a fail, and in a fault run a fault "caught" by a check that read nothing).
TEST(CampaignParser, CheckNamingAnObservationNoReadMakesIsAnError) {
  const std::string read = test::kValidCampaign + "[[host]]\nat = \"1ms\"\nread = 0\nname = \"pos\"\n";
  const std::string check =
      "[[check]]\nkind = \"word_equals\"\nname = \"w\"\nobservation = \"poss\"\nvalue = 1\n";
  EXPECT_TRUE(rejected_at(read + check, "t.toml:38:15: check[1].observation: the name of a [[host]] read "
                                        "(\"poss\" is not one (did you mean \"pos\"?)): one of pos"));
  EXPECT_TRUE(rejected_at(test::kValidCampaign + check,
                          "t.toml:34:15: check[1].observation: the name of a [[host]] read (\"poss\": the "
                          "campaign reads no word)"));
  EXPECT_EQ(error_of(read + replace_line(check, 4, "observation = \"pos\"")), "accepted");
}

// Names are what the outputs carry (junit names, results keys, the report): 1 .. 64 printable
// ASCII characters, as the traceability labels. An empty one made a summary line ": 1 run(s)";
// a control character was dropped in junit.xml but kept in results.json.
TEST(CampaignParser, NamesArePrintableLabels) {
  EXPECT_TRUE(
      rejected_at(replace_line(test::kValidCampaign, 2, "name = \"\""),
                  "t.toml:2:8: campaign.name: the campaign's name: 1 .. 64 printable ASCII characters"));
  EXPECT_TRUE(rejected_at(replace_line(test::kValidCampaign, 25, "name = \"o\\u0001n\""),
                          "t.toml:25:8: check[0].name: the check's name: 1 .. 64"));
  EXPECT_TRUE(rejected_at(replace_line(test::kValidCampaign, 25, "name = \"" + std::string(65, 'n') + "\""),
                          "t.toml:25:8: check[0].name: the check's name: 1 .. 64"));
  EXPECT_EQ(error_of(replace_line(test::kValidCampaign, 25, "name = \"" + std::string(64, 'n') + "\"")),
            "accepted");
}

// docs/campaigns.md ([[check]] name): measurements are named "<check>" or "<check>.<what>",
// and the rig writes its own entries "host" (the handshakes) and "rig" (a rig fault's
// testcase). A check named "on.max" (another check's measurement) or "host"/"rig" gave two
// entries of one name in results.json, junit.xml and trace.vcd; the neighbours pass.
TEST(CampaignParser, CheckNamesCannotCollideWithMeasurementsOrTheRigsEntries) {
  EXPECT_TRUE(rejected_at(replace_line(test::kValidCampaign, 25, "name = \"on.max\""),
                          "t.toml:25:8: check[0].name: a check name without '.' (\"on.max\": '.' joins a "
                          "check's name to the names of its measurements, so it could read as another "
                          "check's measurement)"));
  EXPECT_TRUE(rejected_at(replace_line(test::kValidCampaign, 25, "name = \".\""),
                          "t.toml:25:8: check[0].name: a check name without '.'"));
  EXPECT_TRUE(
      rejected_at(replace_line(test::kValidCampaign, 25, "name = \"host\""),
                  "t.toml:25:8: check[0].name: a check name other than \"host\" (the rig's own entry"));
  EXPECT_TRUE(rejected_at(replace_line(test::kValidCampaign, 25, "name = \"rig\""),
                          "t.toml:25:8: check[0].name: a check name other than \"rig\""));
  for (const char* near : {"hosts", "Host", "rigs", "on_max", "on-max", "host-words"})
    EXPECT_EQ(error_of(replace_line(test::kValidCampaign, 25, fmt::format("name = \"{}\"", near))),
              "accepted")
        << near;
}

TEST(CampaignParser, UnknownCheckKindIsAnError) {
  EXPECT_TRUE(rejected_at(replace_line(test::kValidCampaign, 24, "kind = \"thruput\""),
                          "t.toml:24:8: check[0].kind: a check kind"));
}

TEST(CampaignParser, StimuliOutOfOrderAreAnError) {
  const std::string text = test::kValidCampaign + R"([[wiring]]
rig = "en"
board = "EN"
[[stimulus]]
kind = "level"
line = "en"
at = "20ms"
level = "high"
[[stimulus]]
kind = "level"
line = "en"
at = "10ms"
level = "low"
)";
  EXPECT_TRUE(rejected_at(text, "t.toml:42:6: stimulus[1].at: times in order"));
}

TEST(CampaignParser, StimulusOnAnUnwiredLineIsAnError) {
  const std::string text = test::kValidCampaign + R"([[stimulus]]
kind = "pulse"
line = "en"
at = "20ms"
width = "1ms"
)";
  EXPECT_TRUE(rejected_at(text, "t.toml:33:8: stimulus[0].line: a wired rig line"));
}

TEST(CampaignParser, StimulusOnABoardOutputIsAnError) {
  const std::string text = test::kValidCampaign + R"([[stimulus]]
kind = "pulse"
line = "ls1"
at = "20ms"
width = "1ms"
)";
  EXPECT_TRUE(rejected_at(text, "t.toml:33:8: stimulus[0].line: a line the rig drives"));
}

TEST(CampaignParser, StimulusAfterTheEndIsAnError) {
  const std::string text = test::kValidCampaign + R"([[wiring]]
rig = "en"
board = "EN"
[[stimulus]]
kind = "level"
line = "en"
at = "200ms"
level = "high"
)";
  EXPECT_TRUE(rejected_at(text, "t.toml:37:6: stimulus[0].at: a time within the run"));
}

TEST(CampaignParser, KeyThatAStimulusKindDoesNotTakeIsAnError) {
  // A level stimulus has no width: a leftover key from a pulse must not be ignored.
  const std::string text = test::kValidCampaign + R"([[wiring]]
rig = "en"
board = "EN"
[[stimulus]]
kind = "level"
line = "en"
at = "20ms"
level = "high"
width = "1ms"
)";
  EXPECT_TRUE(rejected_at(text, "t.toml:39:1: stimulus[0].width: unknown key"));
}

TEST(CampaignParser, HostActionsOutOfOrderAreAnError) {
  const std::string text = test::kValidCampaign + R"([[host]]
at = "20ms"
read = 1
name = "count"
[[host]]
at = "5ms"
read = 1
name = "count2"
)";
  EXPECT_TRUE(rejected_at(text, "t.toml:36:6: host[1].at: times in order"));
}

TEST(CampaignParser, HostWriteWithTransmitSetIsAnError) {
  // The rig drives Transmit (bit 15) itself.
  const std::string text = test::kValidCampaign + "[[host]]\nat = \"1ms\"\nwrite = [0x8001, 5, 6]\n";
  EXPECT_TRUE(rejected_at(text, "t.toml:33:9: host[0].write: word 0 with Transmit"));
}

TEST(CampaignParser, HostReadPastTheLastInputWordIsAnError) {
  // reference_pls has 4 input words (0..3).
  const std::string text = test::kValidCampaign + "[[host]]\nat = \"1ms\"\nread = 4\nname = \"x\"\n";
  EXPECT_TRUE(rejected_at(text, "t.toml:33:8: host[0].read: an input word 0 .. 3"));
}

TEST(CampaignParser, FaultCaughtByAnUnknownCheckIsAnError) {
  const std::string text =
      test::kValidCampaign + "[[fault]]\nname = \"f\"\nvariant = \"late\"\ncaught_by = \"of\"\n";
  EXPECT_TRUE(rejected_at(text, "t.toml:34:13: fault[0].caught_by: a check of this campaign"));
}

TEST(CampaignParser, FaultWithAnUnknownVariantIsAnError) {
  const std::string text =
      test::kValidCampaign + "[[fault]]\nname = \"f\"\nvariant = \"lat\"\ncaught_by = \"on\"\n";
  EXPECT_TRUE(rejected_at(text, "t.toml:33:11: fault[0].variant: a variant of reference_pls"));
}

TEST(CampaignParser, DiscreteStimulusAsASignalFaultIsAnError) {
  const std::string text = test::kValidCampaign +
                           "[[fault]]\nname = \"f\"\ncaught_by = \"on\"\n"
                           "signal = { kind = \"level\", line = \"enc.A\", at = \"1ms\", level = \"low\" }\n";
  EXPECT_TRUE(rejected_at(text, "t.toml:34:19: fault[0].signal.kind: a signal fault"));
}

TEST(CampaignParser, MoveThatCannotFollowIsAnError) {
  // A dwell while the shaft turns at 60 rpm.
  const std::string text =
      replace_line(test::kValidCampaign, 22,
                   "duration = \"100ms\"\n[[motion.move]]\nkind = \"dwell\"\nduration = \"1ms\"");
  EXPECT_TRUE(rejected_at(text, "t.toml:23:1: motion.move[1]: a move that can follow"));
}

// A move that outlasts the longest run (an hour, limits::kMaxEnd) is refused: no run sees it
// end, and a rate near 0 overflowed its time (accel 1e-300 rpm/s played a turn in 2 ns). At 60
// rpm = 1 turn/s with 60 rpm/s = 1 turn/s^2 the two ramps take 1 s together, so 3599 turns
// take exactly 3600 s (accepted) and 3599.001 turns 3600.001 s (refused).
TEST(CampaignParser, MoveLongerThanAnHourIsAnError) {
  const auto trapezoid = [](const std::string& turns, const std::string& accel) {
    return replace_line(replace_line(test::kValidCampaign, 22, "accel_rpm_s = " + accel), 20,
                        "kind = \"trapezoid\"\nturns = " + turns);
  };
  EXPECT_EQ(error_of(trapezoid("3599", "60")), "accepted");
  EXPECT_TRUE(rejected_at(trapezoid("3599.001", "60"),
                          "t.toml:22:13: motion.move[0].speed_rpm: a move that ends within 3600 s (this one "
                          "takes 3600.001 s"));
  EXPECT_TRUE(rejected_at(trapezoid("1", "1e-300"), "t.toml:23:15: motion.move[0].accel_rpm_s: a move that "
                                                    "ends within 3600 s"));
}

TEST(CampaignParser, SweepOfAMissingTableIsAnError) {
  const std::string text = test::kValidCampaign + "[[sweep]]\nkey = \"plant.mass\"\nvalues = [1, 2]\n";
  EXPECT_TRUE(rejected_at(text, "t.toml:32:7: sweep[0].key: a key path in this file"));
}

TEST(CampaignParser, BadSweepValueIsCaughtBeforeAnyRun) {
  // The second point sets delay to an integer: rejected at the value in the sweep array.
  const std::string text =
      test::kValidCampaign + "[[sweep]]\nkey = \"dut.params.delay\"\nvalues = [\"50us\", 7]\n";
  EXPECT_TRUE(rejected_at(text, "t.toml:33:19: dut.params.delay: expected a duration"));
}

// A value fine alone that a swept key makes wrong is named at its own line, with the point:
// 60 rpm of a 1,000,000-line encoder is 4,000,000 counts/s, over the 1,000,000 the rig plays.
TEST(CampaignParser, ErrorThatASweepPointMakesNamesThePoint) {
  const std::string text =
      test::kValidCampaign + "[[sweep]]\nkey = \"encoder.lines\"\nvalues = [100, 1000000]\n";
  const std::string got = error_of(text);
  EXPECT_EQ(got.rfind("t.toml:21:13: motion.move[0].speed_rpm: a speed in rpm in -15 .. 15", 0), 0U) << got;
  EXPECT_NE(got.find("(in sweep point encoder.lines=1000000)"), std::string::npos) << got;
}

// An error the file has whatever the point (a name too long, an unknown key, a bad repeat) is
// the file's: it names no sweep point, as the point has nothing to do with it (one a point makes
// still names it: ErrorThatASweepPointMakesNamesThePoint).
TEST(CampaignParser, ErrorOfTheFileWhateverThePointNamesNoPoint) {
  const std::string sweep = "[[sweep]]\nkey = \"dut.params.delay\"\nvalues = [\"50us\", \"100us\"]\n";
  const std::string name65 = replace_line(test::kValidCampaign, 2, "name = \"" + std::string(65, 'n') + "\"");
  const std::string unknown = replace_line(test::kValidCampaign, 3, "end = \"100ms\"\nsede = 1");
  const std::string repeat = replace_line(test::kValidCampaign, 3, "end = \"100ms\"\nrepeat = 0");
  for (const std::string& text : {name65 + sweep, unknown + sweep, repeat + sweep}) {
    const std::string got = error_of(text);
    EXPECT_EQ(got.find("(in sweep point"), std::string::npos) << got;
  }
  EXPECT_TRUE(
      rejected_at(name65 + sweep, "t.toml:2:8: campaign.name: the campaign's name: 1 .. 64 printable"));
  EXPECT_TRUE(rejected_at(unknown + sweep, "t.toml:4:1: campaign.sede: unknown key"));
  EXPECT_TRUE(rejected_at(repeat + sweep, "t.toml:4:10: campaign.repeat: a repetition count in 1 .. 10000"));
}

// The file as written is checked whole even where a sweep replaces a value at every point
// (docs/campaigns.md "Every key is checked"): a wrong type or a value out of range under a
// sweep gets the error it gets without the sweep, naming no point.
TEST(CampaignParser, AValueEveryPointReplacesIsStillCheckedAsWritten) {
  const std::string delay_sweep = "[[sweep]]\nkey = \"dut.params.delay\"\nvalues = [\"50us\", \"100us\"]\n";
  const std::string speed_sweep = "[[sweep]]\nkey = \"motion.move[0].speed_rpm\"\nvalues = [600, 500]\n";
  const auto with_delay = [](const std::string& delay) {
    return replace_line(test::kValidCampaign, 8, "off = 20\ndelay = " + delay);
  };
  const auto with_speed = [](const std::string& rpm) {
    return replace_line(test::kValidCampaign, 21, "speed_rpm = " + rpm);
  };
  struct Case {
    std::string unswept;
    std::string sweep;
    std::string error;
  };
  // delay is reference_pls's 0s .. 1s (rig/duts); a speed is -32767 .. 32767 rpm (limits.hpp).
  for (const Case& c :
       {Case{with_delay("\"banana\""), delay_sweep, "t.toml:9:9: dut.params.delay: expected a duration"},
        Case{with_delay("\"-1ns\""), delay_sweep, "t.toml:9:9: dut.params.delay: a value in 0s .. 1s"},
        Case{with_delay("\"1000000001ns\""), delay_sweep,
             "t.toml:9:9: dut.params.delay: a value in 0s .. 1s"},
        Case{with_speed("32768"), speed_sweep,
             "t.toml:21:13: motion.move[0].speed_rpm: a speed in rpm in -32767 .. 32767"},
        Case{with_speed("99999999"), speed_sweep,
             "t.toml:21:13: motion.move[0].speed_rpm: a speed in rpm"}}) {
    SCOPED_TRACE(c.error);
    EXPECT_TRUE(rejected_at(c.unswept, c.error));
    EXPECT_EQ(error_of(c.unswept + c.sweep), error_of(c.unswept));
  }
  // At the limits the file as written is a campaign, and each point takes the sweep's values.
  for (const std::string& text : {with_delay("\"0s\"") + delay_sweep, with_delay("\"1s\"") + delay_sweep,
                                  with_speed("32767") + speed_sweep, with_speed("-32767") + speed_sweep}) {
    const Campaign c = parse_campaign(text, "t.toml");
    ASSERT_EQ(c.points.size(), 2U);
  }
  const Campaign c = parse_campaign(with_delay("\"1s\"") + delay_sweep, "t.toml");
  EXPECT_EQ(std::get<Nanos>(c.points[0].dut.params.at("delay").value), 50_us);
  EXPECT_EQ(std::get<Nanos>(c.points[1].dut.params.at("delay").value), 100_us);
}

TEST(CampaignParser, SweepsMakeTheCartesianProductLastAxisFastest) {
  const std::string text = replace_line(test::kValidCampaign, 3, "end = \"100ms\"\nrepeat = 2") +
                           "[[sweep]]\nkey = \"dut.params.delay\"\nvalues = [\"50us\", \"100us\"]\n"
                           "[[sweep]]\nkey = \"motion.move[0].speed_rpm\"\nvalues = [30, 60, 90]\n"
                           "[[fault]]\nname = \"f\"\nvariant = \"late\"\ncaught_by = \"on\"\n";
  const Campaign c = parse_campaign(text, "t.toml");
  ASSERT_EQ(c.points.size(), 6U);
  // Point p = 3 * delay index + speed index.
  EXPECT_EQ(std::get<Nanos>(c.points[0].dut.params.at("delay").value), 50_us);
  EXPECT_EQ(std::get<Nanos>(c.points[3].dut.params.at("delay").value), 100_us);
  EXPECT_EQ(c.points[1].motion.moves[0].speed_rpm, 60.0);
  EXPECT_EQ(c.points[5].motion.moves[0].speed_rpm, 90.0);
  // 6 points x 2 repetitions of nominal runs, then the fault once at each point.
  ASSERT_EQ(c.runs.size(), 18U);
  EXPECT_EQ(c.runs[1].point, 0U);
  EXPECT_EQ(c.runs[1].repetition, 1U);
  EXPECT_EQ(c.runs[2].point, 1U);
  EXPECT_FALSE(c.runs[11].fault.has_value());
  ASSERT_TRUE(c.runs[12].fault.has_value());
  EXPECT_EQ(c.runs[12].point, 0U);
  EXPECT_EQ(c.runs[17].point, 5U);
  for (std::size_t i = 0; i < c.runs.size(); ++i) EXPECT_EQ(c.runs[i].index, i);
}

TEST(CampaignParser, ExternalBoardNeedsAHardwareBackendAndItsPins) {
  // backend is not written (it defaults to virtual): the error points at the [dut] table.
  EXPECT_TRUE(
      rejected_at(replace_line(test::kValidCampaign, 5, "model = \"external\""), "t.toml:4:1: dut.backend:"));
  EXPECT_TRUE(rejected_at(replace_line(test::kValidCampaign, 5, "model = \"external\"\nbackend = \"gpiod\""),
                          "t.toml:4:1: dut.pins: missing"));
}

TEST(CampaignParser, MissingFileIsBadInput) {
  try {
    (void)load_campaign("/nonexistent/hilrig/campaign.toml");
    FAIL() << "accepted a missing file";
  } catch (const CampaignError& e) {
    EXPECT_EQ(e.key(), "file");
  }
}

} // namespace
} // namespace hilrig::campaign
