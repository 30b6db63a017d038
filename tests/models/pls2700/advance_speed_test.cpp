// The advances' speed window (models/pls2700/advance_speed.hpp, README "Advance speed" [MODEL]):
// a transducer fault restarts it (R-ADV-5 [X]: no motion is known across the fault), so after
// reset() the window must answer exactly as a window that never saw the steps before it. The
// property is checked against a fresh window fed the same steps, over random step sequences
// with resets anywhere (before, at and after the window fills), and against the arithmetic
// of the window at one point: a sum of S steps over n updates of T ms is S / (n T) steps/ms.
#include <gtest/gtest.h>

#include <cstdint>
#include <random>
#include <vector>

#include "models/pls2700/advance_speed.hpp"

namespace hilrig::models::pls2700 {
namespace {

using namespace hilrig::literals;

TEST(AdvanceSpeed, AResetWindowAnswersAsAFreshOne) {
  std::mt19937 rng(2700);
  for (int trial = 0; trial < 200; ++trial) {
    const int updates = 1 + static_cast<int>(rng() % 12);
    AdvanceSpeed used(updates, 200_us);
    // Steps before the reset: a random number, sometimes more than the window holds.
    const int before = static_cast<int>(rng() % static_cast<unsigned>(3 * updates + 1));
    for (int i = 0; i < before; ++i) {
      used.add(static_cast<int>(rng() % 41) - 20);
    }
    used.reset();
    EXPECT_EQ(used.steps_per_ms(), 0.0);
    AdvanceSpeed fresh(updates, 200_us);
    const int after = 1 + static_cast<int>(rng() % static_cast<unsigned>(3 * updates));
    for (int i = 0; i < after; ++i) {
      const int step = static_cast<int>(rng() % 41) - 20;
      used.add(step);
      fresh.add(step);
      ASSERT_EQ(used.steps_per_ms(), fresh.steps_per_ms())
          << "trial " << trial << ", window " << updates << ", " << before << " steps before the reset, step "
          << i << " after it";
    }
  }
}

TEST(AdvanceSpeed, AFullWindowAfterAResetHoldsOnlyItsOwnSteps) {
  // Window of 4 updates of 0.2 ms: 0.8 ms. Before the reset it held 100 steps per update;
  // after it, 9 steps in each of 4 updates: 36 steps / 0.8 ms = 45 steps/ms, nothing of the
  // 100s left in the sum once the window wraps.
  AdvanceSpeed s(4, 200_us);
  for (int i = 0; i < 6; ++i) {
    s.add(100);
  }
  s.reset();
  for (int i = 0; i < 4; ++i) {
    s.add(9);
  }
  EXPECT_DOUBLE_EQ(s.steps_per_ms(), 45.0);
  s.add(9); // the window slides: still 4 x 9 steps
  EXPECT_DOUBLE_EQ(s.steps_per_ms(), 45.0);
}

} // namespace
} // namespace hilrig::models::pls2700
