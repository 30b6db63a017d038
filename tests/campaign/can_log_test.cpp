// Issue 18 (traces): a campaign whose board reads a resolver writes can.log on the virtual bus
// as a real rig does: the rig's ResolverAngle stream to the resolver-emulator node, in candump
// -l form, its times the campaign's wall-clock start (--epoch / SOURCE_DATE_EPOCH when given)
// plus virtual time. The log reads back line by line (core/candump.hpp's grammar), in
// can-utils' log2asc, and its frames decode back to the campaign's motion.
//
// The protocol (signals/resolver_frames.hpp, rt-config/can/hilrig-frontend.dbc, ResolverAngle
// 0x120): angle 24 bits of 1/2^24 turn, speed 24 bits signed of 1/4096 turn/s, sequence 4 bits
// +1 a frame, channel 0; the rig sends one every 1 ms (a real rig's default stream period),
// and the bus (500 kbit/s) delivers it at its end of frame, ~0.23 ms later: can.log's time.
// The frame carries the shaft at that instant, its angle the code at or above it, at most 15
// codes above (the stream's choice among codes so that the frame's own length is the one it
// was built for: models/resolver_emulator/angle_streamer.hpp).

#include <gtest/gtest.h>

#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <numbers>
#include <sstream>
#include <string>
#include <vector>

#include "core/candump.hpp"
#include "rig/campaign/campaign_parser.hpp"
#include "rig/campaign/motion.hpp"
#include "rig/campaign/plant_motion.hpp"
#include "rig/cli/run_command.hpp"
#include "rig/cli/wall_clock.hpp"
#include "signals/resolver_frames.hpp"
#include "tests/tools/scratch_files.hpp"

namespace hilrig::cli {
namespace {

namespace fs = std::filesystem;

constexpr std::int64_t kEpoch = 1'767'225'600; // 2026-01-01T00:00:00Z
constexpr double kAngleCode = 1.0 / 16'777'216.0;
constexpr double kSpeedCode = 1.0 / 4096.0;

std::string ans1_resolver() { return std::string(HILRIG_SOURCE_DIR) + "/campaigns/ans1/ans1_resolver.toml"; }

std::vector<CandumpRecord> read_log(const fs::path& file) {
  std::istringstream in(hilrig::test::read_file(file));
  std::vector<CandumpRecord> out;
  std::string line;
  for (std::size_t n = 1; std::getline(in, line); ++n) {
    const auto r = read_candump_line(line);
    EXPECT_TRUE(r.has_value()) << "line " << n << ": " << line;
    if (r) out.push_back(*r);
  }
  return out;
}

fs::path run(const std::string& file, const std::string& name, std::optional<std::int64_t> epoch) {
  const fs::path out = hilrig::test::scratch_dir("can_log", name);
  RunOptions o;
  o.file = file;
  o.out = out;
  o.epoch = epoch;
  std::ostringstream err;
  EXPECT_EQ(run_campaign(o, err), 0) << err.str();
  return out;
}

// The ANS1 on its resolver (campaigns/ans1/ans1_resolver.toml: 2 runs of 1000 ms, 100 rpm on
// 360 counts a turn): a frame each millisecond of each run, the runs end to end.
TEST(CanLog, ResolverCampaignOnTheVirtualBusWritesItsFramesFromTheEpoch) {
  const fs::path out = run(ans1_resolver(), "ans1_resolver", kEpoch);
  const std::vector<CandumpRecord> log = read_log(out / "can.log");
  const campaign::Campaign c = campaign::load_campaign(ans1_resolver());
  ASSERT_EQ(c.runs.size(), 2U);
  const campaign::Scenario& s = c.scenario_of(c.runs.front());
  ASSERT_EQ(s.end, Nanos{1'000'000'000});
  // Frames sent at 0, 1, ... 999 ms reach the node before the run's end; the one of 1000 ms
  // would arrive after it.
  ASSERT_EQ(log.size(), 2U * 1000U);

  const Nanos epoch{kEpoch * 1'000'000'000};
  const signals::MotionProfile profile = campaign::build_motion(ans1_resolver(), s.motion, s.encoder).profile;
  const double per_turn = s.encoder.counts_per_turn();
  ASSERT_EQ(per_turn, 360.0);
  for (std::size_t i = 0; i < log.size(); ++i) {
    SCOPED_TRACE(i);
    const CandumpRecord& r = log[i];
    EXPECT_EQ(r.bus, "can0");
    const std::size_t k = i % 1000; // the frame's index in its run
    const Nanos run_start = epoch + s.end * static_cast<std::int64_t>(i / 1000);
    const Nanos t = r.time - run_start; // the run's virtual time at the node's end of frame
    // Sent at k ms; on the bus 108 bits + 0..~24 stuff bits at 2 us (virt::can_frame_bits).
    EXPECT_GE(t, Nanos{static_cast<std::int64_t>(k) * 1'000'000 + 216'000});
    EXPECT_LE(t, Nanos{static_cast<std::int64_t>(k) * 1'000'000 + 270'000});
    if (i > 0) {
      EXPECT_GT(r.time, log[i - 1].time); // one capture, only forward
    }
    const auto f = signals::decode_resolver_angle(r.frame);
    ASSERT_TRUE(f.has_value());
    EXPECT_EQ(f->channel, 0);
    EXPECT_EQ(f->sequence, k % 16);
    EXPECT_TRUE(f->valid);
    const double shaft = profile.position(t) / per_turn;
    const double above = f->angle_turns - (shaft - std::floor(shaft));
    EXPECT_GE(above, 0.0);
    EXPECT_LT(above, 16 * kAngleCode);
    EXPECT_LE(std::abs(f->speed_turns_per_s - profile.velocity(t) / per_turn), kSpeedCode / 2);
  }
  // The epoch is the one results.json and junit.xml carry.
  EXPECT_NE(hilrig::test::read_file(out / "results.json").find("\"started_at\": \"2026-01-01T00:00:00Z\""),
            std::string::npos);
  EXPECT_NE(hilrig::test::read_file(out / "junit.xml").find("timestamp=\"2026-01-01T00:00:00Z\""),
            std::string::npos);
}

// can-utils reads it: log2asc converts every frame (its -I option takes the log as it is).
TEST(CanLog, Log2ascReadsTheLog) {
  const fs::path out = run(ans1_resolver(), "log2asc", kEpoch);
  const fs::path asc = out / "can.asc";
  const std::string command =
      std::string(HILRIG_LOG2ASC) + " -I " + (out / "can.log").string() + " -O " + asc.string() + " can0";
  ASSERT_EQ(std::system(command.c_str()), 0) << command;
  std::istringstream in(hilrig::test::read_file(asc));
  std::size_t frames = 0;
  std::string line;
  while (std::getline(in, line)) {
    if (line.find(" 120 ") != std::string::npos && line.find("Rx") != std::string::npos) ++frames;
  }
  EXPECT_EQ(frames, 2000U);
}

// Without an epoch the log starts at the campaign's start by the wall clock: results.json's
// started_at, to the second.
TEST(CanLog, WithoutAnEpochTheLogStartsAtTheRecordedWallClockStart) {
  const fs::path out = run(ans1_resolver(), "wall", std::nullopt);
  const std::vector<CandumpRecord> log = read_log(out / "can.log");
  ASSERT_FALSE(log.empty());
  const std::string results = hilrig::test::read_file(out / "results.json");
  const std::size_t at = results.find("\"started_at\": \"");
  ASSERT_NE(at, std::string::npos);
  const std::string started = results.substr(at + 15, 20);
  const std::chrono::system_clock::time_point t0{
      std::chrono::duration_cast<std::chrono::system_clock::duration>(
          std::chrono::nanoseconds{log[0].time.count()})};
  EXPECT_EQ(iso8601_utc(std::chrono::floor<std::chrono::seconds>(t0)), started);
  EXPECT_LT(log[0].time.count() % 1'000'000'000, 1'000'000); // the first frame within its first ms
}

// Two runs with the same epoch write the same bytes.
TEST(CanLog, TheSameEpochGivesTheSameBytes) {
  const fs::path a = run(ans1_resolver(), "same_a", kEpoch);
  const fs::path b = run(ans1_resolver(), "same_b", kEpoch);
  for (const char* name : {"can.log", "results.json"})
    EXPECT_EQ(hilrig::test::read_file(a / name), hilrig::test::read_file(b / name)) << name;
}

// --epoch and SOURCE_DATE_EPOCH: whole seconds, 0 .. 2099-12-31T23:59:59Z, decimal digits only
// (the reproducible-builds spec: a malformed value is an error). Swept across both ends.
TEST(CanLog, EpochAcceptsWholeSecondsFromZeroToTheYear2099) {
  EXPECT_EQ(parse_epoch("0"), 0);
  EXPECT_EQ(parse_epoch("1"), 1);
  EXPECT_EQ(parse_epoch("1767225600"), 1'767'225'600);
  EXPECT_EQ(parse_epoch("4102444798"), 4'102'444'798);
  EXPECT_EQ(parse_epoch("4102444799"), 4'102'444'799);
  EXPECT_EQ(iso8601_utc(wall_start(4'102'444'799)), "2099-12-31T23:59:59Z");
  EXPECT_EQ(iso8601_utc(wall_start(0)), "1970-01-01T00:00:00Z");
  for (const char* bad : {"4102444800", "4102444801", "253402300799", "-1", "", " 1", "1 ", "1.5", "1e9",
                          "+1", "0x10", "99999999999999999999999"})
    EXPECT_FALSE(parse_epoch(bad).has_value()) << bad;
}

// A plant's frames carry its speed (PlantMotion::velocity) with its angle: the slope of its
// position, in the history before an input and in the plan after it. A press coasting at
// 10 turn/s whose brake is applied at 125 ms (the valve off; resolver_test.cpp's closed form).
TEST(CanLog, APlantsSpeedIsTheSlopeOfItsPosition) {
  campaign::PlantSpec spec;
  spec.kind = campaign::PlantKind::Press;
  spec.press.flywheel_inertia = 20.0;
  spec.press.crank_inertia = 2.0;
  spec.press.ram_mass = 0.0;
  spec.press.brake_torque = 2000.0;
  spec.press.valve_delay = 0.020;
  spec.press.brake_rise = 0.030;
  spec.press_start.speed = 20.0 * std::numbers::pi;
  spec.press_start.motor = false;
  const double per_turn = 4096.0;
  campaign::PlantMotion motion(spec, per_turn, Nanos{400'000'000});
  motion.input(Nanos{125'000'000}, plants::PlantInput::Valve, false);
  EXPECT_NEAR(motion.velocity(Nanos{50'000'000}), 10.0 * per_turn, 1e-6); // history: 10 turn/s
  int compared = 0;
  for (std::int64_t ns = 1'000'000; ns < 180'000'000; ns += 1'000'000) {
    while (motion.plan_end() < Nanos{ns + 1'000}) motion.extend();
    const double slope = (motion.position(Nanos{ns + 1'000}) - motion.position(Nanos{ns - 1'000})) / 2e-6;
    EXPECT_NEAR(motion.velocity(Nanos{ns}), slope, 1e-3 * per_turn) << ns;
    ++compared;
  }
  EXPECT_EQ(compared, 179);
  EXPECT_LT(motion.velocity(Nanos{179'000'000}), 9.0 * per_turn); // braking by then
}

} // namespace
} // namespace hilrig::cli
