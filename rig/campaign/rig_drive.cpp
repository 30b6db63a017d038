#include "rig/campaign/rig_drive.hpp"

#include <stdexcept>

#include "rig/campaign/executive.hpp"
#include "rig/campaign/run_trace.hpp"
#include "rig/campaign/scenario_reader.hpp"

namespace hilrig::campaign {

signals::QuadratureEncoder rig_encoder(const EncoderSpec& spec) {
  signals::QuadratureEncoder e;
  e.lines_per_turn = static_cast<std::uint32_t>(spec.lines);
  e.units_per_turn = spec.counts_per_turn();
  e.placement = signals::EdgePlacement::WholeCount;
  return e;
}

RigDrive::RigDrive(Scheduler& scheduler, const Scenario& scenario, const BuiltMotion& motion)
    : sched_(scheduler), s_(scenario), built_(motion),
      edges_(motion.profile, rig_encoder(scenario.encoder), scenario.end), count_(edges_.initial_count()) {
  for (const Move& m : s_.motion.moves)
    if (!m.brake_line.empty()) brake_level_[m.brake_line] = m.brake_level;
}

Level RigDrive::initial_level(std::string_view rig) const {
  if (rig == kEncoderA) return level_of(signals::channel_a(edges_.initial_count()));
  if (rig == kEncoderB) return level_of(signals::channel_b(edges_.initial_count()));
  if (const auto it = brake_level_.find(rig); it != brake_level_.end()) return !it->second;
  return Level::Low;
}

void RigDrive::own(const std::string& rig, LineOutput& out) { driven_[rig] = DrivenLine{&out, out.driven()}; }

LineOutput& RigDrive::source(const std::string& rig) {
  DrivenLine* d = find(rig);
  if (d == nullptr) throw std::logic_error("RigDrive::source: the drive does not own " + rig);
  d->sourced = true;
  return sources_.emplace_back(*this, rig, *d);
}

void RigDrive::Source::set(Level level) {
  if (level == level_) return; // the same level again is not an edge
  level_ = level;
  if (!drive_.lost(rig_, drive_.sched_.now())) line_.want(level);
}

RigDrive::DrivenLine* RigDrive::find(std::string_view rig) {
  const auto it = driven_.find(rig);
  return it == driven_.end() ? nullptr : &it->second;
}

RigDrive::DrivenLine* RigDrive::own_encoder(std::string_view rig) {
  DrivenLine* d = find(rig);
  return d != nullptr && !d->sourced ? d : nullptr;
}

bool RigDrive::lost(std::string_view rig, Nanos t) {
  bool lost = false;
  for (MissingEdges& m : missing_) {
    if (m.fault.line != rig || t < m.fault.at || t >= m.fault.until) continue;
    if (++m.seen % m.fault.every == 0) lost = true;
  }
  return lost;
}

void RigDrive::start(const std::vector<Stimulus>& faults, const std::optional<Stimulus>& probe,
                     bool record_motion) {
  record_motion_ = record_motion;
  enc_a_ = own_encoder(kEncoderA);
  enc_b_ = own_encoder(kEncoderB);
  checks::append_motion(motion_, {Nanos{0}, static_cast<double>(count_)});
  for (const Stimulus& f : faults)
    if (f.kind == StimulusKind::MissingEdges) missing_.push_back(MissingEdges{f, 0});
  for (const Stimulus& f : s_.stimuli)
    if (f.kind == StimulusKind::MissingEdges) missing_.push_back(MissingEdges{f, 0});
  next_edge_ = pull_edge();
  schedule_edge();

  for (const Stimulus& st : s_.stimuli) schedule(st);
  for (const Stimulus& st : faults) schedule(st);
  if (probe) schedule(*probe);
  for (const BrakeApplied& b : built_.brakes) {
    if (b.line.empty() || b.at > s_.end) continue;
    DrivenLine* d = find(b.line);
    if (d == nullptr) throw RigFault("brake on a line the rig does not drive: " + b.line);
    const Level l = brake_level_.at(b.line);
    sched_.at(b.at, [d, l] { d->want(l); });
  }
}

std::optional<signals::QuadEdge> RigDrive::pull_edge() {
  if (edge_next_ == edge_filled_) {
    edge_filled_ = edges_.fill(edge_buffer_);
    edge_next_ = 0;
    if (edge_filled_ == 0) return std::nullopt;
  }
  return edge_buffer_[edge_next_++];
}

void RigDrive::encoder_edge() {
  const signals::QuadEdge e = *next_edge_;
  count_ = e.count;
  if (shaft_ != nullptr) shaft_->count(e.time, count_);
  if (record_motion_) checks::append_motion(motion_, {e.time, static_cast<double>(e.count)});
  const bool on_a = e.channel == signals::QuadChannel::A;
  DrivenLine* line = on_a ? enc_a_ : enc_b_;
  if (!lost(on_a ? kEncoderA : kEncoderB, e.time) && line != nullptr) line->want(e.level);
  next_edge_ = pull_edge();
  schedule_edge();
}

void RigDrive::schedule_edge() {
  if (!next_edge_ || next_edge_->time > s_.end) return;
  if (heap_edges_)
    sched_.at(next_edge_->time, [this] { encoder_edge(); });
  else
    sched_.stream_at(*this, next_edge_->time);
}

void RigDrive::BounceTrain::schedule_next() {
  const std::int64_t k = next;
  sched->at(
      at + period * k,
      [this] {
        line->want(next % 2 == 0 ? level : !level);
        if (++next < edges) schedule_next();
      },
      Reservation{first.seq + static_cast<std::uint64_t>(k)});
}

void RigDrive::schedule(const Stimulus& st) {
  DrivenLine* d = find(st.line);
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
  case StimulusKind::Bounce: {
    // First contact at `at`; bounce k opens at at + (2k-1)*period and closes at at + 2k*period.
    const std::int64_t edges = 2 * st.edges + 1;
    trains_.push_back(BounceTrain{&sched_, d, l, st.at, st.period, edges,
                                  sched_.reserve_places(static_cast<std::uint64_t>(edges))});
    trains_.back().schedule_next();
    break;
  }
  case StimulusKind::Glitch:
    // The line inverted for the width, whatever the level it is wanted at meanwhile (a
    // source's edges inside the glitch come out inverted too).
    sched_.at(st.at, [d] {
      ++d->inverted;
      d->show();
    });
    sched_.at(st.at + st.width, [d] {
      --d->inverted;
      d->show();
    });
    break;
  case StimulusKind::Stuck:
    sched_.at(st.at, [d, l] {
      ++d->forced;
      d->out->set(l);
    });
    if (st.until != Nanos::max())
      sched_.at(st.until, [d] {
        --d->forced;
        d->show();
      });
    break;
  case StimulusKind::MissingEdges:
    break; // applied as the encoder plays its edges
  }
}

} // namespace hilrig::campaign
