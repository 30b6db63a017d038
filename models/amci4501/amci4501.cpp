// The module's frame: pins, host words, deferred responses, timers. The mode rules are in
// measure.cpp.
#include "models/amci4501/amci4501.hpp"

#include <algorithm>
#include <stdexcept>

namespace hilrig::models::amci4501 {

namespace {
signals::CountMode count_mode(const Params& p) {
  return p.variant == Variant::X2Counting ? signals::CountMode::X2 : signals::CountMode::X4;
}
} // namespace

Amci4501::Amci4501(Scheduler& scheduler, const Pins& pins, Params params)
    : scheduler_(scheduler), pins_(pins), params_(params),
      cycle_driver_(scheduler, pins.cycle_output, params.cycle_output_on, params.output_off_skew),
      decoder_(count_mode(params), is_high(pins.a.level()), is_high(pins.b.level())) {
  if (params_.timer_resolution <= Nanos{0})
    throw std::invalid_argument("amci4501: timer_resolution must be > 0");
  if (params_.velocity_window <= Nanos{0})
    throw std::invalid_argument("amci4501: velocity_window must be > 0");
  deferred_.reserve(32);
  start_active_ = start_mark_ = active(pins.start.level(), params_.start_jumper);
  latch_active_ = latch_mark_ = active(pins.latch.level(), params_.latch_jumper);
  cycle_output_on_ = false; // off from power-up, not after a turn-off delay
  pins_.cycle_output.set(!params_.cycle_output_on);
  pins_.a.on_edge([this](const Edge& e) { on_encoder(e); });
  pins_.b.on_edge([this](const Edge& e) { on_encoder(e); });
  if (pins_.z != nullptr) pins_.z->on_edge([this](const Edge& e) { on_index(e); });
  pins_.start.on_edge([this](const Edge& e) { on_start(e); });
  pins_.latch.on_edge([this](const Edge& e) { on_latch(e); });
  scheduler_.after(params_.velocity_window - params_.velocity_phase,
                   [this, epoch = velocity_epoch_] { on_velocity_window(epoch); });
}

// ---------------------------------------------------------------- supply

void Amci4501::power_off() {
  if (!powered_) return;
  reset_measurement(); // drops pending responses (their generation) and the timeout
  deferred_.clear();
  instant_inputs_.clear(); // edges of this instant not yet taken: an unpowered module sees none
  powered_ = false;
}

void Amci4501::power_on() {
  if (powered_) return;
  powered_ = true;
  timeout_error_ = false; // before reset_measurement(): power-up clears the words too (L176)
  reset_measurement();
  config_ = Config{};
  decoder_ =
      signals::QuadratureDecoder(count_mode(params_), is_high(pins_.a.level()), is_high(pins_.b.level()));
  velocity_ref_ = 0;
  // [MODEL] The velocity timer starts with the module (L114 counts "in 50ms" from its own
  // timer): after a power cycle the first window is a whole one from power-up, not the rest
  // of a window on the grid the module had before it went off.
  ++velocity_epoch_;
  scheduler_.after(params_.velocity_window, [this, epoch = velocity_epoch_] { on_velocity_window(epoch); });
  no_response_ = timeout_error_ = command_error_ = parameter_error_ = acknowledge_ = false;
  start_active_ = start_mark_ = active(pins_.start.level(), params_.start_jumper);
  latch_active_ = latch_mark_ = active(pins_.latch.level(), params_.latch_jumper);
}

// ---------------------------------------------------------------- host words

void Amci4501::write_output_words(std::size_t first, std::span<const std::uint16_t> words) {
  if (first > kWords || words.size() > kWords - first)
    throw std::out_of_range("amci4501: output word past 7");
  const std::uint16_t old_control = outputs_[0];
  std::copy(words.begin(), words.end(), outputs_.begin() + static_cast<std::ptrdiff_t>(first));
  if (!powered_) return; // the SLC's words wait; an unpowered module sees no edge
  const std::uint16_t control_word = outputs_[0];
  const auto rose = [&](std::uint16_t bit) { return (control_word & bit) != 0 && (old_control & bit) == 0; };
  const auto fell = [&](std::uint16_t bit) { return (control_word & bit) == 0 && (old_control & bit) != 0; };

  // Acted on immediately, no programming cycle (L167). The acknowledge is its rising edge
  // (A10: a bit left high does not acknowledge the next result too).
  const bool received = params_.acknowledge_on_rising_edge ? rose(control::kReceived)
                                                           : (control_word & control::kReceived) != 0;
  if (received) new_value_ = false;
  if ((control_word & control::kClearError) != 0) {
    no_response_ = false;
    timeout_error_ = false;
    missed_ = 0;
  }
  if (rose(control::kTransmit)) program();
  if (fell(control::kTransmit)) acknowledge_ = false;
}

void Amci4501::read_input_words(std::size_t first, std::span<std::uint16_t> out) const {
  if (first > kWords || out.size() > kWords - first) throw std::out_of_range("amci4501: input word past 7");
  const InputWords all = input_words();
  std::copy_n(all.begin() + static_cast<std::ptrdiff_t>(first), out.size(), out.begin());
}

InputWords Amci4501::input_words() const {
  if (!powered_) return InputWords{};
  InputWords w = inputs_;
  w[0] = status();
  return w;
}

std::uint16_t Amci4501::status() const {
  std::uint16_t s = mode_status_bit(config_.mode);
  const auto set = [&](bool on, std::uint16_t bit) {
    if (on) s = static_cast<std::uint16_t>(s | bit);
  };
  set(new_value_, status::kNewValue);
  set(no_response_, status::kNoResponse);
  set(start_mark_, status::kStartMark);
  set(latch_mark_, status::kLatchMark);
  set(command_error_, status::kCommandError);
  set(parameter_error_, status::kParameterError);
  set(timeout_error_, status::kTimeout);
  set(acknowledge_, status::kAcknowledge);
  return s;
}

// Programming cycle (L168): latch, validate, acknowledge. An invalid configuration is
// acknowledged but not applied (A30: the previous one stays in force).
void Amci4501::program() {
  const ProgramResult r = validate_program(outputs_, params_);
  command_error_ = r.command_error;
  parameter_error_ = r.parameter_error;
  acknowledge_ = r.valid() || params_.acknowledge_invalid_program;
  if (!r.valid()) return;
  const int old_mode = config_.mode;
  config_ = r.config;
  if (params_.program_clears_results || config_.mode != old_mode) reset_measurement();
}

// [MODEL] A valid programming cycle starts measuring afresh: cycles in progress and
// responses not yet out are dropped, result words and the handshake are cleared (always on
// a mode change; else per Params::program_clears_results). No Response and Time Out stay
// until control bit 1 clears them (L93, L154; a programming cycle resets only the Command and
// Parameter errors, L118), and while Time Out is set words 1-7 stay as they are, even across
// a mode change (L119).
void Amci4501::reset_measurement() {
  ++generation_;
  cancel_timeout();
  end_cycle_output();
  phase_ = Phase::Idle;
  window_ = false;
  in_pulse_ = false;
  pulses_ = 0;
  have_s2_ = false;
  seen_active_ = {false, false};
  new_value_ = false;
  missed_ = 0;
  if (!timeout_error_) std::fill(inputs_.begin(), inputs_.end(), std::uint16_t{0});
}

// ---------------------------------------------------------------- inputs

bool Amci4501::active(Level level, Jumper jumper) const {
  return jumper == Jumper::Rising ? is_high(level) : !is_high(level);
}

void Amci4501::on_encoder(const Edge& e) {
  if (!powered_) return;
  const int delta = decoder_.update(is_high(pins_.a.level()), is_high(pins_.b.level()));
  if (delta != 0 && config_.mode == 2) mode2_position(delta, e.time);
}

void Amci4501::on_index(const Edge& e) {
  if (!powered_) return;
  decoder_.index(is_high(e.level));
  if (is_high(e.level) && (config_.mode == 2 || params_.z_resets_in_all_modes)) decoder_.set_count(0);
}

// Start and Latch edges wait for the end of their instant (end_of_instant()): the encoder
// edges of that instant come first, whichever the scheduler ran first.
void Amci4501::on_start(const Edge& e) {
  if (!powered_) return;
  instant_inputs_.push_back({true, e.level});
  end_instant_later();
}

void Amci4501::on_latch(const Edge& e) {
  if (!powered_) return;
  instant_inputs_.push_back({false, e.level});
  end_instant_later();
}

void Amci4501::end_instant_later() {
  if (!instant_end_event_.valid())
    instant_end_event_ = scheduler_.at(
        scheduler_.now(), [this] { end_of_instant(); }, Scheduler::Tie::Last);
}

void Amci4501::take_start(Level level, Nanos t) {
  const bool now_active = active(level, params_.start_jumper);
  if (now_active == start_active_) return;
  start_active_ = now_active;
  defer(t, Op::StartMark, now_active);
  start_edge(now_active, t);
}

void Amci4501::take_latch(Level level, Nanos t) {
  const bool now_active = active(level, params_.latch_jumper);
  if (now_active == latch_active_) return;
  latch_active_ = now_active;
  defer(t, Op::LatchMark, now_active);
  latch_edge(now_active, t);
}

// The end of an instant (README, "Same-instant order"), after every encoder and Z edge at it:
// the instant's Start/Latch edges in their order, then the timeout if it is due now and the
// cycle has not ended (a cycle ending at the timeout instant ended within it, L93), then the
// responses due now, which waited for that decision (fire()). Runs from the Tie::Last event
// of the first Start/Latch edge or of the timeout, whichever comes first.
void Amci4501::end_of_instant() {
  if (instant_end_event_.valid()) scheduler_.cancel(instant_end_event_);
  instant_end_event_ = {};
  const Nanos now = scheduler_.now();
  for (std::size_t i = 0; i < instant_inputs_.size(); ++i) {
    const InputEdge in = instant_inputs_[i];
    if (in.start)
      take_start(in.level, now);
    else
      take_latch(in.level, now);
  }
  instant_inputs_.clear();
  if (timeout_event_.valid() && timeout_due_ == now) {
    scheduler_.cancel(timeout_event_);
    on_timeout();
  }
  apply_due();
}

std::uint64_t Amci4501::time_value(std::int64_t from, std::int64_t to) const {
  std::int64_t ticks = to - from;
  if (params_.variant == Variant::TimeOffByOne) ++ticks;
  const std::int64_t tick_ns = params_.timer_resolution.count();
  std::int64_t us = ticks * tick_ns / 1000;
  if (params_.variant == Variant::TimeWrongUnit) us /= 10;
  return static_cast<std::uint64_t>(std::max<std::int64_t>(us, 0));
}

// ---------------------------------------------------------------- responses

Nanos Amci4501::response_delay() const {
  if (params_.variant == Variant::LateOutputs) return params_.late_throughput;
  return config_.mode == 5 ? params_.mode5_throughput : params_.throughput;
}

// A response to the input edge at t, visible one throughput later. The closure holds only
// `this`; the data waits in deferred_ (no allocation once it has grown).
void Amci4501::defer(Nanos t, Op op, bool on, std::uint8_t first, std::span<const std::uint16_t> words) {
  Deferred d{t + response_delay(), generation_, op, on, first, static_cast<std::uint8_t>(words.size()), {}};
  std::copy(words.begin(), words.end(), d.words.begin());
  deferred_.push_back(d);
  scheduler_.at(std::max(d.due, scheduler_.now()), [this] { fire(); });
}

void Amci4501::fire() {
  // The module's own timer before the responses due at its instant: a cycle that times out at
  // t shows nothing that would land at t. Whether it times out is known only at the instant's
  // end (end_of_instant() applies them then).
  if (timeout_event_.valid() && timeout_due_ == scheduler_.now()) return;
  apply_due();
}

// Applies the responses due by now in order of due time (equal: in order deferred); entries
// not yet due stay.
void Amci4501::apply_due() {
  const Nanos now = scheduler_.now();
  while (true) {
    auto next = deferred_.end();
    for (auto it = deferred_.begin(); it != deferred_.end(); ++it)
      if (it->due <= now && (next == deferred_.end() || it->due < next->due)) next = it;
    if (next == deferred_.end()) return;
    const Deferred d = *next;
    deferred_.erase(next);
    apply(d);
  }
}

void Amci4501::apply(const Deferred& d) {
  switch (d.op) {
  case Op::StartMark: // the inputs' own state: survives reprogramming
    start_mark_ = d.on;
    return;
  case Op::LatchMark:
    latch_mark_ = d.on;
    return;
  default:
    break;
  }
  if (d.generation != generation_) return; // superseded by a programming cycle
  const std::span<const std::uint16_t> words{d.words.data(), d.count};
  switch (d.op) {
  case Op::CycleOutput:
    set_cycle_output(d.on);
    break;
  case Op::Publish:
    publish(words, d.first);
    break;
  case Op::Write: // modes 5, 6: no update while a Time Out from modes 1-4 stands (L119)
    if (!timeout_error_) std::copy(words.begin(), words.end(), inputs_.begin() + d.first);
    break;
  default:
    break;
  }
}

// Publishing rule, modes 1-4 (L153, L223, L88): written only when the previous result was
// acknowledged; otherwise the cycle is missed, and after no_response_missed misses No
// Response is set. A missed result is discarded (A10).
void Amci4501::publish(std::span<const std::uint16_t> words, std::uint8_t first) {
  if (timeout_error_) return;
  if (!new_value_) {
    std::copy(words.begin(), words.end(), inputs_.begin() + first);
    new_value_ = true;
    missed_ = 0;
    ++published_;
    return;
  }
  ++missed_;
  ++missed_total_;
  if (missed_ >= params_.no_response_missed && params_.variant != Variant::NoResponseNeverRaised)
    no_response_ = true;
}

void Amci4501::set_cycle_output(bool on) {
  cycle_output_on_ = on;
  cycle_driver_.set(on ? params_.cycle_output_on : !params_.cycle_output_on);
}

// The cycle (mode 1) or the enable window (mode 2) ended at once, not by an input edge (a
// Time Out, a new measurement): the output turns off now, and a change still on its way to it
// is dropped. That change answered an edge inside the cycle; landing after the cycle ended,
// an ON would stay on with no window to end it (L12: the output matches the Latch only in
// the window and turns off at the window's end; L7: active while counting).
void Amci4501::end_cycle_output() {
  std::erase_if(deferred_, [](const Deferred& d) { return d.op == Op::CycleOutput; });
  if (cycle_output_on_) set_cycle_output(false);
}

void Amci4501::arm_timeout(Nanos from) {
  cancel_timeout();
  timeout_due_ = from + timeout_of(config_, params_);
  // At the end of its instant: a cycle that ends at start + timeout ended within it (L93).
  timeout_event_ = scheduler_.at(
      timeout_due_, [this] { end_of_instant(); }, Scheduler::Tie::Last);
}

void Amci4501::cancel_timeout() {
  if (!timeout_event_.valid()) return;
  scheduler_.cancel(timeout_event_);
  timeout_event_ = {};
  // Responses due now wait for the timeout's decision (fire()): the instant still ends.
  if (timeout_due_ == scheduler_.now()) end_instant_later();
}

// Velocity (L114): counts in the last window, every window; modes 1 (word 2, signed) and
// 2 (word 5, 0 when B leads A). Not frozen by the handshake (A37), but by Time Out: "The
// module will not update the input image table data until the timeout error has been
// cleared" (L119); the window still advances, so the first word after the clear is the
// last window's count. [MODEL] saturates at the int16 limits (L114 gives no range).
void Amci4501::on_velocity_window(std::uint32_t epoch) {
  if (epoch != velocity_epoch_) return; // a timer from before a power cycle
  if (powered_) {
    const std::int64_t p = decoder_.count();
    const std::int64_t v = std::clamp<std::int64_t>(p - velocity_ref_, -32768, 32767);
    velocity_ref_ = p;
    if (!timeout_error_ && config_.mode == 1) inputs_[2] = static_cast<std::uint16_t>(v);
    if (!timeout_error_ && config_.mode == 2)
      inputs_[5] = static_cast<std::uint16_t>(std::max<std::int64_t>(v, 0));
  }
  scheduler_.after(params_.velocity_window, [this, epoch] { on_velocity_window(epoch); });
}

} // namespace hilrig::models::amci4501
