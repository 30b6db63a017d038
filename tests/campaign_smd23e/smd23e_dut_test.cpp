// The SMD23E adapter on the virtual bus, driven by hand: what it declares, its shaft sensor
// lines (one STEP edge per step, DIR High for CW) against the spec's move formulas, and the
// staging of the host's words until word 0 is written.

#include <gtest/gtest.h>

#include <array>
#include <cstdint>
#include <vector>

#include "core/scheduler.hpp"
#include "core/trace.hpp"
#include "drivers/virtual/virtual_bus.hpp"
#include "rig/duts/smd23e_dut.hpp"

namespace hilrig::duts {
namespace {

using namespace hilrig::literals;
using Block = std::array<std::uint16_t, 10>;

struct Bench {
  Scheduler sched;
  TraceRecorder trace;
  virt::VirtualBus bus{sched, &trace};
  std::unique_ptr<Dut> dut;

  explicit Bench(const std::string& variant = "nominal", Nanos input_delay = Nanos{0}) {
    const DutInfo info = smd23e_info();
    dut = info.make(sched, info.with_defaults({{"input_delay", input_delay}}), variant, 0);
    dut->attach(bus, {{"STEP", "step"}, {"DIR", "dir"}, {"IN1", "in1"}});
  }
  // As the executive writes: words 9..1, then word 0.
  void write(const Block& b) {
    for (std::size_t w = b.size(); w-- > 1;) dut->host_write(w, b[w]);
    dut->host_write(0, b[0]);
  }
  void at(Nanos t, const Block& b) {
    sched.at(t, [this, b] { write(b); });
  }
  // v_s 1000 steps/s (1, 0), 2048 steps/turn, driver on; then Command Mode. `control`: the
  // input functions (input 1 in bits 0-2).
  void configure(std::uint16_t control = 0) {
    at(0_ms, Block{static_cast<std::uint16_t>(0x8000 | control), 0x8007, 1, 0, 2048, 0, 1024, 50, 20, 0});
    at(1_ms, Block{0, 0x8000, 0, 0, 0, 0, 0, 0, 0, 0});
  }
};

TEST(Smd23eDut, DeclaresPinsVariantsAndRegisterStyleHost) {
  const DutInfo info = smd23e_info();
  EXPECT_EQ(info.name, "smd23e");
  ASSERT_NE(info.pin("STEP"), nullptr);
  EXPECT_EQ(info.pin("STEP")->direction, PinDirection::Output);
  EXPECT_EQ(info.pin("DIR")->direction, PinDirection::Output);
  EXPECT_EQ(info.pin("IN3")->direction, PinDirection::Input);
  EXPECT_EQ(info.variants.front().name, "nominal");
  for (const char* v : {"wrong-acceleration", "lost-steps", "ignored-limit", "late-stop"})
    EXPECT_TRUE(info.has_variant(v)) << v;
  EXPECT_EQ(info.host.output_words, 10U);
  EXPECT_EQ(info.host.input_words, 10U);
  EXPECT_FALSE(info.host.handshake);
}

TEST(Smd23eDut, ShaftSensorShowsATrapezoidMove) {
  Bench b;
  b.configure();
  // Relative 4000 steps at 10 ms, v_p 10000, A = D = 100: T = 90 + 301 + 90 = 481 ms (§3.2).
  b.at(10_ms, Block{2, 0x8000, 4, 0, 10, 0, 100, 100, 0, 0});
  b.sched.run_until(600_ms);
  const std::vector<Edge> step = b.trace.edges_of("step");
  ASSERT_EQ(step.size(), 4000U);
  EXPECT_NEAR(static_cast<double>((step.back().time - 10_ms).count()), 481e6, 1e3);
  // Cruise steps are 1 / v_p = 100 us apart.
  EXPECT_NEAR(static_cast<double>((step[2000].time - step[1999].time).count()), 100e3, 2.0);
  const std::vector<Edge> dir = b.trace.edges_of("dir");
  ASSERT_EQ(dir.size(), 1U);
  EXPECT_EQ(dir[0].level, Level::High);
  EXPECT_EQ(dir[0].time, step[0].time);
}

// Idle with nothing pending in the model, the shaft sensor does not look every 50 us: no
// event at all is left in the scheduler. An input whose effect is delayed (input_delay
// 120 us) and starts an armed indexed move while idle is still looked for from the edge on
// (the looks at the edge + 50, 100, 150 us: the third finds the move) and every step shows on
// STEP; after the move the sensor sleeps again.
TEST(Smd23eDut, IdleSensorSleepsUntilTheModelCanMoveTheShaft) {
  Bench b("nominal", 120_us);
  // Configuration Mode with input 1 Start Indexed Move (control bits 0-2 = 3), then Command Mode.
  b.at(0_ms, Block{0x8000 | 0x0003, 0x8007, 1, 0, 2048, 0, 1024, 50, 20, 0});
  b.at(1_ms, Block{0, 0x8000, 0, 0, 0, 0, 0, 0, 0, 0});
  // A relative indexed move of 1000 steps (MSW bit 1, LSW bit 8), armed, not run.
  b.at(10_ms, Block{2, 0x8000 | 0x0100, 1, 0, 10, 0, 100, 100, 0, 0});
  b.sched.run_until(20_ms);
  EXPECT_EQ(b.sched.pending_count(), 0U);
  EXPECT_TRUE(b.trace.edges_of("step").empty());
  const Nanos edge = 20_ms + 7_us;
  b.sched.at(edge, [&b] { b.bus.line("in1").driver().set(Level::High); });
  b.sched.run_until(edge + 119_us); // the delayed input still pending: the sensor looks
  EXPECT_GE(b.sched.pending_count(), 2U);
  b.sched.run_until(600_ms);
  const std::vector<Edge> step = b.trace.edges_of("step");
  ASSERT_EQ(step.size(), 1000U);
  EXPECT_GT(step.front().time, edge + 120_us);
  EXPECT_EQ(b.sched.pending_count(), 0U);
}

TEST(Smd23eDut, CcwMoveKeepsDirLow) {
  Bench b;
  b.configure();
  // Relative -300 = (0, -300): both words carry the sign (§6.3); v_p = v_s: 300 ms at 1000.
  b.at(10_ms, Block{2, 0x8000, 0, static_cast<std::uint16_t>(-300 & 0xFFFF), 1, 0, 100, 100, 0, 0});
  b.sched.run_until(400_ms);
  EXPECT_EQ(b.trace.edges_of("step").size(), 300U);
  EXPECT_TRUE(b.trace.edges_of("dir").empty());
}

TEST(Smd23eDut, WordsAreStagedUntilWordZero) {
  Bench b;
  b.configure();
  b.sched.run_until(5_ms);
  const std::uint16_t sw1 = b.dut->host_read(0);
  // Words 1..9 of a move alone do nothing; the Relative bit in word 0 starts it.
  b.sched.at(10_ms, [&] {
    for (std::size_t w = 1; w < 10; ++w)
      b.dut->host_write(w, Block{2, 0x8000, 0, 10, 1, 0, 100, 100, 0, 0}[w]);
  });
  b.sched.run_until(50_ms);
  EXPECT_TRUE(b.trace.edges_of("step").empty());
  EXPECT_EQ(b.dut->host_read(0), sw1);
  b.sched.at(60_ms, [&] { b.dut->host_write(0, 2); });
  b.sched.run_until(100_ms);
  EXPECT_EQ(b.trace.edges_of("step").size(), 10U); // 10 steps at v_s: 10 ms
}

TEST(Smd23eDut, LostStepsVariantShowsFewerShaftSteps) {
  Bench b("lost-steps");
  b.configure();
  b.at(10_ms, Block{2, 0x8000, 4, 0, 10, 0, 100, 100, 0, 0});
  b.sched.run_until(600_ms);
  // One in 100 lost (models/smd23e/README.md): 40 of 4000.
  EXPECT_EQ(b.trace.edges_of("step").size(), 3960U);
}

// The times of the STEP edges after `from`.
std::vector<Nanos> steps_after(const Bench& b, Nanos from) {
  std::vector<Nanos> out;
  for (const Edge& e : b.trace.edges_of("step"))
    if (e.time > from) out.push_back(e.time);
  return out;
}

// An E-Stop edge (input 1, code 101) is an immediate stop (L976–980, L593): a jog at v_p = v_s
// = 1000 steps/s set off at 10 ms has its STEP edges on the whole ms, and an edge 1 or 2 ns
// before the one due at 300 ms leaves it out; at or after it, the step is on STEP at 300 ms.
TEST(Smd23eDut, EStopJustBeforeAStepIsDueLeavesItOffTheStepLine) {
  for (const std::int64_t offset : {-2, -1, 0, 1}) {
    SCOPED_TRACE(offset);
    Bench b;
    b.configure(0b101);
    b.at(10_ms, Block{0x0080, 0x8000, 0, 0, 1, 0, 100, 100, 0, 0}); // +Jog, v_p 1000
    const Nanos edge = 300_ms + Nanos{offset};
    b.sched.at(edge, [&b] { b.bus.line("in1").driver().set(Level::High); });
    b.sched.run_until(500_ms);
    const std::vector<Nanos> step = steps_after(b, 0_ms);
    ASSERT_EQ(step.size(), offset < 0 ? 289U : 290U);
    EXPECT_EQ(step.back(), offset < 0 ? 299_ms : 300_ms);
  }
}

// A registration move outputs exactly S steps after the stop input (L1049), so its tail
// does not depend on where between two steps the input comes: v_s 1000, v_p 5000 steps/s, A = D
// = 100 (100,000 steps/s²), S = 1000, started at 10 ms. The ramp ends at 50 ms (120 steps), the
// cruise steps are 200 us apart on 50 ms + k·200 us. From the last step at or before the input
// (t_k): 880 steps at 5000 (176 ms) and 120 down to 1000 steps/s (40 ms), the last at t_k +
// 216 ms, 1000 steps after the input, the last interval the one from 1 step before the end:
// 1 = 1000·t + 100,000·t²/2, t = 954.451 us (§3.8).
TEST(Smd23eDut, RegistrationTailIsTheSameWhateverTheInputsPhase) {
  for (const std::int64_t offset : {-1, 0, 1, 2, 1000, 100'000, 199'999}) {
    SCOPED_TRACE(offset);
    Bench b;
    b.configure(0b100); // input 1: Stop Jog/Registration
    b.at(10_ms, Block{0x0080, 0x8080, 1, 0, 5, 0, 100, 100, 0, 0});
    const Nanos input = 200'200'000_ns + Nanos{offset};
    b.sched.at(input, [&b] { b.bus.line("in1").driver().set(Level::High); });
    b.sched.run_until(500_ms);
    const Nanos t_k = offset < 0 ? 200_ms : 200'200'000_ns;
    const std::vector<Nanos> tail = steps_after(b, input);
    ASSERT_EQ(tail.size(), 1000U);
    EXPECT_EQ(tail.back(), t_k + 216_ms);
    EXPECT_NEAR(static_cast<double>((tail.back() - tail[tail.size() - 2]).count()), 954'451.15, 1.0);
  }
}

TEST(Smd23eDut, UnknownPinOrVariantIsRefused) {
  const DutInfo info = smd23e_info();
  Scheduler sched;
  virt::VirtualBus bus{sched};
  EXPECT_THROW((void)info.make(sched, info.with_defaults({}), "sideways", 0), std::invalid_argument);
  auto dut = info.make(sched, info.with_defaults({}), "nominal", 0);
  EXPECT_THROW(dut->attach(bus, {{"OUT9", "x"}}), std::invalid_argument);
}

} // namespace
} // namespace hilrig::duts
