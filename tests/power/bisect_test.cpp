// The bisection behind `hilrig power` on synthetic monotone predicates: the threshold is found
// within the resolution from either side, the probes are bounded, and a predicate that never
// flips, or flips at the nominal value, or cannot be judged gets a named reason.

#include <gtest/gtest.h>

#include <cmath>

#include "rig/power/bisect.hpp"

namespace hilrig::power {
namespace {

// fails from `t` on (inclusive): the smallest failing deviation is t itself.
auto step_at(double t) {
  return [t](double d) { return d >= t ? Probe::Fail : Probe::Pass; };
}

TEST(Bisect, FindsAnIntegerThresholdExactlyAcrossANeighbourhood) {
  BisectSpec spec;
  spec.max_deviation = 1'000'000;
  spec.resolution = 1;
  spec.first_step = 100;
  spec.integer = true;
  for (const double t : {1.0, 2.0, 99.0, 100.0, 101.0, 272.0, 273.0, 12'345.0, 999'999.0, 1'000'000.0}) {
    const BisectResult r = bisect_threshold(spec, step_at(t));
    ASSERT_TRUE(r.threshold.has_value()) << t;
    EXPECT_EQ(*r.threshold, t);
    EXPECT_EQ(r.last_pass, t - 1);
    // one nominal probe, <= log2(max/first) + 1 doublings, <= log2(bracket) halvings
    EXPECT_LE(r.probes, 1 + 15 + 20) << t;
  }
}

TEST(Bisect, FindsARealThresholdWithinTheResolution) {
  BisectSpec spec;
  spec.max_deviation = 10.0;
  spec.resolution = 1e-6;
  spec.first_step = 0.01;
  for (const double t : {0.0123456, 0.5, std::sqrt(2.0), 9.999}) {
    const BisectResult r = bisect_threshold(spec, step_at(t));
    ASSERT_TRUE(r.threshold.has_value()) << t;
    EXPECT_GE(*r.threshold, t);
    EXPECT_LE(*r.threshold - t, 1e-6);
    EXPECT_LT(r.last_pass, t);
  }
}

TEST(Bisect, NamesAPredicateThatNeverFailsWithinTheRange) {
  BisectSpec spec;
  spec.max_deviation = 1000;
  spec.resolution = 1;
  spec.first_step = 10;
  spec.integer = true;
  const BisectResult r = bisect_threshold(spec, step_at(1001));
  EXPECT_FALSE(r.threshold.has_value());
  EXPECT_EQ(r.last_pass, 1000);
  EXPECT_NE(r.reason.find("never fails"), std::string::npos) << r.reason;
}

TEST(Bisect, NamesAPredicateThatFailsAtTheNominalValue) {
  BisectSpec spec;
  spec.max_deviation = 1000;
  spec.resolution = 1;
  spec.first_step = 10;
  const BisectResult r = bisect_threshold(spec, step_at(0));
  EXPECT_FALSE(r.threshold.has_value());
  EXPECT_EQ(r.probes, 1u);
  EXPECT_NE(r.reason.find("nominal"), std::string::npos) << r.reason;
}

TEST(Bisect, StopsOnACheckThatCannotBeJudged) {
  BisectSpec spec;
  spec.max_deviation = 1000;
  spec.resolution = 1;
  spec.first_step = 10;
  const BisectResult r = bisect_threshold(spec, [](double d) { return d > 50 ? Probe::Error : Probe::Pass; });
  EXPECT_FALSE(r.threshold.has_value());
  EXPECT_NE(r.reason.find("could not be judged"), std::string::npos) << r.reason;
}

TEST(Bisect, TheProbeCountIsBounded) {
  BisectSpec spec;
  spec.max_deviation = 1e12;
  spec.resolution = 1;
  spec.first_step = 1;
  spec.integer = true;
  spec.max_probes = 12;
  std::size_t asked = 0;
  const BisectResult r = bisect_threshold(spec, [&](double d) {
    ++asked;
    return d >= 5e11 ? Probe::Fail : Probe::Pass;
  });
  EXPECT_EQ(asked, 12u);
  EXPECT_EQ(r.probes, 12u);
  EXPECT_FALSE(r.threshold.has_value());
  EXPECT_NE(r.reason.find("12 probes"), std::string::npos) << r.reason;
}

} // namespace
} // namespace hilrig::power
