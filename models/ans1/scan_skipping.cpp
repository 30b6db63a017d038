// Exact scan skipping (docs/virtual-time.md). A scan is a function of the device state, what
// it reads from outside (pins, host words, speed, settings) and the time. When no outside
// change preceded a scan and that scan left the state as it found it, every later scan does the
// same until either something outside changes (wake(), from every edge handler and mutator) or
// a time-driven behaviour's deadline arrives (next_change()). The scans in between are skipped:
// they would have changed nothing, so results, words and traces are the same as scanning every
// period (Params::exact_scan, the oracle the differential test compares against).
#include <algorithm>
#include <limits>
#include <optional>
#include <stdexcept>
#include <tuple>

#include "models/ans1/ans1.hpp"
#include "models/ans1/position.hpp"
#include "models/ans1/quad_state.hpp"

namespace hilrig::models::ans1 {

// Every member a scan may write. A member added to the scan's state belongs here; one left
// out makes a changing scan look quiet, which the differential test catches.
struct Ans1::ScanSnapshot {
  std::array<OutputChannel, kOutputCount> channels;
  Monitors monitors;
  ShiftRegister shift_register;
  PositionSetup position; // presets move the offset
  std::tuple<std::int64_t, std::uint16_t, bool, bool, bool> resolver;
  std::tuple<std::uint16_t, std::uint16_t, bool> gmp;
  std::tuple<std::uint16_t, std::uint16_t, std::uint16_t> inputs;
  std::tuple<std::uint16_t, std::uint16_t, std::uint16_t> outputs;
  std::tuple<std::uint16_t, std::uint16_t, std::uint16_t, std::uint16_t, std::uint16_t, std::uint16_t,
             std::uint16_t>
      masks;
  std::tuple<std::uint16_t, Nanos, std::int8_t> rotation;
  std::tuple<bool, bool, bool, ErrorCode, bool> host;
  friend bool operator==(const ScanSnapshot&, const ScanSnapshot&) = default;
};

Ans1::ScanSnapshot Ans1::snapshot() const {
  return ScanSnapshot{
      channels_,
      monitors_,
      shift_register_,
      position_,
      {resolver_count_, resolver_angle_, resolver_seen_, resolver_fault_active_, resolver_fault_latched_},
      {gmp_, previous_gmp_, first_scan_},
      {electrical_inputs_, active_inputs_, previous_active_inputs_},
      {ls_, outputs_, queued_levels_},
      {masks_.calc, masks_.simple, masks_.pulse, masks_.window, masks_.shift_register, masks_.rpm,
       masks_.timer},
      {time_of_rotation_, last_wrap_, last_wrap_direction_},
      {host_.transmit_seen(), host_.acknowledge(), host_.responding(), host_.error(), host_.hardware_fault()},
  };
}

Nanos Ans1::next_change(bool idle_ticks_recorded) const {
  Nanos next = monitors_.next_change(idle_ticks_recorded);
  for (const OutputChannel& channel : channels_) {
    next = std::min(next, channel.next_change());
  }
  // The stators are sampled at each excitation peak; the last sampled one is not in the
  // snapshot, so a peak that reads the same angle keeps the scan quiet. Read ahead, the peak
  // that changes anything wakes the scan instead (walk_peaks).
  if (!position_.slave_mode && position_.sensor == SensorType::Resolver && !walking_peaks_) {
    next = std::min(next, excitation_.next_peak(scheduler_.now()));
  }
  return next;
}

Nanos Ans1::grid_at_or_after(Nanos t) const {
  if (t == Nanos::max()) {
    return t;
  }
  const Nanos period = scan_period();
  const Nanos first = grid_origin_ + period;
  if (t <= first) {
    return first;
  }
  const std::int64_t periods = (t - grid_origin_ + period - Nanos{1}) / period;
  return grid_origin_ + period * periods;
}

void Ans1::wake() {
  channels_fixed_ = false;
  input_wake();
}

void Ans1::input_wake() {
  settle_position();
  changed_outside_ = true;
  if (params_.exact_scan || in_scan_ || !powered_) {
    return; // scanning every period, or the running scan schedules the next
  }
  wake_now();
}

void Ans1::wake_now() {
  if (in_scan_) {
    return;
  }
  const Nanos at = grid_at_or_after(scheduler_.now());
  if (at < scan_at_) {
    scheduler_.cancel(scan_event_);
    schedule_scan(at);
  }
}

void Ans1::run_scan() {
  const Nanos now = scheduler_.now();
  settle_position(now - scan_period()); // after skipped scans while moving
  scheduler_.cancel(leave_event_);
  leave_event_ = {};
  scan_at_ = Nanos::max();
  grid_origin_ = now;
  const bool outside = changed_outside_;
  changed_outside_ = false;
  const auto skips_motion = [this] {
    return !params_.exact_scan && !position_.slave_mode &&
           (position_.sensor == SensorType::Quadrature || resolver_read_ahead());
  };
  std::optional<ScanSnapshot> before;
  if (!params_.exact_scan && !outside && !skips_motion()) {
    before = snapshot();
  }
  in_scan_ = true;
  scan();
  in_scan_ = false;
  const bool channels_fixed = channels_fixed_; // a wake in the scan cleared it
  channels_fixed_ = false;                     // until this scan proves a fixed point again

  // The period may have changed in the scan.
  Nanos next = now + scan_period();
  if (!changed_outside_ && skips_motion()) {
    if ((channels_fixed || !channels_held_) && scan_repeats(channels_held_)) {
      // Asleep until a deadline, or until the GMP leaves quiet_, or wake(). With the channels
      // left alone at the same GMP, quiet_ is what it was (quiet_interval reads the channels,
      // the setups, the speed and the GMP: any other change of them wakes the scan).
      if (!channels_held_ || gmp_ != quiet_gmp_) {
        quiet_ = quiet_interval();
        quiet_gmp_ = gmp_;
      }
      channels_fixed_ = true;
      channels_until_ = Nanos::max();
      for (const OutputChannel& channel : channels_) {
        channels_until_ = std::min(channels_until_, channel.next_change());
      }
      if (position_.sensor == SensorType::Resolver) {
        walking_peaks_ = true;
        walk_base_ = walk_state_ = resolver_track();
        walk_base_peak_ = walk_front_ = last_peak_;
        walk_.clear();
      }
      quiet_armed_ = true;
      edge_grid_ = now;
      count_at_edge_grid_ = transducer_count();
      next = grid_at_or_after(next_change(true)); // quiet_armed_: settle_position records them
      if (walking_peaks_) {
        walk_peaks(revision_expected());
      } else {
        schedule_count_leave(now);
      }
    }
  } else if (before && !changed_outside_ && *before == snapshot()) {
    next = grid_at_or_after(next_change(false)); // asleep until then, or until wake()
  }
  if (next != Nanos::max()) {
    schedule_scan(next);
  }
  if (quad_->waveform != nullptr) {
    quad_->waveform->forget_before(now); // nothing asks about an earlier time again
  }
}

// ---------------------------------------------------------------- while the encoder moves
//
// A scan that the count alone changes writes the position members (gmp_, previous_gmp_, the
// monitors' last position and the production counters' last position), evaluates the
// position conditions of every output, the shift register, die protection and the counters,
// and watches for crossings (roll-over, shift position, part-cycle position). After a scan that
// a repeat at the same count would leave as it is (scan_repeats), every scan at a GMP inside
// quiet_interval() leaves it as it is too: each condition keeps its value there and no watched
// mark lies inside. So scans are skipped until the GMP leaves the interval (count_edge), a
// deadline of next_change() arrives or anything else wakes the scan; the position members are
// then written as the last skipped scan would have left them (settle_position), from the count
// at that scan's grid point, which count_edge remembers.

bool Ans1::scan_repeats(bool channels_held) const {
  const std::uint16_t fsc = position_.full_scale_count;
  ShiftRegister sr = shift_register_;
  const bool sr_input = sr_setup_.input != 0 && (active_inputs_ & (1U << (sr_setup_.input - 1U))) != 0;
  sr.step(gmp_, gmp_, sr_input, sr_setup_, fsc);
  if (!(sr == shift_register_)) {
    return false;
  }
  const ScanState state = scan_state(scheduler_.now());
  for (const OutputChannel& channel : channels_) {
    if (channels_held) {
      break; // at their fixed point for this state (channels_hold)
    }
    OutputChannel again = channel;
    (void)again.scan(state, params_.time_only_retrigger_restarts);
    if (!(again == channel)) {
      return false;
    }
  }
  Monitors again = monitors_;
  again.scan(scheduler_.now(), MonitorInputs{gmp_, transducer_count(), active_inputs_});
  return monitors_.scan_left_alone(again);
}

// ---------------------------------------------------------------- input edges
//
// An input edge wakes the scan, which reads every input. The output channels read only their
// ANDing inputs (simple, pulse, window), the shift register its SR input, a preset its preset
// input; die protection, the brake monitor and the input edge positions read any input, and
// the monitors run in every scan. When the last scan that ran left every channel at a fixed
// point (scan_repeats, quiet_ armed), only input edges woke the scan since (wake() clears
// channels_fixed_), none of the inputs that changed is one those read, the GMP is inside quiet_
// and no channel's deadline (a timer's expiry) has come, then each channel's scan would start
// from its fixed-point state with every condition at its fixed-point value (the ScanState
// differs only in `now` before the channels' deadline, in input bits no channel reads and in a
// GMP inside quiet_: part 4 of docs/virtual-time.md), so it would return the state it holds
// and leave it as it is: the scan leaves ls_ and masks_ as they are and runs the monitors,
// the arbitration and the host, and scan_repeats does not run the channels again. A die-
// protection train (a fault counted each closing) thus costs a scan of the monitors per edge.

std::uint16_t Ans1::channel_inputs() const {
  std::uint16_t mask = 0;
  const auto add = [&mask](int input) {
    if (input != 0) {
      mask = static_cast<std::uint16_t>(mask | (1U << static_cast<unsigned>(input - 1)));
    }
  };
  for (const OutputChannel& channel : channels_) {
    mask = static_cast<std::uint16_t>(mask | channel.inputs_read());
    add(channel.setup().ls_preset_input);
  }
  add(sr_setup_.input);
  add(position_.preset_input);
  return mask;
}

bool Ans1::channels_hold(Nanos now, std::uint16_t changed) const {
  return channels_fixed_ && !params_.exact_scan && !first_scan_ && now < channels_until_ &&
         quiet_.contains(gmp_) && (changed & channel_inputs()) == 0;
}

QuietInterval Ans1::quiet_interval() const {
  const std::uint16_t fsc = position_.full_scale_count;
  QuietInterval quiet = QuietInterval::around(gmp_, fsc);
  const ScanState state = scan_state(scheduler_.now());
  for (const OutputChannel& channel : channels_) {
    channel.keep_quiet(quiet, state);
  }
  ShiftRegister::keep_quiet(quiet, gmp_, sr_setup_, fsc);
  monitors_.keep_quiet(quiet, gmp_);
  return quiet;
}

Nanos Ans1::last_run_grid(Nanos now) const {
  if (now <= grid_origin_) {
    return grid_origin_; // the last scan that ran
  }
  const Nanos period = scan_period();
  const Nanos g = grid_origin_ + period * ((now - grid_origin_) / period);
  // A scan is the last event at its instant: during an ordinary event at a grid point the
  // scan there has not run yet.
  return g == now && scheduler_.ordinary_event_running() ? g - period : g;
}

std::int64_t Ans1::count_at(Nanos g) const {
  if (walking_peaks_) {
    return track_at(g).count;
  }
  if (quad_->waveform != nullptr) {
    return quad_->waveform->count_at(g) - quad_->base; // the scan at g runs after every edge at g
  }
  return g > edge_grid_ ? transducer_count() : count_at_edge_grid_;
}

void Ans1::count_edge(std::int64_t before) {
  if (!quiet_armed_) {
    wake();
    return;
  }
  const Nanos g = last_run_grid(scheduler_.now());
  if (g > edge_grid_) { // the first edge after grid point g: the count there is the one before it
    record_idle_ticks(g, before);
    edge_grid_ = g;
    count_at_edge_grid_ = before;
  }
  if (!quiet_.contains(global_position(transducer_count(), position_))) {
    wake();
  }
}

void Ans1::record_idle_ticks(Nanos g, std::int64_t after) {
  for (Nanos tick = monitors_.next_idle_tick(); tick != Nanos::max() && grid_at_or_after(tick) <= g;
       tick = monitors_.next_idle_tick()) {
    const Nanos at = grid_at_or_after(tick);
    monitors_.idle_tick(quad_->waveform != nullptr || walking_peaks_ ? count_at(at)
                        : at == edge_grid_                           ? count_at_edge_grid_
                                                                     : after);
  }
}

// A sampled encoder (Ans1Pins::quad_waveform) plays no edge to count_edge: the wake count_edge
// would give at the first edge whose GMP is outside quiet_ is scheduled at that edge's time
// instead, an ordinary event as the edge is. The counts around the present one whose GMP is
// inside quiet_ are a run (the GMP of consecutive counts moves by at most one step of the
// scaling, and a roll-over leaves the interval), so the first edge taking the count outside
// that run is the first whose GMP leaves.
void Ans1::schedule_count_leave(Nanos now) {
  signals::QuadratureWaveform* waveform = quad_->waveform;
  if (waveform == nullptr) {
    return;
  }
  // A scan re-armed with the same interval and scaling before the count left it (a train of
  // input edges while the shaft turns) leaves at the same edge: nothing to walk again.
  LeaveMemo& memo = leave_memo_;
  if (memo.at > now && memo.quiet_lo == quiet_.lo && memo.quiet_hi == quiet_.hi &&
      memo.position == position_ && memo.base == quad_->base) {
    schedule_leave_at(memo.at);
    return;
  }
  const std::int64_t count = transducer_count();
  const std::int64_t cpc = position_.counts_per_cycle;
  const std::int64_t hi = count + counts_inside(count, 1, position_, quiet_);
  const std::int64_t lo = count - counts_inside(count, -1, position_, quiet_);
  // A whole cycle inside: the GMP never leaves (one count per cycle).
  const std::int64_t top = hi - count >= cpc ? std::numeric_limits<std::int64_t>::max() : hi + quad_->base;
  const std::int64_t bottom = count - lo >= cpc ? std::numeric_limits<std::int64_t>::min() : lo + quad_->base;
  const Nanos at = waveform->leaves(now, bottom, top);
  memo = LeaveMemo{quiet_.lo, quiet_.hi, position_, quad_->base, at};
  schedule_leave_at(at);
}

void Ans1::schedule_leave_at(Nanos at) {
  if (at != Nanos::max()) {
    leave_event_ = scheduler_.at(at, [this] {
      leave_event_ = {};
      wake();
    });
  }
}

void Ans1::require_edges() const {
  if (quad_->waveform != nullptr) {
    throw std::logic_error("ANS1: scan every period must be chosen before an encoder waveform is attached");
  }
}

std::uint16_t Ans1::gmp() const {
  if (!quiet_armed_) {
    return gmp_;
  }
  return global_position(count_at(last_run_grid(scheduler_.now())), position_);
}

void Ans1::settle_position(Nanos ran) {
  if (!quiet_armed_) {
    return;
  }
  record_idle_ticks(ran, count_at(ran));
  const std::uint16_t at = global_position(count_at(ran), position_);
  if (walking_peaks_) { // the count as the scan at `ran` left it, having read every peak up to it
    // (the flags are the same at every peak read ahead: a peak that changes them wakes the scan)
    const ResolverTrack t = track_at(ran);
    resolver_count_ = t.count;
    resolver_angle_ = t.angle;
    last_peak_ = std::max(walk_base_peak_, peak_at_or_before(ran));
    walking_peaks_ = false;
    walk_.clear();
    scheduler_.cancel(leave_event_);
    leave_event_ = {};
  }
  quiet_armed_ = false;
  gmp_ = previous_gmp_ = at;
  monitors_.settle_position(at);
}

// ---------------------------------------------------------------- while the resolver turns
//
// The scan reads the stators at the latest excitation peak (one per scan: the period is under
// half the excitation's), so the count at grid point g is the track after every peak at or
// before g. Stators that announce every change of their future (AnalogInput::on_revision: the
// rig's follow the resolver node's CAN frames) give each future peak's reading now. While the
// scan is at a fixed point (scan_repeats), the peaks are read ahead: the first whose reading
// changes the fault flags or takes the GMP out of quiet_ wakes the scan at its time, as the
// quadrature's leaving edge does (the scan at the grid point after it reads it); the count at
// the skipped grid points is the track there (track_at). A revision drops what was read for the
// peaks from its time on and reads them again.

bool Ans1::resolver_read_ahead() const {
  return !params_.exact_scan && !position_.slave_mode && position_.sensor == SensorType::Resolver &&
         pins_.stator_sin != nullptr && pins_.stator_cos != nullptr &&
         pins_.stator_sin->announces_revisions() && pins_.stator_cos->announces_revisions() &&
         scan_period() <= excitation_.half_period();
}

Nanos Ans1::peak_at_or_before(Nanos t) const {
  const Nanos peak = excitation_.latest_peak(t);
  return peak <= t ? peak : Nanos::min();
}

Ans1::ResolverTrack Ans1::track_at(Nanos g) const {
  const auto after = std::upper_bound(walk_.begin(), walk_.end(), g,
                                      [](Nanos t, const PeakReading& r) { return t < r.peak; });
  return after == walk_.begin() ? walk_base_ : std::prev(after)->track;
}

Nanos Ans1::revision_expected() const {
  if (last_revision_ == Nanos::min() || walk_gap_ <= Nanos::zero()) { // 16 peaks before any
    return excitation_.next_peak(walk_front_) + excitation_.half_period() * 15;
  }
  return last_revision_ + walk_gap_;
}

void Ans1::walk_peaks(Nanos until) {
  if (!walking_peaks_) {
    return;
  }
  // Up to the first peak at or after `until` (64 at most): what was read beyond the next
  // revision is read again then (the rig's stators are revised at every frame: a millisecond,
  // ten peaks at 5 kHz), and a walk that stops short of it needs another event.
  for (std::int64_t n = 0; n < 64; ++n) {
    const Nanos peak = excitation_.next_peak(walk_front_);
    const ResolverTrack next = read_peak(walk_state_, peak);
    const bool flags_kept = next.seen == walk_state_.seen && next.fault_active == walk_state_.fault_active &&
                            next.fault_latched == walk_state_.fault_latched;
    if (!flags_kept || !quiet_.contains(global_position(next.count, position_))) {
      schedule_leave_at(peak);
      return;
    }
    if (next.count != walk_state_.count || next.angle != walk_state_.angle) {
      walk_.push_back({peak, next});
    }
    walk_front_ = peak;
    walk_state_ = next;
    if (peak >= until) {
      break;
    }
  }
  // No revision came by the last peak read: 2 peaks more, then twice as many each time.
  leave_event_ = scheduler_.at(walk_front_, [this] {
    leave_event_ = {};
    const std::int64_t more = walk_more_;
    walk_more_ = std::min<std::int64_t>(walk_more_ * 2, 64);
    walk_peaks(excitation_.next_peak(walk_front_) + excitation_.half_period() * (more - 1));
  });
}

void Ans1::stators_revised() {
  const Nanos now = scheduler_.now();
  if (now != last_revision_) { // the next is expected as far on as this one came after the last
    if (last_revision_ != Nanos::min()) {
      walk_gap_ = now - last_revision_;
    }
    last_revision_ = now;
    walk_more_ = 2;
  }
  if (!walking_peaks_) {
    return;
  }
  if (!resolver_read_ahead()) { // a stator no longer announces its changes: scan at the peaks
    wake();
    return;
  }
  while (!walk_.empty() && walk_.back().peak >= now) {
    walk_.pop_back();
  }
  if (walk_front_ >= now) {
    walk_state_ = walk_.empty() ? walk_base_ : walk_.back().track;
    walk_front_ = std::max(walk_base_peak_, peak_at_or_before(now - Nanos{1}));
  }
  // Read again after everything else at this instant that may revise a stator (both stators
  // follow one frame).
  scheduler_.cancel(leave_event_);
  leave_event_ = scheduler_.at(now, [this] {
    leave_event_ = {};
    walk_peaks(revision_expected());
  });
}

} // namespace hilrig::models::ans1
