#include "models/ans1/ans1.hpp"

#include <stdexcept>

#include "models/ans1/position.hpp"
#include "models/ans1/quad_state.hpp"

namespace hilrig::models::ans1 {

namespace {

Params effective_params(Params params, Variant variant) {
  if (variant == Variant::LateOutputs) {
    params.output_delay = microseconds(kLateOutputDelayUs);
  }
  return params;
}

MonitorFaults monitor_faults(Variant variant) {
  MonitorFaults f;
  f.brake_never_faults = variant == Variant::BrakeNeverFaults;
  f.die_check_never_counts = variant == Variant::DieProtectionNeverCounts;
  return f;
}

// Outputs with setpoints or a timer (an overflow output with an LS program follows it, L1226).
std::uint16_t ls_programmed(const std::array<OutputChannel, kOutputCount>& channels) {
  std::uint16_t mask = 0;
  for (std::size_t i = 0; i < channels.size(); ++i) {
    const OutputSetup& o = channels[i].setup();
    bool programmed = o.timer_ms != 0;
    for (const auto& p : o.pairs) {
      programmed = programmed || p.used();
    }
    if (programmed) {
      mask = static_cast<std::uint16_t>(mask | (1U << i));
    }
  }
  return mask;
}

std::uint16_t bit(int point) { return static_cast<std::uint16_t>(1U << static_cast<unsigned>(point - 1)); }

} // namespace

Ans1::Ans1(Scheduler& scheduler, const Params& params, Variant variant)
    : scheduler_(scheduler), params_(effective_params(params, variant)), variant_(variant),
      excitation_(params.excitation_hz, params.excitation_amplitude), quad_(std::make_shared<QuadState>()),
      monitors_(monitor_faults(variant), params.brake_sample_start) {
  quad_->device = this;
  monitors_.configure(MonitorSetup{}, position_.full_scale_count);
  grid_origin_ = scheduler_.now() + params_.scan_phase - scan_period();
  schedule_scan(scheduler_.now() + params_.scan_phase);
  speed_event_ = scheduler_.at(scheduler_.now() + params_.speed_update_period, [this] { speed_update(); });
}

Ans1::Ans1(Scheduler& scheduler, const Ans1Pins& pins, const Params& params, Variant variant)
    : Ans1(scheduler, params, variant) {
  attach(pins);
}

Ans1::~Ans1() {
  scheduler_.cancel(scan_event_);
  scheduler_.cancel(speed_event_);
  scheduler_.cancel(write_event_);
  scheduler_.cancel(leave_event_);
}

std::size_t Ans1::index(int point) {
  if (point < 1 || point > kOutputCount) {
    throw std::out_of_range("ANS1 points are numbered 1..16");
  }
  return static_cast<std::size_t>(point - 1);
}

void Ans1::attach(const Ans1Pins& pins) {
  settle_position();
  pins_ = pins;
  quad_->a = pins.quad_a;
  quad_->b = pins.quad_b;
  const bool sampled = pins.quad_waveform != nullptr && pins.quad_a != nullptr && pins.quad_b != nullptr &&
                       !params_.exact_scan;
  quad_->waveform = sampled ? pins.quad_waveform : nullptr;
  quad_->restart(scheduler_.now());
  std::weak_ptr<QuadState> weak = quad_;
  const auto handler = [weak](const Edge&) {
    if (auto q = weak.lock()) {
      q->edge();
    }
  };
  if (pins.quad_a != nullptr && !sampled) {
    pins.quad_a->on_edge(handler);
  }
  if (pins.quad_b != nullptr && !sampled) {
    pins.quad_b->on_edge(handler);
  }
  // The stators may be read ahead of the scans while they announce what changes them.
  const auto stators_revised = [weak] {
    if (auto q = weak.lock()) {
      q->device->stators_revised();
    }
  };
  for (AnalogInput* stator : {pins.stator_sin, pins.stator_cos}) {
    if (stator != nullptr) {
      stator->on_revision(stators_revised);
    }
  }
  // Z is ignored (L455). The inputs are read at the scan; their edges only wake it.
  const auto input_edge = [weak](const Edge&) {
    if (auto q = weak.lock()) {
      q->device->input_wake();
    }
  };
  for (LineInput* in : pins.inputs) {
    if (in != nullptr) {
      in->on_edge(input_edge);
    }
  }
  for (int n = 1; n <= kOutputCount; ++n) {
    if (LineOutput* out = pins_.outputs[index(n)]) {
      out->set(level_of((pin_levels_ & bit(n)) != 0));
      // From now on through the output driver: an output is on when its pin is high.
      skewed_[index(n)] =
          std::make_unique<SkewedOutput>(scheduler_, *out, Level::High, params_.output_off_skew);
      pins_.outputs[index(n)] = skewed_[index(n)].get();
    }
  }
  wake();
}

// ---------------------------------------------------------------- power

void Ans1::power_off() {
  if (!powered_) return;
  powered_ = false;
  channels_fixed_ = false;
  settle_position(); // what the last scan before the supply went left, as when scanning every period
  scheduler_.cancel(scan_event_);
  scheduler_.cancel(speed_event_);
  scheduler_.cancel(write_event_);
  scheduler_.cancel(leave_event_);
  scan_event_ = speed_event_ = write_event_ = leave_event_ = {};
  scan_at_ = Nanos::max();
  write_count_ = 0;
  queued_levels_ = pin_levels_ = outputs_ = 0;
  for (LineOutput* out : pins_.outputs) {
    if (out != nullptr) out->set(Level::Low); // no supply: nothing conducts
  }
}

void Ans1::power_on() {
  if (powered_) return;
  powered_ = true;
  // Machine Revolutions is "stored in non-volatile memory" (L1215) [MODEL: its count at power-off].
  const std::uint32_t revolutions = monitors_.counters().value(CounterId::Revolutions);
  // RAM starts again as at construction.
  position_ = PositionSetup{};
  sr_setup_ = ShiftRegisterSetup{};
  channels_ = {};
  monitors_ = Monitors(monitor_faults(variant_), params_.brake_sample_start);
  monitors_.configure(MonitorSetup{}, position_.full_scale_count);
  quad_->restart(scheduler_.now());
  resolver_count_ = 0;
  resolver_angle_ = 0;
  resolver_seen_ = false; // absolute: read afresh at the first scan (L768)
  last_peak_ = Nanos::min();
  resolver_fault_active_ = resolver_fault_latched_ = false;
  gmp_ = previous_gmp_ = 0;
  first_scan_ = true;
  electrical_inputs_ = active_inputs_ = previous_active_inputs_ = 0;
  ls_ = outputs_ = 0;
  masks_ = OutputStatusMasks{};
  shift_register_ = ShiftRegister{};
  output_force_enable_ = output_force_state_ = input_force_enable_ = input_force_state_ = 0;
  speed_ = SpeedFilter{};
  speed_reference_count_ = 0;
  rpm_clamped_ = false;
  last_wrap_ = Nanos::min();
  last_wrap_direction_ = 0;
  time_of_rotation_ = 0;
  changed_outside_ = true;
  grid_origin_ = scheduler_.now() + params_.scan_phase - scan_period();
  configure(host_.power_up()); // wakes the scan on the new grid
  monitors_.preset_counter(CounterId::Revolutions, revolutions);
  if (scan_at_ == Nanos::max()) schedule_scan(scheduler_.now() + params_.scan_phase);
  speed_event_ = scheduler_.at(scheduler_.now() + params_.speed_update_period, [this] { speed_update(); });
}

// ---------------------------------------------------------------- programming

void Ans1::configure_position(const PositionSetup& setup) {
  settle_position();
  const bool period_changes = setup.slave_mode != position_.slave_mode;
  const bool fsc_changes = setup.full_scale_count != position_.full_scale_count;
  const bool source_changes = setup.sensor != position_.sensor || period_changes;
  position_ = setup;
  if (source_changes) {
    // A new transducer is not motion: restart resolver tracking and the speed reference.
    resolver_seen_ = false;
    last_peak_ = Nanos::min();
    speed_reference_count_ = transducer_count();
  }
  update_advances();
  if (fsc_changes) {
    monitors_.configure(monitors_.setup(), position_.full_scale_count);
  }
  if (period_changes && !in_scan_) { // from inside a scan (the host), the scan reschedules itself
    scheduler_.cancel(scan_event_);
    grid_origin_ = scheduler_.now();
    schedule_scan(scheduler_.now() + scan_period());
  }
  wake();
}

void Ans1::configure_output(int output, const OutputSetup& setup) {
  channels_[index(output)].configure(setup);
  update_advances();
  wake();
}

void Ans1::configure_shift_register(const ShiftRegisterSetup& setup) {
  if (setup.input == 0) {
    shift_register_.clear(); // disabled or deleted
  }
  sr_setup_ = setup;
  wake();
}

void Ans1::configure_monitors(const MonitorSetup& setup) {
  monitors_.configure(setup, position_.full_scale_count);
  wake();
}

void Ans1::configure(const Ans1Setup& setup) {
  configure_position(setup.position);
  for (int n = 1; n <= kOutputCount; ++n) {
    configure_output(n, setup.output(n));
  }
  configure_shift_register(setup.shift_register);
  configure_monitors(setup.monitors);
}

Ans1Setup Ans1::setup() const {
  Ans1Setup s;
  s.position = position_;
  for (int n = 1; n <= kOutputCount; ++n) {
    s.output(n) = channels_[index(n)].setup();
  }
  s.shift_register = sr_setup_;
  s.monitors = monitors_.setup();
  return s;
}

std::uint16_t Ans1::user_defined_enabled() const { return ans1::user_defined_enabled(monitors_.claims()); }

const OutputSetup& Ans1::output_setup(int output) const { return channels_[index(output)].setup(); }

void Ans1::preset_machine(std::optional<std::uint16_t> value) {
  settle_position();
  if (value) {
    position_.preset_value = *value;
  }
  position_.scaled_offset = preset_offset(position_.preset_value, scaled());
  gmp_ = global_position(scaled(), position_.scaled_offset, position_.full_scale_count);
  wake();
}

void Ans1::preset_output(int output, std::optional<std::uint16_t> value) {
  channels_[index(output)].preset(gmp(), value);
  wake();
}

void Ans1::force_outputs(std::uint16_t enable, std::uint16_t state) {
  output_force_enable_ = enable;
  output_force_state_ = state;
  wake();
}

void Ans1::force_inputs(std::uint16_t enable, std::uint16_t state) {
  input_force_enable_ = enable;
  input_force_state_ = state;
  wake();
}

void Ans1::clear_errors() {
  settle_position();
  if (!resolver_fault_active_) {
    resolver_fault_latched_ = false;
  }
  monitors_.clear_errors();
  wake();
}

// ---------------------------------------------------------------- status

std::uint16_t Ans1::ls_position(int output) const {
  return channels_[index(output)].ls_position(gmp(), position_.full_scale_count);
}

const AdvanceCounts& Ans1::advances(int output) const { return channels_[index(output)].advances(); }

bool Ans1::heartbeat() const { return (scheduler_.now() / milliseconds(500)) % 2 == 1; }

std::int64_t Ans1::transducer_count() const {
  if (position_.slave_mode) {
    return slave_count_;
  }
  if (position_.sensor == SensorType::Quadrature) {
    return quad_->count(scheduler_.now());
  }
  if (walking_peaks_) {
    return count_at(last_run_grid(scheduler_.now()));
  }
  return resolver_count_;
}

Nanos Ans1::scan_period() const {
  return position_.slave_mode ? params_.slave_scan_period : params_.master_scan_period;
}

std::int32_t Ans1::scaled() const {
  return scaled_count(transducer_count(), position_.counts_per_cycle, position_.full_scale_count);
}

// ---------------------------------------------------------------- the scan

void Ans1::schedule_scan(Nanos at) {
  scan_at_ = at;
  scan_event_ = scheduler_.at(
      at, [this] { run_scan(); }, Scheduler::Tie::Last);
}

Ans1::ResolverTrack Ans1::read_peak(ResolverTrack track, Nanos peak) const {
  const double s = pins_.stator_sin != nullptr ? pins_.stator_sin->sample(peak) : 0.0;
  const double c = pins_.stator_cos != nullptr ? pins_.stator_cos->sample(peak) : 0.0;
  const ResolverReading r =
      decode_resolver(s, c, excitation_.value(peak), params_.resolver_min_ratio, params_.resolver_max_ratio);
  if (!r.valid) {
    track.fault_active = true;
    track.fault_latched = true;
    return track; // position holds its last valid value
  }
  track.fault_active = false;
  if (position_.fault_auto_clear) {
    track.fault_latched = false;
  }
  // CntDir = 1: GMP increases counter-clockwise (L1840).
  const auto angle = position_.count_ccw
                         ? static_cast<std::uint16_t>((kResolverCounts - r.angle) % kResolverCounts)
                         : r.angle;
  if (!track.seen) {
    track.count = angle; // absolute within a turn at power-up
    track.seen = true;
  } else {
    track.count += angle_step(track.angle, angle);
  }
  track.angle = angle;
  return track;
}

void Ans1::sample_resolver(Nanos now) {
  const Nanos peak = excitation_.latest_peak(now);
  if (peak > now || peak == last_peak_) {
    return;
  }
  last_peak_ = peak;
  const ResolverTrack t = read_peak(resolver_track(), peak);
  if (!resolver_seen_ && t.seen) {
    speed_reference_count_ = t.count; // the first reading is not motion
  }
  resolver_count_ = t.count;
  resolver_angle_ = t.angle;
  resolver_seen_ = t.seen;
  resolver_fault_active_ = t.fault_active;
  resolver_fault_latched_ = t.fault_latched;
}

void Ans1::read_inputs() {
  std::uint16_t electrical = 0;
  for (int n = 1; n <= kInputCount; ++n) {
    const LineInput* in = pins_.inputs[index(n)];
    if (in != nullptr && is_high(in->level())) {
      electrical = static_cast<std::uint16_t>(electrical | bit(n));
    }
  }
  electrical_inputs_ = electrical;
  // Input Active State bit 1: active when no current flows (L1805). Forces feed all logic.
  const auto logical = static_cast<std::uint16_t>(electrical ^ position_.input_active_state);
  active_inputs_ = static_cast<std::uint16_t>((logical & ~input_force_enable_) |
                                              (input_force_state_ & input_force_enable_));
}

void Ans1::scan() {
  const Nanos now = scheduler_.now();
  ++scans_;
  const bool resolver = !position_.slave_mode && position_.sensor == SensorType::Resolver;
  if (resolver) {
    sample_resolver(now);
  } else {
    resolver_fault_active_ = false; // resolver inputs are ignored (L1485)
  }
  read_inputs();
  const auto rising = static_cast<std::uint16_t>(active_inputs_ & ~previous_active_inputs_);
  const auto changed = static_cast<std::uint16_t>(active_inputs_ ^ previous_active_inputs_);
  const std::uint16_t fsc = position_.full_scale_count;

  gmp_ = global_position(scaled(), position_.scaled_offset, fsc);
  if (!first_scan_ && position_.preset_input != 0 && (rising & bit(position_.preset_input)) != 0) {
    preset_machine();
  }
  if (first_scan_) {
    previous_gmp_ = gmp_;
  }
  for (int n = 1; n <= kOutputCount; ++n) {
    OutputChannel& channel = channels_[index(n)];
    const std::uint8_t input = channel.setup().ls_preset_input;
    if (!first_scan_ && input != 0 && (rising & bit(input)) != 0) {
      channel.preset(gmp_);
    }
  }

  const ShiftRegister sr_before = shift_register_;
  shift_register_.step(previous_gmp_, gmp_,
                       sr_setup_.input != 0 && (active_inputs_ & bit(sr_setup_.input)) != 0, sr_setup_, fsc);
  // Since the last scan, which left the channels at a fixed point, nothing but edges of inputs
  // no channel reads woke the scan (or it is a monitor's deadline): each channel would return
  // the state it holds (scan_skipping.cpp, "input edges"), as ls_ and masks_ show.
  channels_held_ = shift_register_ == sr_before && channels_hold(now, changed);
  scans_channels_held_ += channels_held_ ? 1U : 0U;

  // Time of Rotation: "the time it took for the shaft to complete its last rotation" (L2537),
  // whichever way it turns (L2535), in 0.1 ms: between two roll-overs of GMP (L794) in the same
  // direction, forward onto 0 or backward off it; a roll-over after one the other way starts
  // the timing again (what lies between them is no whole rotation).
  const bool forward_wrap = !first_scan_ && crossed_forward(previous_gmp_, gmp_, 0, fsc);
  const bool backward_wrap = !first_scan_ && crossed_forward(gmp_, previous_gmp_, 0, fsc);
  if (forward_wrap || backward_wrap) {
    const std::int8_t direction = forward_wrap ? 1 : -1;
    if (last_wrap_ != Nanos::min() && last_wrap_direction_ == direction) {
      const std::int64_t tenths = (now - last_wrap_) / microseconds(100);
      time_of_rotation_ = static_cast<std::uint16_t>(tenths > 0xFFFF ? 0xFFFF : tenths);
    }
    last_wrap_ = now;
    last_wrap_direction_ = direction;
  }

  const ScanState state = scan_state(now);

  OutputStatusMasks masks{0, 0, 0, 0, 0, 0, 0};
  std::uint16_t ls = 0;
  for (int n = 1; n <= kOutputCount && !channels_held_; ++n) {
    const OutputState s = channels_[index(n)].scan(state, params_.time_only_retrigger_restarts);
    const auto shift = static_cast<unsigned>(n - 1);
    // Branch-free: eight conditions of sixteen channels every 10 us.
    const auto set = [shift](std::uint16_t& mask, bool on) {
      mask = static_cast<std::uint16_t>(mask | (static_cast<unsigned>(on) << shift));
    };
    set(masks.calc, s.calc);
    set(masks.simple, s.simple);
    set(masks.pulse, s.pulse);
    set(masks.window, s.window);
    set(masks.shift_register, s.sr);
    set(masks.rpm, s.rpm);
    set(masks.timer, s.timer_ok);
    set(ls, s.ls);
  }
  if (!channels_held_) {
    masks_ = masks;
    ls_ = ls;
  }

  // Arbitration ([MODEL] §4.13): transducer fault, then force, then the monitors' fault and
  // overflow outputs, then the LS function.
  monitors_.scan(now, MonitorInputs{gmp_, transducer_count(), active_inputs_});
  std::uint16_t out = apply_claims(monitors_.claims(), ls_, ls_programmed(channels_));
  out = static_cast<std::uint16_t>((out & ~output_force_enable_) |
                                   (output_force_state_ & output_force_enable_));
  if (resolver && resolver_fault()) {
    out = position_.hold_outputs_on_fault ? outputs_ : 0;
  }
  if (variant_ == Variant::OutputStuckOn) {
    out = static_cast<std::uint16_t>(out | bit(1));
  }
  outputs_ = out;
  queue_outputs(now, out);

  previous_active_inputs_ = active_inputs_;
  previous_gmp_ = gmp_;
  first_scan_ = false;
  host_.scan(); // acts on a Transmit edge; its programming takes effect from the next scan
}

ScanState Ans1::scan_state(Nanos now) const {
  ScanState state;
  state.now = now;
  state.gmp = gmp_;
  state.fsc = position_.full_scale_count;
  state.speed = speed_.value();
  state.speed_reported = speed_.reported();
  state.active_inputs = active_inputs_;
  state.shift_register = &shift_register_;
  state.shift_register_enabled = sr_setup_.input != 0;
  state.advance_wrong_sign = variant_ == Variant::AdvanceWrongSign;
  state.late_wrap_to = variant_ == Variant::SetpointOffByOneAtWrap;
  state.timer_error = params_.timer_error;
  return state;
}

// ---------------------------------------------------------------- speed

// What a scan reads of the speed: its sign (edge_shift), its rounded RPM (DA16 w2, the RPM
// window) and the advances it sets (their clamps make status bit 7). A scan that reads the same
// of it does the same, so the filter's tail after a stop (S = k S each update, ~1,600 of them
// before S sticks at the least subnormal, at a reported 0 RPM and advances of 0 counts) wakes
// no scan.
auto Ans1::speed_as_scanned() const -> SpeedAsScanned {
  SpeedAsScanned seen;
  const double s = speed_.value();
  seen.sign = s > 0.0 ? 1 : (s < 0.0 ? -1 : 0);
  seen.reported = speed_.reported();
  for (std::size_t i = 0; i < channels_.size(); ++i) seen.advances[i] = channels_[i].advances();
  return seen;
}

void Ans1::speed_update() {
  const std::int64_t count = transducer_count();
  const std::int64_t delta = count - speed_reference_count_;
  speed_reference_count_ = count;
  const SpeedAsScanned before = speed_as_scanned();
  if (variant_ != Variant::SpeedFilterStuck) {
    speed_.update(delta, position_.counts_per_cycle, params_.speed_update_period, position_.rpm_filter);
  }
  update_advances();
  if (!(speed_as_scanned() == before)) {
    wake(); // a scan reads the speed and the advances it sets; at standstill neither changes
  }
  speed_event_ = scheduler_.at(scheduler_.now() + params_.speed_update_period, [this] { speed_update(); });
}

void Ans1::update_advances() {
  const double scale = variant_ == Variant::AdvanceWrongScale ? 2.0 : 1.0;
  bool clamped = false;
  for (auto& channel : channels_) {
    channel.update_advances(speed_.value(), position_.full_scale_count, scale);
    clamped = clamped || channel.advances().clamped;
  }
  rpm_clamped_ = clamped;
}

// ---------------------------------------------------------------- output pins

void Ans1::queue_outputs(Nanos now, std::uint16_t levels) {
  if (levels == queued_levels_) {
    return;
  }
  queued_levels_ = levels;
  if (write_count_ == kWriteQueue) { // cannot happen with sane delays; keep order anyway
    write_event_ = EventId{};
    write_due_outputs();
  }
  writes_[(write_head_ + write_count_) % kWriteQueue] = PendingWrite{now + params_.output_delay, levels};
  ++write_count_;
  if (write_count_ == 1) {
    write_event_ = scheduler_.at(now + params_.output_delay, [this] { write_due_outputs(); });
  }
}

void Ans1::write_due_outputs() {
  const PendingWrite w = writes_[write_head_];
  write_head_ = (write_head_ + 1) % kWriteQueue;
  --write_count_;
  const auto changed = static_cast<std::uint16_t>(w.levels ^ pin_levels_);
  pin_levels_ = w.levels;
  for (int n = 1; n <= kOutputCount; ++n) {
    if ((changed & bit(n)) != 0) {
      if (LineOutput* out = pins_.outputs[index(n)]) {
        out->set(level_of((w.levels & bit(n)) != 0));
      }
    }
  }
  if (write_count_ > 0) {
    const Nanos next = writes_[write_head_].time;
    write_event_ =
        scheduler_.at(next < scheduler_.now() ? scheduler_.now() : next, [this] { write_due_outputs(); });
  }
}

} // namespace hilrig::models::ans1
