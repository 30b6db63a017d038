#include "rig/cli/latency_command.hpp"

#include <CLI/CLI.hpp>
#include <fmt/core.h>

#include <algorithm>
#include <sys/resource.h>
#include <unistd.h>

#include <cstdio>
#include <memory>
#include <optional>
#include <string>
#include <thread>

#include "core/clock.hpp"
#include "rig/campaign/stop_request.hpp"
#include "rig/cli/exit_status.hpp"
#include "rig/cli/number_checks.hpp"
#include "rig/cli/stop_signals.hpp"
#include "rig/rt/cpu_latency_request.hpp"
#include "rig/rt/rt_loop.hpp"
#include "rig/rt/rt_thread.hpp"

namespace hilrig::cli {

namespace {

struct LatencyOptions {
  double duration_s = 10.0;
  int priority = 80;
  int cpu = -1;
  std::int64_t interval_us = 1000;
  bool quiet_histogram = false;
  bool breakdown = false;
};

// What the loop itself caused, from the thread's own counters around it.
struct LoopCounters {
  long minor_faults = 0;
  long major_faults = 0;
  long voluntary_switches = 0;
  long involuntary_switches = 0;
};

LoopCounters thread_counters() {
  rusage u{};
  getrusage(RUSAGE_THREAD, &u);
  return {u.ru_minflt, u.ru_majflt, u.ru_nvcsw, u.ru_nivcsw};
}

std::string spread_text(const rig::Spread& s) {
  return fmt::format("{} / {} / {}", s.p50.count(), s.p99.count(), s.max.count());
}

// Options the loop cannot honour, refused before anything is measured (exit 2): a CPU the
// machine does not have (the thread would run unpinned, its header saying so in passing), and a
// duration shorter than one interval (no wake-up at all: a table of zeros is no measurement).
std::optional<std::string> refusal(const LatencyOptions& o) {
  const long cpus = ::sysconf(_SC_NPROCESSORS_CONF);
  if (o.cpu >= 0 && cpus > 0 && o.cpu >= cpus)
    return fmt::format("--cpu {}: this machine has CPUs 0 .. {}", o.cpu, cpus - 1);
  const double interval_s = static_cast<double>(o.interval_us) * 1e-6;
  if (o.duration_s < interval_s)
    return fmt::format("--duration {}: shorter than one --interval ({} us): at least {} s", o.duration_s,
                       o.interval_us, interval_s);
  return std::nullopt;
}

int run_latency(const LatencyOptions& o) {
  if (const auto problem = refusal(o)) {
    std::fputs(fmt::format("hilrig latency: {}\n", *problem).c_str(), stderr);
    return kBadInput;
  }
  auto histogram = std::make_unique<rig::LatencyHistogram>();
  // At least one: a duration of exactly one interval is one wake-up, however the division rounds.
  const auto loops = std::max<std::uint64_t>(
      1, static_cast<std::uint64_t>(o.duration_s * 1e6 / static_cast<double>(o.interval_us)));
  rig::RtSetupReport setup;
  // Made and written before the loop (no page of it is new to the loop).
  std::unique_ptr<rig::WakeupTrace> trace;
  // At most 2^20 wake-ups (32 MiB) are stamped; later ones are counted, not kept.
  if (o.breakdown)
    trace = std::make_unique<rig::WakeupTrace>(std::min<std::size_t>(loops, std::size_t{1} << 20));
  rig::Spread clock_cost;
  LoopCounters before, after;
  campaign::StopRequest stop;
  const StopSignals signals(stop);
  // As cyclictest does: no deep C-states while measuring.
  const rig::CpuLatencyRequest no_deep_idle(0);
  // The measuring thread is set up exactly as the campaign RT loop is.
  std::thread rt([&] {
    rig::RtSettings settings;
    settings.priority = o.priority;
    if (o.cpu >= 0) settings.cpu = o.cpu;
    setup = rig::make_current_thread_realtime(settings);
    if (trace) clock_cost = rig::clock_read_cost(1000);
    before = thread_counters();
    const Nanos start = MonotonicClock{}.now();
    rig::measure_wakeups(start, microseconds(o.interval_us), loops, stop.flag(), *histogram, trace.get());
    after = thread_counters();
  });
  rt.join();

  const auto& h = *histogram;
  if (h.count() == 0) { // stopped by a signal before the first wake-up
    std::fputs("hilrig latency: no wake-up measured (stopped before the first)\n", stderr);
    return kRigFault;
  }
  fmt::print("# hilrig latency: SCHED_FIFO priority {} ({}), cpu {} ({}), memory {}\n", o.priority,
             setup.scheduled ? "applied" : "NOT applied",
             o.cpu < 0 ? std::string("any") : std::to_string(o.cpu), setup.pinned ? "pinned" : "not pinned",
             setup.locked ? "locked" : "NOT locked");
  if (!setup.problems.empty()) fmt::print("# problems: {}\n", setup.problems);
  fmt::print("# cpu_dma_latency: {}\n", no_deep_idle.active() ? "held at 0 us" : no_deep_idle.problem());
  fmt::print("# timer slack: {} ns\n", setup.timer_slack_ns);
  fmt::print("T: 0 P:{:2d} I:{} C:{:7d} Min:{:7d} Avg:{:7d} Max:{:7d}\n", o.priority, o.interval_us,
             h.count(), h.min().count() / 1000, h.average().count() / 1000, h.max().count() / 1000);
  if (!o.quiet_histogram) {
    fmt::print("# Histogram\n");
    for (std::size_t us = 0; us <= h.last_bin(); ++us) fmt::print("{:06d} {:06d}\n", us, h.bin(us));
  }
  fmt::print("# Total: {:09d}\n", h.count());
  fmt::print("# Min Latencies: {:05d}\n", h.min().count() / 1000);
  fmt::print("# Avg Latencies: {:05d}\n", h.average().count() / 1000);
  fmt::print("# Max Latencies: {:05d}\n", h.max().count() / 1000);
  fmt::print("# P99 Latencies: {:05d}\n", h.percentile_us(0.99));
  fmt::print("# Histogram Overflows: {:05d}\n", h.overflow());
  fmt::print(
      "# In the loop: minor faults {}, major faults {}, voluntary switches {}, involuntary switches {}\n",
      after.minor_faults - before.minor_faults, after.major_faults - before.major_faults,
      after.voluntary_switches - before.voluntary_switches,
      after.involuntary_switches - before.involuntary_switches);
  if (trace) {
    const rig::WakeupBreakdown b = rig::summarize(trace->stamps());
    fmt::print("# Breakdown: {} wake-ups ({} more not stamped), ns as p50 / p99 / max\n", b.wakeups,
               trace->dropped());
    fmt::print("# Breakdown latency (woke - due): {}\n", spread_text(b.latency));
    fmt::print("# Breakdown work (woke -> histogram updated, next deadline set, one clock read): {}\n",
               spread_text(b.work));
    fmt::print("# Breakdown ahead (back in clock_nanosleep -> due): {}\n", spread_text(b.ahead));
    fmt::print("# Breakdown clock read (CLOCK_MONOTONIC, back to back, 1000 pairs): {}\n",
               spread_text(clock_cost));
  }
  // A box that could not give the loop SCHED_FIFO is not qualified to run a board.
  return setup.scheduled || o.priority == 0 ? kPassed : kRigFault;
}

} // namespace

void add_latency_command(CLI::App& app) {
  auto opts = std::make_shared<LatencyOptions>();
  CLI::App* cmd = app.add_subcommand("latency", "Measure the RT loop's wake-up latency, like cyclictest");
  cmd->add_option("--duration", opts->duration_s, "seconds to measure")->check(positive_number());
  cmd->add_option("--priority", opts->priority, "SCHED_FIFO priority (0 = SCHED_OTHER)")
      ->check(CLI::Range(0, 99));
  cmd->add_option("--cpu", opts->cpu, "pin to this CPU")->check(non_negative_number());
  cmd->add_option("--interval", opts->interval_us, "wake-up interval in us")
      ->check(CLI::Range(10, 1'000'000));
  cmd->add_flag("--quiet", opts->quiet_histogram, "omit the histogram");
  cmd->add_flag("--breakdown", opts->breakdown,
                "also stamp every wake-up (two more clock reads each) and print where the time went");
  cmd->callback([opts] {
    const int code = run_latency(*opts);
    if (code != kPassed) exit_with(code);
  });
}

} // namespace hilrig::cli
