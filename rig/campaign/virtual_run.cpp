#include "rig/campaign/virtual_run.hpp"

#include <algorithm>
#include <map>
#include <memory>

#include <fmt/format.h>

#include "core/scheduler.hpp"
#include "drivers/virtual/virtual_bus.hpp"
#include "rig/campaign/executive.hpp"
#include "rig/campaign/host_sequence.hpp"
#include "rig/campaign/motion.hpp"
#include "rig/campaign/plant_drive.hpp"
#include "rig/campaign/resolver_link.hpp"
#include "rig/campaign/resolver_stators.hpp"
#include "rig/campaign/rig_drive.hpp"
#include "rig/campaign/run_trace.hpp"
#include "rig/campaign/scenario_reader.hpp"
#include "rig/duts/dut.hpp"
#include "signals/quadrature_waveform.hpp"
#include "signals/ssi_slave.hpp"
#include "signals/ssi_slave_node.hpp"

namespace hilrig::campaign {

namespace {

duts::DutParams dut_params(const duts::DutInfo& info, const DutSpec& spec) {
  std::map<std::string, duts::ParamValue, std::less<>> given;
  for (const auto& [name, p] : spec.params) given[name] = p.value;
  return info.with_defaults(given);
}

// The virtual DUT's host interface as the host sequence's words.
class DutWords final : public HostWords {
public:
  explicit DutWords(duts::Dut& dut) : dut_(dut) {}
  void write(std::size_t word, std::uint16_t value) override { dut_.host_write(word, value); }
  std::uint16_t read(std::size_t word) override { return dut_.host_read(word); }

private:
  duts::Dut& dut_;
};

class Simulation {
public:
  explicit Simulation(const RunInputs& in)
      : in_(in), s_(*in.scenario), trace_(std::make_shared<TraceRecorder>()), bus_(sched_, trace_.get()),
        motion_(build_motion("", s_.motion, s_.encoder)), drive_(sched_, s_, motion_) {
    // The encoder alone is ~10^5 edges a second: beyond 2 MiB of samples the trace goes to a
    // temporary file (read back for the VCD and the checks), so memory does not grow with the
    // run (core/trace.hpp, kTraceHeldSamples).
    trace_->spill_beyond(kTraceHeldSamples);
    // The lines the checks read (the executive's capture, a debounce probe's output) kept as
    // edges while recorded: reading them reads no spilled sample back.
    std::vector<std::string> checked_lines;
    for (const CheckSpec& check : s_.checks)
      for (std::string& line : checks::lines_of(check.params)) checked_lines.push_back(std::move(line));
    trace_->keep_edges_of(checked_lines);
    if (s_.plant) plant_ = std::make_unique<PlantDrive>(sched_, s_);
  }

  VirtualRun run() {
    if (s_.dut.backend != "virtual" || s_.dut.model == "external")
      throw RigFault(fmt::format("backend \"{}\" is not available in this build: only \"virtual\" runs",
                                 s_.dut.backend));
    const duts::DutInfo* info = duts::find_dut(s_.dut.model);
    if (info == nullptr) throw RigFault("no DUT model " + s_.dut.model);
    // Until the board is attached, what it and the rig's sources drive is where the lines
    // start: a board output's power-up level is its initial level, not an edge at 0.
    bus_.set_powering_up(true);
    make_lines();
    drive_resolver();
    drive_ssi();
    dut_ = info->make(sched_, dut_params(*info, s_.dut), in_.variant, in_.seed);
    if (in_.exact_scan) {
      dut_->scan_every_period();
      drive_.edges_as_heap_events();
    }
    sample_encoder();
    std::map<std::string, std::string, std::less<>> pins;
    for (const Wire& w : s_.wiring) pins[w.board] = w.rig;
    dut_->attach(bus_, pins);
    bus_.set_powering_up(false);
    schedule_board_faults();
    schedule_power_cycles();
    for (const PanelEvent& p : s_.panel) sched_.at(p.at, [this, i = p.action] { dut_->panel(i); });

    trace_shaft();
    drive_.start(in_.faults, in_.probe, in_.record_motion);
    if (plant_) plant_->start();
    if (in_.host_link != nullptr && *in_.host_link && !s_.host.empty())
      words_ = (*in_.host_link)(*dut_, *info);
    else
      words_ = std::make_unique<DutWords>(*dut_);
    traced_words_ = std::make_unique<TracedHostWords>(*words_, sched_, *trace_, info->host, s_.host);
    host_ = std::make_unique<HostSequence>(sched_, s_, info->host, *traced_words_);
    host_->start();

    const Nanos end = play();
    if (plant_) {
      // The shaft as the plant moved it: its last change is the located standstill.
      out_.motion = plant_->motion().samples();
      out_.counts = plant_->counts();
      out_.profile = plant_->take_trajectory();
      out_.motion_events = plant_->events();
    } else {
      out_.motion = std::move(drive_.motion());
      checks::append_motion(out_.motion, {end, static_cast<double>(drive_.count())});
      out_.profile = motion_.profile;
    }
    out_.observations = std::move(host_->observations());
    out_.handshakes = std::move(host_->handshakes());
    out_.trace = trace_;
    return std::move(out_);
  }

private:
  void make_lines() {
    for (const Wire& w : s_.wiring) {
      if (w.analog) continue; // an analog channel, not a line
      // A line a plant or the [ssi] transducer synthesizes goes through the drive too, so a
      // signal fault on it overrides the source (RigDrive::source).
      if (plant_ && plant_->drives(w.rig)) {
        virt::DigitalLine& line = bus_.line(w.rig, plant_->initial_level(w.rig));
        drive_.own(w.rig, line.driver());
        plant_->own(w.rig, drive_.source(w.rig));
        owned_.push_back(&line.driver());
        continue;
      }
      if (w.rig == s_.ssi.data_line) { // the transducer's (drive_ssi), idle high
        virt::DigitalLine& line = bus_.line(w.rig, Level::High);
        drive_.own(w.rig, line.driver());
        owned_.push_back(&line.driver());
        continue;
      }
      virt::DigitalLine& line = bus_.line(w.rig, drive_.initial_level(w.rig));
      if (plant_ && plant_->watches(w.rig)) plant_->watch(w.rig, line.reader());
      if (w.direction == duts::PinDirection::Input) {
        drive_.own(w.rig, line.driver());
        owned_.push_back(&line.driver());
      }
    }
  }

  // When the encoder lines carry the motion's edges unchanged (no plant, no stimulus or fault
  // on them), a DUT that only samples the count may read it from the motion's waveform.
  // The oracle (--exact-scan) keeps taking every edge.
  void sample_encoder() {
    if (plant_ || in_.exact_scan) return;
    const auto on_encoder = [](const Stimulus& st) { return is_encoder_line(st.line); };
    if (std::any_of(s_.stimuli.begin(), s_.stimuli.end(), on_encoder) ||
        std::any_of(in_.faults.begin(), in_.faults.end(), on_encoder) ||
        (in_.probe && on_encoder(*in_.probe)))
      return;
    encoder_ =
        std::make_unique<signals::QuadratureWaveform>(motion_.profile, rig_encoder(s_.encoder), s_.end);
    dut_->sample_encoder(std::string(kEncoderA), std::string(kEncoderB), *encoder_);
  }

  // Plays the events to the end; returns the time the run ended. A stop request or a
  // tripped guard (both checked before each event: run_guards.hpp) or a failure inside an event (a host link
  // that lost a transaction, a model that threw) ends it early: every line the rig drives goes to its
  // inactive level at that virtual time (so the trace shows it), and out_.rig_fault says why.
  Nanos play() {
    ProgressGuard guard(in_.guards);
    try {
      for (Nanos next = sched_.next_time(); next <= s_.end; next = sched_.next_time()) {
        if (in_.stop != nullptr && in_.stop->requested()) {
          stop_early("interrupted by " + in_.stop->reason(), true);
          return sched_.now();
        }
        if (const auto fault = guard.check(next, trace_->sample_count())) {
          stop_early(*fault, false);
          return sched_.now();
        }
        sched_.step();
      }
      sched_.run_until(s_.end);
      return s_.end;
    } catch (const std::exception& e) {
      stop_early(e.what(), false);
      return sched_.now();
    }
  }

  // The inactive level of a rig-driven line is low: gpiod's "inactive" (an active-low wire
  // is electrically high), a discrete input off, a brake line applied.
  void stop_early(const std::string& why, bool interrupted) {
    out_.interrupted = interrupted;
    out_.rig_fault =
        fmt::format("{} at {:.3f} ms virtual time", why, static_cast<double>(sched_.now().count()) / 1e6);
    try {
      for (LineOutput* line : owned_) line->set(Level::Low);
    } catch (const std::exception& e) {
      out_.rig_fault += fmt::format("; driving the lines inactive failed: {}", e.what());
    }
  }

  // The shaft's count in the trace, from whichever turns it (a plant or the motion).
  void trace_shaft() {
    const double per_turn = s_.encoder.counts_per_turn();
    if (plant_) {
      shaft_ = std::make_unique<ShaftTrace>(*trace_, per_turn, plant_->count());
      plant_->trace_shaft(shaft_.get());
    } else {
      shaft_ = std::make_unique<ShaftTrace>(*trace_, per_turn, drive_.count());
      drive_.trace_shaft(shaft_.get());
    }
  }

  // The stators through the rig's resolver front end (resolver_link.hpp): the shaft streamed
  // over CAN to the emulator node, whose angle they carry.
  void drive_resolver() {
    const ResolverSpec& r = s_.resolver;
    if (r.sin_line.empty()) return;
    using models::resolver_emulator::ShaftSample;
    models::resolver_emulator::ShaftSource shaft;
    if (plant_) {
      // The plant's motion as it happens: the history before its last input, the plan after (a
      // frame sent now carries the plan's angle a frame time ahead, as a real rig's would).
      shaft = [motion = &plant_->motion()](Nanos t) {
        return ShaftSample{motion->position(t), motion->velocity(t)};
      };
    } else {
      shaft = [profile = std::make_shared<const signals::MotionProfile>(motion_.profile)](Nanos t) {
        return ShaftSample{profile->position(t), profile->velocity(t)};
      };
    }
    const ShaftSample at_start = shaft(Nanos{0});
    resolver_ = std::make_unique<ResolverLink>(sched_, bus_, std::move(shaft), s_.encoder.counts_per_turn());
    const auto [sin, cos] = resolver_->stators(r, stator_fault_windows(s_, Stator::Sine),
                                               stator_fault_windows(s_, Stator::Cosine));
    // The stators follow the node's frames: each frame revises them from its arrival on.
    virt::AnalogChannel& sin_channel = bus_.analog(r.sin_line);
    virt::AnalogChannel& cos_channel = bus_.analog(r.cos_line);
    sin_channel.set_waveform(sin, virt::AnalogChannel::Future::Revised);
    cos_channel.set_waveform(cos, virt::AnalogChannel::Future::Revised);
    resolver_->on_frame([&sin_channel, &cos_channel] {
      sin_channel.revise();
      if (&cos_channel != &sin_channel) cos_channel.revise();
    });
    stator_trace_ = trace_stators(sched_, *trace_, r, sin, cos, s_.end);
    resolver_->start(at_start);
  }

  // The [ssi] transducer answers the board's clock with the shaft's position: the plant's
  // angle as it moved (what it reads at a latch has happened), or the motion's.
  void drive_ssi() {
    const SsiSpec& spec = s_.ssi;
    if (spec.data_line.empty()) return;
    const double per_turn = s_.encoder.counts_per_turn();
    std::function<double(Nanos)> turns;
    if (plant_) {
      turns = [motion = &plant_->motion(), per_turn](Nanos t) { return motion->position(t) / per_turn; };
    } else {
      const auto profile = std::make_shared<const signals::MotionProfile>(motion_.profile);
      turns = [profile, per_turn](Nanos t) { return profile->position(t) / per_turn; };
    }
    signals::SsiSlaveParams params;
    params.format = spec.format;
    params.monoflop = spec.monoflop;
    ssi_ =
        std::make_unique<signals::SsiSlave>(params, signals::counts_from_turns(turns, spec.counts_per_turn));
    ssi_node_ = std::make_unique<signals::SsiSlaveNode>(sched_, *ssi_, bus_.line(spec.clock_line).reader(),
                                                        drive_.source(spec.data_line));
  }

  // [[device_fault]] of the board itself: the model raises it at `at`, its condition ends at
  // `until` (the resolver faults are in the stator waveforms).
  void schedule_board_faults() {
    for (const DeviceFaultEvent& f : s_.device_faults) {
      if (f.site != duts::FaultSite::Board) continue;
      sched_.at(f.at, [this, i = f.fault] { dut_->device_fault(i, true); });
      if (f.until <= s_.end) sched_.at(f.until, [this, i = f.fault] { dut_->device_fault(i, false); });
    }
  }

  // [[power_cycle]]: the supply off at `at`, back on `off` later (if within the run).
  void schedule_power_cycles() {
    for (const PowerCycleEvent& p : s_.power_cycles) {
      sched_.at(p.at, [this] { dut_->power(false); });
      if (p.on_at() <= s_.end) sched_.at(p.on_at(), [this] { dut_->power(true); });
    }
  }

  const RunInputs& in_;
  const Scenario& s_;
  Scheduler sched_;
  std::shared_ptr<TraceRecorder> trace_;
  virt::VirtualBus bus_;
  BuiltMotion motion_;
  RigDrive drive_;
  std::unique_ptr<PlantDrive> plant_;                    // when a plant turns the shaft
  std::unique_ptr<signals::QuadratureWaveform> encoder_; // sampled by the DUT (sample_encoder)
  std::unique_ptr<duts::Dut> dut_;
  std::unique_ptr<ResolverLink> resolver_; // the resolver front end, when the board reads one
  std::shared_ptr<void> stator_trace_;     // samples the stators into the trace (trace_stators)
  std::unique_ptr<signals::SsiSlave> ssi_; // the [ssi] transducer, on its lines
  std::unique_ptr<signals::SsiSlaveNode> ssi_node_;
  std::vector<LineOutput*> owned_; // the lines the rig drives
  std::unique_ptr<HostWords> words_;
  std::unique_ptr<ShaftTrace> shaft_;
  std::unique_ptr<TracedHostWords> traced_words_;
  std::unique_ptr<HostSequence> host_;
  VirtualRun out_;
};

} // namespace

VirtualRun run_virtual(const RunInputs& inputs) {
  if (inputs.scenario == nullptr) throw RigFault("no scenario");
  Simulation sim(inputs);
  return sim.run();
}

} // namespace hilrig::campaign
