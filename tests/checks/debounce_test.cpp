#include <gtest/gtest.h>

#include <cmath>
#include <random>

#include "check_test_support.hpp"
#include "rig/checks/debounce.hpp"

namespace hilrig::checks {
namespace {

using namespace hilrig::literals;
using test::find;

TEST(Bisection, FindsAKnownBoundaryWithinResolution) {
  // A board that accepts pulses of at least 1234.567 us. From [0, 10 ms] at 1 us resolution the
  // bracket halves from 10 ms to <= 1 us: 10000/2^14 = 0.61 us, so 14 probes plus the 2 ends.
  const Nanos boundary{1'234'567};
  int runs = 0;
  const auto b = bisect_boundary(
      [&](Nanos w) {
        ++runs;
        return w >= boundary;
      },
      0_ns, 10_ms, 1_us);
  ASSERT_TRUE(b.bracketed);
  EXPECT_GE(b.accepted, boundary);
  EXPECT_LT(b.rejected, boundary);
  EXPECT_LE(b.accepted - b.rejected, 1_us);
  EXPECT_EQ(runs, 16);
  EXPECT_EQ(b.probes.size(), 16U);
}

TEST(Bisection, PropertyBoundaryAlwaysInsideTheFinalBracket) {
  std::mt19937_64 rng(20261122);
  std::uniform_int_distribution<std::int64_t> pick(1, 50'000'000);
  for (int i = 0; i < 200; ++i) {
    const Nanos boundary{pick(rng)};
    const auto b = bisect_boundary([&](Nanos w) { return w >= boundary; }, 0_ns, 50_ms, 100_ns);
    ASSERT_TRUE(b.bracketed);
    EXPECT_LT(b.rejected, boundary);
    EXPECT_GE(b.accepted, boundary);
    EXPECT_LE(b.accepted - b.rejected, 100_ns);
  }
}

TEST(Bisection, UnbracketedWhenTheNarrowestProbeIsAccepted) {
  const auto b = bisect_boundary([](Nanos) { return true; }, 1_us, 1_ms, 1_us);
  EXPECT_FALSE(b.bracketed);
  EXPECT_EQ(b.probes.size(), 2U);
  const auto r = check_debounce(b, {.name = "in1", .filter = 500_us, .tolerance = 10_us});
  EXPECT_EQ(r.outcome(), rig::Outcome::Fail);
  EXPECT_NE(find(r, "in1.boundary").detail.find("not bracketed"), std::string::npos);
}

// A hand-made bisection whose boundary (narrowest accepted) is `accepted`.
Bisection bracket(Nanos rejected, Nanos accepted) {
  return Bisection{true, rejected, accepted, {{rejected, false}, {accepted, true}}};
}

TEST(Debounce, BoundaryPassesAtFilterPlusToleranceAndFailsOneMicrosecondOrNanosecondBeyond) {
  // Filter 1000 us, tolerance 10 us: boundary allowed in [990, 1010] us.
  const DebounceSpec spec{.name = "in1", .filter = 1000_us, .tolerance = 10_us};
  EXPECT_EQ(check_debounce(bracket(1009_us, 1010_us), spec).outcome(), rig::Outcome::Pass);
  EXPECT_EQ(check_debounce(bracket(989_us, 990_us), spec).outcome(), rig::Outcome::Pass);
  EXPECT_EQ(find(check_debounce(bracket(1009_us, 1010_us), spec), "in1.boundary").value, 1010.0);
  for (const Nanos over : {1011_us, 1010_us + 1_ns}) {
    const auto r = check_debounce(bracket(over - 1_us, over), spec);
    EXPECT_EQ(find(r, "in1.boundary").outcome, rig::Outcome::Fail) << over.count();
  }
  EXPECT_EQ(find(check_debounce(bracket(988_us, 989_us), spec), "in1.boundary").outcome, rig::Outcome::Fail);
}

TEST(Debounce, AShortPulseAcceptedIsMisjudged) {
  // A 500 us pulse accepted although the filter is 1000 us (± 10): one misjudged probe.
  Bisection b = bracket(999_us, 1000_us);
  b.probes.push_back({500_us, true});
  const auto r = check_debounce(b, {.name = "in1", .filter = 1000_us, .tolerance = 10_us});
  EXPECT_EQ(find(r, "in1.misjudged").value, 1.0);
  EXPECT_EQ(r.outcome(), rig::Outcome::Fail);
  EXPECT_NE(find(r, "in1.misjudged").detail.find("500 us pulse was accepted"), std::string::npos);
}

} // namespace
} // namespace hilrig::checks
