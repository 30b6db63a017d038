// BisectionPath and Motion::time_at_progress with it: a probe is evaluated again only where
// the path parts from the last one, and the answers are those of the plain bisection for any
// order of targets (forward step by step, backward, at random), on trapezoids, triangles,
// S-ramps, a slow time base and an open-ended jog.
#include <gtest/gtest.h>

#include <cstdint>
#include <limits>
#include <random>
#include <vector>

#include "models/smd23e/bisection_path.hpp"
#include "models/smd23e/kinematics.hpp"

namespace hilrig::models::smd23e {
namespace {

// The bisection of Motion::time_at_progress with nothing remembered: every probe evaluated.
Nanos plain_time_at_progress(const Motion& m, double x) {
  if (x <= 0.0) return m.start();
  if (x > m.total_steps()) return Nanos::max();
  std::int64_t lo = m.start().count();
  std::int64_t hi = m.end() == Nanos::max() ? lo : m.end().count();
  if (m.end() == Nanos::max()) {
    std::int64_t step = 1'000'000;
    while (m.progress(Nanos{hi}) < x) {
      lo = hi;
      hi += step;
      step *= 2;
    }
  }
  while (hi - lo > 1) {
    const std::int64_t mid = lo + (hi - lo) / 2;
    if (m.progress(Nanos{mid}) >= x)
      hi = mid;
    else
      lo = mid;
  }
  return m.progress(Nanos{lo}) >= x ? Nanos{lo} : Nanos{hi};
}

TEST(Smd23eBisectionPath, EvaluatesOnlyWhereThePathParts) {
  BisectionPath path;
  int calls = 0;
  const auto f = [&calls](std::int64_t t) {
    ++calls;
    return static_cast<double>(t) * 0.5;
  };
  // A first bisection evaluates every probe.
  EXPECT_EQ(path.probe(0, 512, f), 256.0);
  EXPECT_EQ(path.probe(1, 256, f), 128.0);
  EXPECT_EQ(path.probe(2, 384, f), 192.0);
  EXPECT_EQ(calls, 3);
  // The next one shares the first two probes, then parts.
  EXPECT_EQ(path.probe(0, 512, f), 256.0);
  EXPECT_EQ(path.probe(1, 256, f), 128.0);
  EXPECT_EQ(calls, 3);
  EXPECT_EQ(path.probe(2, 128, f), 64.0);
  EXPECT_EQ(calls, 4);
  // A point remembered at another depth is not taken for this one.
  EXPECT_EQ(path.probe(3, 512, f), 256.0);
  EXPECT_EQ(calls, 5);
  // Past the deepest depth every probe is evaluated.
  EXPECT_EQ(path.probe(BisectionPath::kDepths, 7, f), 3.5);
  EXPECT_EQ(path.probe(BisectionPath::kDepths, 7, f), 3.5);
  EXPECT_EQ(calls, 7);
}

std::vector<Motion> sample_motions(std::mt19937_64& rng) {
  std::uniform_real_distribution<double> steps(1.0, 40'000.0);
  std::uniform_real_distribution<double> speed(1.0, 30'000.0);
  std::uniform_real_distribution<double> rate(1'000.0, 500'000.0);
  std::uniform_real_distribution<double> start_speed(0.5, 200.0);
  std::uniform_real_distribution<double> scale(0.5, 1.5);
  const std::vector<double> fractions{1.0, 0.0, 0.5, 0.25};
  std::vector<Motion> out;
  for (int i = 0; i < 24; ++i) {
    const double vs = start_speed(rng);
    const RampShape shape{fractions[static_cast<std::size_t>(i) % fractions.size()]};
    const Nanos start{static_cast<std::int64_t>(rng() % 5'000'000'000ULL)};
    out.emplace_back(start, plan_move(steps(rng), vs, vs + speed(rng), rate(rng), rate(rng), shape),
                     i % 3 == 0 ? scale(rng) : 1.0);
  }
  // A jog: up to speed, then on forever.
  std::vector<Piece> jog;
  append_ramp(jog, 10.0, 5'000.0, 20'000.0, RampShape{0.5});
  append_cruise(jog, 5'000.0, std::numeric_limits<double>::infinity());
  out.emplace_back(Nanos{123'456}, jog);
  return out;
}

TEST(Smd23eBisectionPath, TimeAtProgressIsThePlainBisectionsAnswerInAnyOrder) {
  std::mt19937_64 rng(20261127);
  int compared = 0;
  for (const Motion& shared : sample_motions(rng)) {
    const double total =
        shared.total_steps() == std::numeric_limits<double>::infinity() ? 60'000.0 : shared.total_steps();
    std::vector<double> targets;
    // Forward, a whole step at a time (what the shaft sensor asks), with repeats.
    for (double k = 1.0; k <= total && targets.size() < 400; k += 1.0 + static_cast<double>(rng() % 40)) {
      targets.push_back(k);
      if (rng() % 7 == 0) targets.push_back(k);
    }
    // Backward.
    for (double k = total; k > 0.0 && targets.size() < 600; k -= 1.0 + static_cast<double>(rng() % 97))
      targets.push_back(k);
    // At random, fractions and out-of-range targets among them.
    std::uniform_real_distribution<double> anywhere(-2.0, total + 2.0);
    for (int i = 0; i < 200; ++i) targets.push_back(anywhere(rng));
    for (const double x : targets) {
      // The plain bisection on a motion that has remembered nothing.
      ASSERT_EQ(shared.time_at_progress(x), plain_time_at_progress(shared, x))
          << "x " << x << " motion starting " << shared.start().count();
      ++compared;
    }
  }
  EXPECT_GT(compared, 10'000);
}

} // namespace
} // namespace hilrig::models::smd23e
