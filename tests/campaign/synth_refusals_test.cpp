// `hilrig synth` refuses, before it writes anything, what it could not write as asked: a time
// outside its option's own range, a level or a value CLI11 took for an option, stimuli that
// overlap, an output it cannot write, a CAN interface name Linux would not take, and an option
// the chosen profile or mode does not use. Each refusal is exit 2 and names the option and
// what it accepts; each boundary is swept (the last value accepted, the first refused).

#include <gtest/gtest.h>

#include <filesystem>
#include <string>
#include <vector>

#include "tests/campaign/hilrig_process.hpp"
#include "tests/tools/scratch_files.hpp"
#include "tests/tools/vcd_reader.hpp"

namespace hilrig {
namespace {

namespace fs = std::filesystem;

struct Case {
  std::string args;
  std::string says;
};

// Every case refused (exit 2) with `says` in its message, and no --out written.
void expect_refused(const std::string& dir_name, const std::vector<Case>& cases) {
  const fs::path out = test::scratch_dir("campaign", dir_name) / "never.vcd";
  for (const Case& c : cases) {
    const test::ProcessResult r = test::run_hilrig("synth " + c.args + " --out " + out.string());
    EXPECT_EQ(r.status, 2) << c.args << ": " << r.err;
    EXPECT_NE(r.err.find(c.says), std::string::npos) << c.args << ": " << r.err;
    EXPECT_FALSE(fs::exists(out)) << c.args;
  }
}

// Every command line accepted (exit 0) and its --out written.
void expect_written(const std::string& dir_name, const std::vector<std::string>& lines) {
  const fs::path out = test::scratch_dir("campaign", dir_name) / "ok.vcd";
  for (const std::string& args : lines) {
    fs::remove(out);
    const test::ProcessResult r = test::run_hilrig("synth " + args + " --out " + out.string());
    EXPECT_EQ(r.status, 0) << args << ": " << r.err;
    EXPECT_TRUE(fs::exists(out)) << args;
  }
}

// The 7361's Format ranges (ssi7361.md §3): N 2 .. 25, M 1 .. 24, M + N <= 26, in the manual's
// order (N first), and the positions fit the field.
TEST(SynthRefusals, SsiFieldOutsideThe7361sFormat) {
  expect_refused(
      "synth_refuse_ssi_field",
      {
          {"ssi --bits 1 --frames 2", "--bits: 2 .. 25, the 7361's Number of Data Bits N (got 1)"},
          {"ssi --msb 25 --bits 1", "--bits: 2 .. 25, the 7361's Number of Data Bits N (got 1)"},
          {"ssi --msb 25 --bits 2 --counts-per-turn 4", "--msb: 1 .. 24, the 7361's MSB Number M (got 25)"},
          {"ssi --msb 2 --bits 25", "--msb: --msb + --bits at most 26 (the 7361's M + N: the field ends "
                                    "by stream bit 25) (got 2 + 25 = 27)"},
          {"ssi --msb -1", "--msb: 1 .. 24, the 7361's MSB Number M (got -1)"},
          {"ssi --bits 12 --counts-per-turn 8192",
           "--counts-per-turn: 1 .. 2^bits = 4096: positions 0 .. counts-per-turn - 1 fit the 12-bit "
           "field of --bits (got 8192)"},
      });
  expect_written("synth_ok_ssi_field",
                 {"ssi --bits 2 --frames 2 --counts-per-turn 4", "ssi --msb 24 --bits 2 --counts-per-turn 4",
                  "ssi --msb 1 --bits 25", "ssi --msb 2 --bits 24", "ssi --bits 12 --counts-per-turn 4096"});
}

// Each time option's own range, whatever is wrong with the value; whole numbers as typed.
TEST(SynthRefusals, TimesStateTheirOwnRange) {
  expect_refused(
      "synth_refuse_times",
      {
          {"quadrature --duration nan", "--duration: 1ns .. 3600s (got nan)"},
          {"quadrature --duration 3601s", "--duration: 1ns .. 3600s (got 3601s)"},
          {"quadrature --duration 1e-10", "--duration: 1ns .. 3600s (got 1e-10)"},
          {"ssi --first nan", "--first: 1ns .. 3600s (got nan)"},
          {"ssi --first 0", "--first: 1ns .. 3600s (got 0)"},
          {"ssi --first 3601s", "--first: 1ns .. 3600s (got 3601s)"},
          {"ssi --monoflop 3601s", "--monoflop: 0s .. 3600s (got 3601s)"},
          {"ssi --monoflop nan", "--monoflop: 0s .. 3600s (got nan)"},
          {"ssi --monoflop 0", "--monoflop: a monoflop time above 4us (half a period of the 125 kHz clock"},
          {"ssi --output-delay 3601s", "--output-delay: 0s .. 3600s (got 3601s)"},
          {"ssi --late inf", "--late: 0s .. 3600s (got inf)"},
          {"resolver --duration 3601s", "--duration: 1ns .. 3600s (got 3601s)"},
          {"resolver --duration nan", "--duration: 1ns .. 3600s (got nan)"},
          {"resolver --can-frames --frame-period nan", "--frame-period: 1ns .. 3600s (got nan)"},
          {"resolver --can-frames --frame-period 0", "--frame-period: 1ns .. 3600s (got 0)"},
          {"ssi --frames -1", "--frames: 1 .. 100000 (got -1)"},
          {"ssi --frames 0", "--frames: 1 .. 100000 (got 0)"},
          {"quadrature --missing-edge -1", "(got -1)"},
          {"quadrature --simultaneous -1", "(got -1)"},
          {"resolver --can-frames --channel -1", "--channel: 0 .. 15 (got -1)"},
          {"ssi --glitch-mask -1", "--glitch-mask: 0 .. 16777215 (the 24-bit data field of --bits) (got -1)"},
          // SSI frames end within a campaign's run, as quadrature's and discrete's do: at
          // 125 kHz a frame is 500 us, so from 3599.999 s two end at 3600 s, three after.
          {"ssi --first 3599.999s --frames 3", "--frames: frames that end by 3600s"},
          {"ssi --first 3599.999s --frames 10000", "--frames: frames that end by 3600s"},
          {"discrete --train 3599.5s,1s,0.500000001s,1", "its last edge is at 3600.000000001 s"},
          {"quadrature --duration 0.4ns", "--duration: 1ns .. 3600s (got 0.4ns)"},
          {"discrete --set 3600.0000000006s=1", "--set: 0s .. 3600s (got 3600.0000000006s)"},
          {"discrete --set -0.4ns=1", "--set: 0s .. 3600s (got -0.4ns)"},
          {"discrete --train 3597.5s,1s,0.5s,4", "its last edge is at 3601.000000000 s"},
      });
  expect_written("synth_ok_times",
                 {"quadrature --duration 1ns", "quadrature --duration 1e-9", "resolver --duration 1ns",
                  "ssi --first 1ns --frames 1", "ssi --monoflop 4.001us --output-delay 0 --frames 1",
                  "ssi --first 3599.999s --frames 2",
                  // The printed maximum rate, 16666.666... turns/s² (1e6 rpm/s / 60), is accepted.
                  "quadrature --profile trapezoid --rpm 60 --turns 1 --accel 16666.666 --decel 16666.666",
                  "quadrature --profile press --rpm 60 --brake 16666.666",
                  // A train ends with its last pulse's falling edge: start + (count - 1) x
                  // period + width = 3599.5 + 0 + 0.5 s and 3599.999999995 s + 5 ns = 3600 s.
                  "discrete --train 3599.5s,1s,0.5s,1", "discrete --train 3599.999999995s,10ns,5ns,1",
                  "discrete --train 3599s,1s,0.5s,1", "discrete --train 3597.5s,1s,0.5s,3",
                  // Times are judged as they round to whole ns (docs/synth.md "Ranges").
                  "quadrature --duration 0.6ns", "quadrature --duration 0.5ns",
                  "ssi --first 0.5ns --frames 1", "discrete --set 3600.0000000004s=1"});
}

// A level names its option and the item it is in; a value that looks like an option ("-inf")
// is the value of the option before it, judged by that option's range.
TEST(SynthRefusals, BadValuesNameTheirOption) {
  expect_refused(
      "synth_refuse_values",
      {
          {"discrete --initial 2", "--initial: the level '2' is not 0, 1, high or low"},
          {"discrete --set 1ms=2", "--set: 1ms=2: the level '2' is not 0, 1, high or low"},
          {"discrete --bounce 1ms,2,100us,3,1",
           "--bounce: 1ms,2,100us,3,1: the level '2' is not 0, 1, high or low"},
          {"quadrature --rpm -inf", "--rpm: -32767 .. 32767 rpm (got -inf)"},
          {"quadrature --rpm -nan", "--rpm: -32767 .. 32767 rpm (got -nan)"},
          {"ssi --rpm -inf", "--rpm: -32767 .. 32767 rpm (got -inf)"},
          {"resolver --start -inf", "--start: -3600000 .. 3600000 degrees (10000 turns) (got -inf)"},
      });
  // A mistyped option is still named as one.
  const test::ProcessResult r = test::run_hilrig("synth quadrature --rpm 10 -inf --out x.vcd");
  EXPECT_EQ(r.status, 2);
  EXPECT_NE(r.err.find("-inf: no such option"), std::string::npos) << r.err;
  expect_written("synth_ok_values",
                 {"quadrature --rpm -600 --duration 1ms", "discrete --initial high --set 1ms=low"});
}

// Stimuli of one discrete line play one at a time, each as written: a --set inside a train or a
// bounce, or two of those meeting, is refused naming both; a train needs the line at --initial
// when it starts. 1ms,100us,30us,3 is pulses at 1, 1.1, 1.2 ms, the last falling at 1.23 ms.
TEST(SynthRefusals, DiscreteStimuliDoNotOverlap) {
  expect_refused(
      "synth_refuse_stimuli",
      {
          {"discrete --initial 0 --set 1ms=1 --train 2ms,100us,30us,3",
           "--train: --train 2ms,100us,30us,3 pulses away from --initial 0 and back, but --set 1ms=1 left "
           "the "
           "line at 1 before it starts"},
          {"discrete --train 1ms,100us,30us,3 --set 1.15ms=1",
           "--set: --set 1.15ms=1 (at 1150us) overlaps --train 1ms,100us,30us,3 (1ms .. 1230us)"},
          {"discrete --train 1ms,100us,30us,3 --set 1ms=1", "(1ms .. 1230us) overlaps --set 1ms=1 (at 1ms)"},
          {"discrete --train 1ms,100us,30us,3 --set 1.23ms=0", "--set 1.23ms=0 (at 1230us) overlaps --train"},
          {"discrete --train 1ms,100us,30us,3 --train 1.2ms,100us,30us,2",
           "--train 1.2ms,100us,30us,2 (1200us .. "
           "1330us) overlaps --train "
           "1ms,100us,30us,3"},
          {"discrete --bounce 1ms,1,100us,3,1 --train 1.05ms,100us,30us,3",
           "--train: --train 1.05ms,100us,30us,3 (1050us .. 1280us) overlaps --bounce 1ms,1,100us,3,1"},
          {"discrete --set 0.5ms=1 --bounce 0.5ms,0,10us,1,1", "overlaps --set 0.5ms=1"},
      });
  expect_written("synth_ok_stimuli",
                 {
                     "discrete --train 1ms,100us,30us,3 --set 1.230001ms=1",
                     "discrete --train 1ms,100us,30us,3 --set 999.999us=0",
                     "discrete --set 1ms=1 --set 1ms=1 --set 2ms=0 --train 3ms,100us,30us,3",
                     "discrete --train 1ms,100us,30us,3 --train 1.230001ms,100us,30us,2",
                     "discrete --initial 1 --train 1ms,100us,30us,3 --bounce 2ms,0,10us,1,1",
                 });
  // The train as written, then the set: 3 pulses and one rise.
  const fs::path out = test::scratch_dir("campaign", "synth_stimuli_vcd") / "line.vcd";
  ASSERT_EQ(
      test::run_hilrig("synth discrete --train 1ms,100us,30us,3 --set 2ms=1 --out " + out.string()).status,
      0);
  const test::Vcd vcd = test::read_vcd_file(out.string());
  ASSERT_EQ(vcd.leaf("in").changes.size(), 7U);
  EXPECT_EQ(vcd.leaf("in").changes[5].time, 1'230'000);
  EXPECT_EQ(vcd.leaf("in").changes[6].time, 2'000'000);
  EXPECT_EQ(vcd.leaf("in").changes[6].bits(), 1U);
}

// Every output is checked before any is written: a refused one leaves no other behind.
TEST(SynthRefusals, AnOutputThatCannotBeWrittenLeavesNothing) {
  const fs::path dir = test::scratch_dir("campaign", "synth_refuse_outputs");
  const std::string log = (dir / "hl.log").string();
  const std::string vcd = (dir / "ok.vcd").string();
  const std::string nowhere = (dir / "no" / "such" / "x.vcd").string();
  const auto refused = [&](const std::string& args, const std::string& says) {
    fs::remove(log);
    fs::remove(vcd);
    const test::ProcessResult r = test::run_hilrig("synth " + args);
    EXPECT_EQ(r.status, 2) << args << ": " << r.err;
    EXPECT_NE(r.err.find(says), std::string::npos) << args << ": " << r.err;
    EXPECT_FALSE(fs::exists(log)) << args;
    EXPECT_FALSE(fs::exists(vcd)) << args;
  };
  refused("resolver --out " + nowhere + " --duration 1ms --can-frames --can-log " + log,
          "--out: " + nowhere + ": cannot write in " + (dir / "no" / "such").string());
  refused("resolver --out " + vcd + " --duration 1ms --can-log " + (dir / "no" / "hl.log").string(),
          "--can-log: ");
  refused("resolver --out " + vcd + " --duration 1ms --can-log " + vcd,
          "--can-log: a file other than --out's");
  // The same file by another spelling: ./ in front, or a link to it.
  refused("resolver --out " + vcd + " --duration 1ms --can-log " + (dir / "." / "ok.vcd").string(),
          "--can-log: a file other than --out's");
  refused("resolver --out " + dir.string() + " --duration 1ms", "a directory, not a file to write");
  for (const char* kind : {"quadrature", "discrete", "ssi", "resolver"})
    refused(std::string(kind) + " --out " + nowhere, "--out: " + nowhere + ": cannot write in");
  // Written whole, through a temporary: none is left beside it.
  const test::ProcessResult ok =
      test::run_hilrig("synth resolver --out " + vcd + " --duration 1ms --can-log " + log);
  EXPECT_EQ(ok.status, 0) << ok.err;
  EXPECT_TRUE(fs::exists(vcd));
  EXPECT_TRUE(fs::exists(log));
  EXPECT_FALSE(fs::exists(vcd + ".tmp"));
  EXPECT_FALSE(fs::exists(log + ".tmp"));
}

// What is there already and is not a regular file is written through, as a shell redirection
// would: a symlink's target gets the VCD (the link stays a link), a FIFO gets the bytes. A
// temporary renamed over it would have replaced the link, or a device such as /dev/null.
TEST(SynthRefusals, AnOutputThatIsALinkOrADeviceIsWrittenThrough) {
  const fs::path dir = test::scratch_dir("campaign", "synth_write_through");
  const fs::path target = dir / "target.vcd";
  const fs::path link = dir / "link.vcd";
  fs::remove(target);
  fs::remove(link);
  fs::create_symlink(target.filename(), link);
  const test::ProcessResult r = test::run_hilrig("synth ssi --frames 1 --out " + link.string());
  EXPECT_EQ(r.status, 0) << r.err;
  EXPECT_TRUE(fs::is_symlink(link));
  EXPECT_GT(fs::file_size(target), 0U);
  const test::ProcessResult null = test::run_hilrig("synth ssi --frames 1 --out /dev/null");
  EXPECT_EQ(null.status, 0) << null.err;
  EXPECT_TRUE(fs::is_character_file("/dev/null"));
}

// A candump line is "(time) IFACE ID#DATA": the interface name is what Linux takes (1 .. 15
// characters, IFNAMSIZ 16 with its NUL; no whitespace, '/' or ':').
TEST(SynthRefusals, CanBusIsALinuxInterfaceName) {
  expect_refused(
      "synth_refuse_can_bus",
      {
          {"resolver --can-frames --can-bus ''", "--can-bus: an interface name of 1 .. 15 characters"},
          {"resolver --can-frames --can-bus 'a b'", "(' ' in it: got 'a b')"},
          {"resolver --can-frames --can-bus a/b", "('/' in it: got 'a/b')"},
          {"resolver --can-frames --can-bus a:b", "(':' in it: got 'a:b')"},
          {"resolver --can-frames --can-bus 0123456789abcdef", "(16 characters: got '0123456789abcdef')"},
      });
  const fs::path dir = test::scratch_dir("campaign", "synth_can_bus");
  const std::string log = (dir / "hl.log").string();
  const test::ProcessResult r =
      test::run_hilrig("synth resolver --duration 1ms --can-bus 0123456789abcde --can-log " + log +
                       " --out " + (dir / "ok.vcd").string());
  ASSERT_EQ(r.status, 0) << r.err;
  EXPECT_EQ(test::read_file(log).rfind("(0000000000.000000) 0123456789abcde 120#", 0), 0U)
      << test::read_file(log);
}

// An option the chosen profile or mode does not use is refused, naming what it needs.
TEST(SynthRefusals, OptionsThatWouldDoNothing) {
  const std::string move = "quadrature --turns 1 --accel 100 ";
  expect_refused(
      "synth_refuse_unused",
      {
          {"quadrature --profile trapezoid --turns 1 --accel 100 --duration 1ms",
           "--duration: only with --profile constant or press (a trapezoid or scurve runs until it has moved "
           "--turns) (this is --profile trapezoid)"},
          {"quadrature --profile scurve --turns 1 --accel 100 --jerk 1000 --duration 1ms",
           "--duration: only with --profile constant or press"},
          {"quadrature --profile constant --turns 5",
           "--turns: only with --profile trapezoid or scurve (this is "
           "--profile constant)"},
          {"quadrature --profile constant --accel 3", "--accel: only with --profile trapezoid or scurve"},
          {"quadrature --profile press --brake 10 --accel 3",
           "--accel: only with --profile trapezoid or scurve"},
          {"quadrature --profile constant --jerk 5",
           "--jerk: only with --profile scurve (this is --profile constant)"},
          {"quadrature --profile trapezoid --turns 1 --accel 100 --jerk 5",
           "--jerk: only with --profile scurve"},
          {"quadrature --profile constant --brake 2", "--brake: only with --profile press"},
          {"quadrature --profile constant --steps 4", "--steps: only with --profile scurve"},
          {"quadrature --profile constant --decel 4", "--decel: only with --profile trapezoid"},
          {"quadrature --profile scurve --turns 1 --accel 100 --jerk 1000 --decel 4",
           "--decel: only with --profile trapezoid (an scurve slows at --accel)"},
          {"quadrature --index-count 5", "--index-count: only with --index-width > 0"},
          {"quadrature --index-count 5 --index-width 0", "--index-count: only with --index-width > 0"},
          {"quadrature --index-line 5 --index-width 3", "--index-width: not with --index-line"},
          {"quadrature --index-line 5 --index-count 3", "--index-count: not with --index-line"},
          {"quadrature --rate-action fail", "--rate-action: only with --max-input-hz > 0"},
          {"resolver --frame-period 0", "--frame-period: only with --can-frames or --can-log"},
          {"resolver --channel 3", "--channel: only with --can-frames or --can-log"},
          {"resolver --can-bus vcan0", "--can-bus: only with --can-frames or --can-log"},
          {"ssi --stuck high --late 1us",
           "--late: not with --stuck high: a stuck data line sends no bit to change"},
          {"ssi --stuck low --flip-bit 3", "--flip-bit: not with --stuck low"},
          {"ssi --stuck low --glitch-mask 1", "--glitch-mask: not with --stuck low"},
      });
  expect_written("synth_ok_used", {
                                      move + "--profile trapezoid --decel 50",
                                      move + "--profile scurve --jerk 1000 --steps 4",
                                      "quadrature --profile press --brake 100 --duration 1ms",
                                      "quadrature --profile constant --duration 1ms --dwell 1ms",
                                      "quadrature --index-count 5 --index-width 3",
                                      "quadrature --index-line 5",
                                      "quadrature --max-input-hz 1e6 --rate-action fail",
                                      "resolver --can-frames --frame-period 1ms --channel 3 --can-bus vcan0",
                                      "ssi --stuck high --frames 1",
                                  });
}

} // namespace
} // namespace hilrig
