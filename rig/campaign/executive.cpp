#include "rig/campaign/executive.hpp"

#include <algorithm>
#include <array>
#include <atomic>
#include <exception>
#include <thread>
#include <utility>

#include <fmt/format.h>

#include "rig/campaign/motion_record.hpp"
#include "rig/campaign/virtual_run.hpp"
#include "rig/campaign/window_traces.hpp"
#include "rig/checks/debounce.hpp"
#include "rig/checks/registry.hpp"
#include "rig/results/results_json.hpp"
#include "signals/standstill.hpp"

namespace hilrig::campaign {

namespace {

// A window a check leaves open (no edge after the last crossing, and no timeout) ends where the
// run does: the evidence (results.json, the trace cut, the .gtkw zoom) stays inside the run.
void end_windows_at(rig::CheckResult& check, Nanos end) {
  for (rig::Measurement& m : check.measurements)
    if (m.window && m.window->end > end) m.window->end = std::max(end, m.window->begin);
}

// Whether some check reads the rig line `name`.
bool names_line(const Scenario& s, const std::string& name) {
  for (const CheckSpec& check : s.checks) {
    const auto lines = checks::lines_of(check.params);
    if (std::find(lines.begin(), lines.end(), name) != lines.end()) return true;
  }
  return false;
}

// Only the wired lines some check names are copied out of the trace, in one pass: the
// encoder's lines alone are ~10^5 edges a second and no check reads them.
checks::Capture capture_of(const Scenario& s, const VirtualRun& v) {
  checks::Capture c;
  std::vector<std::string> named;
  for (const Wire& w : s.wiring)
    if (names_line(s, w.rig)) named.push_back(w.rig);
  c.lines = v.trace->edges_of(named);
  for (const std::string& name : named) {
    const std::int64_t i = v.trace->find(name);
    if (i < 0) continue;
    const SignalInfo& info = v.trace->signals()[static_cast<std::size_t>(i)];
    if (info.kind == SignalKind::Wire && info.has_initial) c.initial[name] = level_of(info.initial != 0);
  }
  for (const Wire& w : s.wiring)
    if (w.direction == duts::PinDirection::Input) c.rig_driven.insert(w.rig);
  const signals::MotionProfile* profile = &v.profile;
  // Each keeps the segment it last read: a check reads at nearby times (a crossing scan and
  // its bisections), and a plant's profile has a segment per integration step.
  c.position = [profile, hint = std::size_t{0}](Nanos t) mutable { return profile->position(t, hint); };
  c.speed = [profile, hint = std::size_t{0}](Nanos t) mutable { return profile->velocity(t, hint); };
  c.held = [profile, hint = std::size_t{0}](Nanos t) mutable { return profile->held_until(t, hint); };
  c.motion = v.motion;
  c.counts = v.counts;
  if (v.exact_motion) {
    if (s.plant) {
      // A plant located its own standstill: the last change of its motion samples.
      c.standstill = [samples = v.motion, end = s.end](Nanos from) {
        return checks::standstill_after(samples, from, end);
      };
    } else {
      c.standstill = [profile](Nanos from) { return signals::standstill_after(*profile, from); };
    }
  }
  c.observations = v.observations;
  c.begin = Nanos{0};
  c.end = s.end;
  return c;
}

// The host's writes, each timed to its Acknowledge, as one result entry.
rig::CheckResult host_check(const std::vector<rig::Measurement>& handshakes) {
  rig::CheckResult c;
  c.check = rig::kHostCheckName;
  c.kind = "handshake";
  c.measurements = handshakes;
  return c;
}

// A hardware run's own timing (wake-up latency, edge errors) as one result entry.
rig::CheckResult rig_check(const std::vector<rig::Measurement>& timing) {
  rig::CheckResult c;
  c.check = rig::kRigCheckName;
  c.kind = "rt_timing";
  c.measurements = timing;
  return c;
}

} // namespace

std::vector<checks::PhaseBisection> Executive::bisect_phases(const RunInputs& in, const CheckSpec& c,
                                                             const checks::DebounceParams& d) const {
  const std::vector<Nanos> starts = d.probe_starts(c.probe_at);
  // The limits first: they decide the verdict exactly, and bracket a board within them.
  const std::array<Nanos, 2> limits{d.spec.shortest_rejected(), d.spec.longest_accepted()};
  const checks::BisectionPlan& plan = d.plan;
  // Each probe is a fresh run of the same scenario with one more pulse on the input.
  const auto bisect = [&](Nanos start) {
    const checks::PulseProbe probe = [&](Nanos width) {
      RunInputs p = in;
      p.probe = Stimulus{StimulusKind::Pulse, start,  plan.input, plan.level, width, Nanos{0}, 0, 1,
                         Nanos::max(),        c.where};
      const VirtualRun pv = backend_(p);
      if (!pv.rig_fault.empty()) throw RigFault(pv.rig_fault);
      for (const Edge& e : pv.trace->edges_of(plan.output))
        if (e.time >= start) return true;
      return false;
    };
    return checks::PhaseBisection{
        start, checks::bisect_boundary(probe, plan.narrow, plan.wide, plan.resolution, limits)};
  };
  std::vector<checks::PhaseBisection> out(starts.size());
  std::vector<std::exception_ptr> failed(starts.size());
  // The phases are independent runs: spread over threads, each result in its phase's slot, so
  // the outcome is the same for any thread count. A host link may hold one board: one thread.
  std::atomic<std::size_t> next{0};
  const auto worker = [&] {
    for (std::size_t i = next++; i < starts.size(); i = next++) {
      try {
        out[i] = bisect(starts[i]);
      } catch (...) {
        failed[i] = std::current_exception();
      }
    }
  };
  const std::size_t threads = host_link_ ? 1 : std::clamp<std::size_t>(probe_threads_, 1, starts.size());
  std::vector<std::thread> helpers;
  for (std::size_t t = 1; t < threads; ++t) helpers.emplace_back(worker);
  worker();
  for (auto& t : helpers) t.join();
  for (const auto& e : failed)
    if (e) std::rethrow_exception(e);
  return out;
}

Executive::Executive(const Campaign& campaign, RunBackend backend)
    : campaign_(campaign), backend_(backend ? std::move(backend) : RunBackend(run_virtual)) {}

RunOutput Executive::run(const RunSpec& spec) const {
  RunOutput out;
  rig::RunResult& r = out.result;
  r.index = spec.index;
  r.name = spec.label;
  r.seed = spec.seed;
  const Scenario& s = campaign_.scenario_of(spec);

  RunInputs in;
  in.scenario = &s;
  in.variant = s.dut.variant;
  in.seed = spec.seed;
  in.record_motion = false;
  in.host_link = host_link_ ? &host_link_ : nullptr;
  in.stop = stop_;
  in.exact_scan = exact_scan_;
  for (const CheckSpec& c : s.checks)
    in.record_motion = in.record_motion || std::holds_alternative<checks::BrakeParams>(c.params);
  if (spec.fault) {
    const FaultSpec& f = campaign_.faults.at(*spec.fault);
    r.fault = f.name;
    r.must_catch = f.caught_by;
    if (f.variant) in.variant = *f.variant;
    if (f.signal) in.faults.push_back(*f.signal);
  }

  try {
    VirtualRun v = backend_(in);
    if (!v.rig_fault.empty()) {
      // The rig stopped the run: keep what it captured, judge nothing on a partial capture.
      r.error = v.rig_fault;
      r.interrupted = v.interrupted;
      r.observations = v.observations;
      if (!v.handshakes.empty()) r.checks.push_back(host_check(v.handshakes));
      if (!v.rig_timing.empty()) r.checks.push_back(rig_check(v.rig_timing));
      out.trace = v.trace;
      return out;
    }
    out.trace = v.trace; // kept when a probe run below is stopped
    checks::Capture capture = capture_of(s, v);
    // The trace around what the report draws, cut for every check judged in one pass over the
    // recording; a brake's stop is drawn on the motion instead.
    std::vector<std::pair<std::size_t, Lanes>> drawn; // check index, its lanes
    const auto cut = [&] {
      std::vector<WindowCut> cuts;
      for (const auto& [k, lanes] : drawn) cuts.push_back(WindowCut{&r.checks[k], lanes});
      auto traces = cut_window_traces(cuts, *v.trace);
      for (std::size_t i = 0; i < drawn.size(); ++i) r.checks[drawn[i].first].traces = std::move(traces[i]);
    };
    try {
      for (const CheckSpec& c : s.checks) {
        capture.bisections.clear();
        if (const auto* debounce = std::get_if<checks::DebounceParams>(&c.params))
          capture.bisections = bisect_phases(in, c, *debounce);
        r.checks.push_back(checks::run_check(c.name, c.params, capture));
        end_windows_at(r.checks.back(), s.end);
        if (v.trace && !std::holds_alternative<checks::BrakeParams>(c.params))
          drawn.emplace_back(r.checks.size() - 1, lanes_of(c.params, *v.trace));
      }
    } catch (...) {
      // The checks judged before the one that threw keep their traces, as when cut one by one.
      try {
        cut();
      } catch (...) { // NOLINT(bugprone-empty-catch): the first error is the run's
      }
      throw;
    }
    cut();
    if (!v.handshakes.empty()) r.checks.push_back(host_check(v.handshakes));
    if (!v.rig_timing.empty()) r.checks.push_back(rig_check(v.rig_timing));
    r.observations = v.observations;
    // The shaft's speed and position for the report: a plant's run, or a brake check's.
    if (s.plant || in.record_motion) r.motion = record_motion(v.profile, s.end, v.motion_events);
    out.trace = v.trace;
  } catch (const std::exception& e) {
    r.error = e.what();
    r.interrupted = stop_ != nullptr && stop_->requested();
  }
  return out;
}

rig::CampaignResult Executive::planned(const std::vector<RunSpec>& runs, std::uint64_t seed,
                                       rig::Shard shard) const {
  rig::CampaignResult result;
  result.campaign = campaign_.name;
  result.device = campaign_.points.empty() ? std::string() : campaign_.points.front().dut.model;
  result.campaign_sha256 = campaign_.sha256;
  result.campaign_file = campaign_.file;
  result.dut_serial = campaign_.points.empty() ? std::string() : campaign_.points.front().dut.serial;
  result.tool_version = rig::tool_version();
  result.seed = seed;
  result.shard = shard;
  result.planned_runs = runs.size();
  return result;
}

rig::CampaignResult Executive::run_all(const std::vector<RunSpec>& runs, std::uint64_t seed, rig::Shard shard,
                                       const Progress& progress, const TraceSink& sink,
                                       const Recorder& record) const {
  rig::CampaignResult result = planned(runs, seed, shard);
  for (std::size_t i = 0; i < runs.size(); ++i) {
    if (progress) progress(i, runs.size(), runs[i]);
    RunOutput out = run(runs[i]);
    // What the sink could not write (a trace on a full disk) is the run's rig error; its
    // judgement stands and is recorded, and so is every run before and after it: a write that
    // fails loses nothing already captured.
    if (sink) {
      try {
        out.result.trace = sink(runs[i], out);
      } catch (const std::exception& e) {
        out.result.trace.clear();
        if (out.result.error.empty())
          out.result.error = std::string("writing the run's evidence: ") + e.what();
      }
    }
    if (record)
      record(out.result);
    else
      result.runs.push_back(std::move(out.result));
    if (stop_ != nullptr && stop_->requested()) {
      result.interrupted = stop_->reason();
      break;
    }
  }
  rig::finalize(result);
  return result;
}

} // namespace hilrig::campaign
