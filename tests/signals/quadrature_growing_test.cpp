// A profile its owner appends to while the solver reads it (QuadratureEdgeSolver::grow_with,
// how a plant's plan is integrated only as far as the encoder's next edge): the edges must be
// those of the whole profile solved at once, whatever the chunks, the pauses (Growth::Later),
// the buffer size and the `until` cut.

#include "signals/quadrature_edges.hpp"

#include <gtest/gtest.h>

#include <cstdint>
#include <random>
#include <vector>

#include "random_motion.hpp"

using namespace hilrig;
using namespace hilrig::signals;

namespace {

std::vector<QuadEdge> solve_growing(const MotionProfile& whole, const QuadratureEncoder& enc, Nanos until,
                                    std::mt19937_64& rng, std::size_t buffer_size, std::int64_t& initial) {
  const std::vector<Segment>& all = whole.segments();
  MotionProfile growing(whole.position(whole.start_time()), whole.start_time());
  std::size_t given = 0;
  const auto give = [&](std::size_t n) {
    for (; n > 0 && given < all.size(); --n) growing.append(all[given++]);
  };
  give(rng() % 3); // possibly none yet
  QuadratureEdgeSolver solver(growing, enc, until);
  initial = solver.initial_count();
  int asked_after_end = 0;
  using Growth = QuadratureEdgeSolver::Growth;
  solver.grow_with([&] {
    if (rng() % 3 == 0) return Growth::Later; // none for now: fill() stops, the next one asks again
    if (given == all.size()) {
      ++asked_after_end;
      return Growth::Whole;
    }
    give(1 + rng() % 5);
    return Growth::Grown;
  });
  std::vector<QuadEdge> buffer(buffer_size);
  std::vector<QuadEdge> out;
  for (;;) {
    const std::size_t n = solver.fill(buffer);
    if (n == 0 && solver.done()) break;
    out.insert(out.end(), buffer.begin(), buffer.begin() + static_cast<std::ptrdiff_t>(n));
  }
  EXPECT_TRUE(solver.done());
  EXPECT_LE(asked_after_end, 1); // once told no more will come, it does not ask again
  return out;
}

} // namespace

TEST(QuadratureGrowing, GrowingProfileGivesTheWholeProfilesEdges) {
  std::mt19937_64 rng(20261126);
  std::size_t total = 0;
  for (std::uint64_t seed = 1; seed <= 24; ++seed) {
    const MotionProfile whole = signals::testing::random_motion(seed, Nanos{60'000'000});
    QuadratureEncoder enc;
    enc.lines_per_turn = 1024;
    enc.units_per_turn = 4096.0; // the profile is in counts
    enc.index_width = static_cast<std::int64_t>(seed % 3);
    // The whole profile, and cut by `until` inside it (the campaign's end).
    for (const Nanos until :
         {Nanos::max(), whole.start_time() + (whole.end_time() - whole.start_time()) / 3}) {
      const QuadratureTrace reference = solve_quadrature(whole, enc, until);
      total += reference.edges.size();
      std::int64_t initial = 0;
      const std::size_t buffer_size = 2 + rng() % 8;
      const std::vector<QuadEdge> grown = solve_growing(whole, enc, until, rng, buffer_size, initial);
      EXPECT_EQ(initial, reference.initial_count) << "seed " << seed;
      EXPECT_EQ(grown, reference.edges) << "seed " << seed << ", buffer of " << buffer_size;
    }
  }
  EXPECT_GT(total, 100'000U); // edges compared
}
