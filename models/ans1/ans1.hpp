#pragma once
// The virtual ANS1 programmable limit switch (docs/spec/ans1.md). A deterministic state machine
// with the device's own timing: a position-and-output scan every Params::master_scan_period
// (10 us; 40 us as a slave) whose outputs reach the pins Params::output_delay later, a speed
// update every 14.6 ms, fed by timestamped edges and analog samples on its pins. It knows
// nothing of backends: it is built on a Scheduler and core line/analog interfaces.
//
// On the virtual bus:
//   virt::VirtualBus bus(scheduler);
//   Ans1 ans1(scheduler, wire_pins(bus, "ans1."), Params{}, *variant_from_name("nominal"));
//   // the rig drives ans1.A/B/Z and ans1.IN1..IN16 and sets the waveforms of the analog
//   // channels ans1.SIN/ans1.COS = TR * ans1.excitation().value(t) * sin/cos(theta(t));
//   // it reads ans1.OUT1..OUT16 (High = on) and the host words: ans1.host().write(k, v),
//   // ans1.host().read(k).
// Or construct without pins and attach(pins) once before running. The scan runs from
// construction on; keep the device alive while the scheduler runs.
#include <array>
#include <cstdint>
#include <memory>
#include <optional>
#include <vector>

#include "core/scheduler.hpp"
#include "core/skewed_output.hpp"
#include "models/ans1/ans1_pins.hpp"
#include "models/ans1/host_interface.hpp"
#include "models/ans1/monitors.hpp"
#include "models/ans1/output_channel.hpp"
#include "models/ans1/output_setup.hpp"
#include "models/ans1/params.hpp"
#include "models/ans1/position_resolver.hpp"
#include "models/ans1/position_setup.hpp"
#include "models/ans1/quiet_interval.hpp"
#include "models/ans1/setup.hpp"
#include "models/ans1/shift_register.hpp"
#include "models/ans1/speed.hpp"
#include "models/ans1/variants.hpp"

namespace hilrig::models::ans1 {

// DA16 words 10..16 (bit n-1 = output n; a 0 bit means that condition blocks the output).
struct OutputStatusMasks {
  std::uint16_t calc = 0;
  std::uint16_t simple = 0xFFFF;
  std::uint16_t pulse = 0xFFFF;
  std::uint16_t window = 0xFFFF;
  std::uint16_t shift_register = 0xFFFF;
  std::uint16_t rpm = 0xFFFF;
  std::uint16_t timer = 0xFFFF;
};

class Ans1 {
public:
  // Starts scanning at scheduler.now(). Pins may be attached now or later with attach().
  explicit Ans1(Scheduler& scheduler, const Params& params = {}, Variant variant = Variant::Correct);
  Ans1(Scheduler& scheduler, const Ans1Pins& pins, const Params& params = {},
       Variant variant = Variant::Correct);
  ~Ans1();
  Ans1(const Ans1&) = delete;
  Ans1& operator=(const Ans1&) = delete;

  void attach(const Ans1Pins& pins);

  // ---- Programming (what the host interface applies from command blocks) ----
  void configure_position(const PositionSetup& setup);            // CB2 (everything but the preset action)
  void configure_output(int output, const OutputSetup& setup);    // CB3/CB5/CB6; output 1..16
  void configure_shift_register(const ShiftRegisterSetup& setup); // CB9
  void configure_monitors(const MonitorSetup& setup);             // CB7, CB8, CB10, CB11
  // Everything at once (a loaded program, factory defaults). The preset actions are not part
  // of a setup.
  void configure(const Ans1Setup& setup);
  // CB11 bit 12: preset a production counter.
  void preset_counter(CounterId id, std::uint32_t value) {
    monitors_.preset_counter(id, value);
    wake();
  }
  // CB2 bit 14 (Transmit edge): GMP becomes MPV; with a value, MPV is loaded first (bit 11).
  void preset_machine(std::optional<std::uint16_t> value = std::nullopt);
  // CB3 bit 14: LSO = LSPV - GMP; with a value, LSPV is loaded first (bit 9).
  void preset_output(int output, std::optional<std::uint16_t> value = std::nullopt);
  // CB1 words 4/5 and 6/7: bit n-1 = point n.
  void force_outputs(std::uint16_t enable, std::uint16_t state);
  void force_inputs(std::uint16_t enable, std::uint16_t state);
  // Clear Errors: drops a latched resolver fault whose signals are valid again, and the
  // brake overrun faults.
  void clear_errors();
  // The supply off / back on (README "Power cycle"). Off: no scans, every output off, the host
  // reads 0. On: as at power-up, with what flash keeps (HostInterface::power_up: stored programs,
  // the global parameters, the Machine Revolutions count, L1215, L2224-L2250); the resolver is
  // absolute (L768), an encoder count starts at 0 (A36).
  void power_off();
  void power_on();
  [[nodiscard]] bool powered() const { return powered_; }
  // Slave mode: the position a master ANS1 sends, in transducer counts (mod CPC).
  void set_slave_position(std::int64_t count) {
    slave_count_ = count;
    wake();
  }
  // The oracle of scan skipping (Params::exact_scan): from now on, a scan every period.
  // Throws std::logic_error once an attached encoder is sampled (Ans1Pins::quad_waveform):
  // the oracle must be chosen before attach().
  void scan_every_period() {
    require_edges();
    settle_position();
    params_.exact_scan = true;
    wake_now();
  }
  // Something a scan reads changed outside a scan (a pin edge, a host word, a setting): the
  // next scan on the grid runs. Every mutator calls it; a new input must too (scan_skipping.cpp).
  void wake();

  [[nodiscard]] const PositionSetup& position_setup() const { return position_; }
  [[nodiscard]] const OutputSetup& output_setup(int output) const;
  [[nodiscard]] const ShiftRegisterSetup& shift_register_setup() const { return sr_setup_; }
  [[nodiscard]] const Params& params() const { return params_; }
  [[nodiscard]] Variant variant() const { return variant_; }

  // ---- The resolver reference the rig must lock its stator signals to ----
  [[nodiscard]] const ResolverExcitation& excitation() const { return excitation_; }

  // ---- Status (what the data attribute blocks report) ----
  [[nodiscard]] std::uint16_t gmp() const; // DA16 w1 (as of the last scan, skipped or not)
  [[nodiscard]] std::int16_t speed_rpm() const { return speed_.reported(); }         // DA16 w2
  [[nodiscard]] double speed() const { return speed_.value(); }                      // unrounded S
  [[nodiscard]] std::uint16_t time_of_rotation() const { return time_of_rotation_; } // DA16 w4, 0.1 ms
  [[nodiscard]] std::uint16_t input_states() const {
    return active_inputs_;
  } // logical, after polarity and force
  [[nodiscard]] std::uint16_t electrical_inputs() const { return electrical_inputs_; }
  [[nodiscard]] std::uint16_t output_states() const { return outputs_; } // logical output states (DA16 w9)
  [[nodiscard]] std::uint16_t ls_states() const { return ls_; } // LS function only, before arbitration
  [[nodiscard]] std::uint16_t user_defined_enabled() const;     // DA16 w17
  [[nodiscard]] const OutputStatusMasks& status_masks() const { return masks_; }
  [[nodiscard]] std::uint16_t ls_position(int output) const;                      // DA16 w19
  [[nodiscard]] const AdvanceCounts& advances(int output) const;                  // DA19 w9/w10
  [[nodiscard]] bool rpm_clamped() const { return rpm_clamped_; }                 // status bit 7
  [[nodiscard]] bool outputs_forced() const { return output_force_enable_ != 0; } // status bit 6
  [[nodiscard]] bool resolver_fault() const {
    return resolver_fault_active_ || resolver_fault_latched_;
  }                                     // bit 12
  [[nodiscard]] bool heartbeat() const; // status bit 14: toggles every 500 ms
  [[nodiscard]] std::uint16_t output_force_enable() const { return output_force_enable_; }
  [[nodiscard]] std::uint16_t output_force_state() const { return output_force_state_; }
  [[nodiscard]] std::uint16_t input_force_enable() const { return input_force_enable_; }
  [[nodiscard]] std::uint16_t input_force_state() const { return input_force_state_; }
  [[nodiscard]] const ShiftRegister& shift_register() const { return shift_register_; }
  // Brake monitor, die protection, production counters, input edge positions (DA5-8, 16-19).
  [[nodiscard]] const Monitors& monitors() const { return monitors_; }
  // The host's 20 command / 20 status words (spec §5), served at every scan.
  [[nodiscard]] HostInterface& host() { return host_; }
  [[nodiscard]] const HostInterface& host() const { return host_; }
  // The whole programmed setup as the device holds it (offsets include presets).
  [[nodiscard]] Ans1Setup setup() const;
  // The transducer count the position is scaled from: resolver 4,096/turn unwrapped,
  // encoder 4X count, or the slave value. The brake monitor's pos4096 for a resolver.
  [[nodiscard]] std::int64_t transducer_count() const;
  [[nodiscard]] std::uint64_t scans() const { return scans_; }
  // Scans that left the output channels alone (input edges no channel reads; scan_skipping.cpp).
  [[nodiscard]] std::uint64_t scans_channels_held() const { return scans_channels_held_; }
  [[nodiscard]] Nanos scan_period() const;

private:
  struct QuadState;
  struct ScanSnapshot;

  void schedule_scan(Nanos at);
  void run_scan();
  void scan();
  // ---- exact scan skipping (scan_skipping.cpp) ----
  // Everything a scan may change, compared before and after a scan no outside change preceded.
  [[nodiscard]] ScanSnapshot snapshot() const;
  // The earliest time at which a scan with unchanged inputs can change the state: the one
  // place every time-driven behaviour declares itself.
  [[nodiscard]] Nanos next_change(bool idle_ticks_recorded) const;
  // The first scan of the period grid at or after t (max for max).
  [[nodiscard]] Nanos grid_at_or_after(Nanos t) const;
  // Schedules the next scan of the grid if it is earlier than the pending one.
  void wake_now();
  // An input pin's edge: wake() that keeps channels_fixed_ (the scan checks which inputs moved).
  void input_wake();
  // The inputs a scan's output channels, shift register or presets read (bit n-1 = input n).
  [[nodiscard]] std::uint16_t channel_inputs() const;
  // The scan at `now` would leave every output channel as it is: they were at a fixed point
  // after the last scan (channels_fixed_), only input edges woke it, none of an input that
  // changed since (`changed`) is read by a channel, the shift register or a preset, the GMP is
  // inside quiet_ and no channel's deadline has come.
  [[nodiscard]] bool channels_hold(Nanos now, std::uint16_t changed) const;
  // ---- skipping while the encoder moves (scan_skipping.cpp) ----
  // An encoder count changed (before: the count before it): wakes the scan when the GMP
  // leaves the quiet interval, else only remembers the count at the last grid point.
  void count_edge(std::int64_t before);
  // With a sampled encoder, the same wake as count_edge's, scheduled once at the time the
  // count leaves the counts whose GMP is in quiet_ (no event per edge).
  void schedule_count_leave(Nanos now);
  void schedule_leave_at(Nanos at);
  void require_edges() const;
  // Records the position history of an unused brake monitor for its ticks whose scans (at
  // grid points up to g) were skipped: the count at edge_grid_ there, `after` beyond it.
  void record_idle_ticks(Nanos g, std::int64_t after);
  // The latest grid point whose scan has run, or would have run when scanning every period.
  [[nodiscard]] Nanos last_run_grid(Nanos now) const;
  // The transducer count at grid point g (g no earlier than the last edge's grid point).
  [[nodiscard]] std::int64_t count_at(Nanos g) const;
  // Ends skipping while moving: writes the position members as the scan at grid point `ran`
  // (the last one that ran when scanning every period) left them. Before anything changes
  // what they are computed from.
  void settle_position(Nanos ran);
  void settle_position() {
    if (quiet_armed_) settle_position(last_run_grid(scheduler_.now()));
  }
  // A scan now, with the same inputs and count as the one that just ran, leaves every output
  // channel, the shift register and the monitors as they are (the channels not checked again
  // when the scan that just ran left them alone: channels_hold).
  [[nodiscard]] bool scan_repeats(bool channels_held) const;
  [[nodiscard]] QuietInterval quiet_interval() const;
  [[nodiscard]] ScanState scan_state(Nanos now) const;
  // ---- a resolver read ahead (scan_skipping.cpp) ----
  // What the scans make of the stators: the unwrapped count, the last angle, the fault flags.
  struct ResolverTrack {
    std::int64_t count = 0;
    std::uint16_t angle = 0;
    bool seen = false;
    bool fault_active = false;
    bool fault_latched = false;
  };
  [[nodiscard]] ResolverTrack resolver_track() const {
    return {resolver_count_, resolver_angle_, resolver_seen_, resolver_fault_active_,
            resolver_fault_latched_};
  }
  // The track after reading the stators at an excitation peak.
  [[nodiscard]] ResolverTrack read_peak(ResolverTrack track, Nanos peak) const;
  // Both stators announce when their future changes (AnalogInput::announces_revisions) and the
  // scan reads every peak: the peaks can be read ahead of the scans.
  [[nodiscard]] bool resolver_read_ahead() const;
  // Reads the peaks after the walk's front until one would change the flags or take the GMP out
  // of quiet_ (a wake there), or through the first peak at or after `until` (64 at most; a walk
  // again from the last one, 2 peaks on, then twice as many each time, until a revision).
  void walk_peaks(Nanos until);
  // Where a walk reads to: the next revision expected (a gap between the last two after the
  // last one), so the peaks read beyond it are one or two; 16 peaks on before two revisions.
  [[nodiscard]] Nanos revision_expected() const;
  // A stator's values from now on may have changed: the peaks from now on are read again.
  void stators_revised();
  // The track at grid point g while walking: after every peak at or before g.
  [[nodiscard]] ResolverTrack track_at(Nanos g) const;
  [[nodiscard]] Nanos peak_at_or_before(Nanos t) const;
  void speed_update();
  struct SpeedAsScanned {
    int sign = 0;
    std::int16_t reported = 0;
    std::array<AdvanceCounts, kOutputCount> advances{};
    friend bool operator==(const SpeedAsScanned&, const SpeedAsScanned&) = default;
  };
  [[nodiscard]] SpeedAsScanned speed_as_scanned() const;
  void sample_resolver(Nanos now);
  void read_inputs();
  void queue_outputs(Nanos now, std::uint16_t levels);
  void write_due_outputs();
  void update_advances();
  [[nodiscard]] std::int32_t scaled() const;
  [[nodiscard]] static std::size_t index(int point);

  Scheduler& scheduler_;
  Params params_;
  Variant variant_;
  Ans1Pins pins_{};
  std::array<std::unique_ptr<SkewedOutput>, kOutputCount> skewed_; // the output drivers, on pins_
  ResolverExcitation excitation_;
  std::shared_ptr<QuadState> quad_;

  PositionSetup position_{};
  ShiftRegisterSetup sr_setup_{};
  std::array<OutputChannel, kOutputCount> channels_{};
  Monitors monitors_;

  // Transducer
  std::int64_t resolver_count_ = 0;
  std::uint16_t resolver_angle_ = 0;
  bool resolver_seen_ = false;
  Nanos last_peak_ = Nanos::min();
  bool resolver_fault_active_ = false;
  bool resolver_fault_latched_ = false;
  std::int64_t slave_count_ = 0;

  // Scan state
  std::uint16_t gmp_ = 0;
  std::uint16_t previous_gmp_ = 0;
  bool first_scan_ = true;
  std::uint16_t electrical_inputs_ = 0;
  std::uint16_t active_inputs_ = 0;
  std::uint16_t previous_active_inputs_ = 0;
  std::uint16_t ls_ = 0;
  std::uint16_t outputs_ = 0;
  OutputStatusMasks masks_{};
  ShiftRegister shift_register_{};
  std::uint16_t output_force_enable_ = 0;
  std::uint16_t output_force_state_ = 0;
  std::uint16_t input_force_enable_ = 0;
  std::uint16_t input_force_state_ = 0;
  std::uint64_t scans_ = 0;
  bool in_scan_ = false;
  bool powered_ = true;
  // Skipping: the grid's origin (the last scan, or one period before the first), the pending
  // scan's time (max while asleep), and whether anything changed outside since the last scan.
  Nanos grid_origin_{};
  Nanos scan_at_ = Nanos::max();
  bool changed_outside_ = true;
  // Skipping while the encoder moves: while armed, scans are skipped as long as the GMP stays
  // inside quiet_; edge_grid_ is the grid point before the latest count edge (or the last
  // scan) and count_at_edge_grid_ the count there.
  bool quiet_armed_ = false;
  QuietInterval quiet_{};
  Nanos edge_grid_{};
  std::int64_t count_at_edge_grid_ = 0;
  EventId leave_event_{}; // a sampled encoder's count leaving the quiet interval
  // The last leave time found, and what it was found for (schedule_count_leave).
  struct LeaveMemo {
    std::uint16_t quiet_lo = 0;
    std::uint16_t quiet_hi = 0;
    PositionSetup position{};
    std::int64_t base = 0;
    Nanos at = Nanos::min();
  };
  LeaveMemo leave_memo_{};
  // Skipping the output channels in a scan that input edges woke (channels_hold): the last
  // scan that ran left every channel at a fixed point for its state and quiet_, and nothing but
  // input edges woke the scan since (wake() clears it); channels_until_ is the channels' first
  // deadline then; channels_held_ whether the running scan left the channels alone.
  bool channels_fixed_ = false;
  Nanos channels_until_ = Nanos::min();
  bool channels_held_ = false;
  std::uint16_t quiet_gmp_ = 0; // the GMP quiet_ was computed at
  std::uint64_t scans_channels_held_ = 0;
  // A resolver read ahead while armed: the track at the last scan (its last peak read), the
  // peaks after it whose reading moved the count, and the walk's front (its last peak read
  // and the track there). leave_event_ is the wake at the leaving peak or the next walk.
  bool walking_peaks_ = false;
  ResolverTrack walk_base_{};
  Nanos walk_base_peak_ = Nanos::min();
  struct PeakReading {
    Nanos peak;
    ResolverTrack track;
  };
  std::vector<PeakReading> walk_;
  Nanos walk_front_ = Nanos::min();
  ResolverTrack walk_state_{};
  // The last revision, the gap before it (revision_expected), and the peaks the next walk
  // without a revision reads.
  Nanos last_revision_ = Nanos::min();
  Nanos walk_gap_ = Nanos::zero();
  std::int64_t walk_more_ = 2;

  // Speed
  SpeedFilter speed_{};
  std::int64_t speed_reference_count_ = 0;
  bool rpm_clamped_ = false;
  Nanos last_wrap_ = Nanos::min();
  std::int8_t last_wrap_direction_ = 0; // +1 forward onto 0, -1 backward off it
  std::uint16_t time_of_rotation_ = 0;

  // Output pins lag the scan by output_delay: a queue of (time, levels), one event pending.
  struct PendingWrite {
    Nanos time;
    std::uint16_t levels;
  };
  static constexpr std::size_t kWriteQueue = 64;
  std::array<PendingWrite, kWriteQueue> writes_{};
  std::size_t write_head_ = 0;
  std::size_t write_count_ = 0;
  std::uint16_t queued_levels_ = 0;
  std::uint16_t pin_levels_ = 0;

  HostInterface host_{*this}; // last: it reads the device through its public API

  EventId scan_event_{};
  EventId speed_event_{};
  EventId write_event_{};
};

} // namespace hilrig::models::ans1
