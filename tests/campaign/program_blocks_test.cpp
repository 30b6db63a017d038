// Boards programmed in their own words: `[[host]] program = "<block>"` with the block's named
// fields compiles, when the campaign is read, to the command words the manual gives. Each
// device's blocks against the manual's worked examples and command tables (docs/spec/, the
// manual line cited); every field's range swept at its edges (in, and one past: bad input at
// file:line:col: key); and one shipped campaign per device, written in the named form, against
// the same campaign with the raw words: the runs' results are byte for byte the same.

#include <cstdint>
#include <string>
#include <utility>
#include <vector>

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include "campaign_text.hpp"
#include "rig/campaign/campaign_parser.hpp"
#include "rig/duts/device_programs.hpp"
#include "rig/duts/dut.hpp"
#include "rig/results/results_json.hpp"
#include "test_support.hpp"

namespace hilrig::campaign {
namespace {

using Words = std::vector<std::uint16_t>;
using test::error_of;

// A campaign for MODEL whose one write is the [[host]] entry BODY, then a status read and a
// check on it (a campaign judges something). The body starts on line 8.
std::string campaign_with(const std::string& model, const std::string& body) {
  return "[campaign]\nname = \"words\"\nend = \"20ms\"\n[dut]\nmodel = \"" + model +
         "\"\n[[host]]\nat = \"1ms\"\n" + body +
         "\n[[host]]\nat = \"10ms\"\nread = 0\nname = \"status\"\n"
         "[[check]]\nkind = \"word_bits\"\nname = \"status\"\nobservation = \"status\"\nmask = 1\nvalue = "
         "0\n";
}
constexpr int kBodyLine = 8;

Words words_of(const std::string& model, const std::string& body) {
  const Campaign c = parse_campaign(campaign_with(model, body), "t.toml");
  return c.points.at(0).host.at(0).words;
}

::testing::AssertionResult rejected(const std::string& model, const std::string& body, int line_in_body,
                                    int column, const std::string& key, const std::string& says) {
  const std::string got = error_of(campaign_with(model, body));
  const std::string where = "t.toml:" + std::to_string(kBodyLine + line_in_body) + ":" +
                            std::to_string(column) + ": host[0]." + key + ": ";
  if (got.rfind(where, 0) != 0 || got.find(says) == std::string::npos)
    return ::testing::AssertionFailure()
           << "expected \"" << where << "...\" naming \"" << says << "\", got \"" << got << "\"";
  return ::testing::AssertionSuccess();
}

// --- ANS1 (docs/spec/ans1.md §5.3; manual seeds/000) ---------------------------------------

TEST(ProgramAns1, ConfigurationIsCb2WithItsApplyBits) {
  // ans1 manual (seeds/000_08a2edf5547d4d1e.txt:1791-1840): CB2 = block 0010, Apply w1 bit 7,
  // w2 (CPC) bit 8, w3 (FSC) bit 9; w1 b3 QuadEnc. W-07 (L808, L811): a 500-line encoder,
  // CPC 2000, FSC 1440.
  EXPECT_EQ(words_of("ans1", "program = \"configuration\"\nsensor = \"encoder\"\ncpc = 2000\nfsc = 1440"),
            (Words{0x0382, 0x0008, 2000, 1440}));
  // W-04 (L798): the resolver, CPC 3072, FSC 2700.
  EXPECT_EQ(words_of("ans1", "program = \"configuration\"\ncpc = 3072\nfsc = 2700"),
            (Words{0x0382, 0x0000, 3072, 2700}));
  // Bit parameters alone (L1836-L1840): HoldOuts b4, XFltLatch b1, CntDir b0, SlaveMode b2.
  EXPECT_EQ(words_of("ans1", "program = \"configuration\"\nhold_outputs = true\nfault_latch = true"),
            (Words{0x0082, 0x0012}));
  EXPECT_EQ(words_of("ans1", "program = \"configuration\"\nreverse = true\nslave = true"),
            (Words{0x0082, 0x0005}));
  // FSC without CPC applies w3 only; w2 is written 0 and not applied.
  EXPECT_EQ(words_of("ans1", "program = \"configuration\"\nfsc = 360"), (Words{0x0282, 0x0000, 0, 360}));
}

TEST(ProgramAns1, SetpointsAreCb3PairK) {
  // L1842-L1898: CB3 = block 0011, Apply pair k = bit 9 + k, pair k in words 4k..4k+3 (From,
  // To, OnStitch, OffStitch). docs/campaigns.md's walk-through: output 1 from 100 to 300.
  EXPECT_EQ(words_of("ans1", "program = \"setpoints\"\noutput = 1\non = 100\noff = 300"),
            (Words{0x0403, 1, 0, 0, 100, 300, 0, 0}));
  // The brief's example: output 3, on 1000, off 2000.
  EXPECT_EQ(words_of("ans1", "program = \"setpoints\"\noutput = 3\non = 1000\noff = 2000"),
            (Words{0x0403, 3, 0, 0, 1000, 2000, 0, 0}));
  Words pair4(20, 0);
  pair4[0] = 0x2003;
  pair4[1] = 16;
  pair4[16] = 340;
  pair4[17] = 40;
  pair4[18] = 10;
  pair4[19] = 12;
  EXPECT_EQ(words_of("ans1",
                     "program = \"setpoints\"\noutput = 16\npair = 4\non = 340\noff = 40\non_stitch = 10\n"
                     "off_stitch = 12"),
            pair4);
}

TEST(ProgramAns1, AdvancesTimersBrakeAndDataAreTheirBlocks) {
  // W-13 (L893): a 10 ms lead; CB5 (L1945-L1951) bits 9:8 = 01 fixed: w2 Lead, w3 Trail.
  EXPECT_EQ(words_of("ans1", "program = \"fixed_advance\"\noutput = 1\nlead_ms = 10"),
            (Words{0x0105, 1, 10, 0}));
  // Bits 9:8 = 10 variable: w2 Fixed, w3 VAT (us/RPM).
  EXPECT_EQ(words_of("ans1", "program = \"variable_advance\"\noutput = 2\nfixed_ms = 3\nvat = 9999"),
            (Words{0x0205, 2, 3, 9999}));
  // L1957-L1962: bits 11:10 = 01 Time-or-Position, 1x Time-Only; w4 the timer.
  EXPECT_EQ(words_of("ans1", "program = \"timer\"\noutput = 1\ntimer = \"time_or_position\"\nms = 5"),
            (Words{0x0405, 1, 0, 0, 5}));
  EXPECT_EQ(words_of("ans1", "program = \"timer\"\noutput = 2\ntimer = \"time_only\"\nms = 20"),
            (Words{0x0805, 2, 0, 0, 20}));
  // L2099-L2125: CB8 = block 1000, Apply wk = bit 7 + k for the settings given.
  EXPECT_EQ(words_of("ans1",
                     "program = \"brake_monitor\"\ninput = 1\ncsc = 1\nstop_limit_ms = 150\nstop_output = 3"),
            (Words{0x3308, 1, 1, 0, 0, 150, 3}));
  EXPECT_EQ(words_of("ans1", "program = \"brake_monitor\"\nstart_limit_ms = 250"),
            (Words{0x0408, 0, 0, 250}));
  // L1723-L1789: CB1 bit 8 applies w1..w3 (attribute, output, input).
  EXPECT_EQ(words_of("ans1", "program = \"data\"\nattribute = 19"), (Words{0x0101, 19, 1, 1}));
  EXPECT_EQ(words_of("ans1", "program = \"data\"\nattribute = 18\ninput = 2"), (Words{0x0101, 18, 1, 2}));
  // L1713-L1721: CB0 with Clear Errors (bit 4).
  EXPECT_EQ(words_of("ans1", "program = \"clear_errors\""), (Words{0x0010}));
}

TEST(ProgramAns1, RangesAreTheManualsAtBothEdges) {
  // Outputs 1..16 (L1846), positions 0..FSC-1 with FSC <= CPC <= 4096 (L1797), CPC 2..4096.
  for (const int output : {1, 16})
    EXPECT_NO_THROW((void)words_of("ans1", "program = \"setpoints\"\noutput = " + std::to_string(output) +
                                               "\non = 0\noff = 4095"));
  for (const int output : {0, 17})
    EXPECT_TRUE(rejected("ans1",
                         "program = \"setpoints\"\noutput = " + std::to_string(output) + "\non = 1\noff = 2",
                         1, 10, "output", "an integer in 1 .. 16"));
  EXPECT_TRUE(
      rejected("ans1", "program = \"setpoints\"\noutput = 1\non = 4096\noff = 2", 2, 6, "on", "0 .. 4095"));
  EXPECT_TRUE(
      rejected("ans1", "program = \"setpoints\"\noutput = 1\non = -1\noff = 2", 2, 6, "on", "0 .. 4095"));
  EXPECT_TRUE(rejected("ans1", "program = \"configuration\"\ncpc = 1", 1, 7, "cpc", "2 .. 4096"));
  EXPECT_TRUE(rejected("ans1", "program = \"configuration\"\ncpc = 4097", 1, 7, "cpc", "2 .. 4096"));
  EXPECT_NO_THROW((void)words_of("ans1", "program = \"configuration\"\ncpc = 2\nfsc = 1"));
  EXPECT_TRUE(rejected("ans1", "program = \"fixed_advance\"\noutput = 1\nlead_ms = 32768", 2, 11, "lead_ms",
                       "0 .. 32767"));
  EXPECT_TRUE(rejected("ans1", "program = \"brake_monitor\"\ncsc = 256", 1, 7, "csc", "0 .. 255"));
  // A missing required field points at the table; a word not among the choices names them.
  EXPECT_TRUE(rejected("ans1", "program = \"timer\"\noutput = 1\nms = 5\ntimer = \"sometimes\"", 3, 9,
                       "timer", "one of time_or_position, time_only"));
  EXPECT_NE(error_of(campaign_with("ans1", "program = \"setpoints\"\noutput = 1\non = 5"))
                .find("host[0].off: missing"),
            std::string::npos);
}

TEST(ProgramAns1, UnknownBlocksAndFieldsAreBadInput) {
  EXPECT_TRUE(rejected("ans1", "program = \"setpoint\"", 0, 11, "program",
                       "one of clear_errors, configuration, setpoints, fixed_advance"));
  // A field of another block is an unknown key of this one.
  const std::string e =
      error_of(campaign_with("ans1", "program = \"setpoints\"\noutput = 1\non = 1\noff = 2\nms = 5"));
  EXPECT_NE(e.find("host[0].ms"), std::string::npos) << e;
  // write and program together.
  EXPECT_NE(
      error_of(campaign_with("ans1", "program = \"clear_errors\"\nwrite = [0x0010]")).find("exactly one of"),
      std::string::npos);
}

// --- SMD23E (docs/spec/smd23e.md §6.3-§6.5; manual seeds/003) ----------------------------

TEST(ProgramSmd23e, MovesAreTheCommandCodesWithTwoWordValues) {
  // M-16 (L2490-L2787): MSW = 1 << bit for each command; a registration is the jog bit with
  // LSW bit 7 (L2615, L2635). M-03 (L2252): 1,234,567 = (1234, 567); M-04 (L2253):
  // -7,654,321 = (-7654, -321) = (0xE21A, 0xFEBF).
  EXPECT_EQ(words_of("smd23e", "program = \"move\"\nmove = \"relative\"\nsteps = -7654321\nspeed = 1234567\n"
                               "accel = 100\ndecel = 200\njerk = 5"),
            (Words{0x0002, 0x8000, 0xE21A, 0xFEBF, 1234, 567, 100, 200, 0, 5}));
  const std::pair<const char*, std::uint16_t> msw[] = {
      {"absolute", 0x0001}, {"relative", 0x0002}, {"resume", 0x0008}, {"home_cw", 0x0020},
      {"home_ccw", 0x0040}, {"jog_cw", 0x0080},   {"jog_ccw", 0x0100}};
  for (const auto& [move, word0] : msw) {
    const Words w = words_of("smd23e", std::string("program = \"move\"\nmove = \"") + move +
                                           "\"\nspeed = 1000\naccel = 1\ndecel = 5000");
    EXPECT_EQ(w, (Words{word0, 0x8000, 0, 0, 1, 0, 1, 5000, 0, 0})) << move;
  }
  // Registration (L2611-L2661): words 2-3 Stopping Distance, 8-9 Minimum Registration Distance.
  EXPECT_EQ(words_of("smd23e", "program = \"move\"\nmove = \"registration_ccw\"\nsteps = 1000\nspeed = 5000\n"
                               "accel = 100\ndecel = 100\nmin_registration = 2000"),
            (Words{0x0100, 0x8080, 1, 0, 5, 0, 100, 100, 2, 0}));
}

// A registration's words 8-9 are its Minimum Registration Move Distance, every other move's
// word 9 its jerk (L2487-L2756): a field the move has no word for is refused where it is
// written, not dropped; a registration's Stopping Distance is 0..8,388,607 (L2636), its edges
// accepted. Jerk 0 is still a jerk given: refused with a registration too.
TEST(ProgramSmd23e, FieldsTheMoveHasNoWordForAreRefused) {
  const std::string reg =
      "program = \"move\"\nmove = \"registration_cw\"\nspeed = 5000\naccel = 100\ndecel = 100\n";
  EXPECT_TRUE(rejected("smd23e", reg + "steps = 10\njerk = 5", 6, 8, "jerk", "Minimum Registration"));
  EXPECT_TRUE(rejected("smd23e", reg + "steps = 10\njerk = 0", 6, 8, "jerk", "Minimum Registration"));
  EXPECT_TRUE(rejected("smd23e", reg + "steps = -1", 5, 9, "steps", "0..8388607"));
  EXPECT_EQ(words_of("smd23e", reg + "steps = 0")[2], 0);
  EXPECT_EQ(words_of("smd23e", reg + "steps = 8388607"),
            (Words{0x0080, 0x8080, 8388, 607, 5, 0, 100, 100, 0, 0}));
  const std::string rel = "program = \"move\"\nmove = \"relative\"\nspeed = 5000\naccel = 100\ndecel = 100\n";
  EXPECT_TRUE(rejected("smd23e", rel + "steps = -1\nmin_registration = 0", 6, 20, "min_registration",
                       "only with a registration"));
  EXPECT_EQ(words_of("smd23e", rel + "steps = -1\njerk = 5000")[9], 5000);
}

// A command without a profile writes only the words it uses (L2401-L2481): MSW and LSW, and a
// preset's value words 2-3; words 2-9 keep what the last block wrote, so a Hold written during
// a jog is no on-the-fly change of its speed to 0 (L1026, L2890). A position given to a command
// that has no value word is refused where it is written.
TEST(ProgramSmd23e, CommandsAndTheResetDriverFaultBlock) {
  // M-15 (L2922-L2946): Reset Driver Fault = MSW 0x0400, LSW 0x0400 (DriveEn 0).
  EXPECT_EQ(words_of("smd23e", "program = \"command\"\ncommand = \"reset_errors\"\ndrive_enable = false\n"
                               "clear_driver_fault = true"),
            (Words{0x0400, 0x0400}));
  // M-16: Hold 0x0004, Immediate Stop 0x0010, Preset Position 0x0200, Preset Encoder 0x4000.
  EXPECT_EQ(words_of("smd23e", "program = \"command\"\ncommand = \"preset_position\"\nposition = -12"),
            (Words{0x0200, 0x8000, 0, 0xFFF4}));
  EXPECT_EQ(words_of("smd23e", "program = \"command\"\ncommand = \"preset_encoder\"\nposition = 12345"),
            (Words{0x4000, 0x8000, 12, 345}));
  EXPECT_EQ(words_of("smd23e", "program = \"command\"\ncommand = \"preset_position\""),
            (Words{0x0200, 0x8000, 0, 0}));
  EXPECT_EQ(words_of("smd23e", "program = \"command\"\ncommand = \"hold\""), (Words{0x0004, 0x8000}));
  EXPECT_EQ(words_of("smd23e", "program = \"command\"\ncommand = \"immediate_stop\""),
            (Words{0x0010, 0x8000}));
  EXPECT_EQ(words_of("smd23e", "program = \"command\"\ncommand = \"none\""), (Words{0x0000, 0x8000}));
  EXPECT_TRUE(rejected("smd23e", "program = \"command\"\ncommand = \"hold\"\nposition = 5", 2, 12, "position",
                       "only with preset_position or preset_encoder"));
}

TEST(ProgramSmd23e, ConfigurationWordsAndTheirRanges) {
  // L2265-L2341: control word bit 15 Mode, input functions in bits 2-0/5-3/8-6 (codes L2294),
  // bit 10 encoder, 13 stall; word 1 bit 15 DriveEn, bits 0-2 active levels; words 2-3
  // Starting Speed, 4 steps/turn, 6 encoder pulses, 7 idle %, 8 current x10.
  EXPECT_EQ(words_of("smd23e",
                     "program = \"configuration\"\ninput3 = \"emergency_stop\"\nstarting_speed = 1000\n"
                     "steps_per_turn = 2048\nidle_current_percent = 50\nmotor_current_x10 = 20"),
            (Words{0x8140, 0x8007, 1, 0, 2048, 0, 1024, 50, 20, 0}));
  EXPECT_EQ(
      words_of(
          "smd23e",
          "program = \"configuration\"\ninput1 = \"home\"\ninput2_active = \"no_current\"\n"
          "encoder = true\nstall_detection = true\nanti_resonance = false\n"
          "starting_speed = 1999999\nsteps_per_turn = 200\nidle_current_percent = 0\nmotor_current_x10 = 10"),
      (Words{0xE406, 0x8005, 1999, 999, 200, 0, 1024, 0, 10, 0}));
  // M-18 (L2274, L765): current x10 10, 25, 34 valid; 9 and 35 not.
  for (const int current : {10, 25, 34})
    EXPECT_NO_THROW((void)words_of(
        "smd23e",
        "program = \"configuration\"\nidle_current_percent = 0\nstarting_speed = 1\nsteps_per_turn = 200\n"
        "motor_current_x10 = " +
            std::to_string(current)));
  for (const int current : {9, 35})
    EXPECT_TRUE(rejected("smd23e",
                         "program = \"configuration\"\nidle_current_percent = 0\nstarting_speed = "
                         "1\nsteps_per_turn = 200\nmotor_current_x10 = " +
                             std::to_string(current),
                         4, 21, "motor_current_x10", "10 .. 34"));
  // Target +-8,388,607 (L875, L882), speed up to 2,999,999 (L2618), A and D 1..5000 (L2496).
  EXPECT_TRUE(rejected("smd23e",
                       "program = \"move\"\nmove = \"relative\"\nsteps = 8388608\nspeed = 1\naccel = 1\n"
                       "decel = 1",
                       2, 9, "steps", "-8388607 .. 8388607"));
  EXPECT_TRUE(rejected("smd23e",
                       "program = \"move\"\nmove = \"relative\"\nspeed = 3000000\naccel = 1\ndecel = 1", 2, 9,
                       "speed", "1 .. 2999999"));
  EXPECT_TRUE(rejected("smd23e", "program = \"move\"\nmove = \"relative\"\nspeed = 1\naccel = 0\ndecel = 1",
                       3, 9, "accel", "1 .. 5000"));
  EXPECT_NO_THROW((void)words_of("smd23e", "program = \"move\"\nmove = \"relative\"\nsteps = -8388607\n"
                                           "speed = 2999999\naccel = 5000\ndecel = 1"));
}

// --- 4501 (docs/spec/amci4501.md §5.3; manual seeds/001) --------------------------------

TEST(ProgramAmci4501, ModeWordTimeoutAndTheEnableWindow) {
  // L151-L161: bits 2-6 select modes 2-6, none mode 1; bit 0 Received Measurement, bit 1
  // Clear Measurement Error. W5 (L169): timeout 0 means 10 s.
  EXPECT_EQ(words_of("amci4501", "program = \"mode\"\nmode = 1\ntimeout_ms = 1000"), (Words{0x0000, 1000}));
  EXPECT_EQ(words_of("amci4501", "program = \"mode\"\nmode = 3\ntimeout_ms = 32767"), (Words{0x0008, 32767}));
  EXPECT_EQ(words_of("amci4501", "program = \"mode\"\nmode = 4\ntimeout_ms = 1000\nacknowledge = true"),
            (Words{0x0011, 1000}));
  EXPECT_EQ(words_of("amci4501", "program = \"mode\"\nmode = 6\nclear_error = true"), (Words{0x0042, 0}));
  // W4 (L170): an enable-window setpoint of 34,567 is upper word 34, lower word 567.
  EXPECT_EQ(words_of("amci4501", "program = \"mode\"\nmode = 2\ntimeout_ms = 500\non = 1\noff = 34567"),
            (Words{0x0004, 500, 0, 1, 34, 567}));
  // W6 (L169): 0 .. 32,767 ms; W7 (L172): 0 .. 65,535 counts; modes 1..6.
  EXPECT_TRUE(rejected("amci4501", "program = \"mode\"\nmode = 1\ntimeout_ms = 32768", 2, 14, "timeout_ms",
                       "0 .. 32767"));
  EXPECT_TRUE(rejected("amci4501", "program = \"mode\"\nmode = 2\non = 65536", 2, 6, "on", "0 .. 65535"));
  EXPECT_TRUE(rejected("amci4501", "program = \"mode\"\nmode = 7", 1, 8, "mode", "1 .. 6"));
  EXPECT_TRUE(rejected("amci4501", "program = \"mode\"\nmode = 0", 1, 8, "mode", "1 .. 6"));
  // A window belongs to mode 2 only.
  EXPECT_TRUE(rejected("amci4501", "program = \"mode\"\nmode = 3\non = 5", 2, 6, "on", "only with mode = 2"));
  // "The enable window on setpoint must be less than the enable window off setpoint" (L171):
  // on = off and on > off are refused where written; on one below off, to the range's top, is
  // accepted.
  EXPECT_TRUE(rejected("amci4501", "program = \"mode\"\nmode = 2\non = 5\noff = 5", 3, 7, "off",
                       "must be above the on setpoint 5 (L171): 6 .. 65535"));
  EXPECT_TRUE(rejected("amci4501", "program = \"mode\"\nmode = 2\non = 6\noff = 5", 3, 7, "off",
                       "must be above the on setpoint 6 (L171): 7 .. 65535"));
  // Without a window (on = off = 0), at the [[host]] entry (line 6).
  EXPECT_TRUE(rejected("amci4501", "program = \"mode\"\nmode = 2", -2, 1, "off", "1 .. 65535"));
  EXPECT_EQ(words_of("amci4501", "program = \"mode\"\nmode = 2\non = 5\noff = 6"),
            (Words{0x0004, 0, 0, 5, 0, 6}));
  EXPECT_EQ(words_of("amci4501", "program = \"mode\"\nmode = 2\non = 65534\noff = 65535"),
            (Words{0x0004, 0, 65, 534, 65, 535}));
  // The top of the range (L172): above on = 65,535 no off setpoint exists, so on is refused,
  // not an empty off range; on = 65,534 with off = 65,535 (above) is the last window.
  EXPECT_TRUE(rejected("amci4501", "program = \"mode\"\nmode = 2\non = 65535", 2, 6, "on",
                       "no off setpoint exists above 65535 (L172: 0 .. 65535; L171: on below off), so the "
                       "on setpoint must be at most 65534"));
  EXPECT_TRUE(rejected("amci4501", "program = \"mode\"\nmode = 2\non = 65535\noff = 65535", 2, 6, "on",
                       "must be at most 65534"));
  EXPECT_TRUE(rejected("amci4501", "program = \"mode\"\nmode = 2\non = 65534", -2, 1, "off",
                       "must be above the on setpoint 65534 (L171): 65535 .. 65535"));
}

// --- 7361 (docs/spec/ssi7361.md §4-§5; manual seeds/004) ---------------------------------

TEST(ProgramSsi7361, SetupIsTheCommandBitsAndAqWords) {
  // M-01 (L861, L878-880): Format 266 = 0x010A, N = 10 from M = 1. M-02 (L860, L874-876):
  // %Q 62 = Format, Scalars, PrstVal, RUT, PgmDir. M-06 (L864-866): Preset 125,420 =
  // %AQ4 0xE9EC, %AQ5 0x0001. The checkout's Scalars 1000/1024 and RUT 500 (L862-867).
  EXPECT_EQ(words_of("ssi7361",
                     "program = \"setup\"\nbits = 10\nfirst_bit = 1\nmultiplier = 1000\ndivisor = 1024\n"
                     "preset = 125420\nrate_update_ms = 500\ncount_direction = \"positive\""),
            (Words{62, 266, 1000, 1024, 0xE9EC, 0x0001, 500}));
  // M-05 (L942-945): AplyPst alone is %Q 0x0001.
  EXPECT_EQ(words_of("ssi7361", "program = \"setup\"\napply_preset = true"), (Words{0x0001}));
  // M-21: the factory Format 0x0118 (M 1, N 24); bit 16 500 kHz, bit 07 Gray, bit 08 negative.
  EXPECT_EQ(words_of("ssi7361", "program = \"setup\"\nbits = 24\nfirst_bit = 1"), (Words{0x0002, 0x0118}));
  EXPECT_EQ(words_of("ssi7361", "program = \"setup\"\nbits = 24\nfirst_bit = 1\nclock = \"500kHz\""),
            (Words{0x0002, 0x8118}));
  EXPECT_EQ(words_of("ssi7361",
                     "program = \"setup\"\nbits = 10\nfirst_bit = 1\ncode = \"gray\"\nlogic = \"negative\""),
            (Words{0x0002, 0x01CA}));
  // PgmDir with CntDir = Negative (L2103-2111), E2CLR %Q 15.
  EXPECT_EQ(words_of("ssi7361", "program = \"setup\"\ncount_direction = \"negative\""), (Words{0x0060}));
  EXPECT_EQ(words_of("ssi7361", "program = \"setup\"\neeprom_clear = true"), (Words{0x4000}));
  // A negative preset: signed 32-bit, low word first (-5 = 0xFFFB, 0xFFFF).
  EXPECT_EQ(words_of("ssi7361", "program = \"setup\"\npreset = -5\napply_preset = true"),
            (Words{0x0009, 0, 0, 0, 0xFFFB, 0xFFFF}));
}

TEST(ProgramSsi7361, FormatAndScalarRulesAreCheckedWhenRead) {
  // L2012-2013, L2162-2163: N 2..25, M 1..24, M + N <= 26.
  EXPECT_NO_THROW((void)words_of("ssi7361", "program = \"setup\"\nbits = 25\nfirst_bit = 1"));
  EXPECT_TRUE(rejected("ssi7361", "program = \"setup\"\nbits = 24\nfirst_bit = 3", 1, 8, "bits", "<= 26"));
  EXPECT_TRUE(rejected("ssi7361", "program = \"setup\"\nbits = 1\nfirst_bit = 1", 1, 8, "bits", "2 .. 25"));
  EXPECT_TRUE(rejected("ssi7361", "program = \"setup\"\nbits = 26\nfirst_bit = 1", 1, 8, "bits", "2 .. 25"));
  EXPECT_TRUE(
      rejected("ssi7361", "program = \"setup\"\nbits = 10\nfirst_bit = 25", 2, 13, "first_bit", "1 .. 24"));
  // L1192-1194: MUL <= DIV, each 1..32,767; RUT 1..1000 ms (L2021-2022).
  EXPECT_NO_THROW((void)words_of("ssi7361", "program = \"setup\"\nmultiplier = 32767\ndivisor = 32767"));
  EXPECT_TRUE(rejected("ssi7361", "program = \"setup\"\nmultiplier = 2\ndivisor = 1", 1, 14, "multiplier",
                       "<= the divisor"));
  EXPECT_TRUE(
      rejected("ssi7361", "program = \"setup\"\nrate_update_ms = 0", 1, 18, "rate_update_ms", "1 .. 1000"));
  EXPECT_TRUE(rejected("ssi7361", "program = \"setup\"\nrate_update_ms = 1001", 1, 18, "rate_update_ms",
                       "1 .. 1000"));
  // Preset +-33,554,431 (L91, L148).
  EXPECT_TRUE(rejected("ssi7361", "program = \"setup\"\npreset = 33554432", 1, 10, "preset", "33554431"));
}

// The Format word is written whole (L2126-L2152) and the Scalars as a pair (%AQ2/%AQ3, L2091-L2092):
// a Format or Scalars field given alone is refused, and what `hilrig list` shows of it (the
// field's description) names the field(s) it goes with, as docs/campaigns.md does.
TEST(ProgramSsi7361, AFieldThatNeedsAnotherIsRefusedAloneAndListedSo) {
  struct Alone {
    std::string field;
    std::string value;
    std::string with; // what the listing says it goes with
  };
  const duts::ProgramBlockInfo* setup = duts::find_program("ssi7361", "setup");
  ASSERT_NE(setup, nullptr);
  for (const Alone& a :
       {Alone{"bits", "10", "only with first_bit"}, Alone{"first_bit", "2", "only with bits"},
        Alone{"code", "\"gray\"", "only with bits and first_bit"},
        Alone{"logic", "\"negative\"", "only with bits and first_bit"},
        Alone{"clock", "\"500kHz\"", "only with bits and first_bit"},
        Alone{"multiplier", "1", "only with divisor"}, Alone{"divisor", "2", "only with multiplier"}}) {
    SCOPED_TRACE(a.field);
    const std::string got =
        error_of(campaign_with("ssi7361", "program = \"setup\"\n" + a.field + " = " + a.value));
    EXPECT_NE(got.find(": host[0]."), std::string::npos) << got;
    EXPECT_TRUE(got.find("together") != std::string::npos ||
                got.find("with bits and first_bit") != std::string::npos)
        << got;
    bool listed = false;
    for (const duts::ProgramFieldInfo& f : setup->fields)
      if (f.name == a.field) listed = f.description.find(a.with) != std::string::npos;
    EXPECT_TRUE(listed) << a.with;
  }
}

// The words of each write of a 7361 campaign whose [[host]] entries are BODIES, 1 ms apart.
std::vector<Words> ssi7361_writes(const std::vector<std::string>& bodies) {
  std::string text = "[campaign]\nname = \"words\"\nend = \"20ms\"\n[dut]\nmodel = \"ssi7361\"\n";
  for (std::size_t i = 0; i < bodies.size(); ++i)
    text += "[[host]]\nat = \"" + std::to_string(i + 1) + "ms\"\n" + bodies[i] + "\n";
  text += "[[host]]\nat = \"19ms\"\nread = 0\nname = \"status\"\n[[check]]\nkind = \"word_bits\"\nname = "
          "\"status\"\nobservation = \"status\"\nmask = 1\nvalue = 0\n";
  const Campaign c = parse_campaign(text, "t.toml");
  std::vector<Words> out;
  for (const auto& h : c.points.at(0).host)
    if (h.kind == HostAction::Kind::Write) out.push_back(h.words);
  return out;
}

TEST(ProgramSsi7361, CodeLogicAndClockLeftOutKeepTheLastFormatWritten) {
  // The Format word (%AQ1) is written whole (L2126-L2152) and the board cannot be read back:
  // code (bit 07), logic (bit 08) and clock (bit 16) a setup leaves out are what the campaign's
  // last Format write set; before any, the factory binary, positive, 125 kHz (L2159-L2161).
  const std::string fmt = "program = \"setup\"\nbits = 24\nfirst_bit = 1";
  const auto w = ssi7361_writes({
      fmt, // factory bits
      "program = \"setup\"\nbits = 25\nfirst_bit = 1\ncode = \"gray\"\nlogic = \"negative\"\nclock = "
      "\"500kHz\"",                       // 0x80C0 | 0x0119
      "program = \"setup\"\npreset = -1", // no Format: skipped
      fmt,                                // keeps all three
      fmt + "\ncode = \"binary\"",        // clears bit 07 only
      fmt,                                // keeps that
      "write = [2, 280]",                 // a raw Format: 0x0118
      fmt + "\nclock = \"500kHz\"",       // from the raw one
      // Gray, negative, 500 kHz, but first_bit 2 + bits 25 > 26: FMTErr (L2162-L2163), the
      // board keeps its Format, and so does the next block.
      "write = [2, 0x82D9]",
      fmt,
  });
  ASSERT_EQ(w.size(), 10U);
  EXPECT_EQ(w[9], (Words{0x0002, 0x8118}));
  EXPECT_EQ(w[0], (Words{0x0002, 0x0118}));
  EXPECT_EQ(w[1], (Words{0x0002, 0x81D9}));
  EXPECT_EQ(w[3], (Words{0x0002, 0x81D8}));
  EXPECT_EQ(w[4], (Words{0x0002, 0x8198}));
  EXPECT_EQ(w[5], (Words{0x0002, 0x8198}));
  EXPECT_EQ(w[7], (Words{0x0002, 0x8118}));
}

// --- Series 2700 (docs/spec/pls2700.md §5.3; manual seeds/002) ----------------------------

TEST(ProgramPls2700, EachInstructionIsOneBtwInBcd) {
  // W14 (L1464, L1476), the sample program's instructions one BTW each: 8400h; 8801h 0360h;
  // C011h 0000h 0010h 0020h.
  EXPECT_EQ(words_of("pls2700", "program = \"clear_errors\""), (Words{1, 0x8400}));
  EXPECT_EQ(words_of("pls2700", "program = \"setup\"\nscale_factor = 360"), (Words{2, 0x8801, 0x0360}));
  EXPECT_EQ(words_of("pls2700", "program = \"limits\"\noutput = 1\non = 10\noff = 20"),
            (Words{4, 0xC011, 0x0000, 0x0010, 0x0020}));
  // W11 (L1370): 8806h, 0090h, 0002h = Circular Offset 90, tach response code 2.
  EXPECT_EQ(words_of("pls2700", "program = \"setup\"\ncircular_offset = 90\ntach_response = 2"),
            (Words{3, 0x8806, 0x0090, 0x0002}));
  // W5 (L413-L415, L1392): 10 ms ON / 5 ms OFF advances are 1005h; W9 (L1093-L1099) 1003h.
  EXPECT_EQ(words_of("pls2700", "program = \"limits\"\noutput = 6\non = 45\noff = 140\non_advance_ms = 10\n"
                                "off_advance_ms = 5")[2],
            0x1005);
  EXPECT_EQ(words_of("pls2700", "program = \"limits\"\noutput = 4\non = 4095\noff = 0\non_advance_ms = 10\n"
                                "off_advance_ms = 3"),
            (Words{4, 0xC041, 0x1003, 0x4095, 0x0000}));
  // Ranges (L1369, L1393): SF 2..4096, TR 0..4, outputs 1..8, advances 0..99.
  EXPECT_TRUE(
      rejected("pls2700", "program = \"setup\"\nscale_factor = 1", 1, 16, "scale_factor", "2 .. 4096"));
  EXPECT_TRUE(
      rejected("pls2700", "program = \"setup\"\ntach_response = 5", 1, 17, "tach_response", "0 .. 4"));
  EXPECT_TRUE(
      rejected("pls2700", "program = \"limits\"\noutput = 9\non = 1\noff = 2", 1, 10, "output", "1 .. 8"));
  EXPECT_TRUE(rejected("pls2700", "program = \"limits\"\noutput = 1\non = 1\noff = 2\non_advance_ms = 100", 4,
                       17, "on_advance_ms", "0 .. 99"));
  // Nothing to send: the message points at the entry.
  EXPECT_NE(
      error_of(campaign_with("pls2700", "program = \"setup\"")).find("host[0].scale_factor: at least one"),
      std::string::npos);
}

// --- Shipped campaigns: the named form runs exactly as the raw words did ----------------

struct Spelled {
  const char* named; // the [[host]] lines in the shipped file
  const char* raw;   // the words the manual gives for them
};

// The shipped FILE, and the same with every NAMED text replaced by its RAW words.
std::pair<std::string, std::string> named_and_raw(const std::string& file,
                                                  const std::vector<Spelled>& spelled) {
  const std::string named = test::read_file(file);
  std::string raw = named;
  for (const Spelled& s : spelled) {
    std::size_t at = raw.find(s.named);
    if (at == std::string::npos) throw std::logic_error(std::string("not in ") + file + ": " + s.named);
    for (; at != std::string::npos; at = raw.find(s.named, at))
      raw.replace(at, std::string(s.named).size(), s.raw);
  }
  return {named, raw};
}

void expect_same_results(const std::string& device, const std::string& name,
                         const std::vector<Spelled>& spelled) {
  const auto [named_text, raw_text] = named_and_raw(test::campaign_dir(device) + "/" + name, spelled);
  ASSERT_EQ(raw_text.find("program = "), std::string::npos) << "a named block left in the raw form";
  const Campaign named = parse_campaign(named_text, name);
  const Campaign raw = parse_campaign(raw_text, name);
  ASSERT_EQ(named.points.size(), raw.points.size());
  for (std::size_t p = 0; p < named.points.size(); ++p) {
    ASSERT_EQ(named.points[p].host.size(), raw.points[p].host.size());
    for (std::size_t h = 0; h < named.points[p].host.size(); ++h)
      EXPECT_EQ(named.points[p].host[h].words, raw.points[p].host[h].words) << name << " host[" << h << "]";
  }
  const nlohmann::json named_runs = rig::to_json(test::run_everything(named))["runs"];
  const nlohmann::json raw_runs = rig::to_json(test::run_everything(raw))["runs"];
  ASSERT_FALSE(named_runs.empty());
  EXPECT_EQ(named_runs.dump(), raw_runs.dump()) << name;
}

TEST(ProgramShipped, Ans1AdvancesInWordsRunsAsItsRawWords) {
  expect_same_results(
      "ans1", "ans1_advances.toml",
      {{"program = \"configuration\"\nsensor = \"encoder\"\ncpc = 360\nfsc = 360",
        "write = [0x0382, 0x0008, 360, 360]"},
       {"program = \"fixed_advance\"\noutput = 1\nlead_ms = 10", "write = [0x0105, 1, 10, 0]"},
       {"program = \"setpoints\"\noutput = 1\non = 100\noff = 200",
        "write = [0x0403, 1, 0, 0, 100, 200, 0, 0]"}});
}

TEST(ProgramShipped, Smd23eProfileInWordsRunsAsItsRawWords) {
  expect_same_results(
      "smd23e", "smd23e_profile.toml",
      {{"program = \"configuration\"\nstarting_speed = 1000\nsteps_per_turn = 2048\nidle_current_percent = "
        "50\n"
        "motor_current_x10 = 20",
        "write = [32768, 32775, 1, 0, 2048, 0, 1024, 50, 20, 0]"},
       {"program = \"command\"\ncommand = \"none\"", "write = [0, 32768]"},
       {"program = \"move\"\nmove = \"relative\"\nsteps = 4000\nspeed = 10000\naccel = 100\ndecel = 100",
        "write = [2, 32768, 4, 0, 10, 0, 100, 100, 0, 0]"},
       {"program = \"move\"\nmove = \"relative\"\nsteps = 600\nspeed = 10000\naccel = 100\ndecel = 100",
        "write = [2, 32768, 0, 600, 10, 0, 100, 100, 0, 0]"}});
}

TEST(ProgramShipped, Amci4501PassInWordsRunsAsItsRawWords) {
  expect_same_results("amci4501", "amci4501_pass.toml",
                      {{"program = \"mode\"\nmode = 1\ntimeout_ms = 1000", "write = [0x0000, 1000]"},
                       {"program = \"mode\"\nmode = 3\ntimeout_ms = 1000", "write = [0x0008, 1000]"},
                       {"program = \"mode\"\nmode = 4\ntimeout_ms = 1000", "write = [0x0010, 1000]"}});
}

TEST(ProgramShipped, Ssi7361DataTypesInWordsRunsAsItsRawWords) {
  expect_same_results(
      "ssi7361", "ssi7361_data_types.toml",
      {{"program = \"setup\"\nbits = 10\nfirst_bit = 1\nmultiplier = 1\ndivisor = 1",
        "write = [0x0006, 0x010A, 1, 1]"},
       {"program = \"setup\"\nbits = 10\nfirst_bit = 1\ncode = \"gray\"\nlogic = \"negative\"",
        "write = [0x0002, 0x01CA]"},
       {"program = \"setup\"\nbits = 10\nfirst_bit = 1\ncode = \"gray\"", "write = [0x0002, 0x014A]"},
       {"program = \"setup\"\nbits = 10\nfirst_bit = 1\ncode = \"binary\" # the Format word is written "
        "whole: left "
        "out, code stays the gray above\nlogic = \"negative\"",
        "write = [0x0002, 0x018A]"}});
}

TEST(ProgramShipped, Pls2700TachInWordsRunsAsItsRawWords) {
  expect_same_results("pls2700", "pls2700_tach.toml",
                      {{"program = \"setup\"\ntach_response = 4", "write = [2, 0x8804, 0x0004]"},
                       {"program = \"setup\"\ntach_response = 3", "write = [2, 0x8804, 0x0003]"},
                       {"program = \"setup\"\ntach_response = 0", "write = [2, 0x8804, 0x0000]"}});
}

} // namespace
} // namespace hilrig::campaign
