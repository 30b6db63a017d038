// A board served for a week must not grow: the step-train history the model keeps is bounded
// (Smd23e::kKeptRuns), counted here directly rather than through RSS, while the position it
// reports stays exact. Numbers: a relative move of N steps moves the position by N (spec
// §3, relative move); the common ramp (examples file, "handy P0 ramps": 100 -> 1100 steps/s
// in 0.1 s and 60 steps) makes a 1000-step move last 1.0 s and a 500-step one under 1.0 s.
#include "tests/models/smd23e/smd23e_fixture.hpp"

namespace hilrig::models::smd23e::test {
namespace {

using Smd23eHistory = Smd23eBench;

TEST_F(Smd23eHistory, ThousandsOfMovesKeepABoundedHistoryAndAnExactPosition) {
  configure();
  std::int64_t expected = 0;
  std::size_t most_runs = 0;
  for (int i = 0; i < 2'000; ++i) {
    const std::int32_t steps = i % 2 == 0 ? 1000 : -500;
    command(msw::kRelative, kDrive, MoveWords{.value = steps});
    run_to(sched.now() + 1'100_ms); // each move is done within 1.0 s
    expected += steps;
    ASSERT_EQ(position_word(), expected) << "move " << i;
    ASSERT_EQ(dut.shaft_steps(sched.now()), expected) << "move " << i;
    most_runs = std::max(most_runs, dut.runs().size());
  }
  EXPECT_EQ(most_runs, Smd23e::kKeptRuns); // reached, never passed
  // The recent past is still there: the last move (-500) ran within the last 1.1 s.
  EXPECT_EQ(dut.step_position(sched.now() - 1'100_ms), expected + 500);
}

} // namespace
} // namespace hilrig::models::smd23e::test
