#include "models/ssi7361/ssi7361.hpp"

#include <algorithm>
#include <stdexcept>

#include "models/ssi7361/data_path.hpp"

namespace hilrig::models::ssi7361 {

namespace {

// The 7361's SSI master at one clock rate, with the model's clock and frame timer errors.
signals::SsiMaster master_for(bool clock_500khz, const Params& params) {
  signals::SsiMasterParams m = signals::ssi7361_master(clock_500khz);
  m.clock_period_error = params.clock_period_error;
  m.frame_period += params.frame_period_error;
  return signals::SsiMaster(m);
}

} // namespace

Ssi7361::Ssi7361(Scheduler& scheduler, LineOutput& clock, LineInput& data, Params params)
    : scheduler_(scheduler), clock_(clock), data_(data),
      params_(params), masters_{master_for(false, params), master_for(true, params)} {
  steps_[0] = build_steps(masters_[0]);
  steps_[1] = build_steps(masters_[1]);
  clock_.set(Level::High); // the clock idles high: a frame starts with a falling edge (§2.1)
  recompute();
  restart_rate_window();
  start_frame(std::max(params_.first_frame + params_.frame_phase, scheduler_.now()));
}

Ssi7361::~Ssi7361() { cancel_events(); }

void Ssi7361::cancel_events() {
  for (EventId* id : {&frame_event_, &rate_event_, &cycle_event_, &release_event_}) {
    if (id->valid()) scheduler_.cancel(*id);
    *id = EventId{};
  }
}

// ---------------------------------------------------------------- supply

void Ssi7361::power_off() {
  if (!powered_) return;
  powered_ = false;
  cancel_events();
  clock_.set(Level::High);
  ack_ = false;
}

void Ssi7361::power_on() {
  if (powered_) return;
  powered_ = true;
  state_.errors &= ibit::kEepromError;
  raw_ = 0;
  frames_ = 0;
  rate_ = 0;
  rate_overflow_ = false;
  ack_ = false;
  // A Transmit the PLC already holds is no 0->1 edge the module saw [MODEL].
  transmit_ = (commands_[cmd::kQ] & qbit::kTransmit) != 0;
  recompute();
  restart_rate_window();
  start_frame(scheduler_.now() + params_.first_frame + params_.frame_phase);
}

// ---------------------------------------------------------------- SSI master

Ssi7361::FrameSteps Ssi7361::build_steps(const signals::SsiMaster& master) const {
  FrameSteps steps{};
  const Nanos f1{0};
  std::size_t i = 0;
  for (unsigned k = 1; k <= kFrameBits; ++k) {
    Nanos sample = master.sample_time(f1, k); // half a period after R_k (§2.1 [MODEL])
    if (params_.sample_instant == SampleInstant::AtRisingEdge) sample = master.rising_edge(f1, k);
    if (params_.variant == Variant::SampleWrongEdge) sample = master.falling_edge(f1, k);
    steps[i++] = Step{master.falling_edge(f1, k), StepKind::Fall};
    steps[i++] = Step{master.rising_edge(f1, k), StepKind::Rise};
    steps[i++] = Step{sample, StepKind::Sample};
  }
  // In time order. At equal times the insertion order holds: sample k before F_(k+1), and
  // a sample taken at an edge after that edge.
  std::stable_sort(steps.begin(), steps.end(),
                   [](const Step& a, const Step& b) { return a.offset < b.offset; });
  return steps;
}

void Ssi7361::start_frame(Nanos at) {
  frame_event_ = scheduler_.at(at, [this, at] {
    frame_clock_ = state_.setup.ssi.clock_500khz ? 1 : 0; // the clock rate is taken at F1
    frame_start_ = at;
    step_ = 0;
    shift_ = 0;
    on_step();
  });
}

void Ssi7361::on_step() {
  const FrameSteps& steps = steps_[frame_clock_];
  // Run every step due now, then wait for the next one.
  while (step_ < steps.size() && frame_start_ + steps[step_].offset <= scheduler_.now()) {
    switch (steps[step_].kind) {
    case StepKind::Fall:
      clock_.set(Level::Low);
      break;
    case StepKind::Rise:
      clock_.set(Level::High);
      break;
    case StepKind::Sample: {
      const bool bit = !supply_ && params_.read_all_ones_without_supply ? true : is_high(data_.level());
      shift_ = (shift_ << 1) | (bit ? 1u : 0u);
      break;
    }
    }
    ++step_;
  }
  if (step_ < steps.size()) {
    frame_event_ = scheduler_.at(frame_start_ + steps[step_].offset, [this] { on_step(); });
    return;
  }
  finish_frame();
}

void Ssi7361::finish_frame() {
  raw_ = shift_ & kRawMask;
  ++frames_;
  recompute();
  start_frame(frame_start_ + masters_[frame_clock_].frame_period());
}

// ---------------------------------------------------------------- data and rate

// No frame read since power-up: the Data Value is 0, as the raw word and the rate are, not the
// setup and LO applied to a raw 0 that no transducer sent (the manual is silent, [MODEL] in
// docs/spec/ssi7361.md §7 A28).
void Ssi7361::recompute() {
  dv_ = frames_ == 0 ? 0 : ssi7361::data_value(raw_, state_.setup, state_.offset, params_);
}

std::int32_t Ssi7361::data_value() const { return saturate_i32(dv_); }

void Ssi7361::restart_rate_window() {
  if (rate_event_.valid()) scheduler_.cancel(rate_event_);
  dv_at_window_ = dv_;
  frames_at_window_ = frames_;
  rate_event_ = scheduler_.after(milliseconds(state_.setup.rut_ms), [this] { on_rate_update(); });
}

void Ssi7361::on_rate_update() {
  // A rate is the change between two frames read from the transducer (§3): before the window
  // started with a frame and a later frame ended it there is no rate and no ROVErr — at
  // power-up the Data Value of "no frame yet" is not a position.
  const bool two_frames = frames_at_window_ > 0 && frames_ > frames_at_window_;
  if (!two_frames && params_.variant != Variant::RateFromPowerUp) {
    restart_rate_window();
    return;
  }
  const std::int64_t roc = rate_of_change(dv_ - dv_at_window_, state_.setup.rut_ms, params_.rate_rounding);
  if (params_.variant != Variant::RateNotUpdated) {
    rate_ = saturate_i32(roc);
    // ROVErr follows each update: set above the limit, cleared by the next one in range (A20).
    rate_overflow_ = (roc < 0 ? -roc : roc) > params_.rate_overflow_limit;
  }
  restart_rate_window();
}

// ---------------------------------------------------------------- host words

void Ssi7361::write_command_words(std::size_t first, std::span<const std::uint16_t> words) {
  if (first > kCommandWords || words.size() > kCommandWords - first)
    throw std::out_of_range("7361: command word index past %AQ6");
  std::copy(words.begin(), words.end(), commands_.begin() + static_cast<std::ptrdiff_t>(first));
  if (!powered_) return; // the PLC's words wait; an unpowered module sees no edge
  const bool transmit = (commands_[cmd::kQ] & qbit::kTransmit) != 0;
  if (transmit && !transmit_) on_transmit_rise();
  if (!transmit && transmit_) on_transmit_fall();
  transmit_ = transmit;
}

void Ssi7361::on_transmit_rise() {
  if (ack_) return;     // the previous cycle is still acknowledged: ignored (§5.3 [MODEL])
  latched_ = commands_; // words changed while TRMT is 1 do not count
  if (params_.acknowledge_delay == Nanos{0}) {
    run_programming_cycle();
    return;
  }
  cycle_event_ = scheduler_.after(params_.acknowledge_delay, [this] {
    cycle_event_ = EventId{};
    run_programming_cycle();
  });
}

void Ssi7361::on_transmit_fall() {
  if (params_.acknowledge_delay == Nanos{0}) {
    ack_ = false;
    return;
  }
  release_event_ = scheduler_.after(params_.acknowledge_delay, [this] {
    release_event_ = EventId{};
    ack_ = false;
  });
}

void Ssi7361::run_programming_cycle() {
  const CycleOutcome out = run_cycle(state_, latched_, raw_, params_);
  ack_ = true;
  if (!out.accepted && !out.defaults_loaded) return; // old setup and LO kept
  recompute(); // a new format or scalars apply to the latest frame at once
  // RUT programmed (or back at its default): a new rate window.
  if (out.rut_programmed || out.defaults_loaded ||
      (out.preset_applied && params_.preset_restarts_rate_window))
    restart_rate_window();
}

void Ssi7361::read_status_words(std::size_t first, std::span<std::uint16_t> out) const {
  if (first > kStatusWords || out.size() > kStatusWords - first)
    throw std::out_of_range("7361: status word index past %AI6");
  const StatusWords all = status_words();
  std::copy_n(all.begin() + static_cast<std::ptrdiff_t>(first), out.size(), out.begin());
}

StatusWords Ssi7361::status_words() const {
  StatusWords w{};
  if (!powered_) return w;
  w[status::kI] = static_cast<std::uint16_t>(state_.errors | (rate_overflow_ ? ibit::kRateOverflow : 0u) |
                                             (ack_ ? ibit::kAcknowledge : 0u));
  const auto dv = split_words(data_value());
  const auto roc = split_words(rate_);
  w[status::kDataLow] = dv[0];
  w[status::kDataHigh] = dv[1];
  w[status::kRateLow] = roc[0];
  w[status::kRateHigh] = roc[1];
  w[status::kRawLow] = static_cast<std::uint16_t>(raw_ & 0xFFFFu);
  w[status::kRawHigh] = static_cast<std::uint16_t>(raw_ >> 16);
  return w;
}

} // namespace hilrig::models::ssi7361
