// The hilrig program as a person types it: mistyped subcommands and options are named with the
// closest valid ones (exit 2), a negative seed is refused, `serve --fault` lists the choices,
// `run` puts its summary and report path on stdout, the rest on stderr, and `synth <kind>`
// (a command of a command) takes its own options.

#include <sys/wait.h>

#include <gtest/gtest.h>

#include <array>
#include <cstdio>
#include <filesystem>
#include <string>

#include "rig/results/results_json.hpp"
#include "tests/tools/scratch_files.hpp"
#include "tests/tools/vcd_reader.hpp"

namespace hilrig {
namespace {

namespace fs = std::filesystem;

struct Result {
  int status = -1;
  std::string out; // stdout
  std::string err; // stderr
};

// Runs `hilrig ARGS` (arguments are plain words here: no quoting needed) with stderr to a file.
Result hilrig(const std::string& args) {
  // One directory per test: ctest runs the tests of this file in parallel processes, and a
  // shared stderr file would hand one test another's messages.
  const fs::path dir =
      test::scratch_dir("campaign", std::string("command_line_io_") +
                                        ::testing::UnitTest::GetInstance()->current_test_info()->name());
  const fs::path err = dir / "stderr";
  const std::string command = std::string(HILRIG_EXE) + " " + args + " 2>" + err.string();
  Result r;
  FILE* pipe = ::popen(command.c_str(), "r");
  if (pipe == nullptr) return r;
  std::array<char, 4096> buf{};
  std::size_t n = 0;
  while ((n = std::fread(buf.data(), 1, buf.size(), pipe)) > 0) r.out.append(buf.data(), n);
  const int status = ::pclose(pipe);
  r.status = WIFEXITED(status) ? WEXITSTATUS(status) : -1;
  r.err = test::read_file(err);
  return r;
}

const std::string kPass = std::string(HILRIG_SOURCE_DIR) + "/campaigns/reference/reference_pls_pass.toml";

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
      {"quadrature --duration 0ms", "--duration: must be > 0, got 0ms"},
      {"quadrature --duration -1ms", "--duration: must be > 0, got -1ms"}, // "-1ms" is a value too
      {"resolver --duration -1ms", "--duration: must be > 0"},
      {"discrete --train 2ms,1ms,3ms,3", "width must be < period"}, // the pulse as wide as its period
      {"ssi --bits 26", "--bits: Value 26 not in range 1 to 25"},
  };
  for (const Case& c : cases) {
    const Result r = hilrig("synth " + c.args + " --out " + out.string());
    EXPECT_EQ(r.status, 2) << c.args << ": " << r.err;
    EXPECT_NE(r.err.find(c.says), std::string::npos) << c.args << ": " << r.err;
    EXPECT_FALSE(fs::exists(out)) << c.args;
  }
}

} // namespace
} // namespace hilrig
