// `hilrig run FILE --backend hardware --rig RIG`: the same campaign file as on the virtual
// bus, with the rig's ports replaced by the virtual-DUT harness; the same outputs come out,
// plus the rig's timing. A campaign the rig cannot carry is bad input before anything moves.

#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>

#include "rig/cli/run_command.hpp"
#include "rig/hardware/edge_schedule.hpp"
#include "rig/results/results_json.hpp"
#include "tests/hardware/loop_campaign.hpp"
#include "tests/hardware/virtual_dut_ports.hpp"
#include "tests/tools/scratch_files.hpp"

namespace hilrig::hardware {
namespace {

namespace fs = std::filesystem;

fs::path scratch(const std::string& name) { return hilrig::test::scratch_dir("hardware", name); }
using hilrig::test::read_file;
using hilrig::test::write_file;

cli::RunOptions hardware_options(const fs::path& dir, const std::string& rig_text) {
  cli::RunOptions o;
  o.file = write_file(dir, "loop.toml", test::kLoopCampaign).string();
  o.out = dir / "out";
  o.backend = "hardware";
  o.rig = write_file(dir, "rig.toml", rig_text).string();
  o.handle_signals = false;
  // Each run's ports: the virtual reference PLS behind a 200 us wire.
  o.rig_ports = [](const DrivePlan& plan, const campaign::RunInputs& in) -> std::unique_ptr<RigPorts> {
    return std::make_unique<test::VirtualDutPorts>(*in.scenario, plan, build_schedule(in, plan).edges,
                                                   Nanos{200'000}, in.seed);
  };
  return o;
}

TEST(RunHardwareCommand, SameOutputsAsAVirtualRunPlusTheRigTiming) {
  const fs::path dir = scratch("pass");
  std::ostringstream err;
  EXPECT_EQ(cli::run_campaign(hardware_options(dir, test::kLoopRig), err), 0) << err.str();
  for (const char* f : {"results.json", "junit.xml", "report.html", "trace.vcd"})
    EXPECT_TRUE(fs::exists(dir / "out" / f)) << f;
  const rig::CampaignResult r = rig::read_results_file(dir / "out" / "results.json");
  ASSERT_EQ(r.runs.size(), 1U);
  EXPECT_EQ(r.runs[0].error, "");
  bool throughput = false;
  bool timing = false;
  for (const rig::CheckResult& c : r.runs[0].checks) {
    if (c.check == "on") throughput = true;
    if (c.check == "rig" && c.kind == "rt_timing") {
      timing = true;
      ASSERT_FALSE(c.measurements.empty());
      EXPECT_EQ(c.measurements[0].name, "rig.edge_error.max");
    }
  }
  EXPECT_TRUE(throughput);
  EXPECT_TRUE(timing);
  const std::string vcd = read_file(dir / "out" / "trace.vcd");
  EXPECT_NE(vcd.find("ls1"), std::string::npos);
  EXPECT_NE(vcd.find("en"), std::string::npos);
}

TEST(RunHardwareCommand, MissingGpioLineIsBadInputNamingBothFiles) {
  const fs::path dir = scratch("missing");
  std::string rig = test::kLoopRig;
  rig = rig.substr(0, rig.find("[[gpio.line]]\nrig = \"ls1\"")); // the rig has no line for ls1
  std::ostringstream err;
  EXPECT_EQ(cli::run_campaign(hardware_options(dir, rig), err), 2);
  const std::string text = err.str();
  // ls1 is the campaign's fourth [[wiring]], at line 19 of loop.toml.
  EXPECT_NE(text.find("loop.toml:19:1: wiring[3].rig: "), std::string::npos) << text;
  EXPECT_NE(text.find("rig.toml: \"ls1\" has no [[gpio.line]]"), std::string::npos) << text;
  EXPECT_FALSE(fs::exists(dir / "out" / "results.json")); // nothing ran
}

TEST(RunHardwareCommand, HardwareNeedsARigConfig) {
  const fs::path dir = scratch("norig");
  cli::RunOptions o = hardware_options(dir, test::kLoopRig);
  o.rig.clear();
  std::ostringstream err;
  EXPECT_EQ(cli::run_campaign(o, err), 2);
  EXPECT_NE(err.str().find("--backend hardware needs --rig"), std::string::npos) << err.str();
}

} // namespace
} // namespace hilrig::hardware
