#include "models/pls2700/pls2700.hpp"

#include <algorithm>
#include <stdexcept>
#include <string>

#include "models/pls2700/error_codes.hpp"
#include "models/pls2700/instructions.hpp"
#include "models/pls2700/params_check.hpp"

namespace hilrig::models::pls2700 {

namespace {

// Params that do not go together (params_check.hpp) are refused before the module runs: no
// reference off the update grid, no empty fault band.
const Params& checked(ModelVariant model, const Params& params) {
  if (const auto conflict = params_conflict(model, params))
    throw std::invalid_argument("pls2700 " + std::string(conflict->fields.front()) + ": " +
                                conflict->expected);
  return params;
}

} // namespace

Pls2700::Pls2700(Scheduler& scheduler, ModelVariant model, const Params& params, Fault fault)
    : scheduler_(scheduler), model_(traits(model)), params_(checked(model, params)), fault_(fault),
      period_(fault == Fault::LateOutputs ? model_.update_period * 2 : model_.update_period),
      excitation_(params.excitation_hz, params.excitation_amplitude),
      advance_speed_{AdvanceSpeed(advance_window_updates(params.advance_speed_window, period_), period_),
                     AdvanceSpeed(advance_window_updates(params.advance_speed_window, period_), period_)},
      inputs_(std::make_shared<InputState>()), outputs_(std::make_shared<OutputPins>()) {
  setup_.mask = params_.power_up_mask;
  switch_program_ = params_.program_switch_at_program;
  for (std::size_t ch = 0; ch < 2; ++ch) {
    restart_tach(ch);
  }
  // The update clock is locked to the reference: each update samples the stators at a
  // reference peak (README "Decoder"). Sampling at an earlier peak would add its age to every
  // latency, past the manual's 200/400 us position throughput (L457).
  first_update_ = excitation_.peak_at_or_after(scheduler_.now() + params_.update_phase);
  schedule_update(first_update_);
}

Pls2700::Pls2700(Scheduler& scheduler, const Pls2700Pins& pins, ModelVariant model, const Params& params,
                 Fault fault)
    : Pls2700(scheduler, model, params, fault) {
  attach(pins);
}

Pls2700::~Pls2700() { scheduler_.cancel(update_event_); }

void Pls2700::attach(const Pls2700Pins& pins) {
  pins_ = pins;
  *outputs_ = pins.outputs;
  if (params_.output_off_skew != Nanos{0}) {
    drivers_ = std::make_shared<std::array<std::unique_ptr<SkewedOutput>, kOutputCount>>();
    for (std::size_t i = 0; i < outputs_->size(); ++i) {
      if (LineOutput* out = (*outputs_)[i]) {
        (*drivers_)[i] =
            std::make_unique<SkewedOutput>(scheduler_, *out, Level::High, params_.output_off_skew);
        (*outputs_)[i] = (*drivers_)[i].get();
      }
    }
  }
  for (std::size_t ch = 0; ch < 2; ++ch) {
    LineInput* in = pins.inputs[ch];
    if (in == nullptr || !model_.has_inputs) {
      continue;
    }
    (*inputs_)[ch].level = in->level();
    // Edges are queued with their time and act at the next update (no debounce, L1716).
    in->on_edge([state = inputs_, ch](const Edge& e) {
      InputQueue& q = (*state)[ch];
      q.level = e.level;
      if (q.count == kInputQueue) { // full: the oldest edge is lost
        q.head = (q.head + 1) % kInputQueue;
        --q.count;
      }
      q.events[(q.head + q.count) % kInputQueue] = InputEvent{e.time, e.level};
      ++q.count;
    });
  }
  drive_outputs(output_states_);
}

void Pls2700::schedule_update(Nanos at) {
  update_event_ = scheduler_.at(at, [this] { update(); });
}

void Pls2700::restart_tach(std::size_t ch) {
  const int code = setup_.channels[ch].tach_code;
  const bool thirty_two = params_.tach_32ms_on_single_channel && model_.channels == 1;
  const Nanos interval = tach_interval(code, thirty_two);
  // Fault variant: the 30 ms response sums over 60 ms but still scales as 30 ms.
  const Nanos window = (fault_ == Fault::TachWindowWrong && code == 0) ? interval * 2 : interval;
  // The interval starts at the sample its first counted step starts from: the last update, or
  // the first one still to come. Starting it at `now` would also count the step from the last
  // update to `now`, one update too many in the first value.
  Nanos start = last_update_ >= Nanos{0} ? last_update_ : first_update_;
  if (fault_ == Fault::TachFirstIntervalLong) {
    start = scheduler_.now();
  }
  tach_[ch].restart(start, window, interval, tach_in_tenths(code));
}

void Pls2700::sample_channel(std::size_t ch, Nanos peak) {
  const AnalogInput* sin = pins_.stator_sin[ch];
  const AnalogInput* cos = pins_.stator_cos[ch];
  const double ref = excitation_.value(peak);
  const StatorReading r =
      decode_stators(sin != nullptr ? sin->sample(peak) : 0.0, cos != nullptr ? cos->sample(peak) : 0.0, ref,
                     params_.min_stator_ratio, params_.max_stator_ratio);
  fault_present_[ch] = !r.valid;
  if (!r.valid) {
    fault_latched_[ch] = true; // Err1, held until Clear Errors (L601, L1359)
    have_raw_[ch] = false;
    raw_step_[ch] = 0;
    advance_speed_[ch].reset();
    return;
  }
  const ChannelSetup& c = setup_.channels[ch];
  const int previous_mp = mp_[ch];
  raw_step_[ch] = have_raw_[ch] ? circular_step(raw_[ch], r.raw, kInternalCounts) : 0;
  raw_[ch] = r.raw;
  mp_[ch] =
      pls2700::machine_position(absolute_position(r.raw, c.scale_factor), c.circular_offset, c.scale_factor);
  if (have_raw_[ch]) {
    cycles_[ch].advance(circular_step(previous_mp, mp_[ch], c.scale_factor));
  }
  if (have_raw_[ch]) {
    advance_speed_[ch].add(raw_step_[ch]);
  }
  have_raw_[ch] = true;
  tach_[ch].add(raw_step_[ch]);
}

void Pls2700::run_cycles(Nanos now) {
  for (std::size_t ch = 0; ch < 2; ++ch) {
    CycleLogic& cycle = cycles_[ch];
    cycle.end_of_cycle(setup_.channels[ch].cycle_length);
    InputQueue& q = (*inputs_)[ch];
    while (q.count > 0 && q.events[q.head].time + params_.input_delay <= now) {
      cycle.input(q.events[q.head].level);
      q.head = (q.head + 1) % kInputQueue;
      --q.count;
    }
  }
}

void Pls2700::update() {
  const Nanos now = scheduler_.now();
  const Nanos peak = excitation_.latest_peak(now);
  for (std::size_t ch = 0; ch < static_cast<std::size_t>(channels()); ++ch) {
    sample_channel(ch, peak);
    tach_[ch].update(now); // the value is replaced once per interval, held between (R-T-7 [I])
  }
  if (model_.has_inputs) {
    run_cycles(now);
  }
  output_states_ = evaluate_outputs();
  drive_outputs(output_states_);
  ++updates_;
  last_update_ = now;
  schedule_update(now + period_);
}

double Pls2700::speed_counts_per_ms(std::size_t ch) const {
  // R-ADV-5 [X]: the windowed speed (advance_speed.hpp), in MP counts per ms.
  const double sf = static_cast<double>(setup_.channels[ch].scale_factor);
  if (fault_ == Fault::AdvanceSpeedJitter) {
    const double period_ms = static_cast<double>(period_.count()) / 1e6;
    return static_cast<double>(raw_step_[ch]) * sf / kInternalCounts / period_ms;
  }
  return advance_speed_[ch].steps_per_ms() * sf / kInternalCounts;
}

std::uint8_t Pls2700::evaluate_outputs() const {
  const WindowRules rules{params_.wrap_pairs, params_.equal_pair_full_turn};
  unsigned states = 0;
  for (int out = 1; out <= kOutputCount; ++out) {
    const auto ch = static_cast<std::size_t>(owner_channel(model_, setup_, out));
    const bool faulted = params_.fault_turns_off_all_outputs ? any_fault_latched() : fault_latched_[ch];
    const auto bit = static_cast<unsigned>(out - 1);
    if (faulted || ((static_cast<unsigned>(setup_.mask) >> bit) & 1u) == 0) {
      continue;
    }
    const OutputSetup& o = setup_.outputs[static_cast<std::size_t>(out - 1)];
    double v = speed_counts_per_ms(ch);
    if (v < 0.0 && params_.reverse_advance == ReverseAdvance::Disabled) {
      v = 0.0;
    }
    if (fault_ == Fault::AdvanceWrongSign) {
      v = -v;
    }
    const double s_on = v * o.advance_on_ms;
    const double s_off = v * o.advance_off_ms;
    bool on = false;
    if (model_.has_inputs) {
      const CycleLogic& cycle = cycles_[ch];
      on = cycle.cycling() && cycle_output_on(o, cycle.ls_position(), setup_.channels[ch].cycle_length, s_on,
                                              s_off, cycle.another_cycle_follows());
    } else {
      const int mp = mp_[ch];
      on = output_on(o, mp, setup_.channels[ch].scale_factor, s_on, s_off, rules) &&
           !holes_[static_cast<std::size_t>(out - 1)].hole(mp);
    }
    if (on) {
      states |= 1u << bit;
    }
  }
  return static_cast<std::uint8_t>(states);
}

void Pls2700::drive_outputs(std::uint8_t levels) {
  const auto write = [](const OutputPins& pins, std::uint8_t lv) {
    for (std::size_t i = 0; i < pins.size(); ++i) {
      if (pins[i] != nullptr) {
        pins[i]->set(level_of(((static_cast<unsigned>(lv) >> i) & 1u) != 0));
      }
    }
  };
  if (params_.output_delay <= Nanos{0}) {
    write(*outputs_, levels);
    return;
  }
  scheduler_.after(params_.output_delay,
                   [pins = outputs_, keep = drivers_, levels, write] { write(*pins, levels); });
}

bool Pls2700::any_fault_latched() const {
  for (std::size_t ch = 0; ch < static_cast<std::size_t>(channels()); ++ch) {
    if (fault_latched_[ch]) {
      return true;
    }
  }
  return false;
}

void Pls2700::clear_errors() {
  error_byte_ = error::kNone;
  for (std::size_t ch = 0; ch < 2; ++ch) {
    fault_latched_[ch] = fault_present_[ch]; // a fault still present stays
  }
}

void Pls2700::after_program(const Setup& before, int entered_output) {
  for (std::size_t ch = 0; ch < 2; ++ch) {
    if (before.channels[ch].tach_code != setup_.channels[ch].tach_code) {
      restart_tach(ch);
    }
    if (before.channels[ch].trigger != setup_.channels[ch].trigger) {
      cycles_[ch].set_trigger(setup_.channels[ch].trigger);
    }
  }
  // R-LS-5: a reprogrammed output clears its old ranges, then sets its new ones.
  for (int out = 1; out <= kOutputCount; ++out) {
    const auto i = static_cast<std::size_t>(out - 1);
    const OutputSetup& old_o = before.outputs[i];
    const OutputSetup& new_o = setup_.outputs[i];
    const bool same = old_o.pair_count == new_o.pair_count &&
                      std::equal(old_o.pairs.begin(), old_o.pairs.end(), new_o.pairs.begin());
    if (same && out != entered_output) {
      continue; // an entered pair re-sets its range even when unchanged (L1074)
    }
    const int sf = setup_.channels[static_cast<std::size_t>(owner_channel(model_, setup_, out))].scale_factor;
    for (int k = 0; k < old_o.pair_count; ++k) {
      holes_[i].clear_range(old_o.pairs[static_cast<std::size_t>(k)], sf);
    }
    for (int k = 0; k < new_o.pair_count; ++k) {
      holes_[i].set_range(new_o.pairs[static_cast<std::size_t>(k)], sf);
    }
  }
}

std::uint8_t Pls2700::write_btw(std::span<const std::uint16_t> words) {
  if (words.empty() || words.size() > kMaxBtwWords || !powered_) {
    return error_byte(); // a PLC cannot send these; an unpowered module takes none
  }
  const bool latch = fault_ != Fault::ErrorLatchMissing;
  if (latch && (error_byte_ != error::kNone || any_fault_latched()) && words[0] != kClearErrors) {
    error_byte_ = error::kMessageIgnored; // L1413, L1435, L1763
    return error_byte_;
  }
  error_byte_ = error::kNone;
  const InstructionRules rules{model_.off_le_on_rule && fault_ != Fault::OffLeOnNotEnforced};
  std::uint8_t first_error = error::kNone;
  std::size_t i = 0;
  while (i < words.size()) {
    const Setup before = setup_;
    const InstructionResult r = execute_instruction(words.subspan(i), model_, rules, setup_);
    if (r.error != error::kNone) {
      if (latch) {
        error_byte_ = r.error; // this and all later instructions are discarded (L1340, L1438)
        return error_byte_;
      }
      if (first_error == error::kNone) {
        first_error = r.error;
      }
    } else if (r.kind == InstructionKind::ClearErrors) {
      clear_errors();
      if (latch && any_fault_latched()) {
        error_byte_ = error::kMessageIgnored; // the transducer is still faulted [I]
        return error_byte_;
      }
    } else {
      after_program(before, r.output);
    }
    i += std::max<std::size_t>(r.length, 1);
  }
  error_byte_ = first_error;
  return error_byte_;
}

std::uint16_t Pls2700::position_word(int channel) const {
  const std::size_t ch = index(channel);
  if (channel > channels()) {
    return 0;
  }
  return fault_latched_[ch] ? kFaultWord : static_cast<std::uint16_t>(mp_[ch]);
}

std::uint16_t Pls2700::tach_word(int channel) const {
  const std::size_t ch = index(channel);
  if (channel > channels()) {
    return 0;
  }
  if (fault_latched_[ch]) {
    return kFaultWord;
  }
  std::uint16_t word = tach_[ch].value();
  if (model_.has_inputs && input_energized(channel)) {
    word = static_cast<std::uint16_t>(word | 0x4000u); // IN1/IN2, regardless of polarity (L1607)
  }
  return word;
}

bool Pls2700::input_energized(int channel) const { return is_high((*inputs_)[index(channel)].level); }

std::uint16_t Pls2700::btr_word(std::size_t word) const {
  if (!powered_) return 0; // [MODEL] an unpowered module answers no block transfer
  if (model_.channels == 1) {
    switch (word) {
    case 0:
      return position_word(1);
    case 1:
      return tach_word(1);
    case 2:
      return status_word();
    default:
      return 0;
    }
  }
  switch (word) {
  case 0:
    return position_word(1);
  case 1:
    return tach_word(1);
  case 2:
    return position_word(2);
  case 3:
    return tach_word(2);
  case 4:
    return status_word();
  default:
    return 0;
  }
}

std::size_t Pls2700::read_btr(std::span<std::uint16_t> out) const {
  const std::size_t n = std::min(out.size(), btr_words());
  for (std::size_t k = 0; k < n; ++k) {
    out[k] = btr_word(k);
  }
  return n;
}

int Pls2700::owner(int output) const { return owner_channel(model_, setup_, output) + 1; }

bool Pls2700::autozero(int channel) {
  if (!program_mode() || channel < 1 || channel > channels() || fault_latched_[index(channel)]) {
    return false;
  }
  ChannelSetup& c = setup_.channels[index(channel)];
  c.circular_offset = autozero_offset(c.circular_offset, mp_[index(channel)], c.scale_factor);
  mp_[index(channel)] = 0; // the display shows 0 at once
  return true;
}

bool Pls2700::keyboard_delete_pair(int output, int pair) {
  if (!program_mode() || output < 1 || output > kOutputCount) {
    return false;
  }
  OutputSetup& o = setup_.outputs[static_cast<std::size_t>(output - 1)];
  if (pair < 1 || pair > o.pair_count) {
    return false;
  }
  const int sf =
      setup_.channels[static_cast<std::size_t>(owner_channel(model_, setup_, output))].scale_factor;
  holes_[static_cast<std::size_t>(output - 1)].clear_range(o.pairs[static_cast<std::size_t>(pair - 1)], sf);
  for (int k = pair; k < o.pair_count; ++k) {
    o.pairs[static_cast<std::size_t>(k - 1)] = o.pairs[static_cast<std::size_t>(k)];
  }
  --o.pair_count;
  o.pairs[static_cast<std::size_t>(o.pair_count)] = SetpointPair{};
  return true;
}

void Pls2700::power_off() {
  if (!powered_) return;
  powered_ = false;
  scheduler_.cancel(update_event_);
  update_event_ = {};
  output_states_ = 0;
  drive_outputs(0);
}

void Pls2700::power_on() {
  if (powered_) return;
  powered_ = true;
  for (HoleTable& h : holes_) {
    h.rebuild(); // from the stored pairs (L1074)
  }
  setup_.mask = params_.power_up_mask; // R-M-2 [I]: the mask's retention is not stated
  error_byte_ = error::kNone;          // [MODEL] a programming error is not kept in nvRAM
  for (std::size_t ch = 0; ch < 2; ++ch) {
    raw_[ch] = mp_[ch] = raw_step_[ch] = 0;
    have_raw_[ch] = false; // the absolute resolver is read afresh at the first update
    fault_present_[ch] = fault_latched_[ch] = false;
    advance_speed_[ch] = AdvanceSpeed(advance_window_updates(params_.advance_speed_window, period_), period_);
    cycles_[ch] = CycleLogic{};
    cycles_[ch].set_trigger(setup_.channels[ch].trigger);
    InputQueue& q = (*inputs_)[ch];
    q.head = q.count = 0; // edges while off were not seen; the level stays
  }
  last_update_ = Nanos{-1};
  first_update_ = excitation_.peak_at_or_after(scheduler_.now() + params_.update_phase);
  for (std::size_t ch = 0; ch < 2; ++ch) {
    restart_tach(ch);
  }
  schedule_update(first_update_);
}

} // namespace hilrig::models::pls2700
