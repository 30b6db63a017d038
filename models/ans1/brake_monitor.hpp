#pragma once
// The ANS1 press brake monitor (spec §4.10, manual L1027-L1056, CB8, DA19): times the brake
// from release to first motion (start time) and from application to standstill (stop time),
// and raises the start/stop overrun faults when a time exceeds its limit.
//
// How the device calls it (ans1-core: Monitors does this for you; call it directly only in
// tests): exactly once per 1 ms timer tick, in time order,
//     brake.tick(now, released, pos4096, gmp);
//   released: logical state of the brake input (after polarity and force): active = released;
//   pos4096:  transducer position on a 4096 counts/turn base, UNWRAPPED (it keeps counting past
//             a turn), because CSC is defined on that base whatever CPC/FSC are (L1046);
//   gmp:      Global Machine Position, only recorded as released/applied position.
// The input is sampled on the tick (1 ms resolution, L640); an edge is a change between two
// ticks, or between the level the input had when the setup took effect and the first tick.
// Results: status(); faults: start_fault()/stop_fault() (true = fault; the fault output is then
// OFF [MODEL A5, chapter 3: normally on, off = fault]). An overrun trips on the tick it becomes
// certain (start: no motion when the limit is passed; stop: no standstill by limit + 125 ms),
// not only when the press next moves or stops.
#include <array>
#include <cstdint>
#include <optional>

#include "core/time.hpp"
#include "models/ans1/monitor_setup.hpp"

namespace hilrig::models::ans1 {

// What DA19 words 2..6 report.
struct BrakeStatus {
  std::uint16_t released_position = 0; // DA19 w3: GMP at the last release
  std::uint16_t start_time_ms = 0;     // DA19 w4: 32768 when over 32767 (L2616)
  std::uint16_t applied_position = 0;  // DA19 w5: GMP at application, published at standstill (L1038)
  std::uint16_t stop_time_ms = 0;      // DA19 w6: net of the 125 ms detection window (L1052)
  std::uint32_t completed_starts = 0;  // how many start times were measured (for tests and reports)
  std::uint32_t completed_stops = 0;   // how many stop times were measured
  std::uint32_t noise_rejections = 0;  // applications rejected as noise by the debounce
  friend bool operator==(const BrakeStatus&, const BrakeStatus&) = default;
};

class BrakeMonitor {
public:
  enum class Phase : std::uint8_t {
    Idle,       // no cycle running
    Starting,   // released, waiting for motion > 2*CSC
    Debouncing, // applied, qualifying the edge (16..31 ms samples, decision at 32 ms)
    Stopping,   // qualified, waiting for < CSC counts of motion within 125 ms
  };

  static constexpr Nanos kTick = milliseconds(1);
  static constexpr Nanos kSampleStart = milliseconds(16);    // L1039
  static constexpr int kSamples = 16;                        // L1039-L1040
  static constexpr int kNoiseActiveSamples = 8;              // L1039: 8 "released" samples abort
  static constexpr int kQualifyInactiveSamples = 12;         // L1040: 12 of 16 "applied" needed
  static constexpr std::int64_t kStopWindowMs = 125;         // L1042, L1052
  static constexpr std::uint16_t kStartTimeOverflow = 32768; // L2616 [A8]

  // sample_start: when the 16 debounce samples start after the application edge (L1039's
  // 16 ms; a detection-power knob, models/ans1/README.md). Off the 1 ms tick the samples fall
  // between ticks: take them with sample() at next_sample().
  explicit BrakeMonitor(bool never_faults = false, Nanos sample_start = kSampleStart)
      : never_faults_(never_faults), sample_start_(sample_start) {}

  // A new setup ends any running cycle; measured times and faults are kept unless the monitor
  // is disabled (input 0), which clears them. `released_now`: the input's level as the setup
  // takes effect (the device's last scan read it), so a release after it is an edge at the next
  // tick (L1054, L2614); none before the device's first scan, when the first tick takes the
  // level. A new setup on the input the monitor already samples keeps the level its last tick
  // saw: an edge since that tick is found at the next one.
  void configure(const BrakeSetup& setup, std::optional<bool> released_now = std::nullopt);
  void tick(Nanos now, bool released, std::int64_t pos4096, std::uint16_t gmp);
  // The debounce samples (and the decision a ms after the last) due at or before `now`; tick()
  // takes those due by its own time, so only a sample start off the whole ms needs this.
  void sample(Nanos now, bool released, std::uint16_t gmp);
  // When the next debounce sample (or the decision) is due; max when none is running.
  [[nodiscard]] Nanos next_sample() const {
    return phase_ == Phase::Debouncing ? next_sample_ : Nanos::max();
  }
  // Clear Errors (CB bit 4): drops both overrun faults.
  void clear_errors();

  [[nodiscard]] const BrakeSetup& setup() const { return setup_; }
  [[nodiscard]] const BrakeStatus& status() const { return status_; }
  [[nodiscard]] Phase phase() const { return phase_; }
  [[nodiscard]] bool released() const { return released_; }
  // A tick of a monitor that is set up, primed, with no cycle running and its input at the
  // level the last tick saw finds no edge: it only records the position history.
  [[nodiscard]] bool tick_records_only(bool released) const {
    return setup_.input == 0 || (primed_ && phase_ == Phase::Idle && released == released_);
  }
  [[nodiscard]] bool start_fault() const { return start_fault_; }
  [[nodiscard]] bool stop_fault() const { return stop_fault_; }

private:
  static constexpr std::size_t kHistory = 128; // > 125 ticks of position history
  [[nodiscard]] std::int64_t position_ms_ago(std::int64_t ms) const;
  void begin_debounce(Nanos now, std::uint16_t gmp);
  void debounce(Nanos at, bool released, std::uint16_t gmp);
  void still_starting(std::int64_t elapsed_ms);
  void still_stopping(std::int64_t elapsed_ms);
  void finish_start(std::int64_t elapsed_ms);
  void finish_stop(std::int64_t elapsed_ms);

  BrakeSetup setup_{};
  BrakeStatus status_{};
  bool never_faults_;
  Nanos sample_start_;
  Phase phase_ = Phase::Idle;
  bool primed_ = false;   // released_ holds a level to compare the next tick with
  bool released_ = false; // level seen at the previous tick
  Nanos t0_{};            // start of the running cycle (release or application tick)
  std::int64_t start_pos_ = 0;
  std::uint16_t pending_applied_position_ = 0;
  Nanos next_sample_{};   // the next debounce sample (or, after the 16th, the decision)
  int samples_taken_ = 0; // debounce samples taken since the edge
  int active_samples_ = 0;
  int inactive_samples_ = 0;
  bool overrun_tripped_ = false; // the running cycle already tripped its overrun before ending
  bool start_fault_ = false;
  bool stop_fault_ = false;
  std::array<std::int64_t, kHistory> history_{};
  std::uint64_t ticks_ = 0; // ticks recorded in history_
  friend bool operator==(const BrakeMonitor&, const BrakeMonitor&) = default;
};

} // namespace hilrig::models::ans1
