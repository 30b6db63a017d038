// A Registration move's Stopping Distance tail is output once, from the first controlled stop
// condition (L1049: "When the command terminates under Controlled Stop conditions, the SMD23E
// will output a programmed number of steps as part of bringing the move to a stop"; the
// conditions, L1065–1066). A later condition — the command bit cleared, another Stop Jog edge —
// neither restarts nor extends the tail.
//
// Numbers: v_s = 1000 steps/s, v_p = 10,000 steps/s, A = D = 100 steps/ms/s (100,000
// steps/s², L848–851). A ramp between v_s and v_p is (10,000² − 1000²)/(2·100,000) = 495
// steps and 9000/100,000 = 90 ms. The move starts at 0 and is at v_p from 90 ms, so at 300 ms
// it is 495 + 10,000·0.21 = 2595 steps out. S = 2000 ≥ 495: cruise 1505 steps (150.5 ms), then
// decelerate over 495 (90 ms): the last step is at 300 + 150.5 + 90 = 540.5 ms, at 4595.
#include "tests/models/smd23e/smd23e_fixture.hpp"

namespace hilrig::models::smd23e::test {
namespace {

constexpr std::int32_t kStoppingDistance = 2000;
constexpr std::int64_t kAtTrigger = 2595;        // steps out at 300 ms
constexpr std::int64_t kEnd = kAtTrigger + 2000; // 4595
constexpr double kLastStepS = 0.5405;            // 300 + 150.5 + 90 ms

class Smd23eRegistrationTail : public Smd23eBench {
protected:
  void SetUp() override {
    configure(ConfigWords{.control = 0b100, .vs = 1000}); // input 1: Stop Jog/Registration
  }
  static MoveWords words(std::int32_t min_distance) {
    const MultiWord m = encode_multiword(min_distance); // words 8–9: M (L2642)
    return MoveWords{.value = kStoppingDistance,
                     .vp = 10'000,
                     .accel = 100,
                     .decel = 100,
                     .word8 = m.upper,
                     .word9 = m.lower};
  }
  void start(std::uint16_t bit, std::int32_t min_distance = 0) {
    command(bit, kDrive | lsw::kRegistration, words(min_distance));
  }
  // The command bit returns to 0 (L1065), the rest of the block kept.
  void clear_bit(std::int32_t min_distance = 0) {
    write(0, kDrive | lsw::kRegistration, words(min_distance));
  }
  void stop_pulse(Nanos at_time) {
    at(at_time, in1, Level::High);
    at(at_time + 5_ms, in1, Level::Low);
  }
  // The step train's last step is `position`, at t_s (±1 µs: 1/1000 step at v_s), and none
  // follows it.
  void expect_last_step(double t_s, std::int64_t position) {
    const std::int64_t dir = position < 0 ? -1 : 1;
    EXPECT_EQ(dut.step_position(Nanos::from_seconds(t_s - 1e-6)), position - dir);
    EXPECT_EQ(dut.step_position(Nanos::from_seconds(t_s + 1e-6)), position);
    EXPECT_EQ(position_word(), position);
  }
  void expect_exactly_s_from_300_ms(int dir) {
    expect_last_step(kLastStepS, dir * kEnd);
    EXPECT_TRUE(bit1(sw1::kStopped));
    EXPECT_TRUE(bit1(sw1::kMoveComplete));
  }
};

// When the command bit is cleared, relative to the Stop Jog edge at 300 ms that ends the move.
enum class Clear : std::uint8_t { DuringTail, AfterEnd };
struct TailCase {
  const char* name;
  std::uint16_t bit;
  int dir;
  std::int32_t min_distance; // M = 1000 is reached at 90 + 50.5 = 140.5 ms, before the edge
  Clear clear;
};

class Smd23eRegistrationTailCases : public Smd23eRegistrationTail,
                                    public ::testing::WithParamInterface<TailCase> {};

TEST_P(Smd23eRegistrationTailCases, TheCommandBitClearedAfterTheTriggerAddsNoSteps) {
  const TailCase c = GetParam();
  start(c.bit, c.min_distance);
  stop_pulse(300_ms);
  run_to(c.clear == Clear::DuringTail ? 400_ms : 600_ms);
  ASSERT_EQ(bit1(sw1::kStopped), c.clear == Clear::AfterEnd);
  clear_bit(c.min_distance);
  run_to(1_s);
  expect_exactly_s_from_300_ms(c.dir);
}

INSTANTIATE_TEST_SUITE_P(
    Cases, Smd23eRegistrationTailCases,
    ::testing::Values(TailCase{"CwDuringTail", msw::kJogCw, 1, 0, Clear::DuringTail},
                      TailCase{"CcwDuringTail", msw::kJogCcw, -1, 0, Clear::DuringTail},
                      TailCase{"CwMinReachedDuringTail", msw::kJogCw, 1, 1000, Clear::DuringTail},
                      TailCase{"CcwMinReachedDuringTail", msw::kJogCcw, -1, 1000, Clear::DuringTail},
                      TailCase{"CwAfterEnd", msw::kJogCw, 1, 0, Clear::AfterEnd},
                      TailCase{"CcwAfterEnd", msw::kJogCcw, -1, 0, Clear::AfterEnd}),
    [](const ::testing::TestParamInfo<TailCase>& i) { return std::string(i.param.name); });

// Before any trigger the bit returning to 0 is itself the controlled stop condition (L1065):
// S steps from there, as from the input; a Stop Jog edge in that tail changes nothing.
TEST_F(Smd23eRegistrationTail, TheBitClearedBeforeTheTriggerIsTheStopAndAnInputEdgeInItsTailAddsNothing) {
  start(msw::kJogCw);
  run_to(300_ms);
  clear_bit();
  stop_pulse(400_ms);
  run_to(1_s);
  expect_exactly_s_from_300_ms(1);
}

// A second Stop Jog edge during the tail is not a new trigger either.
TEST_F(Smd23eRegistrationTail, ASecondStopInputEdgeInTheTailAddsNothing) {
  start(msw::kJogCw);
  stop_pulse(300_ms);
  stop_pulse(400_ms);
  run_to(1_s);
  expect_exactly_s_from_300_ms(1);
}

// The bit cleared before M = 3000 stays cleared: the condition is a level and the stop begins
// when M is reached (L1058), at 90 + 2505/10,000 s = 340.5 ms; S from there: 5000, the last
// step at 340.5 + 150.5 + 90 = 581 ms.
TEST_F(Smd23eRegistrationTail, TheBitClearedBeforeTheMinimumDistanceStopsAtTheMinimumDistance) {
  start(msw::kJogCw, 3000);
  run_to(300_ms);
  clear_bit(3000);
  run_to(1_s);
  expect_last_step(0.581, 5000);
  EXPECT_TRUE(bit1(sw1::kMoveComplete));
}

// A Hold stops a registration move at D without the S tail (L1070). The bit cleared while the
// Hold decelerates does not turn that stop into a tail: from 2595 at 300 ms, 495 steps over
// 90 ms, 3090 at 390 ms.
TEST_F(Smd23eRegistrationTail, TheBitClearedDuringAHoldsDecelerationAddsNoTail) {
  start(msw::kJogCw);
  run_to(300_ms);
  write(msw::kJogCw | msw::kHold, kDrive | lsw::kRegistration, words(0));
  run_to(350_ms);
  clear_bit();
  run_to(1_s);
  expect_last_step(0.39, 3090);
  EXPECT_FALSE(bit1(sw1::kHoldState));
}

} // namespace
} // namespace hilrig::models::smd23e::test
