// One solver restarted over a profile its owner restarts and appends to again (how the rig
// follows a plant's plan, a new plan at each input): after restart() its edges and initial
// count are a new solver's, wherever the last solve stopped (part-way, at the `until` cut,
// told the profile was whole) and whatever the growth.

#include "signals/quadrature_edges.hpp"

#include <gtest/gtest.h>

#include <array>
#include <cstdint>
#include <random>
#include <vector>

#include "random_motion.hpp"

using namespace hilrig;
using namespace hilrig::signals;

TEST(QuadratureRestart, RestartedSolverGivesANewSolversEdges) {
  std::mt19937_64 rng(20261127);
  QuadratureEncoder enc;
  enc.lines_per_turn = 1024;
  enc.units_per_turn = 4096.0; // the profiles are in counts
  enc.index_width = 1;
  const Nanos until{40'000'000};
  MotionProfile plan;
  const std::vector<Segment>* source = nullptr;
  std::size_t given = 0;
  const auto give = [&](std::size_t n) {
    for (; n > 0 && given < source->size(); --n) plan.append((*source)[given++]);
  };
  using Growth = QuadratureEdgeSolver::Growth;
  QuadratureEdgeSolver solver(plan, enc, until);
  solver.grow_with([&] {
    if (rng() % 4 == 0) return Growth::Later;
    if (given == source->size()) return Growth::Whole;
    give(1 + rng() % 4);
    return Growth::Grown;
  });
  std::size_t compared = 0;
  std::array<QuadEdge, 4> buffer{};
  for (std::uint64_t seed = 1; seed <= 30; ++seed) {
    const MotionProfile whole = signals::testing::random_motion(seed, Nanos{60'000'000});
    const QuadratureTrace reference = solve_quadrature(whole, enc, until);
    source = &whole.segments();
    given = 0;
    plan.restart(whole.position(whole.start_time()), whole.start_time());
    give(rng() % 2);
    solver.restart();
    EXPECT_EQ(solver.initial_count(), reference.initial_count) << "seed " << seed;
    // Every third profile is left part-way: the next restart must not carry anything over.
    const std::size_t stop_after = seed % 3 == 0 ? reference.edges.size() / 2 : reference.edges.size() + 1;
    std::vector<QuadEdge> out;
    while (out.size() < stop_after) {
      const std::size_t n = solver.fill(buffer);
      if (n == 0 && solver.done()) break;
      out.insert(out.end(), buffer.begin(), buffer.begin() + static_cast<std::ptrdiff_t>(n));
    }
    if (seed % 3 == 0) {
      ASSERT_GE(out.size(), stop_after);
      out.resize(stop_after);
      EXPECT_EQ(out, std::vector<QuadEdge>(reference.edges.begin(),
                                           reference.edges.begin() + static_cast<std::ptrdiff_t>(stop_after)))
          << "seed " << seed;
    } else {
      EXPECT_TRUE(solver.done());
      EXPECT_EQ(out, reference.edges) << "seed " << seed;
    }
    compared += out.size();
  }
  EXPECT_GT(compared, 10'000U);
}
