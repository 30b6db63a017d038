#pragma once
// The [MODEL] choices of the virtual SMD23E (spec §7, §9) as named parameters with the
// digest's defaults, and the fault variants (models that are wrong on purpose).

#include <cstdint>
#include <optional>
#include <string_view>
#include <vector>

#include "core/time.hpp"

namespace hilrig::models::smd23e {

// Device variants that are wrong on purpose, for fault-injection campaigns.
enum class Fault : std::uint8_t {
  None,
  WrongAcceleration, // ramps run at wrong_accel_factor × the programmed A and D
  LostSteps,         // the shaft misses one step in every lost_step_interval issued
  IgnoredLimit,      // CW/CCW limit inputs have no effect
  LateStop,          // stops requested by inputs or Hold/Immediate Stop act late_stop_delay late
};

[[nodiscard]] std::string_view fault_name(Fault f);
[[nodiscard]] std::string_view fault_description(Fault f); // what the variant does wrong
[[nodiscard]] std::optional<Fault> fault_from_name(std::string_view name);
[[nodiscard]] std::vector<std::string_view> fault_names(); // every variant except None

struct Params {
  // Unit: E units have the internal 1,024-count encoder; M12 units have 2 inputs.
  bool has_encoder = true;
  bool m12 = false;
  // Heartbeat (SW2 bit 11) half period [M ≈ 500 ms].
  Nanos heartbeat_half_period = milliseconds(500);
  // [MODEL] Where the heartbeat's square wave stands at power-up, in [0, 2 half periods):
  // the rig draws it from the run's seed.
  Nanos heartbeat_phase{0};
  // Homing pause between search stops [M 2 s].
  Nanos homing_pause = seconds(2);
  // Idle current reduction delay [M 1.5 s].
  Nanos idle_current_delay = milliseconds(1500);
  // [A] input filter / reaction delay from input edge to effect; 0.
  Nanos input_delay = Nanos{0};
  // [U §3.3] linear fraction of trapezoidal S ramps (J = 2…5000); 0.5 gives the manual's +33 %.
  double scurve_linear_fraction = 0.5;
  // [U §9 #4] Stop Jog/Registration input: true = level (L1058), false = edge only.
  bool stop_input_level_sensitive = true;
  // [U §9 #5] capture on every transition of a Start-Indexed input (L589) or rising only.
  bool capture_on_any_transition = true;
  // [U §2.3] stall when |motor-derived counts − encoder counts| exceeds this.
  double stall_threshold_counts = 16.0;
  // [U §9 #9] dwell after the last segment of a Dwell move; no.
  bool dwell_after_last_segment = false;
  // [U §3.5] Input word 8 shows the present (idle-reduced) current, not the configured one.
  bool report_present_current = true;
  // [U §9 #1, #34] reproduce the example dump's SW2 bit 13 and NetLoss at power-up; text: no.
  bool sw2_bit13_as_figure = false;
  bool netloss_at_powerup = false;
  // [U §6.2] a valid configuration already in flash at power-up (skips 0x6408).
  bool flash_config_valid = false;
  // A detection-power knob (README, docs/power.md): the indexer's time base off by this fraction,
  // so every planned motion runs (1 + step_clock_error) times as long in real time: step rate
  // and speeds / (1 + e), accelerations / (1 + e)². 0 = the manual's profiles (§3.2, §3.3).
  double step_clock_error = 0.0;
  // [U §4] stall stop type: immediate.
  // Fault variant and its knobs.
  Fault fault = Fault::None;
  double wrong_accel_factor = 0.5;
  std::int64_t lost_step_interval = 100;
  Nanos late_stop_delay = milliseconds(20);
};

} // namespace hilrig::models::smd23e
