// Programmable fault outputs (spec §4.13): priority of die protection over brake overrun over
// counter overflow over the LS program, and the overflow output's LS gating (L1226).
#include <gtest/gtest.h>

#include "models/ans1/fault_outputs.hpp"

namespace hilrig::models::ans1 {
namespace {

TEST(FaultOutputs, DieProtectionOutranksBrakeOutranksCounterOutranksLs) {
  // Output 1 is claimed by all three, output 2 by brake and counter, output 3 by the counter
  // only, output 4 by nobody. DP says off, brake says on, counter says on, LS says on.
  const OutputClaims c = make_claims(/*dp*/ 0x1, 0x0, /*brake*/ 0x3, 0x3, /*counter*/ 0x7, 0x7);
  EXPECT_EQ(c.owned_mask, 0x3);
  EXPECT_EQ(c.gated_mask, 0x4);
  EXPECT_EQ(c.brake_mask, 0x2);
  EXPECT_EQ(apply_claims(c, /*ls*/ 0xF, /*programmed*/ 0x0), 0xE); // output 1 off by DP
}

TEST(FaultOutputs, OverflowOutputWithAnLsProgramFollowsItOnlyAtTheLimit) {
  // L1226: output 3 has setpoints; it follows them only while the counter is in overflow.
  const OutputClaims at_limit = make_claims(0, 0, 0, 0, 0x4, 0x4);
  const OutputClaims below = make_claims(0, 0, 0, 0, 0x4, 0x0);
  EXPECT_EQ(apply_claims(at_limit, 0x4, 0x4), 0x4);
  EXPECT_EQ(apply_claims(at_limit, 0x0, 0x4), 0x0);
  EXPECT_EQ(apply_claims(below, 0x4, 0x4), 0x0);
  // Without an LS program the output simply shows the overflow state.
  EXPECT_EQ(apply_claims(at_limit, 0x0, 0x0), 0x4);
}

TEST(FaultOutputs, UserDefinedEnabledMaskShowsDisabledBrakeAndCounterOutputs) {
  // DA16 w17 (L2557): 0 for a brake/counter output that is off; DP outputs are not "user".
  const OutputClaims c = make_claims(0x1, 0x0, 0x2, 0x0, 0x4, 0x0);
  EXPECT_EQ(user_defined_enabled(c), 0xFFF9);
}

} // namespace
} // namespace hilrig::models::ans1
