#pragma once
// The virtual SMD23E: an integrated stepper indexer/driver/motor as a deterministic state
// machine on a Scheduler (virtual time). The host talks to it through its 10 output and 10
// input words (RegisterMap: input registers 0–9, holding registers 1024–1033, as on Modbus
// TCP, spec §6.1); its discrete inputs are LineInputs (High = current flows). The motor shaft
// is a plant driven by the indexer's step train and observable as a function of time.
// The device must outlive the scheduler's pending events (as a virt::DigitalLine must).

#include <array>
#include <cstdint>
#include <functional>
#include <optional>
#include <span>
#include <vector>

#include "core/line.hpp"
#include "core/register_map.hpp"
#include "core/scheduler.hpp"
#include "models/smd23e/kinematics.hpp"
#include "models/smd23e/params.hpp"
#include "models/smd23e/status_bits.hpp"
#include "signals/quadrature_decoder.hpp"

namespace hilrig::models::smd23e {

inline constexpr std::uint16_t kInputBase = 0;     // input registers 0–9
inline constexpr std::uint16_t kOutputBase = 1024; // holding registers 1024–1033
inline constexpr std::size_t kWords = 10;
using Words = std::array<std::uint16_t, kWords>;

// One stretch of motion of the step train, in physical steps since power-up.
struct ShaftRun {
  std::int64_t origin = 0; // step position where this chain of motion started
  int dir = 1;             // +1 CW, −1 CCW
  double base = 0.0;       // progress already travelled in this chain before `motion`
  Motion motion;
  Nanos stop = Nanos::max();      // when the run ended (planned end or interruption)
  std::int64_t issued_before = 0; // steps issued (unsigned) before this run
  std::int64_t lost_before = 0;   // signed steps the shaft lost before this run
};

class Smd23e final : public RegisterMap {
public:
  explicit Smd23e(Scheduler& scheduler, Params params = {});
  Smd23e(const Smd23e&) = delete;
  Smd23e& operator=(const Smd23e&) = delete;
  ~Smd23e() override;

  // Wires discrete input 1…3 (2 on M12 units) to a line; High = current flows.
  void connect_input(int number, LineInput& line);
  // The motor shaft's encoder as quadrature lines, 1024 counts a turn (a rig plant turning
  // the shaft; virtual only, the real encoder is internal, spec §1.2). Connected, the encoder
  // counts follow the lines instead of the steps, and stall detection compares them with the
  // steps issued.
  void connect_encoder(LineInput& a, LineInput& b);
  // Stall detection against the connected encoder at now (spec §2.3, L1255, L2885): the steps
  // issued and the counts turned since the present move set off; call after each step issued,
  // the encoder's own edges call it too.
  void watch_encoder();

  // RegisterMap: input registers 0–9; holding registers 1024–1033 (output words) and 0–9
  // (input words, FC 3 reads both, spec §6.1); writes only to 1024–1033.
  RegisterStatus read_input_registers(std::uint16_t address, std::span<std::uint16_t> out) override;
  RegisterStatus read_holding_registers(std::uint16_t address, std::span<std::uint16_t> out) override;
  RegisterStatus write_holding_registers(std::uint16_t address,
                                         std::span<const std::uint16_t> values) override;

  // The host's view, at the scheduler's now.
  void write_outputs(const Words& words);
  [[nodiscard]] Words input_words() const;
  [[nodiscard]] const Words& output_words() const { return out_; }
  [[nodiscard]] std::uint16_t status1() const;
  [[nodiscard]] std::uint16_t status2() const;

  // Plant observation. step_position: net steps issued (CW +) since power-up, at any t up to
  // now back to the start of the oldest kept run (the last kKeptRuns); shaft_steps: where the shaft actually
  // is, in steps (differs with lost steps or a blocked shaft). motor_position: the Motor Position register
  // (presets and homing applied).
  [[nodiscard]] std::int64_t step_position(Nanos t) const;
  [[nodiscard]] std::int64_t shaft_steps(Nanos t) const;
  [[nodiscard]] std::int64_t motor_position() const;
  [[nodiscard]] std::int64_t encoder_position() const;
  [[nodiscard]] const std::vector<ShaftRun>& runs() const { return runs_; }
  // Runs kept in the history: a board served for a week makes millions of moves, and only
  // the present run (and a little of the past, for tests and traces) is ever looked at.
  static constexpr std::size_t kKeptRuns = 64;
  [[nodiscard]] bool moving() const { return run_.has_value(); }
  // When the present run issues its next whole step after now (the same rule step_position
  // counts by, exact to 1 ns); Nanos::max() when not moving or no further step comes.
  [[nodiscard]] Nanos next_step_time(Nanos now) const;
  // The shaft stays where it is until an outside call (a host write, an input edge, a fault,
  // power): no run, no pause before the next move, no delayed input or late stop pending.
  // shaft_steps() is the same at every later time until then.
  [[nodiscard]] bool at_rest_until_told() const { return !run_ && !pause_event_.valid() && deferred_ == 0; }
  [[nodiscard]] double motor_current_amps() const;
  [[nodiscard]] const Params& params() const { return p_; }

  // Plant and environment events (tests and campaigns).
  void block_shaft(bool blocked);
  void over_temperature();
  // The over-temperature condition starts (hot) or ends: while it lasts the driver faults
  // whenever it is enabled, and Reset Driver Fault does not clear the fault (L2922).
  void set_over_temperature(bool hot);
  void set_temperature_warning(bool warn) { temp_warn_ = warn; }
  void network_link(bool up);

  // The supply goes off / comes back ([[power_cycle]], README "Power cycle"). Off: the step
  // train stops where it is, the unit answers nothing (input words 0) and ignores its inputs.
  // On: as at power-up (L2243, L2284): Command Mode; the flash configuration and assembled
  // move loaded (L1132, L1836, L2235, L2433), or 0x6408 without one; every error and the
  // post-save lock-out cleared (L2331, L2476); Motor and Encoder Position 0, Position Invalid.
  void power_off();
  void power_on();
  [[nodiscard]] bool powered() const { return powered_; }

private:
  enum class Kind : std::uint8_t { Position, EncoderMove, Jog, Registration, Home, Blend, Dwell };
  enum class HomeStage : std::uint8_t { Search, Pause1, Back, Pause2, Creep, ProxCreep };

  struct MoveSpec {
    double vp = 0;
    double a = 0;
    double d = 0;
    RampShape shape{};
    std::uint16_t jerk = 0;
  };
  struct Segment {
    std::int32_t offset = 0;
    MoveSpec spec;
  };
  struct Run {
    Kind kind = Kind::Position;
    int dir = 1;
    MoveSpec spec;
    std::int64_t target = 0;    // register target for Position/Encoder moves (for Resume)
    bool stopping = false;      // controlled stop under way
    bool holding = false;       // the stop is a Hold
    bool error_in_hold = false; // an error came while the Hold brought it to a stop
    bool reg_triggered = false;
    bool reg_hold_pending = false;
    std::int64_t reg_min = 0;
    std::int64_t reg_stop = 0;
    double chain_start = 0.0; // progress at the start of this command (registration M)
    std::uint16_t command_bit = 0;
    HomeStage home_stage = HomeStage::Search;
    int home_dir = 1;
    std::size_t segment = 0; // assembled moves
    // Dwell Move: the dwell time, word 9 of the Run command that started it (L1179, L2436).
    std::uint32_t dwell_ms = 0;
    std::function<void()> on_end;
  };
  struct Held {
    Kind kind = Kind::Position;
    int dir = 1;
    std::int64_t target = 0;
  };

  // Configuration (§6.4).
  struct Config {
    Words words{};
    std::int32_t vs = 1;
  };
  [[nodiscard]] std::optional<Config> validate_config(const Words& w) const;
  [[nodiscard]] InputFunction function_of(int input) const;
  [[nodiscard]] int input_with(InputFunction f) const; // −1 when none
  [[nodiscard]] bool input_active(int input) const;
  [[nodiscard]] bool function_active(InputFunction f) const;
  [[nodiscard]] bool encoder_enabled() const;
  [[nodiscard]] double vs() const { return static_cast<double>(cfg_.vs); }
  [[nodiscard]] std::int32_t steps_per_turn() const { return static_cast<std::int32_t>(cfg_.words[4]); }

  // Output word processing.
  void process(const Words& previous);
  void process_config(const Words& previous);
  void process_command(const Words& previous);
  void dispatch(std::uint16_t msw_bit, bool indexed_start);
  void command_error() { set_error(cmd_err_); }
  // Sets an error flag. A move held, or on its way into the Hold state, cannot be resumed
  // after an error (L1224, L1239, L1247): it is forgotten, and Resume then reads as one with
  // nothing held (a Command Error, [A] §3.11). The Hold State bit stays as the Hold left it.
  void set_error(bool& flag);
  [[nodiscard]] std::optional<MoveSpec> read_spec(bool allow_below_vs) const;
  [[nodiscard]] std::optional<std::int32_t> read_value(std::size_t upper_word, std::int32_t limit) const;
  [[nodiscard]] bool may_start(int dir, bool jog);
  void begin_command();

  // Moves.
  void start_position_move(bool absolute);
  void start_encoder_move(bool absolute);
  void start_jog(int dir, bool registration, std::uint16_t bit);
  void start_home(int dir);
  void start_assembled();
  void resume();
  void run_dwell_segment(std::size_t index, std::uint32_t dwell_ms);
  void home_next(HomeStage stage);
  void homing_error();
  [[nodiscard]] bool limit_toward(int dir) const; // the limit ending travel in dir is active
  void change_jog(const MoveSpec& spec);

  // Motion engine.
  void start_motion(Run run, std::vector<Piece> pieces, int dir);
  void continue_motion(std::vector<Piece> pieces);
  void keep_recent_runs();
  void end_motion(Nanos at);
  void on_motion_end();
  [[nodiscard]] double progress() const; // of the current chain, at now
  [[nodiscard]] double velocity() const;
  void controlled_stop(bool hold);
  void registration_stop();
  void immediate_stop();
  void schedule_registration_min();
  void schedule_stall_check();
  void act(std::function<void()> action, bool stop_like);

  // Inputs.
  void on_input(int input, Level level);
  void limit_active(int dir);
  void capture_encoder();

  Scheduler& sched_;
  Params p_;
  Nanos epoch_;
  Words out_{};
  Config cfg_{};
  std::optional<Config> pending_cfg_;
  bool configured_ = false;
  bool config_mode_ = false;
  bool config_error_ = true;
  bool flash_locked_ = false;
  std::uint16_t flash_result_ = 0;
  bool powered_ = true;
  // Flash memory: what survives a power cycle (Save Configuration L2331, Save Assembled Move
  // L2476); RAM copies above are loaded from it at power-up.
  std::optional<Config> flash_config_;
  std::vector<Segment> flash_segments_;
  void load_flash(); // at power-up

  // Status flags.
  bool cmd_err_ = false;
  bool in_err_ = false;
  bool pos_invalid_ = true;
  bool move_complete_ = false;
  bool homed_ = false;
  bool hold_state_ = false;
  bool inv_par_ = false;
  bool limit_cond_ = false;
  bool stall_ = false;
  bool drv_fault_ = false;
  bool hot_ = false; // the over-temperature condition (set_over_temperature)
  bool net_loss_ = false;
  bool temp_warn_ = false;
  bool lock_cw_ = false;
  bool lock_ccw_ = false;
  bool program_mode_ = false;
  bool transmit_segment_ = false;
  bool segment_refused_ = false; // a segment of this programming cycle was refused (L1196)
  std::uint16_t last_jerk_ = 0;

  std::array<Level, 3> raw_{Level::Low, Level::Low, Level::Low};

  std::int64_t reg_offset_ = 0; // Motor Position register − step position
  std::int64_t enc_offset_ = 0; // Encoder register − counts derived from the shaft
  // The connected shaft encoder (connect_encoder), counting from 0 at power-up.
  std::optional<signals::QuadratureDecoder> shaft_encoder_;
  // Where the step train, the shaft and the connected encoder stood when the present motion
  // set off from rest (start_motion): stall detection watches the encoder "while a move is in
  // progress" (L1255), so each move is judged by what it did itself, not by a disagreement
  // left over from an earlier stall (which neither Reset Errors nor a preset undoes).
  std::int64_t watch_steps_ = 0;
  std::int64_t watch_shaft_ = 0;
  std::int64_t watch_count_ = 0;
  std::int64_t captured_ = 0;
  bool shaft_blocked_ = false;
  std::int64_t shaft_frozen_ = 0;
  std::int64_t slip_ = 0;
  Nanos last_motion_end_{0};
  // Idle current % in effect, and a re-configured one waiting for the end of a move (L2350).
  std::optional<std::uint16_t> idle_percent_;
  std::optional<std::uint16_t> pending_idle_percent_;

  std::vector<ShaftRun> runs_;
  std::optional<Run> run_;
  std::optional<Held> held_;
  std::vector<Segment> segments_;
  std::uint16_t armed_ = 0; // indexed command bit waiting for a Start Indexed edge
  EventId end_event_{};
  EventId aux_event_{};
  EventId stall_event_{};
  EventId pause_event_{};
  int deferred_ = 0;     // delayed inputs and late stops scheduled and not run yet
  EventId home_pause_{}; // pause_event_ when it is a homing pause
};

} // namespace hilrig::models::smd23e
