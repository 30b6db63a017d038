// The hilrig program as a person types it: mistyped subcommands and options are named with the
// closest valid ones (exit 2), a negative seed is refused, `serve --fault` lists the choices,
// `run` puts its summary and report path on stdout, the rest on stderr, and `synth <kind>`
// (a command of a command) takes its own options.

#include <fcntl.h>
#include <sys/file.h>
#include <sys/wait.h>
#include <unistd.h>

#include <gtest/gtest.h>

#include <array>
#include <cstdint>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "rig/results/results_json.hpp"
#include "tests/campaign/hilrig_process.hpp"
#include "tests/tools/scratch_files.hpp"
#include "tests/tools/vcd_reader.hpp"

namespace hilrig {
namespace {

namespace fs = std::filesystem;

using Result = test::ProcessResult;
Result hilrig(const std::string& args, const std::string& wrap = "") { return test::run_hilrig(args, wrap); }

const std::string kPass = std::string(HILRIG_SOURCE_DIR) + "/campaigns/reference/reference_pls_pass.toml";

// `hilrig merge` exits as `hilrig run` of the unsharded campaign would (docs/ci.md): a run a
// rig fault stopped, or a shard a signal stopped, is 3 (the rig's failure), not 1 (the
// board's); the same shard as it ran is 0.
TEST(CommandLine, MergeOfARigFaultOrAnInterruptedShardExitsThree) {
  const fs::path dir = test::scratch_dir("campaign", "merge_exit_three");
  ASSERT_EQ(hilrig("run " + kPass + " --out " + (dir / "ran").string() + " --trace none").status, 0);
  nlohmann::json shard = nlohmann::json::parse(test::read_file(dir / "ran" / "results.json"));
  const auto write = [&](const std::string& name, const nlohmann::json& j) {
    std::ofstream(dir / name) << j.dump();
    return (dir / name).string();
  };
  const std::string clean = write("clean.json", shard);
  nlohmann::json faulted = shard;
  faulted["runs"][0]["error"] = "the run made no progress";
  const std::string rig_fault = write("faulted.json", faulted);
  nlohmann::json stopped = shard;
  stopped["interrupted"] = "SIGTERM";
  const std::string interrupted = write("stopped.json", stopped);
  EXPECT_EQ(hilrig("merge " + (dir / "m0.json").string() + " " + clean).status, 0);
  const Result a = hilrig("merge " + (dir / "m1.json").string() + " " + rig_fault);
  EXPECT_EQ(a.status, 3) << a.err << a.out;
  const Result b = hilrig("merge " + (dir / "m2.json").string() + " " + interrupted);
  EXPECT_EQ(b.status, 3) << b.err << b.out;
}

// The kill-recovery merge writes into a run's own directory (`hilrig merge OUT/results.json
// OUT/runs.jsonl`): while a run still holds that directory's .hilrig.lock the merge refuses, 3,
// as a second `hilrig run` there does, and writes nothing; once it is released, it merges. A
// directory that does not exist yet is made.
TEST(CommandLine, MergeIntoADirectoryARunHoldsIsRefused) {
  const fs::path dir = test::scratch_dir("campaign", "merge_locked");
  ASSERT_EQ(hilrig("run " + kPass + " --out " + (dir / "ran").string() + " --trace none").status, 0);
  const std::string shard = (dir / "ran" / "results.json").string();
  const fs::path out = dir / "busy" / "results.json";
  fs::create_directories(out.parent_path());
  {
    const int fd = ::open((out.parent_path() / ".hilrig.lock").c_str(), O_RDWR | O_CREAT | O_CLOEXEC, 0644);
    ASSERT_GE(fd, 0);
    ASSERT_EQ(::flock(fd, LOCK_EX | LOCK_NB), 0);
    const Result held = hilrig("merge " + out.string() + " " + shard);
    EXPECT_EQ(held.status, 3) << held.err;
    EXPECT_NE(held.err.find("is being written by a hilrig run"), std::string::npos) << held.err;
    EXPECT_FALSE(fs::exists(out));
    ::close(fd);
  }
  EXPECT_EQ(hilrig("merge " + out.string() + " " + shard).status, 0);
  EXPECT_TRUE(fs::exists(out));
  EXPECT_EQ(hilrig("merge " + (dir / "new" / "deeper" / "m.json").string() + " " + shard).status, 0);
  EXPECT_TRUE(fs::exists(dir / "new" / "deeper" / "m.junit.xml"));
}

TEST(CommandLine, UnknownSubcommandNamesTheClosest) {
  const Result r = hilrig("rn " + kPass);
  EXPECT_EQ(r.status, 2);
  EXPECT_EQ(r.err.rfind("hilrig: rn: no such command (did you mean \"run\"?); commands: ", 0), 0U) << r.err;
  EXPECT_NE(r.err.find("check"), std::string::npos) << r.err;
}

TEST(CommandLine, UnknownOptionNamesTheClosestInsteadOfAMissingOne) {
  // CLI11 alone says "--out is required" here.
  const Result r = hilrig("run " + kPass + " --ot somewhere");
  EXPECT_EQ(r.status, 2);
  EXPECT_EQ(r.err.rfind("hilrig run: --ot: no such option (did you mean \"--out\"?)", 0), 0U) << r.err;
  const Result seed = hilrig("run " + kPass + " --out x --sed 3");
  EXPECT_NE(seed.err.find("--sed: no such option (did you mean \"--seed\"?)"), std::string::npos) << seed.err;
  // Negative numbers are values, not options.
  EXPECT_EQ(hilrig("compare a.json b.json --default-rel -1").err.find("no such option"), std::string::npos);
}

// --station NAME (issue 18, traceability): 1..64 printable ASCII characters; 65 (one past the
// cap) or a control character is refused before anything runs, 64 runs.
TEST(CommandLine, StationIsALabelOfAtMost64PrintableCharacters) {
  const fs::path out = test::scratch_dir("campaign", "station_label");
  const Result long_name =
      hilrig("run " + kPass + " --out " + out.string() + " --station " + std::string(65, 'S'));
  EXPECT_EQ(long_name.status, 2);
  EXPECT_NE(long_name.err.find("--station"), std::string::npos) << long_name.err;
  EXPECT_NE(long_name.err.find("1 .. 64 printable ASCII characters"), std::string::npos) << long_name.err;
  EXPECT_FALSE(fs::exists(out / "results.json"));
  const Result tab = hilrig("run " + kPass + " --out " + out.string() + " --station \"$(printf 'a\\tb')\"");
  EXPECT_EQ(tab.status, 2) << tab.err;
  const Result at_cap =
      hilrig("run " + kPass + " --out " + out.string() + " --station " + std::string(64, 'S'));
  EXPECT_EQ(at_cap.status, 0) << at_cap.err;
  EXPECT_NE(test::read_file(out / "results.json").find("\"station\": \"" + std::string(64, 'S') + "\""),
            std::string::npos);
}

TEST(CommandLine, NegativeSeedIsRefused) {
  const fs::path out = test::scratch_dir("campaign", "negative_seed");
  const Result r = hilrig("run " + kPass + " --out " + out.string() + " --seed -1");
  EXPECT_EQ(r.status, 2);
  // The valid range is named: 0..2^64-1 (rig/cli/seed_option, one parser for every --seed).
  EXPECT_NE(r.err.find("a seed is a decimal integer 0..18446744073709551615"), std::string::npos) << r.err;
  EXPECT_FALSE(fs::exists(out / "results.json"));
}

TEST(CommandLine, UnknownTracePolicyNamesTheClosestAndRunsNothing) {
  const fs::path out = test::scratch_dir("campaign", "trace_policy_typo");
  const Result r = hilrig("run " + kPass + " --out " + out.string() + " --trace faild");
  EXPECT_EQ(r.status, 2);
  EXPECT_NE(r.err.find("--trace: faild is not one of all, failed, none (did you mean \"failed\"?)"),
            std::string::npos)
      << r.err;
  EXPECT_FALSE(fs::exists(out / "results.json"));
  const Result far = hilrig("run " + kPass + " --out " + out.string() + " --trace everything");
  EXPECT_EQ(far.status, 2);
  EXPECT_NE(far.err.find("--trace: everything is not one of all, failed, none\n"), std::string::npos)
      << far.err;
}

// A device fault and a power cycle are the virtual board's: `run --backend hardware` refuses
// the campaign before it even reads the rig config (exit 2, the entry's file:line:col) and
// writes nothing.
TEST(CommandLine, HardwareBackendRefusesDeviceFaultsAndPowerCycles) {
  const std::string dir = std::string(HILRIG_SOURCE_DIR) + "/campaigns/ssi7361/";
  const fs::path out = test::scratch_dir("campaign", "hardware_device_fault");
  const Result fault = hilrig(
      "run " + dir + "ssi7361_eeprom.toml --backend hardware --rig no-such-rig.toml --out " + out.string());
  EXPECT_EQ(fault.status, 2);
  EXPECT_NE(
      fault.err.find("ssi7361_eeprom.toml:47:1: device_fault[0].fault: no [[device_fault]] on a hardware "
                     "backend: \"eeprom_error\" is made by a virtual board's model"),
      std::string::npos)
      << fault.err;
  EXPECT_NE(fault.err.find("--backend virtual"), std::string::npos) << fault.err;
  EXPECT_EQ(fault.err.find("no-such-rig"), std::string::npos) << fault.err;
  EXPECT_FALSE(fs::exists(out / "results.json"));

  const Result power =
      hilrig("run " + dir + "ssi7361_power_cycle.toml --backend hardware --rig no-such-rig.toml --out " +
             out.string());
  EXPECT_EQ(power.status, 2);
  EXPECT_NE(
      power.err.find("ssi7361_power_cycle.toml:49:1: power_cycle[0].at: no [[power_cycle]] on a hardware "
                     "backend"),
      std::string::npos)
      << power.err;
  EXPECT_FALSE(fs::exists(out / "results.json"));
  // The same campaigns run on the virtual board (ssi7361_eeprom passes there: test_device_faults).
}

TEST(CommandLine, ServeFaultListsTheChoices) {
  const Result r = hilrig("serve smd23e --pty --fault lost-step");
  EXPECT_EQ(r.status, 2);
  EXPECT_NE(r.err.find("unknown fault variant 'lost-step' for smd23e (one of: none, wrong-acceleration, "
                       "lost-steps, ignored-limit, late-stop)"),
            std::string::npos)
      << r.err;
}

// --byte-timeout is an RTU link's (docs/serve.md): beyond 0s..10s it is refused naming the range,
// and on TCP, whatever its value, naming the link it applies to; before anything serves. So is
// --scan, the ANS1's scan period, given for another device.
TEST(CommandLine, ServeByteTimeoutIsAnRtuDurationInItsRange) {
  for (const char* args : {"serve ans1 --pty --byte-timeout 11s", "serve ans1 --pty --byte-timeout -1ms",
                           "serve ans1 --pty --byte-timeout soon"}) {
    SCOPED_TRACE(args);
    const Result r = hilrig(args);
    EXPECT_EQ(r.status, 2);
    EXPECT_NE(r.err.find("an RTU link's wait for a frame's next byte, 0s..10s"), std::string::npos) << r.err;
  }
  for (const char* value : {"0s", "100ms", "10s"}) {
    const Result tcp =
        hilrig(std::string("serve ans1 --modbus-tcp 0 --byte-timeout ") + value, "timeout 20 ");
    EXPECT_EQ(tcp.status, 2) << value;
    EXPECT_NE(tcp.err.find(std::string("--byte-timeout ") + value + ": applies to an RTU link only"),
              std::string::npos)
        << tcp.err;
    EXPECT_EQ(tcp.err.find("0s..10s"), std::string::npos) << tcp.err;
  }
  const Result scan = hilrig("serve pls2700 --modbus-tcp 0 --scan 100us", "timeout 20 ");
  EXPECT_EQ(scan.status, 2);
  EXPECT_NE(scan.err.find("--scan 100us: applies to the ans1 only"), std::string::npos) << scan.err;
}

// --idle-timeout is 1ms .. 9000000000s, the longest a duration's text holds (docs/serve.md): a
// value beyond either end is refused naming the whole range, and a unit hilrig does not take
// is named as such. A value in range passes on to the next option (--byte-timeout, refused on
// TCP), so acceptance is seen without serving.
TEST(CommandLine, ServeIdleTimeoutNamesItsWholeRangeAndABadUnit) {
  const std::string range = ": a duration of 1ms .. 9000000000s, like \"60s\"";
  for (const std::string value : {"9000000001s", "0.999ms", "1e400s"}) {
    const Result r = hilrig("serve ans1 --modbus-tcp 0 --idle-timeout " + value);
    EXPECT_EQ(r.status, 2) << value;
    EXPECT_NE(r.err.find("--idle-timeout " + value + range), std::string::npos) << r.err;
  }
  for (const std::string unit : {"h", "min"}) {
    const Result r = hilrig("serve ans1 --modbus-tcp 0 --idle-timeout 100" + unit);
    EXPECT_EQ(r.status, 2) << unit;
    EXPECT_NE(r.err.find("--idle-timeout 100" + unit + ": \"" + unit +
                         "\" is not a unit (one of ns, us, ms or s)" + range),
              std::string::npos)
        << r.err;
  }
  for (const std::string value : {"9000000000s", "8999999999s", "1ms", "1.001ms"}) {
    const Result r = hilrig("serve ans1 --modbus-tcp 0 --idle-timeout " + value + " --byte-timeout 0s");
    EXPECT_EQ(r.status, 2) << value;
    EXPECT_NE(r.err.find("--byte-timeout 0s: applies to an RTU link only"), std::string::npos) << r.err;
  }
}

// Parameters each in range that do not go together are refused before anything serves (exit
// 2): a reference off the 2741's 200 us update grid (L377; models/pls2700/README.md
// "Decoder"), an empty transducer-fault band.
TEST(CommandLine, ServePls2700RefusesParamsThatDoNotGoTogether) {
  const Result off_grid =
      hilrig("serve pls2700 --modbus-tcp 0 --model 2741 --param excitation_hz=3000", "timeout 20 ");
  EXPECT_EQ(off_grid.status, 2);
  EXPECT_NE(off_grid.err.find("--param excitation_hz=3000: a reference whose half period 1/(2f) divides the "
                              "2741's 200 us update"),
            std::string::npos)
      << off_grid.err;
  EXPECT_NE(off_grid.err.find("a multiple of 2500 Hz up to 10000: 2500, 5000, 7500, 10000"),
            std::string::npos)
      << off_grid.err;
  const Result empty_band =
      hilrig("serve pls2700 --modbus-tcp 0 --param min_stator_ratio=0.6 --param max_stator_ratio=0.5",
             "timeout 20 ");
  EXPECT_EQ(empty_band.status, 2);
  EXPECT_NE(empty_band.err.find("--param min_stator_ratio=0.6: min_stator_ratio at most max_stator_ratio"),
            std::string::npos)
      << empty_band.err;
}

// `hilrig serve --help` names every device's fault variants, the same list a wrong one is
// answered with.
TEST(CommandLine, ServeHelpListsEveryDevicesFaults) {
  const Result help = hilrig("serve --help");
  EXPECT_EQ(help.status, 0);
  std::string text = help.out;
  // CLI11 wraps the description: compare with the line breaks and their indentation gone.
  std::string flat;
  for (std::size_t i = 0; i < text.size(); ++i) {
    if (text[i] != '\n') {
      flat += text[i];
      continue;
    }
    while (i + 1 < text.size() && text[i + 1] == ' ') ++i;
    flat += ' ';
  }
  for (const char* device : {"ans1", "smd23e", "pls2700", "amci4501", "ssi7361"}) {
    SCOPED_TRACE(device);
    const Result r = hilrig(std::string("serve ") + device + " --pty --fault no-such-fault");
    EXPECT_EQ(r.status, 2);
    const std::size_t from = r.err.find("(one of: ");
    const std::size_t to = r.err.find(')', from);
    ASSERT_NE(to, std::string::npos) << r.err;
    const std::string choices = r.err.substr(from + 9, to - from - 9);
    EXPECT_NE(flat.find(std::string(device) + ": " + choices), std::string::npos) << choices << "\n" << flat;
  }
}

TEST(CommandLine, SummaryAndReportPathOnStdoutTheRestOnStderr) {
  const fs::path out = test::scratch_dir("campaign", "stdout_summary");
  const Result r = hilrig("run " + kPass + " --out " + out.string() + " --progress");
  EXPECT_EQ(r.status, 0);
  EXPECT_EQ(r.out,
            "reference-pls-pass: 4 run(s), 4 passed, 0 failed, 0 errored; faults caught 0/0; verdict pass\n"
            "report: " +
                (out / "report.html").string() + "\n");
  EXPECT_NE(r.err.find("[4/4] run 3: pass in "), std::string::npos) << r.err;
  EXPECT_EQ(r.err.find("verdict"), std::string::npos) << r.err;
}

// `hilrig --version` alone builds no command's options (rig/main.cpp); CLI11 still answers it.
TEST(CommandLine, VersionAloneNamesTheToolVersion) {
  const Result r = hilrig("--version");
  EXPECT_EQ(r.status, 0);
  EXPECT_EQ(r.out, std::string("hilrig ") + rig::tool_version() + "\n");
  EXPECT_EQ(r.err, "");
}

// --help still builds every command: the listing names each.
TEST(CommandLine, HelpListsEveryCommand) {
  const Result r = hilrig("--help");
  EXPECT_EQ(r.status, 0);
  for (const char* command :
       {"synth", "run", "check", "list", "compare", "merge", "serve", "latency", "power", "trend"}) {
    EXPECT_NE(r.out.find(std::string("\n  ") + command + " "), std::string::npos) << command << "\n" << r.out;
  }
}

TEST(CommandLine, CheckValidatesADirectory) {
  const Result r = hilrig("check " + std::string(HILRIG_SOURCE_DIR) + "/campaigns/reference");
  EXPECT_EQ(r.status, 0) << r.err;
  EXPECT_NE(r.out.find("reference_pls_faults.toml: ok (5 run(s), 2 check(s) a run)"), std::string::npos)
      << r.out;
}

// `hilrig synth <kind> --out F ...` through the program itself: the words after "synth" name
// one of its kinds, whose options they are (the hints once checked them against synth's own,
// so every synth command line was refused as "--out: no such option"). The in-process runner
// of tests/signals/ does not go through main(); this does.
TEST(CommandLine, SynthEveryKindRunsFromTheCommandLine) {
  const fs::path dir = test::scratch_dir("campaign", "command_line_synth");
  // 1 line at 60 RPM: 4 counts/turn x 1 turn/s; 0.9 s reaches 3.6 counts. The rig's placement
  // (docs/campaigns.md "[encoder]": count n is entered when the motion reaches n) puts the
  // edges at 1, 2, 3 counts: 250, 500 and 750 ms, A then B then A (states 00 10 11 01).
  const std::string quad = (dir / "quad.vcd").string();
  Result r = hilrig("synth quadrature --out " + quad + " --lines 1 --rpm 60 --duration 0.9s");
  ASSERT_EQ(r.status, 0) << r.err;
  const test::Vcd vcd = test::read_vcd_file(quad);
  ASSERT_EQ(vcd.leaf("A").changes.size(), 2U);
  ASSERT_EQ(vcd.leaf("B").changes.size(), 1U);
  EXPECT_EQ(vcd.leaf("A").changes[0].time, 250'000'000);
  EXPECT_EQ(vcd.leaf("B").changes[0].time, 500'000'000);
  EXPECT_EQ(vcd.leaf("A").changes[1].time, 750'000'000);
  // A level set at 1 ms and cleared at 3 ms: two changes, at those times.
  const std::string discrete = (dir / "discrete.vcd").string();
  r = hilrig("synth discrete --out " + discrete + " --set 1ms=1 --set 3ms=0");
  ASSERT_EQ(r.status, 0) << r.err;
  const test::Vcd in = test::read_vcd_file(discrete);
  ASSERT_EQ(in.leaf("in").changes.size(), 2U);
  EXPECT_EQ(in.leaf("in").changes[0].time, 1'000'000);
  EXPECT_EQ(in.leaf("in").changes[1].time, 3'000'000);
  for (const std::string& kind :
       {std::string("resolver --rpm 600 --duration 1ms"), std::string("ssi --frames 2")}) {
    const fs::path out = dir / "kind.vcd";
    fs::remove(out);
    r = hilrig("synth " + kind + " --out " + out.string());
    EXPECT_EQ(r.status, 0) << kind << ": " << r.err;
    EXPECT_TRUE(fs::exists(out)) << kind;
  }
}

TEST(CommandLine, SynthMistypedKindOrOptionNamesTheClosest) {
  Result r = hilrig("synth quadratur --out x.vcd");
  EXPECT_EQ(r.status, 2);
  EXPECT_EQ(
      r.err.rfind("hilrig synth: quadratur: no such command (did you mean \"quadrature\"?); commands: ", 0),
      0U)
      << r.err;
  r = hilrig("synth quadrature --line 5 --out x.vcd");
  EXPECT_EQ(r.status, 2);
  EXPECT_EQ(r.err.rfind("hilrig synth quadrature: --line: no such option (did you mean \"--lines\"?)", 0), 0U)
      << r.err;
}

// A value out of range is bad input (exit 2) with the option and its bound named, whether
// CLI11, the command or the signal library finds it; nothing is written.
TEST(CommandLine, SynthBadValuesNameTheOptionAndItsRange) {
  const fs::path out = test::scratch_dir("campaign", "command_line_synth_bad") / "never.vcd";
  struct Case {
    std::string args;
    std::string says;
  };
  const Case cases[] = {
      {"quadrature --lines 0", "--lines: 0 is not > 0"},   // CLI11 once said "0 not in range 0 to 1.8e308"
      {"quadrature --lines -3", "--lines: -3 is not > 0"}, // a negative number is a value
      {"quadrature --lines abc", "--lines: abc is not a number"},
      {"quadrature --duration 0ms", "--duration: 1ns .. 3600s (got 0ms)"},
      {"quadrature --duration -1ms", "--duration: 1ns .. 3600s (got -1ms)"}, // "-1ms" is a value too
      {"resolver --duration -1ms", "--duration: 1ns .. 3600s (got -1ms)"},
      {"discrete --train 2ms,1ms,3ms,3", "--train: a width 0 < width < period 1ms (got 3ms)"},
      {"ssi --bits 26", "--bits: 2 .. 25, the 7361's Number of Data Bits N (got 26)"},
      // Non-finite and huge numbers: the campaign's limits (docs/campaigns.md "Ranges and limits").
      {"quadrature --rpm nan", "--rpm: -32767 .. 32767 rpm (got nan)"},
      {"quadrature --start inf", "--start: -10000 .. 10000 turns (got inf)"},
      {"quadrature --rpm 1e300 --duration 1ms", "--rpm: -32767 .. 32767 rpm (got 1e+300)"},
      // 1,000,000 counts/s over 4096 counts/turn: 244.140625 turn/s = 14648.4375 rpm.
      {"quadrature --lines 1024 --rpm 15000", "--rpm: at most 1000000 encoder counts/s (X4): 14648.4 rpm"},
      {"quadrature --duration inf", "--duration: 1ns .. 3600s (got inf)"},
      {"quadrature --dwell 3601s", "--dwell: 0s .. 3600s (got 3601s)"},
      {"quadrature --dwell -1s", "--dwell: 0s .. 3600s (got -1s)"},
      {"discrete --set 3601s=1", "--set: 0s .. 3600s (got 3601s)"},
      {"discrete --set -1s=1", "--set: 0s .. 3600s (got -1s)"},
      {"quadrature --turns 10001 --profile trapezoid --accel 10",
       "--turns: -10000 .. 10000 turns (got 10001)"},
      {"ssi --rpm nan", "--rpm: -32767 .. 32767 rpm (got nan)"},
      {"ssi --rpm inf", "--rpm: -32767 .. 32767 rpm (got inf)"},
      {"ssi --start nan", "--start: -10000 .. 10000 turns (got nan)"},
      {"ssi --start 1e300", "--start: -10000 .. 10000 turns (got 1e+300)"},
      {"resolver --rpm nan", "--rpm: -32767 .. 32767 rpm (got nan)"},
      {"resolver --start inf", "--start: -3600000 .. 3600000 degrees (10000 turns) (got inf)"},
      // Memory: 1000 rpm on 1024 lines for an hour is 1000 / 60 x 4096 x 3600 = 245,760,000 edges.
      {"quadrature --rpm 1000 --duration 3600s",
       "quadrature: this motion makes 245760000 edges; synth writes at most 10000000: shorten --duration"},
      // 1 MHz for 10 s: 10^7 samples and the one at t = 0.
      {"resolver --rate 1e6 --duration 10s",
       "--duration x --rate makes 10000001 samples; synth writes at most "
       "5000000"},
      // 1 s of 1 us frames: 10^6 and the one at t = 0.
      {"resolver --can-frames --frame-period 1us --duration 1s",
       "--frame-period: --duration / --frame-period makes 1000001 angle frames; synth writes at most "
       "1000000"},
      {"ssi --frames 100001", "--frames: 1 .. 100000 (got 100001)"},
      // Values once accepted silently.
      {"quadrature --index-line 1024", "--index-line: a line 0 .. 1023 of --lines 1024 (got 1024)"},
      {"quadrature --index-line -1", "--index-line: a line 0 .. 1023 of --lines 1024 (got -1)"},
      {"quadrature --index-width 1 --index-count 4096", "--index-count: a count within the turn, 0 .. 4095"},
      {"quadrature --index-width 1 --index-count -1", "--index-count: a count within the turn, 0 .. 4095"},
      {"quadrature --index-width -1", "--index-width: 0 .. 4096 counts, at most a turn (got -1)"},
      {"quadrature --index-width 4097", "--index-width: 0 .. 4096 counts, at most a turn (got 4097)"},
      {"quadrature --profile trapezoid --accel 10 --decel -1",
       "--decel: 0 .. 16666.666... turns/s² (1000000 rpm/s) (got -1)"},
      // 1e6 rpm/s / 60 = 16666.666... turns/s²: the digits printed are accepted, one more is not.
      {"quadrature --profile trapezoid --rpm 60 --turns 1 --accel 16666.667",
       "--accel: 0 .. 16666.666... turns/s² (1000000 rpm/s) (got 16666.667)"},
      {"quadrature --profile trapezoid --rpm 60 --turns 1 --accel 10 --decel 16666.667",
       "--decel: 0 .. 16666.666... turns/s² (1000000 rpm/s) (got 16666.667)"},
      {"quadrature --profile press --rpm 60 --brake 16666.667",
       "--brake: 0 .. 16666.666... turns/s² (1000000 rpm/s) (got 16666.667)"},
      {"quadrature --max-input-hz -1", "--max-input-hz: -1 is not >= 0"},
      {"ssi --flip-bit 0", "--flip-bit: Value 0 not in range 1 to 25"},
      {"ssi --glitch-mask 1024 --bits 10 --counts-per-turn 1024",
       "--glitch-mask: 0 .. 1023 (the 10-bit data field of --bits) (got 1024)"},
      {"discrete --train 1ms,100us,10us,0", "--train: a count 1 .. 5000000 (got 0)"},
      {"discrete --set 1ms=1 --set 1ms=0", "--set: one level at each time (got 1ms=1 and 1ms=0)"},
      // The option, not the signal library's identifier.
      {"ssi --msb 0", "--msb: 1 .. 24, the 7361's MSB Number M (got 0)"},
      {"ssi --msb 20 --bits 10",
       "--msb: --msb + --bits at most 26 (the 7361's M + N: the field ends by stream "
       "bit 25) (got 20 + 10 = 30)"},
      {"ssi --flip-bit 26", "--flip-bit: Value 26 not in range 1 to 25"},
      {"ssi --output-delay -1us", "--output-delay: 0s .. 3600s (got -1us)"},
      {"ssi --late -1us", "--late: 0s .. 3600s (got -1us)"},
      {"resolver --excitation-hz 2199", "--excitation-hz: 2200 .. 7000 Hz (got 2199)"},
      {"resolver --amplitude 0", "--amplitude: 0 < amplitude <= 100 (got 0)"},
      {"resolver --tr 0", "--tr: 0 < ratio <= 10 (got 0)"},
      // A sampled carrier needs more than two samples a period (Nyquist): the 5 kHz default at
      // 10 kHz, at 9,999 Hz and at 3 % under it aliases; one sample a ns is the trace's limit.
      {"resolver --rate 10000", "--rate: above twice --excitation-hz (10000 Hz: the carrier's Nyquist rate) "
                                "and at most 1000000000 Hz, "
                                "one sample a nanosecond (got 10000)"},
      {"resolver --rate 9999", "--rate: above twice --excitation-hz (10000 Hz: the carrier's Nyquist rate)"},
      {"resolver --rate 9700", "--rate: above twice --excitation-hz (10000 Hz: the carrier's Nyquist rate)"},
      {"resolver --excitation-hz 7000 --rate 14000",
       "--rate: above twice --excitation-hz (14000 Hz: the carrier's Nyquist rate)"},
      {"resolver --rate 1.000001e9 --duration 1ns",
       "--rate: above twice --excitation-hz (10000 Hz: the carrier's"},
      {"quadrature --profile trapezoid --accel 10 --rpm 0",
       "--rpm: a trapezoid profile needs |rpm| 0.01 .. 32767 (got 0)"},
      {"quadrature --profile scurve --accel 10 --jerk 10 --rpm 0",
       "--rpm: a scurve profile needs |rpm| 0.01 .. 32767 (got 0)"},
      {"quadrature --profile press --brake 10 --rpm 0",
       "--rpm: a press profile needs |rpm| 0.01 .. 32767 (got 0)"},
      {"quadrature --profile trapezoid --accel 0",
       "--accel: a trapezoid needs 0 < accel <= 16666.666... turns/s²"},
      // The default motion: 1024 lines at 600 rpm for 10 ms is 4096 x 10 x 0.01 = 409.6 counts: 409 edges.
      {"quadrature --missing-edge 999999",
       "--missing-edge: an edge index 0 .. 408: this motion makes 409 edges "
       "(got 999999)"},
      // 1 line at 600 rpm for 0.26 s: 10.4 counts, edges 0 .. 9 (A B A B ...): edge 9 is the last B.
      {"quadrature --lines 1 --rpm 600 --duration 0.26s --simultaneous 9",
       "--simultaneous: edge 9 has no later A edge to move onto it: this motion makes 10 edges"},
      {"quadrature --lines 1 --rpm 600 --duration 0.26s --simultaneous 11",
       "--simultaneous: an edge index 0 .. 9: this motion makes 10 edges (got 11)"},
      {"quadrature --glitch A,-1ms,1us", "--glitch: 0s .. 3600s (got -1ms)"},
      {"quadrature --glitch A,1ms,0us", "--glitch: 1ns .. 3600s (got 0us)"},
      {"quadrature --phase-error nan", "--phase-error: -2 .. 2 quarter periods (got nan)"},
      {"discrete --train 1ms,100us,100us,3", "--train: a width 0 < width < period 100us (got 100us)"},
      {"discrete --bounce 1ms,1,1us,3,7,1us",
       "--bounce: a window of at least 2 x bounces x min_width = 2 x 3 x 1us = 6us (got 1us)"},
  };
  for (const Case& c : cases) {
    const Result r = hilrig("synth " + c.args + " --out " + out.string());
    EXPECT_EQ(r.status, 2) << c.args << ": " << r.err;
    EXPECT_NE(r.err.find(c.says), std::string::npos) << c.args << ": " << r.err;
    EXPECT_FALSE(fs::exists(out)) << c.args;
  }
}

// The neighbourhood of --rate's bounds: just above twice the 5 kHz carrier and one sample a ns
// are accepted (the refusals are rows of the table above).
TEST(CommandLine, SynthResolverRatesInsideTheBoundsAreWritten) {
  const fs::path out = test::scratch_dir("campaign", "command_line_synth_rate") / "rate.vcd";
  for (const char* args : {"--rate 10001 --duration 1ms", "--rate 10300 --duration 1ms",
                           "--excitation-hz 7000 --rate 14001 --duration 1ms", "--rate 1e9 --duration 1us"}) {
    const Result r = hilrig(std::string("synth resolver ") + args + " --out " + out.string());
    EXPECT_EQ(r.status, 0) << args << ": " << r.err;
    EXPECT_TRUE(fs::exists(out)) << args;
    fs::remove(out);
  }
}

// Several --missing-edge name the edges as solved (they once renumbered after each loss, so
// "3 and 4" lost original edges 3 and 6). 1 line at 600 RPM is 40 counts/s: count k at k x 25 ms,
// and 0.26 s reaches 10.4 counts, so edges 0 .. 9 at 25 .. 250 ms, A on even indices (counts 1, 3,
// ...: states 10, 01) and B on odd ones. Losing edge 3 (B at 100 ms) takes B's next (150 ms) with
// it; edge 4 (A at 125 ms) takes A's next (175 ms). Left: A at 25, 75, 225; B at 50, 200, 250 ms,
// whichever order the options come in.
TEST(CommandLine, SynthMissingEdgesNameTheSolvedEdges) {
  const fs::path dir = test::scratch_dir("campaign", "command_line_synth_missing");
  for (const std::string& order :
       {std::string("--missing-edge 3 --missing-edge 4"), std::string("--missing-edge 4 --missing-edge 3")}) {
    SCOPED_TRACE(order);
    const std::string out = (dir / "missing.vcd").string();
    const Result r =
        hilrig("synth quadrature --lines 1 --rpm 600 --duration 0.26s " + order + " --out " + out);
    ASSERT_EQ(r.status, 0) << r.err;
    const test::Vcd vcd = test::read_vcd_file(out);
    const auto times = [&vcd](const char* leaf) {
      std::vector<std::int64_t> t;
      for (const auto& c : vcd.leaf(leaf).changes) t.push_back(c.time);
      return t;
    };
    EXPECT_EQ(times("A"), (std::vector<std::int64_t>{25'000'000, 75'000'000, 225'000'000}));
    EXPECT_EQ(times("B"), (std::vector<std::int64_t>{50'000'000, 200'000'000, 250'000'000}));
  }
  const fs::path never = dir / "never.vcd";
  const Result twice = hilrig(
      "synth quadrature --lines 1 --rpm 600 --duration 0.26s --missing-edge 3 --missing-edge 3 --out " +
      never.string());
  EXPECT_EQ(twice.status, 2);
  EXPECT_NE(twice.err.find("--missing-edge: edge 3 is named twice"), std::string::npos) << twice.err;
  EXPECT_FALSE(fs::exists(never));
}

// The edge cap counts, before solving, what the motion makes: the counts crossed plus Z's edges.
TEST(CommandLine, SynthCountsEdgesBeforeSolving) {
  const fs::path out = test::scratch_dir("campaign", "command_line_synth_cap") / "cap.vcd";
  // 1 line (4 counts/turn) at 60 RPM (1 turn/s) with Z 1 count wide at count 2 (--index-line 0):
  // 2.6 s reaches 10.4 counts, so counts 1 .. 10 are 10 A/B edges; Z rises at 2 and 6 and falls at
  // 3 and 7 (10 is a rise too): 5 Z edges, 15 in all. The summary counts the solved edges.
  const Result small =
      hilrig("synth quadrature --lines 1 --rpm 60 --duration 2.6s --index-line 0 --out " + out.string());
  ASSERT_EQ(small.status, 0) << small.err;
  EXPECT_NE(small.out.find(": 15 edges over 2.600000 s, count 0 -> 10 (4 counts/turn)"), std::string::npos)
      << small.out;
  fs::remove(out);
  // One edge over the cap, refused by the count alone (nothing is solved): 2500 lines (10^4
  // counts/turn) at 6000 RPM (100 turn/s: 10^6 counts/s, the rate limit itself) for 10.0000015 s
  // reaches 10^7 + 1.5 counts, so counts 1 .. 10^7 + 1: 10,000,001 edges.
  const Result over =
      hilrig("synth quadrature --lines 2500 --rpm 6000 --duration 10.0000015s --out " + out.string());
  EXPECT_EQ(over.status, 2);
  EXPECT_NE(over.err.find("quadrature: this motion makes 10000001 edges; synth writes at most 10000000"),
            std::string::npos)
      << over.err;
  EXPECT_FALSE(fs::exists(out));
}

} // namespace
} // namespace hilrig
