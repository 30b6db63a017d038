#include "rig/campaign/plant_drive.hpp"

#include <limits>

#include "rig/campaign/rig_drive.hpp"
#include "rig/campaign/run_trace.hpp"
#include "rig/campaign/scenario_reader.hpp"

namespace hilrig::campaign {

namespace {

// An input change in the machine's words (a press valve is the clutch/brake solenoid).
std::string event_words(plants::PlantInput which, bool level) {
  switch (which) {
  case plants::PlantInput::Valve:
    return level ? "valve on: clutch engaged, brake released" : "valve off: brake applied, clutch released";
  case plants::PlantInput::MotorEnable:
    return level ? "motor enabled" : "motor disabled";
  case plants::PlantInput::Direction:
    return level ? "direction forward" : "direction reverse";
  case plants::PlantInput::Step:
    return "step";
  }
  return "input";
}

} // namespace

PlantDrive::PlantDrive(Scheduler& scheduler, const Scenario& scenario)
    : sched_(scheduler), s_(scenario), spec_(*scenario.plant),
      motion_(spec_, scenario.encoder.counts_per_turn(), scenario.end),
      encoder_(rig_encoder(scenario.encoder)), solver_(motion_.plan(), encoder_, scenario.end),
      grows_per_look_(spec_.kind == PlantKind::StepperLoad ? kGrowsPerLook : std::numeric_limits<int>::max()),
      valve_(spec_.kind != PlantKind::Press || spec_.press_start.valve) {
  count_ = encoder_.count_at(motion_.plan().position(motion_.plan().start_time()));
  checks::append_motion(counts_, {motion_.plan().start_time(), static_cast<double>(count_)});
  solver_.grow_with([this] {
    using Growth = signals::QuadratureEdgeSolver::Growth;
    if (grows_left_ == 0) return Growth::Later;
    --grows_left_;
    return motion_.grow() ? Growth::Grown : Growth::Whole;
  });
}

bool PlantDrive::drives(std::string_view rig) const {
  return is_encoder_line(rig) || (!spec_.valve_monitor.empty() && rig == spec_.valve_monitor);
}

bool PlantDrive::watches(std::string_view rig) const { return spec_.inputs.contains(rig); }

Level PlantDrive::initial_level(std::string_view rig) const {
  if (rig == kEncoderA) return level_of(signals::channel_a(count_));
  if (rig == kEncoderB) return level_of(signals::channel_b(count_));
  return level_of(valve_);
}

void PlantDrive::own(const std::string& rig, LineOutput& out) {
  if (rig == kEncoderA) enc_a_ = &out;
  if (rig == kEncoderB) enc_b_ = &out;
  if (rig == spec_.valve_monitor) monitor_ = &out;
}

void PlantDrive::watch(const std::string& rig, LineInput& in) {
  const plants::PlantInput which = spec_.inputs.find(rig)->second;
  watched_.emplace_back(which, &in);
  in.on_edge([this, which](const Edge& e) { apply(which, e.level == Level::High); });
}

void PlantDrive::start() {
  // A board output acts from time 0 with the level it starts at, whatever the plant's start
  // state says.
  for (const auto& [which, in] : watched_) apply(which, in->level() == Level::High);
  for (const PlantCommand& c : spec_.commands) {
    if (c.at > s_.end) continue;
    sched_.at(c.at, [this, c] { apply(c.input, c.level == Level::High); });
  }
  resolve();
}

void PlantDrive::apply(plants::PlantInput which, bool level) {
  const Nanos now = sched_.now();
  motion_.input(now, which, level);
  // Every step pulse would drown the plot: the steps show as the motion itself.
  auto& last = last_level_.at(static_cast<std::size_t>(which));
  if (which != plants::PlantInput::Step && last != level) events_.push_back({now, event_words(which, level)});
  last = level;
  if (which == plants::PlantInput::Valve) {
    valve_ = level;
    if (monitor_ != nullptr) monitor_->set(level_of(level));
  }
  resolve();
}

void PlantDrive::resolve() {
  ++generation_;
  // The old plan's pending events are dead (their generation checks would drop them).
  sched_.cancel(next_event_);
  sched_.cancel(extend_event_);
  next_event_ = extend_event_ = EventId{};
  solver_.restart();
  next_ = filled_ = 0;
  // The new plan starts where the old one was at this instant; a count that rounding puts
  // on the other side of an edge is set right here, once.
  const std::int64_t start = solver_.initial_count();
  if (start != count_) {
    count_ = start;
    if (shaft_ != nullptr) shaft_->count(sched_.now(), count_);
    checks::append_motion(counts_, {sched_.now(), static_cast<double>(count_)});
    if (enc_a_ != nullptr) enc_a_->set(level_of(signals::channel_a(count_)));
    if (enc_b_ != nullptr) enc_b_->set(level_of(signals::channel_b(count_)));
  }
  // The plan reaches a horizon: there it runs on (before any edge of that instant, which the
  // new plan's initial count covers). Its place is taken now; its event waits for extend_by().
  extend_owed_ = motion_.plan_end() < s_.end;
  if (extend_owed_) extend_place_ = sched_.reserve();
  schedule_next();
}

// Until the drive's next event reaches the horizon, that event runs first and looks again
// (or an input replaces the plan): the extension is scheduled before the scheduler can get
// to its place, and runs there as if scheduled when the plan began.
void PlantDrive::extend_by(Nanos next) {
  if (!extend_owed_ || next < motion_.plan_end()) return;
  extend_owed_ = false;
  extend_event_ = sched_.at(
      motion_.plan_end(),
      [this, g = generation_] {
        if (g != generation_) return;
        extend_event_ = EventId{};
        motion_.extend();
        resolve();
      },
      extend_place_);
}

void PlantDrive::schedule_next() {
  next_place_ = sched_.reserve();
  seek();
}

void PlantDrive::seek() {
  grows_left_ = grows_per_look_;
  next_event_ = EventId{};
  if (next_ == filled_) {
    filled_ = solver_.fill(buffer_);
    next_ = 0;
    if (filled_ == 0) {
      if (solver_.done()) {
        extend_by(Nanos::max());
        return;
      }
      // No edge in the plan so far: none before its end, where the search goes on. That
      // look runs in the edge's place, so an edge found at its instant runs where it would
      // have; an input before it replaces the plan and drops the look, as it would the edge.
      const Nanos look = motion_.plan().end_time();
      extend_by(look);
      next_event_ = sched_.at(
          look,
          [this, g = generation_] {
            if (g == generation_) seek();
          },
          next_place_);
      return;
    }
  }
  const Nanos at = buffer_[next_].time;
  extend_by(at);
  if (at > s_.end) return;
  next_event_ = sched_.at(
      at,
      [this, g = generation_] {
        if (g == generation_) play();
      },
      next_place_);
}

void PlantDrive::play() {
  const signals::QuadEdge e = buffer_[next_++];
  if (e.channel != signals::QuadChannel::Z) {
    count_ = e.count;
    if (shaft_ != nullptr) shaft_->count(e.time, count_);
    checks::append_motion(counts_, {e.time, static_cast<double>(count_)});
    LineOutput* line = e.channel == signals::QuadChannel::A ? enc_a_ : enc_b_;
    if (line != nullptr) line->set(e.level);
  }
  schedule_next();
}

std::vector<rig::MotionEvent> PlantDrive::events() const {
  std::vector<rig::MotionEvent> out = events_;
  for (const Nanos t : motion_.standstills()) out.push_back({t, "standstill (located by the plant)"});
  return out;
}

} // namespace hilrig::campaign
