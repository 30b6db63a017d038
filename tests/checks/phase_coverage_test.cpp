// Phase coverage of crossings against a scan period: bins by integer ns, the worst-case
// phase (just after a scan) counted, and the report's wording when coverage is incomplete.

#include <gtest/gtest.h>

#include <vector>

#include "rig/checks/phase_coverage.hpp"

namespace hilrig::checks {
namespace {

using namespace hilrig::literals;

TEST(PhaseCoverage, CrossingsSteppingSevenMicrosecondsCoverEveryBinOfATenMicrosecondScan) {
  // ans1_throughput.toml: swing pairs of 180.007 ms, i.e. 7 us later in the 10 us scan each.
  std::vector<Nanos> crossings;
  for (std::int64_t k = 0; k < 10; ++k) crossings.push_back(35'041'667_ns + k * 180'007_us);
  const PhaseCoverage cov = phase_coverage(crossings, 10_us, 10);
  EXPECT_EQ(cov.covered, 10U);
  EXPECT_TRUE(cov.complete());
  EXPECT_EQ(cov.describe(10_us), "10/10 bins of the 10 us period covered");
}

TEST(PhaseCoverage, CyclesSteppingThreePointSevenMicrosecondsCoverEveryTenthOfAMicrosecond) {
  // ans1_throughput.toml: 100 cycles of 190.0037 ms, i.e. 3.7 us later in the 10 us scan each;
  // 37 and 100 share no factor, so the hundred crossings fill all hundred 0.1 us bins, and 99
  // of them leave one bin empty.
  std::vector<Nanos> crossings;
  for (std::int64_t k = 0; k < 100; ++k) crossings.push_back(35'041'667_ns + k * 190'003'700_ns);
  EXPECT_EQ(phase_coverage(crossings, 10_us, 100).covered, 100U);
  crossings.pop_back();
  EXPECT_EQ(phase_coverage(crossings, 10_us, 100).covered, 99U);
}

TEST(PhaseCoverage, FourMicrosecondStepsLeaveHalfTheBinsEmpty) {
  // The campaign before issue 16: 180.014 ms pairs, 4 us a swing: phases 0, 4, 8, 2, 6.
  std::vector<Nanos> crossings;
  for (std::int64_t k = 0; k < 10; ++k) crossings.push_back(k * 180'014_us);
  const PhaseCoverage cov = phase_coverage(crossings, 10_us, 10);
  EXPECT_EQ(cov.covered, 5U);
  EXPECT_FALSE(cov.complete());
  EXPECT_NE(cov.describe(10_us).find("coverage incomplete"), std::string::npos);
}

TEST(PhaseCoverage, BinEdgesAreHalfOpenToTheNanosecond) {
  // Bin k of a 10 us period in 10 bins is [k us, k+1 us): 999 ns is bin 0, 1000 ns bin 1,
  // and one period later the same; a negative time wraps into the period.
  EXPECT_EQ(phase_coverage(std::vector<Nanos>{999_ns, 10_us + 999_ns}, 10_us, 10).covered, 1U);
  EXPECT_EQ(phase_coverage(std::vector<Nanos>{999_ns, 1000_ns}, 10_us, 10).covered, 2U);
  EXPECT_EQ(phase_coverage(std::vector<Nanos>{Nanos{-1}, 9'999_ns}, 10_us, 10).covered, 1U);
  EXPECT_EQ(phase_coverage(std::vector<Nanos>{}, 10_us, 10).covered, 0U);
}

TEST(PhaseCoverage, AMeasurementWithoutAPeriodIsAnError) {
  const Measurement m =
      phase_coverage_measurement("t.phase_coverage", std::vector<Nanos>{1_us}, Nanos{0}, 10);
  EXPECT_EQ(m.outcome, rig::Outcome::Error);
  const Measurement ok = phase_coverage_measurement("t.phase_coverage", std::vector<Nanos>{1_us}, 10_us, 10);
  EXPECT_EQ(ok.value, 1.0);
  EXPECT_EQ(ok.unit, "bins");
}

} // namespace
} // namespace hilrig::checks
