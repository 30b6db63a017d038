#include "rig/hardware/hardware_run.hpp"

#include <algorithm>
#include <array>
#include <atomic>
#include <memory>
#include <mutex>
#include <optional>
#include <thread>

#include <fmt/format.h>

#include "core/scheduler.hpp"
#include "core/trace.hpp"
#include "models/resolver_emulator/angle_streamer.hpp"
#include "rig/campaign/executive.hpp"
#include "rig/campaign/host_sequence.hpp"
#include "rig/checks/support.hpp"
#include "rig/duts/dut.hpp"
#include "rig/hardware/edge_schedule.hpp"
#include "rig/hardware/resolver_stream.hpp"
#include "rig/rt/rt_loop.hpp"
#include "rig/rt/rt_thread.hpp"

namespace hilrig::hardware {

namespace {

using campaign::RunInputs;
using campaign::VirtualRun;
using rig::LoopSample;
using rig::monotonic_now;

constexpr std::size_t kRingCapacity = std::size_t{1} << 16;
constexpr std::size_t kSentRingCapacity = std::size_t{1} << 14; // 16 s of 1 ms frames between drains
constexpr Nanos kAuxWake{10'000'000}; // the host/CAN thread looks at the bus state this often

// The first fault wins; raising one asks every thread to stop.
class FaultFlag {
public:
  void raise(const std::string& why) {
    const std::lock_guard lock(mutex_);
    if (why_.empty()) why_ = why;
    stop_.store(true, std::memory_order_relaxed);
  }
  [[nodiscard]] const std::atomic<bool>& stop() const { return stop_; }
  [[nodiscard]] bool stopped() const { return stop_.load(std::memory_order_relaxed); }
  [[nodiscard]] std::string why() const {
    const std::lock_guard lock(mutex_);
    return why_;
  }

private:
  mutable std::mutex mutex_;
  std::string why_;
  std::atomic<bool> stop_{false};
};

// What the host thread leaves behind.
struct AuxResult {
  std::vector<rig::Observation> observations;
  std::vector<rig::Measurement> handshakes;
  bool interrupted = false; // by the stop request
};

// The host actions in real time: a Scheduler whose clock follows CLOCK_MONOTONIC from the
// run's start, woken at each event (and every kAuxWake to look at the stop request) until
// the scenario's end.
void run_aux(const campaign::Scenario& s, const DrivePlan& plan, RigPorts& ports, Nanos start,
             const campaign::StopRequest* stop, FaultFlag& fault, AuxResult& out) {
  Scheduler sched;
  std::unique_ptr<campaign::HostSequence> host;
  if (plan.host && ports.host() != nullptr) {
    const duts::DutInfo* info = duts::find_dut(s.dut.model);
    host = std::make_unique<campaign::HostSequence>(
        sched, s, info != nullptr ? info->host : duts::HostInterface{}, *ports.host());
    host->start();
  }
  try {
    while (!fault.stopped()) {
      if (stop != nullptr && stop->requested()) {
        out.interrupted = true;
        fault.raise("interrupted by " + stop->reason());
        break;
      }
      // A late thread still plays every host action due by the end, in order.
      const Nanos elapsed = monotonic_now() - start;
      const Nanos next = sched.next_time();
      if (next > s.end && elapsed >= s.end) break;
      const Nanos wake = std::min({next, std::max(elapsed, Nanos{0}) + kAuxWake, s.end});
      (void)rig::sleep_until(start + wake);
      if (wake >= Nanos{0} && wake >= sched.now()) sched.run_until(wake);
    }
  } catch (const std::exception& e) {
    fault.raise(fmt::format("host link: {}", e.what()));
  }
  if (host) {
    out.observations = std::move(host->observations());
    out.handshakes = std::move(host->handshakes());
  }
}

std::vector<rig::Measurement> timing_of(const rig::RtLoopStats& st, Nanos tolerance,
                                        const rig::RtSetupReport& setup) {
  using checks::measure;
  using checks::to_us;
  const std::string rt =
      setup.problems.empty() ? std::string() : fmt::format(" (the loop ran without: {})", setup.problems);
  std::vector<rig::Measurement> m;
  m.push_back(measure("rig.edge_error.max", to_us(st.max_edge_error), "us", std::nullopt, to_us(tolerance),
                      fmt::format("latest output edge after its scheduled time, over {} edges; {} later than "
                                  "the edge tolerance{}",
                                  st.edges_played, st.missed_deadlines, rt)));
  m.push_back(measure("rig.wakeup.max", to_us(st.wakeups.max()), "us", std::nullopt, std::nullopt,
                      fmt::format("RT loop wake-up latency, worst of {} wake-ups", st.wakeups.count())));
  m.push_back(measure("rig.wakeup.p99", static_cast<double>(st.wakeups.percentile_us(0.99)), "us",
                      std::nullopt, std::nullopt, "RT loop wake-up latency, 99th percentile (1 us bins)"));
  m.push_back(measure("rig.wakeup.avg", to_us(st.wakeups.average()), "us", std::nullopt, std::nullopt,
                      "RT loop wake-up latency, average"));
  return m;
}

// The resolver interface's lost frames, each kind its own figure (allowed: none).
std::vector<rig::Measurement> overruns_of(const CanOverruns& o, const std::string& bus) {
  using checks::measure;
  const auto count = [](std::uint64_t n) { return static_cast<double>(n); };
  return {
      measure("rig.can.controller_rx_overflows", count(o.controller_rx), "frames", std::nullopt, 0.0,
              fmt::format(
                  "{}: error frames reporting a controller receive overrun (CAN_ERR_CRTL_RX_OVERFLOW)", bus)),
      measure(
          "rig.can.controller_tx_overflows", count(o.controller_tx), "frames", std::nullopt, 0.0,
          fmt::format("{}: error frames reporting a controller transmit overrun (CAN_ERR_CRTL_TX_OVERFLOW)",
                      bus)),
      measure(
          "rig.can.socket_rx_drops", count(o.socket_drops), "frames", std::nullopt, 0.0,
          fmt::format("{}: frames the kernel dropped from the rig's full socket receive queue (SO_RXQ_OVFL)",
                      bus))};
}

std::string overrun_fault(const CanOverruns& o, const std::string& bus) {
  return fmt::format(
      "CAN {}: {} frame(s) lost (controller RX overflow {}, TX overflow {}, socket receive queue "
      "drops {}): the run's bus evidence is incomplete",
      bus, o.total(), o.controller_rx, o.controller_tx, o.socket_drops);
}

} // namespace

VirtualRun run_hardware(const RunInputs& in, const DrivePlan& plan, RigPorts& ports,
                        const HardwareRunOptions& o) {
  if (in.scenario == nullptr) throw campaign::RigFault("no scenario");
  const campaign::Scenario& s = *in.scenario;
  const EdgeSchedule schedule = build_schedule(in, plan);

  auto trace = std::make_shared<TraceRecorder>();
  trace->spill_beyond(kTraceHeldSamples); // as the virtual run: long runs go to a temporary file
  std::vector<std::uint32_t> out_signal;
  std::vector<std::uint32_t> in_signal;
  for (const PlannedLine& p : plan.outputs) {
    out_signal.push_back(trace->declare(p.rig));
    trace->set_initial(out_signal.back(), is_high(p.initial) ? 1 : 0);
  }
  // Each captured line's level as the trace has it so far: read before the run, it is where
  // the line starts, and a sample at the level a line already has is no edge.
  std::vector<std::optional<Level>> in_level(plan.inputs.size());
  for (std::size_t i = 0; i < plan.inputs.size(); ++i) {
    in_signal.push_back(trace->declare(plan.inputs[i].rig));
    in_level[i] = ports.input_level(i);
    if (in_level[i]) trace->set_initial(in_signal.back(), is_high(*in_level[i]) ? 1 : 0);
  }

  rig::SpscRing<LoopSample> ring(kRingCapacity);
  auto stats = std::make_unique<rig::RtLoopStats>(); // large: the histogram
  FaultFlag fault;
  // The campaign's own tolerance, when it sets one, over the rig's default.
  const Nanos tolerance = s.edge_tolerance.value_or(o.rt.edge_tolerance);
  const rig::RtLoopConfig loop{tolerance, o.poll_period};
  rig::RtSetupReport setup;
  std::atomic<bool> loop_done{false};
  // The run starts `lead` after the loop's thread is real-time: mlockall faults in every
  // mapped page first, which takes long on a slow box, and must not eat the schedule.
  std::atomic<std::int64_t> start_ns{0};
  std::atomic<bool> ready{false};
  // The resolver stream's thread (when there is one) is made real-time before the start is
  // fixed too: setting a thread up takes long on a slow box, and must neither eat the stream's
  // schedule nor run (mlockall holds the address space) while the loop plays.
  ResolverCan* can = plan.resolver ? ports.resolver() : nullptr;
  std::atomic<bool> stream_set_up{can == nullptr};
  rig::SpscRing<SentFrame> sent_ring(kSentRingCapacity);
  ResolverStreamStats stream;
  rig::RtSetupReport stream_setup;
  std::atomic<bool> stream_done{can == nullptr};
  std::thread stream_thread;
  if (can != nullptr) {
    models::resolver_emulator::AngleStreamParams p;
    p.period = o.resolver_period;
    p.units_per_turn = s.encoder.counts_per_turn();
    stream_thread = std::thread([&, p] {
      // The loop's thread locks the process's memory (MCL_FUTURE covers this thread's pages).
      if (o.realtime)
        stream_setup = rig::make_current_thread_realtime(
            rig::RtSettings{o.rt.resolver_priority, o.rt.resolver_cpu, /*lock_memory=*/false});
      stream_set_up.store(true, std::memory_order_release);
      stream_set_up.notify_all();
      ready.wait(false, std::memory_order_acquire);
      const Nanos start{start_ns.load(std::memory_order_relaxed)};
      const std::string why = play_resolver_stream(schedule.motion.profile, p, s.end, *can, start, sent_ring,
                                                   fault.stop(), stream);
      if (!why.empty()) fault.raise(why);
      stream_done.store(true, std::memory_order_release);
    });
  }
  std::thread rt([&] {
    if (o.realtime) setup = rig::make_current_thread_realtime(rig::RtSettings{o.rt.priority, o.rt.cpu});
    stream_set_up.wait(false, std::memory_order_acquire);
    const Nanos start = monotonic_now() + o.lead;
    ports.begin(start);
    start_ns.store(start.count(), std::memory_order_relaxed);
    ready.store(true, std::memory_order_release);
    ready.notify_all();
    rig::play(schedule.edges, start, ports.outputs(), ports.inputs(), ring, fault.stop(), loop, *stats);
    if (ports.inputs() != nullptr)
      rig::capture_until(start + s.end, *ports.inputs(), ring, fault.stop(), o.poll_period, *stats);
    loop_done.store(true, std::memory_order_release);
  });
  ready.wait(false, std::memory_order_acquire);
  const Nanos start{start_ns.load(std::memory_order_relaxed)};
  AuxResult aux;
  std::thread aux_thread([&] { run_aux(s, plan, ports, start, in.stop, fault, aux); });

  std::vector<LoopSample> samples;
  samples.reserve(schedule.edges.size() + 1024);
  std::vector<SentFrame> frames;
  LoopSample sample{};
  SentFrame frame{};
  for (;;) {
    const bool done =
        loop_done.load(std::memory_order_acquire) && stream_done.load(std::memory_order_acquire);
    while (ring.pop(sample)) samples.push_back(sample);
    while (sent_ring.pop(frame)) frames.push_back(frame);
    if (done) break;
    (void)rig::sleep_until(monotonic_now() + Nanos{1'000'000});
  }
  rt.join();
  aux_thread.join();
  if (stream_thread.joinable()) stream_thread.join();
  while (ring.pop(sample)) samples.push_back(sample);
  while (sent_ring.pop(frame)) frames.push_back(frame);
  if (fault.stopped()) {
    // Stopped early: every rig-driven line to its inactive level (low), in the trace too.
    for (std::size_t i = 0; i < plan.outputs.size(); ++i) {
      ports.outputs().write(static_cast<std::uint16_t>(i), Level::Low);
      const Nanos now = monotonic_now();
      samples.push_back(
          LoopSample{LoopSample::Kind::Output, static_cast<std::uint16_t>(i), Level::Low, now, now});
    }
  }

  // Into the trace in time order (inputs and outputs interleave across the two sources).
  std::stable_sort(samples.begin(), samples.end(),
                   [](const LoopSample& a, const LoopSample& b) { return a.actual < b.actual; });
  for (const LoopSample& x : samples) {
    const bool output = x.kind == LoopSample::Kind::Output;
    if (x.line >= (output ? out_signal.size() : in_signal.size())) continue;
    const std::uint32_t sig = output ? out_signal[x.line] : in_signal[x.line];
    const Nanos t = x.actual - start;
    if (!output) {
      if (in_level[x.line] == x.level) continue; // e.g. an event queued before the level was read
      in_level[x.line] = x.level;
    }
    if (t < Nanos{0}) {
      trace->set_initial(sig, is_high(x.level) ? 1 : 0); // an input edge while the rig set up
      continue;
    }
    trace->edge(sig, Edge{t, x.level});
  }
  if (can != nullptr)
    for (const SentFrame& f : frames) trace->can(can->bus(), f.at, f.frame);

  VirtualRun v;
  v.exact_motion = false;
  v.trace = trace;
  v.profile = schedule.motion.profile;
  v.motion = schedule.positions;
  v.observations = std::move(aux.observations);
  v.handshakes = std::move(aux.handshakes);
  v.rig_timing = timing_of(*stats, tolerance, setup);
  std::optional<CanOverruns> overruns;
  if (can != nullptr) {
    const std::string without =
        stream_setup.problems.empty()
            ? std::string()
            : fmt::format(" (the stream thread ran without: {})", stream_setup.problems);
    v.rig_timing.push_back(checks::measure(
        "rig.resolver.stale_frames", static_cast<double>(stream.stale), "frames", std::nullopt, std::nullopt,
        fmt::format("resolver frames skipped because the stream thread woke more than a period ({} us) late; "
                    "{} frames sent{}",
                    checks::to_us(o.resolver_period), stream.sent, without)));
    overruns = can->overruns();
    for (rig::Measurement& m : overruns_of(*overruns, can->bus())) v.rig_timing.push_back(std::move(m));
  }
  v.rig_fault = fault.why();
  v.interrupted = aux.interrupted;
  if (v.rig_fault.empty() && overruns && overruns->total() > 0)
    v.rig_fault = overrun_fault(*overruns, can->bus());
  if (v.rig_fault.empty() && can != nullptr && stream.sent == 0)
    v.rig_fault =
        fmt::format("the resolver stream sent no frame: all {} were more than a period late", stream.stale);
  if (v.rig_fault.empty() && stream.ring_overflows > 0)
    v.rig_fault =
        fmt::format("{} sent resolver frame(s) lost: the ring between the stream thread and the recorder "
                    "overflowed",
                    stream.ring_overflows);
  if (v.rig_fault.empty() && stats->missed_deadlines > 0)
    v.rig_fault =
        fmt::format("{} output edge(s) later than the edge tolerance ({} us); the latest by {} us",
                    stats->missed_deadlines, checks::to_us(tolerance), checks::to_us(stats->max_edge_error));
  if (v.rig_fault.empty() && stats->ring_overflows > 0)
    v.rig_fault =
        fmt::format("{} captured sample(s) lost: the ring between the RT loop and the recorder overflowed",
                    stats->ring_overflows);
  return v;
}

} // namespace hilrig::hardware
