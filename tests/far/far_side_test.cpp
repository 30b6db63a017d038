// The far side of `hilrig serve` (rig/far/far_side.hpp) around the served ANS1, on a directory
// laid out as gpio-sim's sysfs and on the virtual CAN bus. The test plays the rig: it drives
// the encoder lines' value files, streams ResolverAngle frames, programs the board through its
// host words and reads what the board pulls on its output line. Virtual time throughout.
//
// Expected values from the ANS1 digest (docs/spec/ans1.md): CB2 with QuadEnc, CPC =
// FSC = 400 makes GMP the rig's 4X count; CB3 pair 1 [From, To) switches output 1 on from
// From up to but not including To (A17), in either direction; on the resolver (CPC 4096,
// FSC 360) GMP is the shaft angle in degrees. Forward quadrature is A leading B:
// (A,B) = 00 -> 10 -> 11 -> 01 -> 00, one count per change.
#include <gtest/gtest.h>

#include <array>
#include <cstdint>
#include <initializer_list>
#include <string>
#include <vector>

#include "drivers/virtual/can_bus.hpp"
#include "drivers/virtual/virtual_bus.hpp"
#include "models/resolver_emulator/angle_streamer.hpp"
#include "rig/cli/serve_devices.hpp"
#include "rig/far/far_config.hpp"
#include "rig/far/far_side.hpp"
#include "signals/move_builders.hpp"
#include "tests/far/fake_sim_chip.hpp"

namespace hilrig::test {
namespace {

constexpr unsigned kLineA = 0;
constexpr unsigned kLineB = 1;
constexpr unsigned kLineOut1 = 8;

const char* const kEncoderPins = R"([[pin]]
board = "A"
offset = 0
[[pin]]
board = "B"
offset = 1
[[pin]]
board = "OUT1"
offset = 8
)";

// The ANS1's host words at the registers `hilrig serve` gives them (command word k = holding
// 1024 + k, status word k = input register k), with the Transmit/Acknowledge handshake
// (bit 15 of word 0); the device answers at its next scans, so each step runs 1 ms.
void program(Scheduler& s, RegisterMap& map, std::initializer_list<std::uint16_t> words) {
  const std::vector<std::uint16_t> w(words);
  ASSERT_EQ(map.write_holding_registers(1025, std::span(w).subspan(1)), RegisterStatus::Ok);
  const std::array<std::uint16_t, 1> transmit{static_cast<std::uint16_t>(w[0] | 0x8000U)};
  ASSERT_EQ(map.write_holding_registers(1024, transmit), RegisterStatus::Ok);
  s.run_until(s.now() + milliseconds(1));
  std::array<std::uint16_t, 1> status{};
  ASSERT_EQ(map.read_input_registers(0, status), RegisterStatus::Ok);
  ASSERT_NE(status[0] & 0x8000U, 0U) << "no Acknowledge";
  EXPECT_EQ(status[0] & 0x2000U, 0U) << "command error";
  const std::array<std::uint16_t, 1> clear{w[0]};
  ASSERT_EQ(map.write_holding_registers(1024, clear), RegisterStatus::Ok);
  s.run_until(s.now() + milliseconds(1));
}

struct ServedAns1 {
  Scheduler scheduler;
  cli::ServedModel model = cli::find_served_device("ans1")->build(scheduler, {});
};

TEST(FarSide, TheRigsQuadratureMovesTheBoardAndItsOutputIsPulled) {
  FakeSimChip chip(16);
  ServedAns1 b;
  far::FarSide far(b.scheduler, far::parse_far_config(kEncoderPins, "far.toml"), chip.dir(), nullptr);
  ASSERT_TRUE(b.model.attach_far);
  b.model.attach_far(far);
  far.check_all_taken("ans1");
  EXPECT_EQ(chip.take_pull(kLineOut1), "pull-down"); // an output starts off
  program(b.scheduler, *b.model.registers, {0x0382, 0x0008, 400, 400});
  program(b.scheduler, *b.model.registers, {0x0403, 1, 0, 0, 10, 20, 0, 0});

  // The rig steps the encoder one count per millisecond; after each step the far side polls
  // and the model runs to the next step. Record the count after which each pull appeared.
  static constexpr std::array<std::array<Level, 2>, 4> kPhase{{{Level::Low, Level::Low},
                                                               {Level::High, Level::Low},
                                                               {Level::High, Level::High},
                                                               {Level::Low, Level::High}}};
  std::vector<std::pair<int, std::string>> pulls;
  int count = 0;
  const auto step_to = [&](int target) {
    while (count != target) {
      count += target > count ? 1 : -1;
      const auto& ab = kPhase[static_cast<std::size_t>(((count % 4) + 4) % 4)];
      chip.set_value(kLineA, ab[0]);
      chip.set_value(kLineB, ab[1]);
      far.poll(b.scheduler.now());
      b.scheduler.run_until(b.scheduler.now() + milliseconds(1));
      if (std::string p = chip.take_pull(kLineOut1); !p.empty()) pulls.emplace_back(count, p);
    }
  };
  step_to(25);
  step_to(5);
  const std::vector<std::pair<int, std::string>> expected{
      {10, "pull-up"}, {20, "pull-down"}, {19, "pull-up"}, {9, "pull-down"}};
  EXPECT_EQ(pulls, expected);
  const far::FarSideCounters c = far.counters();
  EXPECT_EQ(c.input_edges, 45U); // 25 counts forward, 20 back: one line changes per count
  EXPECT_EQ(c.output_edges, 4U);
}

TEST(FarSide, ResolverFramesOnCanFeedTheBoardsStators) {
  FakeSimChip chip(16);
  ServedAns1 b;
  virt::VirtualBus bus(b.scheduler);
  virt::CanBus& can = bus.can("can0");
  CanPort& rig_port = can.attach("rig");
  CanPort& node_port = can.attach("resolver_emu");
  far::FarConfig config = far::parse_far_config(R"([[pin]]
board = "OUT1"
offset = 8
[resolver]
ratio = 0.95
)",
                                                "far.toml");
  far::FarSide far(b.scheduler, config, chip.dir(), &node_port);
  b.model.attach_far(far);
  far.check_all_taken("ans1");
  (void)chip.take_pull(kLineOut1);
  // 100 RPM from angle 0: 600 degrees/s, so GMP 100 at 166.7 ms and 200 at 333.3 ms (plus the
  // frame's ~0.25 ms on the bus and a 100 us stator sample: well inside the windows below).
  signals::MotionProfile profile(0.0);
  signals::constant_speed(profile, 100.0 / 60.0, milliseconds(500));
  models::resolver_emulator::AngleStreamer stream(b.scheduler, rig_port, profile, {});
  stream.start(Nanos{0});
  // CB2: resolver, XFltLatch (the fault of the frameless start clears itself), CPC 4096, FSC 360.
  program(b.scheduler, *b.model.registers, {0x0382, 0x0002, 4096, 360});
  program(b.scheduler, *b.model.registers, {0x0403, 1, 0, 0, 100, 200, 0, 0});
  b.scheduler.run_until(milliseconds(160));
  EXPECT_EQ(chip.take_pull(kLineOut1), "");
  b.scheduler.run_until(milliseconds(175));
  EXPECT_EQ(chip.take_pull(kLineOut1), "pull-up");
  b.scheduler.run_until(milliseconds(325));
  EXPECT_EQ(chip.take_pull(kLineOut1), "");
  b.scheduler.run_until(milliseconds(340));
  EXPECT_EQ(chip.take_pull(kLineOut1), "pull-down");
  ASSERT_NE(far.resolver(), nullptr);
  EXPECT_EQ(far.resolver()->counters().lost_frames, 0U);
}

TEST(FarSide, APinTheBoardDoesNotHaveIsBadInputAtItsLine) {
  FakeSimChip chip(4);
  ServedAns1 b;
  far::FarSide far(
      b.scheduler,
      far::parse_far_config("[[pin]]\nboard = \"A\"\noffset = 0\n[[pin]]\nboard = \"OUT99\"\noffset = 1\n",
                            "far.toml"),
      chip.dir(), nullptr);
  b.model.attach_far(far);
  try {
    far.check_all_taken("ans1");
    FAIL() << "OUT99 accepted";
  } catch (const campaign::CampaignError& e) {
    EXPECT_EQ(e.key(), "pin[1].board");
    EXPECT_EQ(e.where().line, 4U);
  }
}

TEST(FarSide, AResolverNeedsAPortAndPinsNeedAChip) {
  Scheduler s;
  EXPECT_THROW(far::FarSide(s, far::parse_far_config("[resolver]\n", "far.toml"), "", nullptr),
               std::invalid_argument);
  EXPECT_THROW(far::FarSide(s, far::parse_far_config(kEncoderPins, "far.toml"), "", nullptr),
               std::invalid_argument);
}

} // namespace
} // namespace hilrig::test
