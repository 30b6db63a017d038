// Register interface, configuration and command dispatch of the virtual SMD23E (spec §6).
#include "models/smd23e/smd23e.hpp"

#include <algorithm>
#include <bit>
#include <cmath>

#include "models/smd23e/multiword.hpp"

namespace hilrig::models::smd23e {

namespace {
constexpr std::int32_t kMaxTarget = 8'388'607;
constexpr std::int32_t kMaxSpeed = 2'999'999;
constexpr std::int32_t kMaxStartSpeed = 1'999'999;
// The move commands: the moves Move Complete reports (L2860) and Find Home (L887).
constexpr std::uint16_t kMoveBits = msw::kAbsolute | msw::kRelative | msw::kHomeCw | msw::kHomeCcw |
                                    msw::kJogCw | msw::kJogCcw | msw::kRunAssembled;
} // namespace

Smd23e::Smd23e(Scheduler& scheduler, Params params)
    : sched_(scheduler), p_(params), epoch_(scheduler.now() - params.heartbeat_phase) {
  net_loss_ = p_.netloss_at_powerup;
  if (p_.flash_config_valid) {
    // A typical saved configuration: v_s 100, 2048 steps/turn, encoder on, 2.0 A, 50 % idle.
    Words w{};
    w[0] = ccw::kEncoderEnable;
    w[1] = cfgw::kDriverEnable;
    w[3] = 100;
    w[4] = 2048;
    w[6] = 1024;
    w[7] = 50;
    w[8] = 20;
    flash_config_ = validate_config(w);
  }
  load_flash();
}

void Smd23e::load_flash() {
  if (flash_config_) {
    cfg_ = *flash_config_;
    configured_ = true;
    config_error_ = false;
    idle_percent_ = cfg_.words[7];
  }
  segments_ = flash_segments_; // restored at power-up, runnable once configured (L1132, L1205)
}

void Smd23e::power_off() {
  if (!powered_) return;
  if (run_ || pause_event_.valid()) immediate_stop(); // motor power gone: the steps stop here
  powered_ = false;
}

void Smd23e::power_on() {
  if (powered_) return;
  powered_ = true;
  epoch_ = sched_.now() - p_.heartbeat_phase;
  // RAM is gone: configuration, RAM assembled move, every flag and error (L2284, L2372).
  cfg_ = Config{};
  configured_ = false;
  config_mode_ = false;
  config_error_ = true;
  flash_locked_ = false; // the lock-out after a flash save lasts until power is cycled (L2331)
  flash_result_ = 0;
  cmd_err_ = in_err_ = move_complete_ = homed_ = hold_state_ = inv_par_ = false;
  limit_cond_ = stall_ = drv_fault_ = lock_cw_ = lock_ccw_ = false;
  program_mode_ = transmit_segment_ = segment_refused_ = false;
  net_loss_ = false;
  pos_invalid_ = true; // 0x6408 includes Position Invalid (L2284); a flash load leaves it set
  last_jerk_ = 0;
  armed_ = 0;
  held_.reset();
  idle_percent_.reset();
  pending_idle_percent_.reset();
  segments_.clear();
  // Motor Position and Encoder Position count from 0 again: the shaft stays where it is.
  reg_offset_ = -step_position(sched_.now());
  enc_offset_ = 0;
  enc_offset_ = -encoder_position();
  captured_ = 0;
  last_motion_end_ = sched_.now();
  load_flash();
  if (hot_) over_temperature(); // still hot: the driver faults again once enabled ([MODEL])
}

Smd23e::~Smd23e() {
  sched_.cancel(end_event_);
  sched_.cancel(aux_event_);
  sched_.cancel(stall_event_);
  sched_.cancel(pause_event_);
}

void Smd23e::connect_input(int number, LineInput& line) {
  if (number < 1 || number > (p_.m12 ? 2 : 3)) {
    return;
  }
  raw_[static_cast<std::size_t>(number - 1)] = line.level();
  line.on_edge([this, number](const Edge& e) {
    if (p_.input_delay > Nanos{0}) {
      ++deferred_;
      sched_.after(p_.input_delay, [this, number, level = e.level] {
        --deferred_;
        on_input(number - 1, level);
      });
    } else {
      on_input(number - 1, e.level);
    }
  });
}

// ---- RegisterMap ---------------------------------------------------------------------------

RegisterStatus Smd23e::read_input_registers(std::uint16_t address, std::span<std::uint16_t> out) {
  if (out.empty() || address + out.size() > kWords) {
    return RegisterStatus::IllegalDataAddress;
  }
  const Words in = input_words();
  for (std::size_t i = 0; i < out.size(); ++i) {
    out[i] = in[address + i];
  }
  return RegisterStatus::Ok;
}

RegisterStatus Smd23e::read_holding_registers(std::uint16_t address, std::span<std::uint16_t> out) {
  if (address + out.size() <= kWords && !out.empty()) {
    return read_input_registers(address, out);
  }
  if (out.empty() || address < kOutputBase || address + out.size() > kOutputBase + kWords) {
    return RegisterStatus::IllegalDataAddress;
  }
  for (std::size_t i = 0; i < out.size(); ++i) {
    out[i] = out_[address - kOutputBase + i];
  }
  return RegisterStatus::Ok;
}

RegisterStatus Smd23e::write_holding_registers(std::uint16_t address, std::span<const std::uint16_t> values) {
  if (values.empty() || address < kOutputBase || address + values.size() > kOutputBase + kWords) {
    return RegisterStatus::IllegalDataAddress;
  }
  Words w = out_;
  for (std::size_t i = 0; i < values.size(); ++i) {
    w[address - kOutputBase + i] = values[i];
  }
  write_outputs(w);
  return RegisterStatus::Ok;
}

void Smd23e::write_outputs(const Words& words) {
  const Words previous = out_;
  out_ = words;
  if (!powered_) return; // unseen; at power-up the words already held are no edge ([MODEL])
  process(previous);
  if (hot_) {
    over_temperature(); // the driver enabled while still over temperature faults at once ([MODEL])
  }
}

// ---- Status words --------------------------------------------------------------------------

std::uint16_t Smd23e::status1() const {
  std::uint16_t s = sw1::kControllerOk;
  auto set = [&s](bool on, std::uint16_t bit) {
    if (on) {
      s = static_cast<std::uint16_t>(s | bit);
    }
  };
  set(config_mode_, sw1::kConfigMode);
  set(config_error_, sw1::kConfigError);
  set(cmd_err_, sw1::kCommandError);
  set(in_err_, sw1::kInputError);
  set(pos_invalid_, sw1::kPositionInvalid);
  set(transmit_segment_, sw1::kTransmitSegment);
  set(program_mode_, sw1::kProgramMode);
  set(move_complete_, sw1::kMoveComplete);
  set(homed_, sw1::kHomed);
  set(hold_state_, sw1::kHoldState);
  set(!run_.has_value(), sw1::kStopped);
  if (run_ && !runs_.empty()) {
    const Phase ph = runs_.back().motion.phase(sched_.now());
    set(ph == Phase::Accelerate, sw1::kAccelerating);
    set(ph == Phase::Decelerate, sw1::kDecelerating);
    set(run_->dir > 0, sw1::kMovingCw);
    set(run_->dir < 0, sw1::kMovingCcw);
  }
  return s;
}

std::uint16_t Smd23e::status2() const {
  std::uint16_t s = 0;
  auto set = [&s](bool on, std::uint16_t bit) {
    if (on) {
      s = static_cast<std::uint16_t>(s | bit);
    }
  };
  const bool drive =
      configured_ && (cfg_.words[1] & cfgw::kDriverEnable) != 0 && (out_[1] & lsw::kDriveEnable) != 0;
  set(drive, sw2::kDriverEnabled);
  set(stall_, sw2::kStall);
  set(p_.sw2_bit13_as_figure, sw2::kOut1Figure);
  const std::int64_t half = std::max<std::int64_t>(1, p_.heartbeat_half_period.count());
  set(!config_mode_ && (((sched_.now() - epoch_).count() / half) & 1) != 0, sw2::kHeartbeat);
  set(limit_cond_, sw2::kLimitCondition);
  set(inv_par_, sw2::kInvalidJogChange);
  set(drv_fault_, sw2::kDriverFault);
  set(net_loss_, sw2::kNetworkLost);
  set(temp_warn_, sw2::kTempWarning);
  for (int i = 0; i < 3; ++i) {
    set(input_active(i), static_cast<std::uint16_t>(1U << i));
  }
  return s;
}

Words Smd23e::input_words() const {
  Words in{};
  if (!powered_) return in; // [MODEL] no answer while off: the host reads 0
  if (config_mode_) {
    const bool read_present = (out_[1] & cfgw::kReadPresent) != 0 && configured_;
    const Words& src = read_present ? cfg_.words : out_;
    for (std::size_t i : {1U, 2U, 3U, 4U, 6U, 7U, 8U}) {
      in[i] = src[i];
    }
    in[0] = read_present ? static_cast<std::uint16_t>(cfg_.words[0] | msw::kConfigMode)
                         : (config_error_ ? status1() : out_[0]);
    in[9] = flash_result_;
    return in;
  }
  in[0] = status1();
  in[1] = status2();
  const MultiWord pos = encode_multiword(motor_position());
  const MultiWord enc = encode_multiword(encoder_position());
  const MultiWord cap = encode_multiword(captured_);
  in[2] = pos.upper;
  in[3] = pos.lower;
  in[4] = enc.upper;
  in[5] = enc.lower;
  in[6] = cap.upper;
  in[7] = cap.lower;
  in[8] = static_cast<std::uint16_t>(std::lround(motor_current_amps() * 10.0));
  in[9] = last_jerk_;
  return in;
}

double Smd23e::motor_current_amps() const {
  const bool drive =
      configured_ && (cfg_.words[1] & cfgw::kDriverEnable) != 0 && (out_[1] & lsw::kDriveEnable) != 0;
  if (!drive || drv_fault_) {
    return 0.0;
  }
  const double full = static_cast<double>(cfg_.words[8]) / 10.0;
  const bool idle = !run_ && sched_.now() - last_motion_end_ >= p_.idle_current_delay;
  if (!idle || !p_.report_present_current) {
    return full;
  }
  // The idle percentage is the level the current drops *to* (spec §4, L1265).
  return full * static_cast<double>(idle_percent_.value_or(cfg_.words[7])) / 100.0;
}

// ---- Configuration -------------------------------------------------------------------------

InputFunction Smd23e::function_of(int input) const {
  if (!configured_) {
    return InputFunction::GeneralPurpose;
  }
  return static_cast<InputFunction>(
      (static_cast<unsigned>(cfg_.words[0]) >> (3U * static_cast<unsigned>(input))) & 7U);
}

int Smd23e::input_with(InputFunction f) const {
  for (int i = 0; i < 3; ++i) {
    if (function_of(i) == f) {
      return i;
    }
  }
  return -1;
}

bool Smd23e::input_active(int input) const {
  // Active level bit: 1 = active while current flows (NO), 0 = active with no current (NC).
  const bool no = ((configured_ ? cfg_.words[1] : 0U) >> input & 1U) != 0;
  return is_high(raw_[static_cast<std::size_t>(input)]) == no;
}

bool Smd23e::function_active(InputFunction f) const {
  const int i = input_with(f);
  return i >= 0 && input_active(i);
}

bool Smd23e::encoder_enabled() const {
  return p_.has_encoder && configured_ && (cfg_.words[0] & ccw::kEncoderEnable) != 0;
}

std::optional<Smd23e::Config> Smd23e::validate_config(const Words& w) const {
  const std::uint16_t control = w[0];
  const std::uint16_t word = w[1];
  if ((control & ccw::kReserved) != 0 || (word & cfgw::kReserved) != 0) {
    return std::nullopt;
  }
  std::array<unsigned, 3> codes{};
  for (std::size_t i = 0; i < 3; ++i) {
    codes[i] = (control >> (3 * i)) & 7U;
    if (codes[i] == 7U) {
      return std::nullopt;
    }
  }
  for (std::size_t i = 0; i < 3; ++i) {
    for (std::size_t j = i + 1; j < 3; ++j) {
      if (codes[i] != 0 && codes[i] == codes[j]) {
        return std::nullopt; // two inputs with the same function (general purpose may repeat)
      }
    }
  }
  if (p_.m12 && codes[2] != 0) {
    return std::nullopt;
  }
  const bool encoder = (control & ccw::kEncoderEnable) != 0;
  if ((control & ccw::kStallEnable) != 0 && !encoder) {
    return std::nullopt;
  }
  if (encoder && !p_.has_encoder) {
    return std::nullopt;
  }
  const std::int32_t upper = as_signed(w[2]);
  const std::int32_t lower = as_signed(w[3]);
  if (upper < 0 || lower < 0 || lower > 999) {
    return std::nullopt; // L2379: a Starting Speed lower word above 999 is invalid
  }
  const std::int32_t vs = upper * 1000 + lower;
  if (vs < 1 || vs > kMaxStartSpeed) {
    return std::nullopt;
  }
  if (w[4] < 200 || w[4] > 32767 || w[5] != 0 || w[6] != 1024 || w[7] > 100 || w[8] < 10 || w[8] > 34 ||
      w[9] != 0) {
    return std::nullopt;
  }
  Config c;
  c.words = w;
  c.words[0] = static_cast<std::uint16_t>(control & ~msw::kConfigMode);
  c.vs = vs;
  return c;
}

void Smd23e::process(const Words& previous) {
  if (flash_locked_) {
    return; // after a flash save the unit answers nothing until power is cycled (L2331)
  }
  const bool to_config = (out_[0] & msw::kConfigMode) != 0;
  if (to_config) {
    config_mode_ = true;
    process_config(previous);
    return;
  }
  // Leaving Configuration Mode changes nothing in the edge rule: a command bit is judged
  // against the Control Word last written, whatever its mode (L2403). A bit set in the
  // Configuration Mode Control Word and still set now made no transition and does not run
  // (L2405); one that was 0 there and is 1 now did go 0→1, and runs.
  config_mode_ = false;
  process_command(previous);
}

void Smd23e::process_config(const Words& previous) {
  if ((out_[1] & cfgw::kReadPresent) != 0) {
    return; // no new configuration while Read Present Configuration is set
  }
  const auto c = validate_config(out_);
  // Every write in Configuration Mode is "a configuration ... written" (L2846), "new
  // Configuration Data" (L1132), the same words again included: the manual ties both to the
  // write, not to a change or to entering the mode (spec §6.4 [A]). An invalid one is written
  // too: "after any invalid configuration has been written to the driver" (L2830).
  // It ends the move in every state, a Dwell Move's pause and a held move too ([MODEL]): the
  // assembled move it runs is erased, a held move would resume under other settings, and
  // after an invalid one the motor is not powered (L2828).
  if (run_ || pause_event_.valid() || held_) {
    immediate_stop();
  }
  pos_invalid_ = true; // a configuration written sets Position Invalid (L2846)
  if (!c) {
    // Unconfigured again: commands ignored, 0x6408 as at power-up (L2239, L2284, L2372).
    config_error_ = true;
    configured_ = false;
    return;
  }
  const bool save = (out_[1] & cfgw::kSaveConfig) != 0 && (previous[1] & cfgw::kSaveConfig) == 0;
  Config applied = *c;
  applied.words[1] = static_cast<std::uint16_t>(applied.words[1] & ~cfgw::kSaveConfig);
  cfg_ = applied;
  // A changed idle current takes effect only at the end of the first move after
  // re-configuration (L2350); the first configuration since power-up has nothing to keep.
  if (!idle_percent_) {
    idle_percent_ = applied.words[7];
  }
  pending_idle_percent_ = applied.words[7];
  configured_ = true;
  config_error_ = false;
  segments_ = flash_segments_; // it erases the RAM assembled move (L1132); a flash one stays ([MODEL])
  last_motion_end_ = sched_.now();
  if (save) {
    flash_result_ = 0xAAAA;
    flash_locked_ = true;
    flash_config_ = applied;
  }
}

// ---- Commands ------------------------------------------------------------------------------

std::optional<std::int32_t> Smd23e::read_value(std::size_t upper_word, std::int32_t limit) const {
  const auto v = decode_multiword(out_[upper_word], out_[upper_word + 1]);
  if (!v || *v > limit || *v < -limit) {
    return std::nullopt;
  }
  return v;
}

std::optional<Smd23e::MoveSpec> Smd23e::read_spec(bool with_jerk) const {
  const auto vp = read_value(4, kMaxSpeed);
  const std::uint16_t a = out_[6];
  const std::uint16_t d = out_[7];
  const std::uint16_t j = with_jerk ? out_[9] : 0;
  if (!vp || *vp < cfg_.vs || a < 1 || a > 5000 || d < 1 || d > 5000 || j > 5000) {
    return std::nullopt;
  }
  MoveSpec s;
  s.vp = static_cast<double>(*vp);
  const double scale = p_.fault == Fault::WrongAcceleration ? p_.wrong_accel_factor : 1.0;
  s.a = 1000.0 * a * scale; // steps/ms/s → steps/s² (L848–851)
  s.d = 1000.0 * d * scale;
  s.jerk = j;
  s.shape.linear_fraction = j == 0 ? 1.0 : (j == 1 ? 0.0 : p_.scurve_linear_fraction);
  return s;
}

bool Smd23e::may_start(int dir, bool jog) {
  (void)jog;
  if (run_ || pause_event_.valid()) {
    command_error(); // a move must finish or be stopped before the next starts (spec §9 #38)
    return false;
  }
  const bool drive = (cfg_.words[1] & cfgw::kDriverEnable) != 0 && (out_[1] & lsw::kDriveEnable) != 0;
  if (!drive || drv_fault_) {
    command_error();
    return false;
  }
  if (function_active(InputFunction::EmergencyStop)) {
    set_error(in_err_); // no move of any kind starts while E-Stop is active (L593)
    return false;
  }
  const bool limit_ahead =
      (dir > 0 &&
       ((p_.fault != Fault::IgnoredLimit && function_active(InputFunction::CwLimit)) || lock_cw_)) ||
      (dir < 0 &&
       ((p_.fault != Fault::IgnoredLimit && function_active(InputFunction::CcwLimit)) || lock_ccw_));
  if (limit_ahead) {
    set_error(in_err_); // L1043, L2835
    return false;
  }
  return true;
}

void Smd23e::begin_command() {
  move_complete_ = false;
  homed_ = false;
  hold_state_ = false;
  held_.reset();
}

void Smd23e::process_command(const Words& previous) {
  if (!configured_) {
    return; // commands are ignored while unconfigured (L2239)
  }
  const std::uint16_t msw = out_[0];
  const std::uint16_t lsw = out_[1];
  const auto rising = static_cast<std::uint16_t>(msw & ~previous[0]);
  const auto falling = static_cast<std::uint16_t>(previous[0] & ~msw);
  const auto lsw_rising = static_cast<std::uint16_t>(lsw & ~previous[1]);

  // Driver disabled while moving: motor voltage removed, the step train stops.
  if ((lsw & lsw::kDriveEnable) == 0 && run_) {
    immediate_stop();
    pos_invalid_ = true;
  }
  if (armed_ != 0 && ((msw & armed_) == 0 || (lsw & lsw::kIndexed) == 0)) {
    armed_ = 0; // clearing the command before the input edge cancels an indexed move
  }
  // A jog/registration command bit returning to 0 is a controlled stop (L1033, L1063).
  if (run_ && (run_->kind == Kind::Jog || run_->kind == Kind::Registration) &&
      (falling & run_->command_bit) != 0 && (rising & msw::kHold) == 0) {
    if (run_->kind == Kind::Jog) {
      controlled_stop(false);
    } else if (!run_->stopping && progress() - run_->chain_start >= static_cast<double>(run_->reg_min)) {
      // A stop already under way (the S tail of an earlier condition, or a Hold) is not
      // restarted: the move outputs S once from the first stop condition (L1049, L1054).
      registration_stop();
    }
  }
  // Jog speed/acceleration changes on the fly (L1026).
  if (run_ && run_->kind == Kind::Jog && !run_->stopping &&
      (out_[4] != previous[4] || out_[5] != previous[5] || out_[6] != previous[6] ||
       out_[7] != previous[7])) {
    const auto vp = decode_multiword(out_[4], out_[5]);
    const std::uint16_t a = out_[6];
    const std::uint16_t d = out_[7];
    if (!vp || *vp < 1 || *vp > kMaxSpeed || a < 1 || a > 5000 || d < 1 || d > 5000) {
      set_error(inv_par_); // the motor keeps its old values
    } else {
      MoveSpec s = run_->spec;
      const double scale = p_.fault == Fault::WrongAcceleration ? p_.wrong_accel_factor : 1.0;
      s.vp = std::max(static_cast<double>(*vp), vs()); // below v_s the jog runs at v_s
      s.a = 1000.0 * a * scale;
      s.d = 1000.0 * d * scale;
      change_jog(s);
    }
  }
  // Home proximity (profile B): decelerate on the rising edge of LSW bit 11.
  if ((lsw_rising & lsw::kHomeProximity) != 0 && run_ && run_->kind == Kind::Home &&
      run_->home_stage == HomeStage::Search && (cfg_.words[0] & ccw::kHomeProximityEnable) != 0) {
    run_->home_stage = HomeStage::ProxCreep;
    std::vector<Piece> pieces;
    const double v = velocity();
    append_ramp(pieces, v, vs(), run_->spec.d, run_->spec.shape);
    append_cruise(pieces, vs(), std::numeric_limits<double>::infinity());
    continue_motion(std::move(pieces));
    if (function_active(InputFunction::Home)) {
      home_next(HomeStage::ProxCreep);
    }
  }

  // Assembled-move programming handshake (§6.5).
  if (program_mode_) {
    if ((falling & msw::kProgramMove) != 0) {
      program_mode_ = false;
      transmit_segment_ = false;
      if (segment_refused_) {
        // "All of the segments ... must be written to the SMD23E before the move can be run"
        // (L1179): a cycle with a refused segment leaves no move to run ([MODEL]).
        segments_.clear();
      }
      if ((lsw & lsw::kSaveAssembled) != 0) {
        flash_locked_ = true;
        flash_segments_ = segments_;
      }
      return;
    }
    if ((falling & msw::kProgramSegment) != 0) {
      transmit_segment_ = true;
    }
    if ((rising & msw::kProgramSegment) != 0) {
      transmit_segment_ = false;
      const auto offset = read_value(2, kMaxTarget);
      const auto spec = read_spec(true);
      // Equal speeds in consecutive segments are a Blend rule (L1118), judged at Run: the
      // type is chosen only then (L1179, L2472).
      if (!offset || !spec || out_[8] != 0 || segments_.size() >= 16) {
        segment_refused_ = true;
        command_error(); // L1118 (v_p >= v_s), L1196
      } else {
        segments_.push_back({*offset, *spec});
      }
    }
    return;
  }

  auto cmd = static_cast<std::uint16_t>(rising & ~(msw::kConfigMode | msw::kProgramSegment));
  if (cmd == 0) {
    return;
  }
  if ((cmd & msw::kResetErrors) != 0) {
    cmd_err_ = false;
    in_err_ = false;
    limit_cond_ = false;
    lock_cw_ = false;
    lock_ccw_ = false;
    move_complete_ = false;
    inv_par_ = false;
    stall_ = false;
    net_loss_ = false;
    // M-15: only with DriveEn = 0, and once the over-temperature condition is gone (L2922).
    if ((lsw & lsw::kClearDriverFault) != 0 && (lsw & lsw::kDriveEnable) == 0 && !hot_) {
      drv_fault_ = false;
    }
    cmd = static_cast<std::uint16_t>(cmd & ~msw::kResetErrors);
    if (cmd == 0) {
      return;
    }
  }
  if (std::popcount(cmd) > 1) {
    command_error(); // several command bits rising together [A]
    return;
  }
  if ((lsw & lsw::kReserved) != 0) {
    command_error(); // reserved LSW bits must be 0 [A]
    return;
  }
  if ((lsw & lsw::kIndexed) != 0 && (cmd & kMoveBits) != 0) {
    armed_ = cmd; // runs on the next Start Indexed input edge (§3.10)
    return;
  }
  dispatch(cmd, false);
}

void Smd23e::dispatch(std::uint16_t bit, bool indexed_start) {
  (void)indexed_start;
  const std::uint16_t lsw = out_[1];
  if ((bit & kMoveBits) != 0) {
    // Move Complete "is reset to '0' when the next move command is written" (L2860): also
    // when the move is then refused; out-of-range jog or registration parameters set it again.
    move_complete_ = false;
  }
  switch (bit) {
  case msw::kHold:
    if (run_ && !run_->stopping) {
      if (run_->kind == Kind::Registration) {
        if (progress() - run_->chain_start >= static_cast<double>(run_->reg_min)) {
          act(
              [this] {
                if (run_ && run_->kind == Kind::Registration && !run_->stopping) {
                  controlled_stop(false); // no S tail, no Hold state (L1070)
                }
              },
              true);
        } else {
          run_->reg_hold_pending = true;
        }
      } else {
        act(
            [this] {
              if (run_ && !run_->stopping) {
                controlled_stop(true);
              }
            },
            true);
      }
    } else if (pause_event_.valid()) {
      sched_.cancel(pause_event_); // homing pause or dwell: the move ends
      pause_event_ = {};
      hold_state_ = true;
    }
    return;
  case msw::kImmediateStop:
    if (run_ || pause_event_.valid()) {
      act(
          [this] {
            if (run_ || pause_event_.valid()) {
              immediate_stop();
              pos_invalid_ = true; // only a stop during a move invalidates the position (L2450)
            }
          },
          true);
    } else if (held_) {
      // A held move stands at its Starting Speed stop: the Immediate Stop ends it for good (it
      // "cannot be restarted", L943) and, with no step to cut short, keeps the position valid
      // (L2450: invalid only when set during a move).
      held_.reset();
      hold_state_ = false;
    }
    return;
  case msw::kResume:
    resume();
    return;
  case msw::kAbsolute:
  case msw::kRelative:
    if ((lsw & lsw::kEncoderMove) != 0) {
      start_encoder_move(bit == msw::kAbsolute);
    } else {
      start_position_move(bit == msw::kAbsolute);
    }
    return;
  case msw::kHomeCw:
  case msw::kHomeCcw:
    start_home(bit == msw::kHomeCw ? 1 : -1);
    return;
  case msw::kJogCw:
  case msw::kJogCcw:
    start_jog(bit == msw::kJogCw ? 1 : -1, (lsw & lsw::kRegistration) != 0, bit);
    return;
  case msw::kPresetPosition: {
    const auto v = read_value(2, kMaxTarget);
    if (!v || run_) {
      command_error();
      return;
    }
    reg_offset_ = *v - step_position(sched_.now());
    pos_invalid_ = false;
    move_complete_ = false;
    return;
  }
  case msw::kPresetEncoder: {
    const auto v = read_value(2, kMaxTarget);
    if (!v || !encoder_enabled()) {
      command_error();
      return;
    }
    enc_offset_ += *v - encoder_position();
    return;
  }
  case msw::kProgramMove:
    if (run_) {
      command_error();
      return;
    }
    program_mode_ = true;
    transmit_segment_ = true;
    segment_refused_ = false;
    segments_.clear();
    return;
  case msw::kRunAssembled:
    start_assembled();
    return;
  default:
    command_error();
    return;
  }
}

} // namespace hilrig::models::smd23e
