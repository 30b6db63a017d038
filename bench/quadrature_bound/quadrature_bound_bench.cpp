// Quadrature edge solving against its memory-bandwidth bound, in one binary so both rates
// come from the same run on the same core. hilrig: the trapezoid of bench/signals
// (BM_TrapezoidEdges: 1,000,000 counts at up to 1 M counts/s). Peer: writing the same
// number of QuadEdge records into the same 4,096-record buffer, once with a plain store
// loop (records with changing fields, what the solver must at least do) and once with
// memset (the store bandwidth of the buffer). items_per_second is edges (records) per second.

#include "signals/move_builders.hpp"
#include "signals/quadrature_edges.hpp"

#include <benchmark/benchmark.h>

#include <array>
#include <cstdint>
#include <cstring>

using namespace hilrig;
using namespace hilrig::signals;

namespace {

constexpr std::size_t kBufferEdges = 4096; // the buffer bench/signals solves into

QuadratureEncoder encoder_in_counts() {
  QuadratureEncoder enc;
  enc.lines_per_turn = 1024;
  enc.units_per_turn = 4096.0;
  return enc;
}

MotionProfile trapezoid() {
  MotionProfile p;
  trapezoid_move(p, 1e6, MoveLimits{1e6, 4e6, 4e6});
  return p;
}

// How many edges the trapezoid has: the peers write exactly as many records.
std::int64_t trapezoid_edge_count() {
  const MotionProfile p = trapezoid();
  std::int64_t edges = 0;
  for_each_quadrature_edge(p, encoder_in_counts(), [&](const QuadEdge&) { ++edges; });
  return edges;
}

void BM_SolveTrapezoid(benchmark::State& state) {
  const MotionProfile p = trapezoid();
  const QuadratureEncoder enc = encoder_in_counts();
  std::array<QuadEdge, kBufferEdges> buffer;
  std::int64_t edges = 0;
  for (auto _ : state) { // NOLINT(clang-analyzer-deadcode.DeadStores): the benchmark idiom
    QuadratureEdgeSolver solver(p, enc);
    for (std::size_t n = solver.fill(buffer); n != 0; n = solver.fill(buffer)) {
      benchmark::DoNotOptimize(buffer.data());
      edges += static_cast<std::int64_t>(n);
    }
    benchmark::ClobberMemory();
  }
  state.SetItemsProcessed(edges);
  state.counters["bytes_per_edge"] = static_cast<double>(sizeof(QuadEdge));
}
BENCHMARK(BM_SolveTrapezoid)->Unit(benchmark::kMillisecond);

// Peer 1: a sequential store loop writing records whose fields change as the solver's do.
void BM_StoreRecords(benchmark::State& state) {
  const std::int64_t total = trapezoid_edge_count();
  std::array<QuadEdge, kBufferEdges> buffer;
  std::int64_t edges = 0;
  for (auto _ : state) { // NOLINT(clang-analyzer-deadcode.DeadStores)
    std::int64_t count = 0;
    for (std::int64_t left = total; left > 0;) {
      const auto n = static_cast<std::size_t>(
          left < static_cast<std::int64_t>(kBufferEdges) ? left : static_cast<std::int64_t>(kBufferEdges));
      for (std::size_t i = 0; i < n; ++i) {
        buffer[i] = QuadEdge{Nanos{count * 1000}, count, (count & 1) != 0 ? QuadChannel::B : QuadChannel::A,
                             (count & 2) != 0 ? Level::High : Level::Low};
        ++count;
      }
      benchmark::DoNotOptimize(buffer.data());
      benchmark::ClobberMemory();
      left -= static_cast<std::int64_t>(n);
    }
    edges += total;
  }
  state.SetItemsProcessed(edges);
}
BENCHMARK(BM_StoreRecords)->Unit(benchmark::kMillisecond);

// Peer 2: memset of the same bytes (sizeof(QuadEdge) per edge) into the same buffer.
void BM_MemsetRecords(benchmark::State& state) {
  const std::int64_t total = trapezoid_edge_count();
  std::array<QuadEdge, kBufferEdges> buffer;
  std::int64_t edges = 0;
  int fill = 0;
  for (auto _ : state) { // NOLINT(clang-analyzer-deadcode.DeadStores)
    for (std::int64_t left = total; left > 0;) {
      const auto n = static_cast<std::size_t>(
          left < static_cast<std::int64_t>(kBufferEdges) ? left : static_cast<std::int64_t>(kBufferEdges));
      std::memset(static_cast<void*>(buffer.data()), fill++ & 0xFF, n * sizeof(QuadEdge));
      benchmark::DoNotOptimize(buffer.data());
      benchmark::ClobberMemory();
      left -= static_cast<std::int64_t>(n);
    }
    edges += total;
  }
  state.SetItemsProcessed(edges);
}
BENCHMARK(BM_MemsetRecords)->Unit(benchmark::kMillisecond);

} // namespace

BENCHMARK_MAIN();
