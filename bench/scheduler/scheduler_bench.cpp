// Scheduler throughput in the "hold" model of discrete-event simulation: a pending set of
// N events; each executed event schedules one new event at a pseudo-random future time, so
// the set stays at N. Items/s is events executed per second. Target: >= 10 M/s at N = 1000.
#include <benchmark/benchmark.h>

#include <cstdint>
#include <vector>

#include "core/scheduler.hpp"

namespace {

using hilrig::Nanos;
using hilrig::Scheduler;

struct Hold {
  Scheduler* scheduler;
  std::uint64_t rng;

  // xorshift64: cheap, deterministic delays of 1 ns .. 1 ms.
  Nanos next_delay() {
    rng ^= rng << 13U;
    rng ^= rng >> 7U;
    rng ^= rng << 17U;
    return Nanos{static_cast<std::int64_t>(rng % 1'000'000U) + 1};
  }
};

// The event's action: schedules its successor. One pointer, so std::function keeps it inline.
struct Hop {
  Hold* hold;
  void operator()() const { hold->scheduler->after(hold->next_delay(), Hop{hold}); }
};

void BM_SchedulerHold(benchmark::State& state) {
  Scheduler scheduler;
  Hold hold{&scheduler, 0x9E37'79B9'7F4A'7C15ULL};
  const auto pending = static_cast<int>(state.range(0));
  for (int i = 0; i < pending; ++i) scheduler.after(hold.next_delay(), Hop{&hold});
  for (auto _ : state) { // NOLINT(clang-analyzer-deadcode.DeadStores): the benchmark idiom
    scheduler.step();
  }
  state.SetItemsProcessed(static_cast<std::int64_t>(state.iterations()));
  state.counters["pending"] = static_cast<double>(scheduler.pending_count());
}
BENCHMARK(BM_SchedulerHold)->Arg(1000)->Arg(100)->Arg(10000);

// The same with every other event cancelled and replaced, as timeouts that are re-armed do.
void BM_SchedulerCancelRearm(benchmark::State& state) {
  Scheduler scheduler;
  Hold hold{&scheduler, 0x2545'F491'4F6C'DD1DULL};
  std::vector<hilrig::EventId> ids;
  ids.reserve(1000);
  for (int i = 0; i < 1000; ++i) ids.push_back(scheduler.after(hold.next_delay(), Hop{&hold}));
  std::size_t k = 0;
  for (auto _ : state) { // NOLINT(clang-analyzer-deadcode.DeadStores)
    const std::size_t i = k++ % ids.size();
    if (scheduler.cancel(ids[i])) ids[i] = scheduler.after(hold.next_delay(), Hop{&hold});
    scheduler.step();
  }
  state.SetItemsProcessed(static_cast<std::int64_t>(state.iterations()));
}
BENCHMARK(BM_SchedulerCancelRearm);

} // namespace

BENCHMARK_MAIN();
