#include "rig/hardware/hardware_run.hpp"

#include <algorithm>
#include <array>
#include <atomic>
#include <ctime>
#include <memory>
#include <mutex>
#include <optional>
#include <thread>

#include <fmt/format.h>

#include "core/scheduler.hpp"
#include "models/resolver_emulator/angle_streamer.hpp"
#include "rig/campaign/executive.hpp"
#include "rig/campaign/host_sequence.hpp"
#include "rig/checks/support.hpp"
#include "rig/duts/dut.hpp"
#include "rig/hardware/edge_schedule.hpp"
#include "rig/rt/rt_loop.hpp"
#include "rig/rt/rt_thread.hpp"

namespace hilrig::hardware {

namespace {

using campaign::RunInputs;
using campaign::VirtualRun;
using rig::LoopSample;

constexpr std::size_t kRingCapacity = std::size_t{1} << 16;
constexpr Nanos kAuxWake{10'000'000}; // the host/CAN thread looks at the bus state this often

Nanos monotonic_now() noexcept {
  timespec ts{};
  clock_gettime(CLOCK_MONOTONIC, &ts);
  return Nanos{static_cast<std::int64_t>(ts.tv_sec) * 1'000'000'000 + ts.tv_nsec};
}

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

// The resolver stream's CAN port: frames go out on the rig's interface and are kept, with
// the time they were sent, for can.log.
class StreamPort final : public CanPort {
public:
  StreamPort(ResolverCan& can, Nanos start, FaultFlag& fault) : can_(can), start_(start), fault_(fault) {}
  void send(const CanFrame& frame) override {
    const Nanos at = monotonic_now() - start_;
    const std::string why = can_.send(frame);
    if (!why.empty()) {
      fault_.raise(why);
      return;
    }
    sent.push_back({at, frame});
  }
  void on_receive(CanReceiveHandler /*handler*/) override {} // the stream only sends

  std::vector<std::pair<Nanos, CanFrame>> sent;

private:
  ResolverCan& can_;
  Nanos start_;
  FaultFlag& fault_;
};

// What the host/CAN thread leaves behind.
struct AuxResult {
  std::vector<rig::Observation> observations;
  std::vector<rig::Measurement> handshakes;
  std::vector<std::pair<Nanos, CanFrame>> frames;
  std::int64_t stale_frames = 0; // resolver frames skipped because the thread woke too late
  bool interrupted = false;      // by the stop request
};

// The host actions and the resolver stream in real time: a Scheduler whose clock follows
// CLOCK_MONOTONIC from the run's start, woken at each event (and every kAuxWake to read the
// bus state) until the scenario's end.
void run_aux(const campaign::Scenario& s, const DrivePlan& plan, RigPorts& ports,
             const signals::MotionProfile& profile, const HardwareRunOptions& o, Nanos start,
             const campaign::StopRequest* stop, FaultFlag& fault, AuxResult& out) {
  Scheduler sched;
  std::unique_ptr<campaign::HostSequence> host;
  if (plan.host && ports.host() != nullptr) {
    const duts::DutInfo* info = duts::find_dut(s.dut.model);
    host = std::make_unique<campaign::HostSequence>(
        sched, s, info != nullptr ? info->host : duts::HostInterface{}, *ports.host());
    host->start();
  }
  ResolverCan* can = plan.resolver ? ports.resolver() : nullptr;
  std::unique_ptr<StreamPort> port;
  std::unique_ptr<models::resolver_emulator::AngleStreamer> stream;
  if (can != nullptr) {
    port = std::make_unique<StreamPort>(*can, start, fault);
    models::resolver_emulator::AngleStreamParams p;
    p.period = o.resolver_period;
    p.units_per_turn = s.encoder.counts_per_turn();
    stream = std::make_unique<models::resolver_emulator::AngleStreamer>(sched, *port, profile, p);
    stream->start(Nanos{0});
  }
  try {
    while (!fault.stopped()) {
      if (stop != nullptr && stop->requested()) {
        out.interrupted = true;
        fault.raise("interrupted by " + stop->reason());
        break;
      }
      if (can != nullptr) {
        const std::string why = can->check();
        if (!why.empty()) {
          fault.raise(why);
          break;
        }
      }
      // A late thread still plays every host action due by the end, in order; but a resolver
      // frame more than a period late would tell the front end an angle the shaft has
      // already left, so the stream skips to the next period boundary after now instead.
      Nanos elapsed = monotonic_now() - start;
      if (stream && elapsed > sched.now() + o.resolver_period && elapsed < s.end) {
        stream->stop();
        const Nanos resume = (elapsed / o.resolver_period + 1) * o.resolver_period;
        out.stale_frames += (resume - sched.now()) / o.resolver_period - 1;
        sched.run_until(elapsed);
        stream->start(resume);
        elapsed = monotonic_now() - start;
      }
      const Nanos next = sched.next_time();
      if (next > s.end && elapsed >= s.end) break;
      const Nanos wake = std::min({next, std::max(elapsed, Nanos{0}) + kAuxWake, s.end});
      (void)rig::sleep_until(start + wake);
      if (wake >= Nanos{0} && wake >= sched.now()) sched.run_until(wake);
    }
  } catch (const std::exception& e) {
    fault.raise(fmt::format("host link: {}", e.what()));
  }
  if (stream) stream->stop();
  if (host) {
    out.observations = std::move(host->observations());
    out.handshakes = std::move(host->handshakes());
  }
  if (port) out.frames = std::move(port->sent);
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

} // namespace

VirtualRun run_hardware(const RunInputs& in, const DrivePlan& plan, RigPorts& ports,
                        const HardwareRunOptions& o) {
  if (in.scenario == nullptr) throw campaign::RigFault("no scenario");
  const campaign::Scenario& s = *in.scenario;
  const EdgeSchedule schedule = build_schedule(in, plan);

  auto trace = std::make_shared<TraceRecorder>();
  trace->spill_beyond(std::size_t{1} << 16); // as the virtual run: long runs go to a temporary file
  std::vector<std::uint32_t> out_signal;
  std::vector<std::uint32_t> in_signal;
  for (const PlannedLine& p : plan.outputs) {
    out_signal.push_back(trace->declare(p.rig));
    trace->set_initial(out_signal.back(), is_high(p.initial) ? 1 : 0);
  }
  for (std::size_t i = 0; i < plan.inputs.size(); ++i) {
    in_signal.push_back(trace->declare(plan.inputs[i].rig));
    if (const auto l = ports.input_level(i)) trace->set_initial(in_signal.back(), is_high(*l) ? 1 : 0);
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
  std::thread rt([&] {
    if (o.realtime) setup = rig::make_current_thread_realtime(rig::RtSettings{o.rt.priority, o.rt.cpu});
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
  std::thread aux_thread(
      [&] { run_aux(s, plan, ports, schedule.motion.profile, o, start, in.stop, fault, aux); });

  std::vector<LoopSample> samples;
  samples.reserve(schedule.edges.size() + 1024);
  LoopSample sample{};
  for (;;) {
    const bool done = loop_done.load(std::memory_order_acquire);
    while (ring.pop(sample)) samples.push_back(sample);
    if (done) break;
    (void)rig::sleep_until(monotonic_now() + Nanos{1'000'000});
  }
  rt.join();
  aux_thread.join();
  while (ring.pop(sample)) samples.push_back(sample);
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
    if (t < Nanos{0}) {
      trace->set_initial(sig, is_high(x.level) ? 1 : 0); // an input edge while the rig set up
      continue;
    }
    trace->edge(sig, Edge{t, x.level});
  }
  if (plan.resolver && ports.resolver() != nullptr)
    for (const auto& [t, frame] : aux.frames) trace->can(ports.resolver()->bus(), t, frame);

  VirtualRun v;
  v.exact_motion = false;
  v.trace = trace;
  v.profile = schedule.motion.profile;
  v.motion = schedule.positions;
  v.observations = std::move(aux.observations);
  v.handshakes = std::move(aux.handshakes);
  v.rig_timing = timing_of(*stats, tolerance, setup);
  if (plan.resolver && ports.resolver() != nullptr)
    v.rig_timing.push_back(checks::measure(
        "rig.resolver.stale_frames", static_cast<double>(aux.stale_frames), "frames", std::nullopt,
        std::nullopt,
        fmt::format("resolver frames skipped because the stream thread woke more than a period ({} us) late; "
                    "{} frames sent",
                    checks::to_us(o.resolver_period), aux.frames.size())));
  v.rig_fault = fault.why();
  v.interrupted = aux.interrupted;
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
