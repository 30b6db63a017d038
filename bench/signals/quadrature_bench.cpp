// Quadrature edge solving throughput: edges solved per second for a trapezoid move, a
// constant-speed run and an S-curve, streamed into a caller's buffer (no allocation per
// edge). items_per_second is the number to read.

#include "signals/move_builders.hpp"
#include "signals/quadrature_edges.hpp"

#include <benchmark/benchmark.h>

#include <array>

using namespace hilrig;
using namespace hilrig::literals;
using namespace hilrig::signals;

namespace {

QuadratureEncoder encoder_in_counts() {
  QuadratureEncoder enc;
  enc.lines_per_turn = 1024;
  enc.units_per_turn = 4096.0;
  return enc;
}

void solve_all(benchmark::State& state, const MotionProfile& profile, const QuadratureEncoder& enc) {
  std::array<QuadEdge, 4096> buffer;
  std::int64_t edges = 0;
  for (auto _ : state) {
    QuadratureEdgeSolver solver(profile, enc);
    for (std::size_t n = solver.fill(buffer); n != 0; n = solver.fill(buffer)) {
      benchmark::DoNotOptimize(buffer.data());
      edges += static_cast<std::int64_t>(n);
    }
    benchmark::ClobberMemory();
  }
  state.SetItemsProcessed(edges);
}

void BM_TrapezoidEdges(benchmark::State& state) {
  // 1,000,000 counts at up to 1 M counts/s: mostly cruise, two long ramps.
  MotionProfile p;
  trapezoid_move(p, 1e6, MoveLimits{1e6, 4e6, 4e6});
  solve_all(state, p, encoder_in_counts());
}
BENCHMARK(BM_TrapezoidEdges)->Unit(benchmark::kMillisecond);

void BM_TriangleEdges(benchmark::State& state) {
  // All acceleration: every edge takes the square-root path.
  MotionProfile p;
  trapezoid_move(p, 1e6, MoveLimits{1e9, 1e7, 1e7});
  solve_all(state, p, encoder_in_counts());
}
BENCHMARK(BM_TriangleEdges)->Unit(benchmark::kMillisecond);

void BM_TrapezoidEdgesWithIndex(benchmark::State& state) {
  MotionProfile p;
  trapezoid_move(p, 1e6, MoveLimits{1e6, 4e6, 4e6});
  QuadratureEncoder enc = encoder_in_counts();
  enc.gate_index_to_line(0);
  solve_all(state, p, enc);
}
BENCHMARK(BM_TrapezoidEdgesWithIndex)->Unit(benchmark::kMillisecond);

void BM_SCurveEdges(benchmark::State& state) {
  MotionProfile p;
  s_curve_move(p, 1e6, SCurveLimits{1e6, 4e6, 1e8, 16});
  solve_all(state, p, encoder_in_counts());
}
BENCHMARK(BM_SCurveEdges)->Unit(benchmark::kMillisecond);

void BM_ForEachCallback(benchmark::State& state) {
  MotionProfile p;
  trapezoid_move(p, 1e6, MoveLimits{1e6, 4e6, 4e6});
  const QuadratureEncoder enc = encoder_in_counts();
  std::int64_t edges = 0;
  for (auto _ : state) {
    std::int64_t sum = 0;
    for_each_quadrature_edge(p, enc, [&](const QuadEdge& e) { sum += e.time.count(); });
    benchmark::DoNotOptimize(sum);
    edges += 1'000'000;
  }
  state.SetItemsProcessed(edges);
}
BENCHMARK(BM_ForEachCallback)->Unit(benchmark::kMillisecond);

} // namespace

BENCHMARK_MAIN();
