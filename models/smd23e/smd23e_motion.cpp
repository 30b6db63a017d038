// Motion engine of the virtual SMD23E: moves, stops, homing, assembled moves, inputs and
// the shaft plant (spec §3, §4, §5).
#include <algorithm>
#include <cmath>
#include <limits>

#include "models/smd23e/multiword.hpp"
#include "models/smd23e/smd23e.hpp"

namespace hilrig::models::smd23e {

namespace {
constexpr double kInf = std::numeric_limits<double>::infinity();
constexpr double kEps = 1e-6; // steps: absorbs floating error in a planned total of whole steps
constexpr std::int32_t kMaxTarget = 8'388'607;

// Steps issued by a progress: the whole steps it reaches(), the same rule as the step's due
// time (Motion::time_at_progress), so a step is issued at t exactly when it is due at or before
// t. A stop just before a step is due issues none (L976–980: the step train stops at once).
std::int64_t whole(double progress) {
  const double below = std::floor(progress);
  return static_cast<std::int64_t>(below) + (reaches(progress, below + 1.0) ? 1 : 0);
}
// A planned total (a move of n steps, an encoder move's stop point) in whole steps.
std::int64_t planned_whole(double total) { return static_cast<std::int64_t>(std::floor(total + kEps)); }

std::int64_t floor_div(std::int64_t a, std::int64_t b) {
  const std::int64_t q = a / b;
  return (a % b != 0 && ((a < 0) != (b < 0))) ? q - 1 : q;
}

// The progress of a run at t. Where its motion has run to its planned end, the total is snapped
// to the whole step it was planned as (a move's n steps, a registration's last step): its sum
// of pieces may fall an ulp short, and that last step is due at the end.
double run_progress(const ShaftRun& r, Nanos t) {
  const Nanos at = std::min(t, r.stop);
  const double p = r.base + r.motion.progress(at);
  if (at < r.motion.end()) return p;
  const double w = std::round(p);
  return std::abs(p - w) <= kEps ? w : p;
}
std::int64_t issued_at(const ShaftRun& r, Nanos t) {
  return r.issued_before + whole(run_progress(r, t)) - whole(r.base);
}
} // namespace

// ---- Plant -----------------------------------------------------------------------------------

std::int64_t Smd23e::step_position(Nanos t) const {
  for (auto it = runs_.rbegin(); it != runs_.rend(); ++it) {
    if (it->motion.start() <= t) {
      return it->origin + it->dir * whole(run_progress(*it, t));
    }
  }
  return 0;
}

std::int64_t Smd23e::shaft_steps(Nanos t) const {
  if (shaft_blocked_) {
    return shaft_frozen_;
  }
  std::int64_t lost = 0;
  if (p_.fault == Fault::LostSteps) {
    for (auto it = runs_.rbegin(); it != runs_.rend(); ++it) {
      if (it->motion.start() <= t) {
        const std::int64_t n = std::max<std::int64_t>(1, p_.lost_step_interval);
        lost =
            it->lost_before + it->dir * (floor_div(issued_at(*it, t), n) - floor_div(it->issued_before, n));
        break;
      }
    }
  }
  return step_position(t) - lost - slip_;
}

std::int64_t Smd23e::motor_position() const { return step_position(sched_.now()) + reg_offset_; }

std::int64_t Smd23e::encoder_position() const {
  if (!p_.has_encoder || steps_per_turn() == 0) {
    return 0;
  }
  if (shaft_encoder_) return shaft_encoder_->count() + enc_offset_;
  // [A] counts = shaft steps × 1024 / steps per turn (spec §2.3).
  return floor_div(shaft_steps(sched_.now()) * 1024, steps_per_turn()) + enc_offset_;
}

void Smd23e::connect_encoder(LineInput& a, LineInput& b) {
  shaft_encoder_.emplace(signals::CountMode::X4, is_high(a.level()), is_high(b.level()));
  const auto edge = [this, &a, &b](const Edge&) {
    shaft_encoder_->update(is_high(a.level()), is_high(b.level()));
    watch_encoder();
  };
  a.on_edge(edge);
  b.on_edge(edge);
}

void Smd23e::watch_encoder() {
  const bool enabled = encoder_enabled() && (cfg_.words[0] & ccw::kStallEnable) != 0;
  if (!shaft_encoder_ || !enabled || !run_ || steps_per_turn() == 0) return;
  // [A §2.3] the encoder disagrees when it is more than the threshold from the counts the
  // steps issued should have turned, both counted from where this move set off (L1255).
  const std::int64_t expected =
      floor_div((step_position(sched_.now()) - watch_steps_) * 1024, steps_per_turn());
  const auto lag = static_cast<double>(std::abs(expected - (shaft_encoder_->count() - watch_count_)));
  if (lag <= p_.stall_threshold_counts) return;
  immediate_stop(); // [A] a stall is an immediate stop
  set_error(stall_);
  pos_invalid_ = true;
}

void Smd23e::block_shaft(bool blocked) {
  if (blocked == shaft_blocked_) {
    return;
  }
  const std::int64_t here = shaft_steps(sched_.now());
  if (blocked) {
    shaft_frozen_ = here;
    shaft_blocked_ = true;
    schedule_stall_check();
  } else {
    shaft_blocked_ = false;
    slip_ += shaft_steps(sched_.now()) - shaft_frozen_;
  }
}

void Smd23e::over_temperature() {
  const bool drive =
      configured_ && (cfg_.words[1] & cfgw::kDriverEnable) != 0 && (out_[1] & lsw::kDriveEnable) != 0;
  if (!drive) {
    return;
  }
  set_error(drv_fault_); // motor power removed (L565, L2892)
  if (run_ || pause_event_.valid()) {
    immediate_stop();
    pos_invalid_ = true;
  }
}

void Smd23e::set_over_temperature(bool hot) {
  hot_ = hot;
  if (hot) {
    over_temperature();
  }
}

void Smd23e::network_link(bool up) {
  if (!up) {
    if (run_ || pause_event_.valid()) {
      immediate_stop(); // [A] motion stops on link loss
      pos_invalid_ = true;
    }
    return;
  }
  net_loss_ = true;
  set_error(in_err_);
  pos_invalid_ = true;
}

// ---- Motion engine ---------------------------------------------------------------------------

double Smd23e::progress() const { return run_progress(runs_.back(), sched_.now()); }

double Smd23e::velocity() const { return runs_.back().motion.velocity(sched_.now()); }

Nanos Smd23e::next_step_time(Nanos now) const {
  if (!run_ || runs_.empty()) return Nanos::max();
  const ShaftRun& r = runs_.back();
  const double k = static_cast<double>(whole(run_progress(r, now))) + 1.0;
  const Nanos t = r.motion.time_at_progress(k, r.base);
  if (t != Nanos::max()) return t;
  // A total an ulp short of its last whole step: run_progress snaps it at the motion's end.
  const Nanos end = r.motion.end();
  return end != Nanos::max() && end > now && run_progress(r, end) >= k ? end : Nanos::max();
}

void Smd23e::start_motion(Run run, std::vector<Piece> pieces, int dir) {
  const Nanos now = sched_.now();
  watch_steps_ = step_position(now); // the stall watch starts afresh with each move (L1255)
  watch_shaft_ = shaft_steps(now);
  watch_count_ = shaft_encoder_ ? shaft_encoder_->count() : 0;
  ShaftRun sr;
  sr.origin = step_position(now);
  sr.dir = dir;
  if (!runs_.empty()) {
    const ShaftRun& last = runs_.back();
    sr.issued_before = issued_at(last, now);
    const std::int64_t n = std::max<std::int64_t>(1, p_.lost_step_interval);
    sr.lost_before =
        last.lost_before + last.dir * (floor_div(sr.issued_before, n) - floor_div(last.issued_before, n));
  }
  sr.motion = Motion(now, std::move(pieces), 1.0 + p_.step_clock_error);
  runs_.push_back(std::move(sr));
  keep_recent_runs();
  run.dir = dir;
  run_ = std::move(run);
  const Nanos end = runs_.back().motion.end();
  sched_.cancel(end_event_);
  if (end != Nanos::max()) {
    end_event_ = sched_.at(end, [this] { on_motion_end(); });
  }
  schedule_stall_check();
}

void Smd23e::continue_motion(std::vector<Piece> pieces) {
  const Nanos now = sched_.now();
  ShaftRun& last = runs_.back();
  ShaftRun sr;
  sr.origin = last.origin;
  sr.dir = last.dir;
  sr.base = run_progress(last, now);
  sr.issued_before = issued_at(last, now);
  const std::int64_t n = std::max<std::int64_t>(1, p_.lost_step_interval);
  sr.lost_before =
      last.lost_before + last.dir * (floor_div(sr.issued_before, n) - floor_div(last.issued_before, n));
  last.stop = now;
  sr.motion = Motion(now, std::move(pieces), 1.0 + p_.step_clock_error);
  runs_.push_back(std::move(sr));
  keep_recent_runs();
  const Nanos end = runs_.back().motion.end();
  sched_.cancel(end_event_);
  end_event_ = {};
  if (end != Nanos::max()) {
    end_event_ = sched_.at(end, [this] { on_motion_end(); });
  }
  schedule_stall_check();
}

void Smd23e::keep_recent_runs() {
  if (runs_.size() > kKeptRuns) {
    runs_.erase(runs_.begin(), runs_.end() - static_cast<std::ptrdiff_t>(kKeptRuns));
  }
}

void Smd23e::end_motion(Nanos at) {
  if (pending_idle_percent_) {
    idle_percent_ = pending_idle_percent_; // the end of the first move after re-configuration
    pending_idle_percent_.reset();
  }
  if (!runs_.empty()) {
    ShaftRun& last = runs_.back();
    last.stop = std::min(last.stop, at);
  }
  sched_.cancel(end_event_);
  sched_.cancel(aux_event_);
  sched_.cancel(stall_event_);
  end_event_ = aux_event_ = stall_event_ = {};
  last_motion_end_ = at;
}

void Smd23e::immediate_stop() {
  end_motion(sched_.now());
  sched_.cancel(pause_event_);
  pause_event_ = {};
  run_.reset();
  held_.reset();
  hold_state_ = false;
}

void Smd23e::controlled_stop(bool hold) {
  Run& r = *run_;
  r.stopping = true;
  r.holding = hold;
  sched_.cancel(aux_event_);
  aux_event_ = {};
  MoveSpec spec = r.spec;
  if (r.kind == Kind::Blend) {
    // A blend move stops at the deceleration of the segment it is in (L1138).
    double start = 0.0;
    const double p = progress();
    for (const Segment& s : segments_) {
      spec = s.spec;
      start += std::abs(static_cast<double>(s.offset));
      if (p < start) {
        break;
      }
    }
  }
  std::vector<Piece> pieces;
  append_ramp(pieces, velocity(), vs(), spec.d, spec.shape);
  continue_motion(std::move(pieces));
  if (runs_.back().motion.pieces().empty()) {
    end_event_ = sched_.at(sched_.now(), [this] { on_motion_end(); });
  }
}

void Smd23e::registration_stop() {
  Run& r = *run_;
  r.stopping = true;
  r.reg_triggered = true;
  sched_.cancel(aux_event_);
  aux_event_ = {};
  // Exactly Stopping Distance further steps from the trigger (L1052–1054).
  const double p = progress();
  const double remaining = static_cast<double>(whole(p) + r.reg_stop) - p;
  const double v = velocity();
  const double d = r.spec.d;
  const double n_dec = (v * v - vs() * vs()) / (2.0 * d);
  std::vector<Piece> pieces;
  if (remaining > 0.0) {
    if (remaining >= n_dec) {
      append_cruise(pieces, v, remaining - n_dec);
      append_ramp(pieces, v, vs(), d, RampShape{});
    } else {
      // Too short to reach v_s: decelerate at D, then stop abruptly at what speed remains.
      const double v_end = std::sqrt(std::max(0.0, v * v - 2.0 * d * remaining));
      pieces.push_back({(v - v_end) / d, v, -d, 0.0, Phase::Decelerate});
    }
  }
  continue_motion(std::move(pieces));
  if (runs_.back().motion.pieces().empty()) {
    end_event_ = sched_.at(sched_.now(), [this] { on_motion_end(); });
  }
}

void Smd23e::act(std::function<void()> action, bool stop_like) {
  if (stop_like && p_.fault == Fault::LateStop) {
    ++deferred_;
    sched_.after(p_.late_stop_delay, [this, action = std::move(action)] {
      --deferred_;
      action();
    });
  } else {
    action();
  }
}

void Smd23e::on_motion_end() {
  end_event_ = {};
  const Nanos now = sched_.now();
  end_motion(now);
  Run r = std::move(*run_);
  run_.reset();
  if (r.holding) {
    hold_state_ = true;
    if (!r.error_in_hold &&
        (r.kind == Kind::Position || r.kind == Kind::EncoderMove || r.kind == Kind::Jog)) {
      held_ = Held{r.kind, r.dir, r.target};
    }
    return;
  }
  switch (r.kind) {
  case Kind::Position:
  case Kind::EncoderMove:
  case Kind::Jog:
  case Kind::Registration:
  case Kind::Blend:
    move_complete_ = true;
    return;
  case Kind::Dwell: {
    const std::size_t next = r.segment + 1;
    // The dwell time came with the Run command (L1179, L2436); word 9 written since is not
    // read again: only a new 0→1 command edge takes new data (L2403).
    const std::uint32_t dwell = r.dwell_ms;
    if (next >= segments_.size()) {
      if (!p_.dwell_after_last_segment) {
        move_complete_ = true;
        return;
      }
      pause_event_ = sched_.after(milliseconds(dwell), [this] {
        pause_event_ = {};
        move_complete_ = true;
      });
      return;
    }
    pause_event_ = sched_.after(milliseconds(dwell), [this, next, dwell] {
      pause_event_ = {};
      run_dwell_segment(next, dwell);
    });
    return;
  }
  case Kind::Home: {
    const HomeStage next = r.home_stage == HomeStage::Search ? HomeStage::Pause1 : HomeStage::Pause2;
    const int dir = r.home_dir;
    const MoveSpec spec = r.spec;
    home_pause_ = pause_event_ = sched_.after(p_.homing_pause, [this, next, dir, spec] {
      pause_event_ = home_pause_ = {};
      // The next run sets off on the levels, not only on edges: a limit already active in its
      // direction (the opposite limit for the reverse search, L1365; both, L1367) is an error.
      if (limit_toward(next == HomeStage::Pause1 ? -dir : dir)) {
        homing_error();
        return;
      }
      Run h;
      h.kind = Kind::Home;
      h.home_dir = dir;
      h.spec = spec;
      std::vector<Piece> pieces;
      if (next == HomeStage::Pause1) {
        h.home_stage = HomeStage::Back; // reverse at v_p until Home goes inactive
        append_ramp(pieces, vs(), spec.vp, spec.a, spec.shape);
        append_cruise(pieces, spec.vp, kInf);
        start_motion(std::move(h), std::move(pieces), -dir);
      } else {
        h.home_stage = HomeStage::Creep; // creep at v_s to the Home edge
        append_cruise(pieces, vs(), kInf);
        start_motion(std::move(h), std::move(pieces), dir);
      }
    });
    return;
  }
  }
}

void Smd23e::schedule_stall_check() {
  sched_.cancel(stall_event_);
  stall_event_ = {};
  const bool enabled = encoder_enabled() && (cfg_.words[0] & ccw::kStallEnable) != 0;
  if (!enabled || !run_ || !shaft_blocked_) {
    return;
  }
  const double threshold = p_.stall_threshold_counts * steps_per_turn() / 1024.0;
  const ShaftRun& r = runs_.back();
  // Steps issued this move that the shaft did not turn: the block, not an earlier one's slip.
  const double lag = std::abs(
      static_cast<double>((step_position(sched_.now()) - watch_steps_) - (shaft_frozen_ - watch_shaft_)));
  const double x = r.motion.progress(sched_.now()) + std::max(0.0, threshold - lag) + 1.0;
  const Nanos t = r.motion.time_at_progress(x);
  if (t == Nanos::max()) {
    return;
  }
  stall_event_ = sched_.at(t, [this] {
    stall_event_ = {};
    immediate_stop(); // [A] a stall is an immediate stop
    set_error(stall_);
    pos_invalid_ = true;
  });
}

void Smd23e::schedule_registration_min() {
  const double x = static_cast<double>(run_->reg_min) - runs_.back().base;
  const Nanos t = runs_.back().motion.time_at_progress(x);
  if (t == Nanos::max()) {
    return;
  }
  aux_event_ = sched_.at(t, [this] {
    aux_event_ = {};
    if (!run_ || run_->kind != Kind::Registration || run_->stopping) {
      return;
    }
    // Stop conditions are level-sensitive once M is travelled (L1058, L1068).
    const bool bit_gone = (out_[0] & run_->command_bit) == 0;
    const bool input = p_.stop_input_level_sensitive && function_active(InputFunction::StopJog);
    if (run_->reg_hold_pending) {
      controlled_stop(false);
    } else if (bit_gone || input) {
      registration_stop();
    }
  });
}

// ---- Moves -----------------------------------------------------------------------------------

void Smd23e::start_position_move(bool absolute) {
  const auto value = read_value(2, kMaxTarget);
  const auto spec = read_spec(true);
  if (!value || !spec || (absolute && pos_invalid_)) {
    command_error(); // L840; absolute with Position Invalid [A]
    return;
  }
  const std::int64_t here = motor_position();
  const std::int64_t target = absolute ? *value : here + *value;
  const int dir = target >= here ? 1 : -1;
  if (!may_start(dir, false)) {
    return;
  }
  begin_command();
  last_jerk_ = spec->jerk;
  Run r;
  r.kind = Kind::Position;
  r.spec = *spec;
  r.target = target;
  const auto n = static_cast<double>(target > here ? target - here : here - target);
  start_motion(std::move(r), plan_move(n, vs(), spec->vp, spec->a, spec->d, spec->shape), dir);
  if (n == 0.0) {
    end_event_ = sched_.at(sched_.now(), [this] { on_motion_end(); }); // [A] zero length: done at once
  }
}

void Smd23e::start_encoder_move(bool absolute) {
  const auto value = read_value(2, kMaxTarget);
  const auto spec = read_spec(true);
  if (!value || !spec || !encoder_enabled() || (absolute && pos_invalid_)) {
    command_error();
    return;
  }
  const std::int64_t here = encoder_position();
  const std::int64_t delta = absolute ? *value - here : *value;
  const int dir = delta >= 0 ? 1 : -1;
  if (!may_start(dir, false)) {
    return;
  }
  begin_command();
  last_jerk_ = spec->jerk;
  // The encoder target marks where deceleration begins (L1086), converted to steps.
  const double x = static_cast<double>(delta < 0 ? -delta : delta) * steps_per_turn() / 1024.0;
  const double vp = std::min(spec->vp, std::sqrt(vs() * vs() + 2.0 * spec->shape.effective(spec->a) * x));
  std::vector<Piece> pieces;
  append_ramp(pieces, vs(), vp, spec->a, spec->shape);
  append_cruise(pieces, vp, x - ramp_steps(vs(), vp, spec->a, spec->shape));
  append_ramp(pieces, vp, vs(), spec->d, spec->shape);
  Run r;
  r.kind = Kind::EncoderMove;
  r.spec = *spec;
  const double total = x + ramp_steps(vp, vs(), spec->d, spec->shape);
  r.target = motor_position() + dir * planned_whole(total);
  start_motion(std::move(r), std::move(pieces), dir);
}

void Smd23e::start_jog(int dir, bool registration, std::uint16_t bit) {
  const auto spec = read_spec(!registration);
  std::optional<std::int32_t> stop_distance;
  std::optional<std::int32_t> min_distance;
  if (registration) {
    stop_distance = read_value(2, kMaxTarget);
    min_distance = read_value(8, kMaxTarget);
  }
  if (!spec ||
      (registration && (!stop_distance || *stop_distance < 0 || !min_distance || *min_distance < 0))) {
    command_error();
    move_complete_ = true; // out-of-range jog/registration parameters: CmdErr and MvCmp (L2860)
    return;
  }
  if (!may_start(dir, true)) {
    return;
  }
  begin_command();
  last_jerk_ = spec->jerk;
  Run r;
  r.kind = registration ? Kind::Registration : Kind::Jog;
  r.spec = *spec;
  r.command_bit = bit;
  r.reg_stop = registration ? *stop_distance : 0;
  r.reg_min = registration ? *min_distance : 0;
  std::vector<Piece> pieces;
  append_ramp(pieces, vs(), spec->vp, spec->a, spec->shape);
  append_cruise(pieces, spec->vp, kInf);
  start_motion(std::move(r), std::move(pieces), dir);
  if (registration) {
    if (r.reg_min == 0 && p_.stop_input_level_sensitive && function_active(InputFunction::StopJog)) {
      registration_stop();
    } else {
      schedule_registration_min();
    }
  }
}

void Smd23e::change_jog(const MoveSpec& spec) {
  Run& r = *run_;
  const double v = velocity();
  r.spec.vp = spec.vp;
  r.spec.a = spec.a;
  r.spec.d = spec.d;
  std::vector<Piece> pieces;
  append_ramp(pieces, v, spec.vp, spec.vp > v ? spec.a : spec.d, r.spec.shape);
  append_cruise(pieces, spec.vp, kInf);
  continue_motion(std::move(pieces));
}

void Smd23e::set_error(bool& flag) {
  flag = true;
  held_.reset();
  if (run_ && run_->holding) {
    run_->error_in_hold = true;
  }
}

void Smd23e::resume() {
  if (!held_ || run_) {
    command_error(); // [A] Resume with nothing held
    return;
  }
  const Held h = *held_;
  const auto spec = read_spec(true);
  if (!spec) {
    command_error();
    return;
  }
  const int dir = h.kind == Kind::Jog ? h.dir : (h.target >= motor_position() ? 1 : -1);
  if (!may_start(dir, h.kind == Kind::Jog)) {
    return;
  }
  begin_command();
  last_jerk_ = spec->jerk;
  Run r;
  r.kind = h.kind;
  r.spec = *spec;
  r.target = h.target;
  if (h.kind == Kind::Jog) {
    // [MODEL] A jog moves while its command is active (L1012) and stops when the command bit
    // returns to 0 (L1033); a resumed jog's command is the Resume bit that restarted it (the
    // manual does not say how a resumed jog ends; spec §9 #26).
    r.command_bit = msw::kResume;
    std::vector<Piece> pieces;
    append_ramp(pieces, vs(), spec->vp, spec->a, spec->shape);
    append_cruise(pieces, spec->vp, kInf);
    start_motion(std::move(r), std::move(pieces), dir);
    return;
  }
  // The target cannot change; v_p, A, D and J may (L969–974).
  const std::int64_t here = motor_position();
  const auto n = static_cast<double>(h.target > here ? h.target - here : here - h.target);
  r.kind = Kind::Position;
  start_motion(std::move(r), plan_move(n, vs(), spec->vp, spec->a, spec->d, spec->shape), dir);
  if (n == 0.0) {
    end_event_ = sched_.at(sched_.now(), [this] { on_motion_end(); });
  }
}

void Smd23e::start_home(int dir) {
  const auto spec = read_spec(true);
  if (!spec || input_with(InputFunction::Home) < 0) {
    command_error(); // no Home input configured [A]
    return;
  }
  const bool proximity = (cfg_.words[0] & ccw::kHomeProximityEnable) != 0;
  // Profile C starts at step 4 with the search-direction limit active (L1382), profile A at
  // step 5 with Home active (L1331): both set off opposite to the requested direction. The
  // first run is judged on the limit levels like any move (L1043), so with both limits active,
  // or the opposite limit active where the search starts reversed, it stops with an Input
  // Error before moving (L1367).
  const bool reversed = limit_toward(dir) || (!proximity && function_active(InputFunction::Home));
  const int first_dir = reversed ? -dir : dir;
  if (!may_start(first_dir, false)) {
    return;
  }
  begin_command();
  last_jerk_ = spec->jerk;
  Run r;
  r.kind = Kind::Home;
  r.home_dir = dir;
  r.spec = *spec;
  r.home_stage = reversed ? HomeStage::Back : HomeStage::Search;
  std::vector<Piece> pieces;
  append_ramp(pieces, vs(), spec->vp, spec->a, spec->shape);
  append_cruise(pieces, spec->vp, kInf);
  start_motion(std::move(r), std::move(pieces), first_dir);
}

void Smd23e::homing_error() {
  // "stop all motion and issue a Home Invalid error" (L1365); the bit is Input Error (L2836).
  immediate_stop(); // also ends a homing pause
  set_error(in_err_);
  pos_invalid_ = true;
}

bool Smd23e::limit_toward(int dir) const {
  return p_.fault != Fault::IgnoredLimit &&
         function_active(dir > 0 ? InputFunction::CwLimit : InputFunction::CcwLimit);
}

void Smd23e::home_next(HomeStage stage) {
  if (!run_ || run_->kind != Kind::Home || run_->home_stage != stage) {
    return;
  }
  // The Home edge met at v_s in the requested direction: position := 0 (L1275, L1287).
  immediate_stop();
  reg_offset_ = -step_position(sched_.now());
  if (encoder_enabled()) {
    enc_offset_ -= encoder_position();
  }
  homed_ = true;
  pos_invalid_ = false;
}

void Smd23e::start_assembled() {
  if (segments_.empty()) {
    command_error();
    return;
  }
  const bool dwell = (out_[1] & lsw::kDwellType) != 0;
  if (dwell) {
    const int dir = segments_.front().offset >= 0 ? 1 : -1;
    if (!may_start(dir, false)) {
      return;
    }
    begin_command();
    run_dwell_segment(0, out_[9]);
    return;
  }
  for (std::size_t i = 1; i < segments_.size(); ++i) {
    if (segments_[i].spec.vp == segments_[i - 1].spec.vp) {
      command_error(); // a Blend segment's v_p must differ from the previous one's (L1118)
      return;
    }
  }
  const int dir = (out_[1] & lsw::kBlendCcw) != 0 ? -1 : 1;
  // Blend: back to back; speed changes start at each boundary, up with the new segment's A,
  // down with the old segment's D; the last segment ends at v_s (L1117–1118).
  std::vector<Piece> pieces;
  double v = vs();
  for (std::size_t i = 0; i < segments_.size(); ++i) {
    const Segment& s = segments_[i];
    const double n = std::abs(static_cast<double>(s.offset));
    const bool up = s.spec.vp > v;
    const double rate = up ? s.spec.a : (i > 0 ? segments_[i - 1].spec.d : s.spec.d);
    const RampShape shape = up || i == 0 ? s.spec.shape : segments_[i - 1].spec.shape;
    const double ramp = ramp_steps(v, s.spec.vp, rate, shape);
    const double tail = i + 1 == segments_.size() ? ramp_steps(s.spec.vp, vs(), s.spec.d, s.spec.shape) : 0.0;
    if (ramp + tail > n) {
      command_error(); // [A] a segment too short for its speed changes
      return;
    }
    append_ramp(pieces, v, s.spec.vp, rate, shape);
    append_cruise(pieces, s.spec.vp, n - ramp - tail);
    v = s.spec.vp;
    if (tail > 0.0) {
      append_ramp(pieces, v, vs(), s.spec.d, s.spec.shape);
    }
  }
  if (!may_start(dir, false)) {
    return;
  }
  begin_command();
  last_jerk_ = segments_.back().spec.jerk;
  Run r;
  r.kind = Kind::Blend;
  r.spec = segments_.front().spec;
  r.spec.d = segments_.back().spec.d;
  start_motion(std::move(r), std::move(pieces), dir);
}

void Smd23e::run_dwell_segment(std::size_t index, std::uint32_t dwell_ms) {
  const Segment& s = segments_[index];
  const int dir = s.offset >= 0 ? 1 : -1;
  const bool limit = p_.fault != Fault::IgnoredLimit &&
                     (function_active(dir > 0 ? InputFunction::CwLimit : InputFunction::CcwLimit) ||
                      (dir > 0 ? lock_cw_ : lock_ccw_));
  if (limit || function_active(InputFunction::EmergencyStop)) {
    set_error(in_err_);
    return;
  }
  Run r;
  r.kind = Kind::Dwell;
  r.spec = s.spec;
  r.segment = index;
  r.dwell_ms = dwell_ms;
  last_jerk_ = s.spec.jerk;
  const double n = std::abs(static_cast<double>(s.offset));
  start_motion(std::move(r), plan_move(n, vs(), s.spec.vp, s.spec.a, s.spec.d, s.spec.shape), dir);
}

// ---- Inputs ----------------------------------------------------------------------------------

void Smd23e::capture_encoder() {
  if (encoder_enabled()) {
    captured_ = encoder_position();
  }
}

void Smd23e::on_input(int input, Level level) {
  const bool before = input_active(input);
  raw_[static_cast<std::size_t>(input)] = level;
  const bool after = input_active(input);
  if (before == after || !powered_ || !configured_ || config_mode_) {
    return;
  }
  switch (function_of(input)) {
  case InputFunction::GeneralPurpose:
  case InputFunction::Invalid:
    return;
  case InputFunction::CwLimit:
  case InputFunction::CcwLimit: {
    const int dir = function_of(input) == InputFunction::CwLimit ? 1 : -1;
    if (after) {
      limit_active(dir);
    } else if (!function_active(InputFunction::CwLimit) && !function_active(InputFunction::CcwLimit)) {
      limit_cond_ = false; // cleared when the limit goes inactive (L2889)
    }
    return;
  }
  case InputFunction::StartIndexed:
    if (after || p_.capture_on_any_transition) {
      capture_encoder();
    }
    if (after && armed_ != 0 && !run_ && !pause_event_.valid()) {
      dispatch(armed_, true); // every rising edge re-runs the armed move (§3.10)
    }
    return;
  case InputFunction::StopJog:
    if (!after || !run_ || (run_->kind != Kind::Jog && run_->kind != Kind::Registration) || run_->stopping) {
      return;
    }
    capture_encoder();
    act(
        [this] {
          if (!run_ || run_->stopping) {
            return;
          }
          if (run_->kind == Kind::Jog) {
            controlled_stop(false);
          } else if (run_->kind == Kind::Registration &&
                     progress() - run_->chain_start >= static_cast<double>(run_->reg_min)) {
            registration_stop();
          }
        },
        true);
    return;
  case InputFunction::EmergencyStop:
    if (after) {
      set_error(in_err_); // L2833
      if (run_ || pause_event_.valid()) {
        act(
            [this] {
              if (run_ || pause_event_.valid()) {
                immediate_stop();
                pos_invalid_ = true;
              }
            },
            true);
      }
    }
    return;
  case InputFunction::Home:
    if (!run_ || run_->kind != Kind::Home || run_->stopping) {
      return;
    }
    switch (run_->home_stage) {
    case HomeStage::Search:
      if (after && (cfg_.words[0] & ccw::kHomeProximityEnable) == 0) {
        controlled_stop(false); // then wait 2 s and reverse (profile A step 3)
      }
      return;
    case HomeStage::Back:
      if (!after) {
        controlled_stop(false); // profile A step 6
      }
      return;
    case HomeStage::Creep:
    case HomeStage::ProxCreep:
      if (after) {
        home_next(run_->home_stage);
      }
      return;
    case HomeStage::Pause1:
    case HomeStage::Pause2:
      return;
    }
    return;
  }
}

void Smd23e::limit_active(int dir) {
  if (p_.fault == Fault::IgnoredLimit) {
    return;
  }
  // Both limits active while finding home, moving or in a pause, is an error (L1367).
  const auto homing = [this] { return (run_ && run_->kind == Kind::Home) || sched_.pending(home_pause_); };
  if (homing() && limit_toward(1) && limit_toward(-1)) {
    act(
        [this, homing] {
          if (homing()) {
            homing_error();
          }
        },
        true);
    return;
  }
  if (!run_) {
    return;
  }
  const Kind kind = run_->kind;
  const int travel = run_->dir;
  if (kind == Kind::Home) {
    if (dir == run_->home_dir && run_->home_stage == HomeStage::Search) {
      // Profile C: the search-direction limit is an immediate stop, then the reverse search.
      act(
          [this] {
            if (!run_ || run_->kind != Kind::Home) {
              return;
            }
            sched_.cancel(end_event_);
            on_motion_end(); // stops the step train here, waits 2 s, then reverses
          },
          true);
      return;
    }
    act(
        [this] {
          if (run_) {
            homing_error();
          }
        },
        true);
    return;
  }
  if ((kind == Kind::Jog || kind == Kind::Registration) && dir != travel) {
    return; // the opposite limit is ignored while jogging (L1018, L1056)
  }
  act(
      [this, dir, travel] {
        if (!run_) {
          return;
        }
        immediate_stop();
        set_error(in_err_);
        limit_cond_ = true;
        pos_invalid_ = true;
        if (dir == travel) {
          (dir > 0 ? lock_cw_ : lock_ccw_) = true; // that direction is refused until Reset Errors
        }
      },
      true);
}

} // namespace hilrig::models::smd23e
