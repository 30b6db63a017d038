#include "rig/campaign/virtual_run.hpp"

#include <map>
#include <memory>

#include <fmt/format.h>

#include "core/scheduler.hpp"
#include "drivers/virtual/virtual_bus.hpp"
#include "rig/campaign/executive.hpp"
#include "rig/campaign/motion.hpp"
#include "rig/campaign/quadrature_edges.hpp"
#include "rig/campaign/resolver_stators.hpp"
#include "rig/campaign/scenario_reader.hpp"
#include "rig/checks/support.hpp"
#include "rig/duts/dut.hpp"

namespace hilrig::campaign {

namespace {

// A line the rig drives: the level the stimulus wants, and faults that override it.
struct DrivenLine {
  LineOutput* out = nullptr;
  Level intended = Level::Low;
  int forced = 0; // stuck faults in force
  void want(Level l) {
    intended = l;
    if (forced == 0) out->set(l);
  }
};

duts::DutParams dut_params(const duts::DutInfo& info, const DutSpec& spec) {
  std::map<std::string, duts::ParamValue, std::less<>> given;
  for (const auto& [name, p] : spec.params) given[name] = p.value;
  return info.with_defaults(given);
}

class Simulation {
public:
  explicit Simulation(const RunInputs& in)
      : in_(in), s_(*in.scenario), trace_(std::make_shared<TraceRecorder>()), bus_(sched_, trace_.get()),
        motion_(build_motion("", s_.motion, s_.encoder)), edges_(motion_.profile) {}

  VirtualRun run() {
    if (s_.dut.backend != "virtual" || s_.dut.model == "external")
      throw RigFault(fmt::format("backend \"{}\" is not available in this build: only \"virtual\" runs",
                                 s_.dut.backend));
    const duts::DutInfo* info = duts::find_dut(s_.dut.model);
    if (info == nullptr) throw RigFault("no DUT model " + s_.dut.model);
    host_ = info->host;
    make_lines();
    drive_resolver();
    dut_ = info->make(sched_, dut_params(*info, s_.dut), in_.variant, in_.seed);
    std::map<std::string, std::string, std::less<>> pins;
    for (const Wire& w : s_.wiring) pins[w.board] = w.rig;
    dut_->attach(bus_, pins);

    schedule_encoder();
    for (const Stimulus& st : s_.stimuli) schedule(st);
    for (const Stimulus& st : in_.faults) schedule(st);
    if (in_.probe) schedule(*in_.probe);
    for (const BrakeApplied& b : motion_.brakes) {
      if (b.line.empty() || b.at > s_.end) continue;
      DrivenLine* d = &driven_.at(b.line);
      const Level l = brake_level_.at(b.line);
      sched_.at(b.at, [d, l] { d->want(l); });
    }
    if (!s_.host.empty()) sched_.at(s_.host.front().at, [this] { host_step(); });

    sched_.run_until(s_.end);
    out_.motion.push_back({s_.end, static_cast<double>(count_)});
    out_.trace = trace_;
    out_.profile = motion_.profile;
    return std::move(out_);
  }

private:
  void make_lines() {
    const std::int64_t start = edges_.start_count();
    count_ = start;
    for (const Move& m : s_.motion.moves)
      if (!m.brake_line.empty()) brake_level_[m.brake_line] = m.brake_level;
    for (const Wire& w : s_.wiring) {
      if (w.analog) continue; // an analog channel, not a line
      Level initial = Level::Low;
      if (w.rig == kEncoderA) initial = a_level(start);
      if (w.rig == kEncoderB) initial = b_level(start);
      if (const auto it = brake_level_.find(w.rig); it != brake_level_.end()) initial = !it->second;
      virt::DigitalLine& line = bus_.line(w.rig, initial);
      if (w.direction == duts::PinDirection::Input) driven_[w.rig] = DrivenLine{&line.driver(), initial, 0};
    }
    enc_a_ = find_driven(kEncoderA);
    enc_b_ = find_driven(kEncoderB);
  }

  void drive_resolver() {
    const ResolverSpec& r = s_.resolver;
    if (r.sin_line.empty()) return;
    const auto profile = std::make_shared<const signals::MotionProfile>(motion_.profile);
    const double per_turn = s_.encoder.counts_per_turn();
    bus_.analog(r.sin_line).set_waveform(stator_waveform(profile, per_turn, r, Stator::Sine));
    bus_.analog(r.cos_line).set_waveform(stator_waveform(profile, per_turn, r, Stator::Cosine));
  }

  DrivenLine* find_driven(std::string_view rig) {
    const auto it = driven_.find(rig);
    return it == driven_.end() ? nullptr : &it->second;
  }

  void schedule_encoder() {
    out_.motion.push_back({Nanos{0}, static_cast<double>(count_)});
    for (const Stimulus& f : in_.faults)
      if (f.kind == StimulusKind::MissingEdges) missing_.push_back(MissingEdges{&f, 0});
    for (const Stimulus& f : s_.stimuli)
      if (f.kind == StimulusKind::MissingEdges) missing_.push_back(MissingEdges{&f, 0});
    next_edge_ = edges_.next();
    if (next_edge_ && next_edge_->time <= s_.end) sched_.at(next_edge_->time, [this] { encoder_edge(); });
  }

  void encoder_edge() {
    const CountEdge e = *next_edge_;
    count_ = e.count;
    if (in_.record_motion) out_.motion.push_back({e.time, static_cast<double>(e.count)});
    DrivenLine* line = e.on_a ? enc_a_ : enc_b_;
    const std::string_view name = e.on_a ? kEncoderA : kEncoderB;
    bool lost = false;
    for (MissingEdges& m : missing_) {
      if (m.fault->line != name || e.time < m.fault->at || e.time >= m.fault->until) continue;
      if (++m.seen % m.fault->every == 0) lost = true;
    }
    if (line != nullptr && !lost) line->want(e.level);
    next_edge_ = edges_.next();
    if (next_edge_ && next_edge_->time <= s_.end) sched_.at(next_edge_->time, [this] { encoder_edge(); });
  }

  void schedule(const Stimulus& st) {
    DrivenLine* d = find_driven(st.line);
    if (d == nullptr) throw RigFault("stimulus on a line the rig does not drive: " + st.line);
    const Level l = st.level;
    switch (st.kind) {
    case StimulusKind::Level:
      sched_.at(st.at, [d, l] { d->want(l); });
      break;
    case StimulusKind::Pulse:
      sched_.at(st.at, [d, l] { d->want(l); });
      sched_.at(st.at + st.width, [d, l] { d->want(!l); });
      break;
    case StimulusKind::Bounce:
      // First contact at `at`; bounce k opens at at + (2k-1)*period and closes at at + 2k*period.
      sched_.at(st.at, [d, l] { d->want(l); });
      for (std::int64_t k = 1; k <= st.edges; ++k) {
        sched_.at(st.at + st.period * (2 * k - 1), [d, l] { d->want(!l); });
        sched_.at(st.at + st.period * (2 * k), [d, l] { d->want(l); });
      }
      break;
    case StimulusKind::Glitch:
      sched_.at(st.at, [d] {
        if (d->forced == 0) d->out->set(!d->intended);
      });
      sched_.at(st.at + st.width, [d] {
        if (d->forced == 0) d->out->set(d->intended);
      });
      break;
    case StimulusKind::Stuck:
      sched_.at(st.at, [d, l] {
        ++d->forced;
        d->out->set(l);
      });
      if (st.until != Nanos::max())
        sched_.at(st.until, [d] {
          if (--d->forced == 0) d->out->set(d->intended);
        });
      break;
    case StimulusKind::MissingEdges:
      break; // applied as the encoder plays its edges
    }
  }

  // Host actions run one after another; each starts at its time or when the one before
  // it has finished its handshake, whichever is later.
  void host_step() {
    const HostAction& h = s_.host[host_next_];
    if (h.kind == HostAction::Kind::Read) {
      const std::uint16_t raw = dut_->host_read(h.word);
      const double value =
          h.is_signed ? static_cast<double>(static_cast<std::int16_t>(raw)) : static_cast<double>(raw);
      out_.observations.push_back(rig::Observation{h.name, value, h.unit, sched_.now()});
      host_done();
      return;
    }
    for (std::size_t w = h.words.size(); w-- > 1;) dut_->host_write(w, h.words[w]);
    dut_->host_write(0, h.words[0]);
    if (!host_.handshake) {
      host_done();
      return;
    }
    write_started_ = sched_.now();
    dut_->host_write(0, static_cast<std::uint16_t>(h.words[0] | (1U << host_.transmit_bit)));
    sched_.after(s_.host_poll, [this] { host_poll_ack(true); });
  }

  bool ack() const {
    return ((static_cast<unsigned>(dut_->host_read(0)) >> host_.acknowledge_bit) & 1U) != 0U;
  }

  void host_poll_ack(bool want) {
    const HostAction& h = s_.host[host_next_];
    const Nanos waited = sched_.now() - write_started_;
    const std::string name =
        fmt::format("host.{}.ack", h.name.empty() ? fmt::format("write{}", host_next_) : h.name);
    if (ack() == want) {
      if (want) {
        out_.handshakes.push_back(
            checks::measure(name, checks::to_us(waited), "us", std::nullopt, checks::to_us(h.timeout),
                            fmt::format("Acknowledge {} after Transmit (polled every {} us)", "set",
                                        checks::to_us(s_.host_poll)),
                            rig::TraceWindow{write_started_, sched_.now()}));
        dut_->host_write(0, h.words[0]);
        write_started_ = sched_.now();
        sched_.after(s_.host_poll, [this] { host_poll_ack(false); });
      } else {
        host_done();
      }
      return;
    }
    if (waited >= h.timeout) {
      out_.handshakes.push_back(
          checks::failure(want ? name : name + "_clear",
                          fmt::format("no Acknowledge {} within {} us of {} Transmit", want ? "set" : "clear",
                                      checks::to_us(h.timeout), want ? "setting" : "clearing"),
                          rig::TraceWindow{write_started_, sched_.now()}));
      if (want) dut_->host_write(0, h.words[0]);
      host_done();
      return;
    }
    sched_.after(s_.host_poll, [this, want] { host_poll_ack(want); });
  }

  void host_done() {
    if (++host_next_ >= s_.host.size()) return;
    const Nanos at = std::max(sched_.now(), s_.host[host_next_].at);
    if (at > s_.end) return;
    sched_.at(at, [this] { host_step(); });
  }

  struct MissingEdges {
    const Stimulus* fault;
    std::int64_t seen;
  };

  const RunInputs& in_;
  const Scenario& s_;
  Scheduler sched_;
  std::shared_ptr<TraceRecorder> trace_;
  virt::VirtualBus bus_;
  BuiltMotion motion_;
  QuadratureEdges edges_;
  std::unique_ptr<duts::Dut> dut_;
  duts::HostInterface host_;
  std::map<std::string, DrivenLine, std::less<>> driven_;
  std::map<std::string, Level, std::less<>> brake_level_;
  DrivenLine* enc_a_ = nullptr;
  DrivenLine* enc_b_ = nullptr;
  std::optional<CountEdge> next_edge_;
  std::vector<MissingEdges> missing_;
  std::int64_t count_ = 0;
  std::size_t host_next_ = 0;
  Nanos write_started_{0};
  VirtualRun out_;
};

} // namespace

VirtualRun run_virtual(const RunInputs& inputs) {
  if (inputs.scenario == nullptr) throw RigFault("no scenario");
  Simulation sim(inputs);
  return sim.run();
}

} // namespace hilrig::campaign
