// The fold at the end of `hilrig run` (rig/results/fold_run_log.hpp) does not hold the runs:
// the peak of the heap it uses, counted by a replacement of the global operator new, is the
// same for a log of 400 runs as for one of 40 (within a slack far below the 360 more runs'
// share), where folding the same log into memory (read_run_log) grows with the runs.
// Its own executable: the counting allocator replaces operator new for the whole program.

#include <gtest/gtest.h>

#include <atomic>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <new>
#include <string>

#include "rig/results/fold_run_log.hpp"
#include "rig/results/run_log.hpp"
#include "sample_campaign.hpp"
#include "tests/tools/scratch_files.hpp"

namespace {

// Live heap bytes allocated through operator new, and the highest they reached.
std::atomic<std::size_t> g_live{0};
std::atomic<std::size_t> g_peak{0};
constexpr std::size_t kHeader = alignof(std::max_align_t); // the size, kept before the block

void* counted_new(std::size_t size) {
  auto* base = static_cast<unsigned char*>(std::malloc(size + kHeader));
  if (base == nullptr) throw std::bad_alloc();
  *reinterpret_cast<std::size_t*>(base) = size;
  const std::size_t live = g_live += size;
  for (std::size_t peak = g_peak; live > peak && !g_peak.compare_exchange_weak(peak, live);) {}
  return base + kHeader;
}

void counted_delete(void* p) noexcept {
  if (p == nullptr) return;
  auto* base = static_cast<unsigned char*>(p) - kHeader;
  g_live -= *reinterpret_cast<std::size_t*>(base);
  std::free(base);
}

} // namespace

void* operator new(std::size_t size) { return counted_new(size); }
void* operator new[](std::size_t size) { return counted_new(size); }
void operator delete(void* p) noexcept { counted_delete(p); }
void operator delete[](void* p) noexcept { counted_delete(p); }
void operator delete(void* p, std::size_t) noexcept { counted_delete(p); }
void operator delete[](void* p, std::size_t) noexcept { counted_delete(p); }
// The nothrow forms too (std::stable_sort's temporary buffer takes one and frees it with the
// sized delete above): left to the runtime, ASan's would hand out a block without the header.
void* operator new(std::size_t size, const std::nothrow_t&) noexcept {
  try {
    return counted_new(size);
  } catch (const std::bad_alloc&) {
    return nullptr;
  }
}
void* operator new[](std::size_t size, const std::nothrow_t&) noexcept {
  try {
    return counted_new(size);
  } catch (const std::bad_alloc&) {
    return nullptr;
  }
}
void operator delete(void* p, const std::nothrow_t&) noexcept { counted_delete(p); }
void operator delete[](void* p, const std::nothrow_t&) noexcept { counted_delete(p); }

namespace hilrig::rig {
namespace {

namespace fs = std::filesystem;

// A log of n sample runs, each carrying a 1000-value latency series (about 8 KB a run held
// in memory), so a fold that kept the runs would grow by megabytes between 40 and 400 runs.
fs::path write_log(const std::string& name, std::size_t n) {
  const fs::path dir = hilrig::test::scratch_dir("results", name);
  CampaignResult c = test::sample_campaign(n);
  for (RunResult& run : c.runs) run.checks[0].series[0].values.assign(1000, 12.5);
  finalize(c);
  RunLog log(dir / kRunLogName, c);
  for (const RunResult& run : c.runs) log.append(run);
  return dir;
}

// The heap the call used at its highest, above what was live when it began.
template <class F> std::size_t peak_of(F&& call) {
  const std::size_t before = g_live;
  g_peak = before;
  call();
  return g_peak - before;
}

constexpr std::size_t kSlack = 256 * 1024; // the summary lists' first entries, fault run indices

TEST(FoldMemory, PeakDoesNotGrowWithTheRuns) {
  const fs::path small = write_log("fold_memory_40", 40);
  const fs::path large = write_log("fold_memory_400", 400);
  const JunitClock clock;
  const CampaignResult facts;
  const std::size_t fold_small =
      peak_of([&] { (void)fold_run_log(small / kRunLogName, small, facts, clock); });
  const std::size_t fold_large =
      peak_of([&] { (void)fold_run_log(large / kRunLogName, large, facts, clock); });
  std::printf("fold peak: 40 runs %zu B, 400 runs %zu B\n", fold_small, fold_large);
  EXPECT_LE(fold_large, fold_small + kSlack)
      << "40 runs: " << fold_small << " B, 400 runs: " << fold_large << " B";
  // The measure sees a fold that holds the runs: read_run_log's peak grows by 360 runs' share.
  const std::size_t held_small = peak_of([&] { (void)read_run_log(small / kRunLogName); });
  const std::size_t held_large = peak_of([&] { (void)read_run_log(large / kRunLogName); });
  std::printf("read_run_log peak: 40 runs %zu B, 400 runs %zu B\n", held_small, held_large);
  EXPECT_GT(held_large, held_small + 360 * 8'000) << held_small << " B vs " << held_large << " B";
}

// The log's writer keeps the runs for the fold only within its budget: appending 120 runs
// with a 1 MiB budget peaks near the budget (the runs dropped when it was passed), where the
// default budget holds them all and grows by the 100 more runs' share.
TEST(FoldMemory, WriterHoldsRunsWithinItsBudget) {
  CampaignResult c = test::sample_campaign(120);
  for (RunResult& run : c.runs) run.checks[0].series[0].values.assign(1000, 12.5);
  finalize(c);
  const fs::path dir = hilrig::test::scratch_dir("results", "writer_budget");
  constexpr std::size_t kBudget = 1024 * 1024;
  CampaignResult header = c; // as `hilrig run` gives it: the facts, no run
  header.runs.clear();
  const auto append = [&](std::size_t n, std::size_t budget) {
    return peak_of([&] {
      RunLog log(dir / kRunLogName, header, budget);
      for (std::size_t i = 0; i < n; ++i) log.append(c.runs[i]);
      EXPECT_EQ(log.holds_runs(), budget != kBudget) << n;
    });
  };
  const std::size_t bounded = append(120, kBudget);
  std::printf("writer peak, 120 runs: budget 1 MiB %zu B\n", bounded);
  EXPECT_LE(bounded, 2 * kBudget);
  const std::size_t small = append(20, kRunLogHeldBytes);
  const std::size_t large = append(120, kRunLogHeldBytes);
  std::printf("writer peak, default budget: 20 runs %zu B, 120 runs %zu B\n", small, large);
  EXPECT_GT(large, small + 100 * 8'000);
}

} // namespace
} // namespace hilrig::rig
