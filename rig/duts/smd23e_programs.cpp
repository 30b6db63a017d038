// The SMD23E's blocks in its manual's words (docs/spec/smd23e.md §3.1, §6.3-§6.5; manual
// seeds/003, Lnnn): the configuration (Configuration Mode, L2265-L2341), moves and the other
// commands (Command Mode, L2401-L2756). Every block is the ten output words: MSW, LSW, then
// the block's words 2..9; values of a million and more are the manual's two-word format
// (upper = v / 1000, lower = v % 1000, both with the value's sign, L2247-L2253).

#include <cstdint>
#include <optional>
#include <span>
#include <string>
#include <vector>

#include <fmt/format.h>

#include "rig/duts/device_programs.hpp"

namespace hilrig::duts {
namespace {

using Words = std::vector<std::uint16_t>;
constexpr std::int64_t kMaxSteps = 8'388'607; // target, offset, preset (L875, L882)
constexpr std::int64_t kMaxSpeed = 2'999'999; // programmed speed (L2494, L2618)
constexpr std::int64_t kMaxRate = 5000;       // steps/ms/s (L2496-L2497)

void put_multiword(Words& w, std::size_t at, std::int64_t v) {
  w[at] = word(v / 1000);
  w[at + 1] = word(v % 1000);
}

// Configuration Mode (L2265-L2341): word 0 the Configuration Control Word (bit 15 Mode), word 1
// the Configuration Word, words 2..8 the settings.
struct Configuration {
  std::int64_t input1 = 0; // input functions, the codes of L2294-L2319
  std::int64_t input2 = 0;
  std::int64_t input3 = 0;
  std::int64_t input1_active = 1; // 0 no_current, 1 current
  std::int64_t input2_active = 1;
  std::int64_t input3_active = 1;
  bool encoder = false;
  bool stall_detection = false;
  bool home_proximity = false;
  bool anti_resonance = true;
  bool drive_enable = true;
  bool save_to_flash = false;
  std::int64_t starting_speed = 1;
  std::int64_t steps_per_turn = 200;
  std::int64_t encoder_pulses = 1024;
  std::int64_t idle_current_percent = 0;
  std::int64_t motor_current_x10 = 10;
};
Words configuration(const Configuration& c) {
  Words w(10, 0);
  w[0] = static_cast<std::uint16_t>(bit(15) | bit(14, !c.anti_resonance) | bit(13, c.stall_detection) |
                                    bit(11, c.home_proximity) | bit(10, c.encoder) | (c.input3 << 6) |
                                    (c.input2 << 3) | c.input1);
  w[1] = static_cast<std::uint16_t>(bit(15, c.drive_enable) | bit(10, c.save_to_flash) |
                                    bit(2, c.input3_active == 1) | bit(1, c.input2_active == 1) |
                                    bit(0, c.input1_active == 1));
  put_multiword(w, 2, c.starting_speed);
  w[4] = word(c.steps_per_turn);
  w[6] = word(c.encoder_pulses);
  w[7] = word(c.idle_current_percent);
  w[8] = word(c.motor_current_x10);
  return w;
}

// A move (L2487-L2756): Absolute, Relative, Resume, Find Home, Jog and Registration blocks.
enum MoveKind : std::int64_t {
  kAbsolute,
  kRelative,
  kJogCw,
  kJogCcw,
  kRegistrationCw,
  kRegistrationCcw,
  kHomeCw,
  kHomeCcw,
  kResume
};
struct Move {
  std::int64_t move = kRelative;
  std::int64_t steps = 0;
  std::int64_t speed = 0;
  std::int64_t accel = 0;
  std::int64_t decel = 0;
  std::optional<std::int64_t> jerk;             // word 9; not with a registration
  std::optional<std::int64_t> min_registration; // words 8-9; a registration only
  bool encoder_move = false;
  bool drive_enable = true;
};
Words move(const Move& m) {
  static constexpr std::uint16_t kMsw[] = {0x0001, 0x0002, 0x0080, 0x0100, 0x0080,
                                           0x0100, 0x0020, 0x0040, 0x0008};
  const bool registration = m.move == kRegistrationCw || m.move == kRegistrationCcw;
  // Word 9 is the jerk of every move but a registration, whose words 8-9 are its Minimum
  // Registration Move Distance (L2636-L2643): a field the block has no word for is refused,
  // not dropped. A registration's Stopping Distance is 0..8,388,607 (L2636); a deliberately
  // invalid block is written raw.
  if (registration && m.jerk)
    throw ProgramFieldError("jerk",
                            "no jerk with a registration move: its word 9 is the Minimum Registration "
                            "Move Distance (L2636-L2643); leave jerk out");
  if (!registration && m.min_registration)
    throw ProgramFieldError("min_registration",
                            "only with a registration move (registration_cw, registration_ccw, L2636-L2643)");
  if (registration && m.steps < 0)
    throw ProgramFieldError("steps",
                            fmt::format("a registration's Stopping Distance: 0..{} (L2636)", kMaxSteps));
  Words w(10, 0);
  w[0] = kMsw[m.move];
  w[1] = static_cast<std::uint16_t>(bit(15, m.drive_enable) | bit(7, registration) | bit(2, m.encoder_move));
  put_multiword(w, 2, m.steps);
  put_multiword(w, 4, m.speed);
  w[6] = word(m.accel);
  w[7] = word(m.decel);
  if (registration)
    put_multiword(w, 8, m.min_registration.value_or(0));
  else
    w[9] = word(m.jerk.value_or(0));
  return w;
}

// A command without a profile (L2401-L2481): none (all command bits clear, between commands,
// L2403), Hold, Immediate Stop, Reset Errors, Preset Position or Preset Encoder (words 2-3).
struct Command {
  std::int64_t command = 0;
  std::optional<std::int64_t> position; // a preset's value (0 when absent)
  bool drive_enable = true;
  bool clear_driver_fault = false;
};
// Only the words the command uses are written: a profile-less command leaves words 2-9 as the
// last block left them, so a Hold (or the cleared command word that stops a jog) written during
// a jog is not also an on-the-fly change of its speed and ramps to 0 (an Invalid Parameter,
// L1026, L2890), and a preset writes its value words 2-3 only.
Words command(const Command& c) {
  static constexpr std::uint16_t kMsw[] = {0x0000, 0x0004, 0x0010, 0x0400, 0x0200, 0x4000};
  const bool preset = kMsw[c.command] == 0x0200 || kMsw[c.command] == 0x4000;
  if (!preset && c.position)
    throw ProgramFieldError("position",
                            "only with preset_position or preset_encoder (words 2-3, L2685, L2700)");
  Words w(preset ? 4 : 2, 0);
  w[0] = kMsw[c.command];
  w[1] = static_cast<std::uint16_t>(bit(15, c.drive_enable) | bit(10, c.clear_driver_fault));
  if (preset) put_multiword(w, 2, c.position.value_or(0));
  return w;
}

const std::vector<std::string> kInputFunctions = {
    "general", "cw_limit", "ccw_limit", "start_indexed_move", "stop_jog", "emergency_stop", "home"};
const std::vector<std::string> kActiveLevels = {"no_current", "current"};

// A two-word value (L2247-L2253) read back; nullopt when the words are not one.
std::optional<std::int64_t> multiword(std::span<const std::uint16_t> w, std::size_t at) {
  const auto upper = static_cast<std::int16_t>(w[at]);
  const auto lower = static_cast<std::int16_t>(w[at + 1]);
  if (lower > 999 || lower < -999 || (upper > 0 && lower < 0) || (upper < 0 && lower > 0))
    return std::nullopt;
  return std::int64_t{upper} * 1000 + lower;
}

} // namespace

PlannedMove smd23e_planned_move(std::span<const std::vector<std::uint16_t>> earlier,
                                std::span<const std::uint16_t> words) {
  const auto refuse = [](const std::string& what) { throw NoPlannedMove(what); };
  // A Relative Move (MSW 0x0002, L2503-L2516) run at once: an absolute move's length hangs on
  // where the run stands; an encoder move's target is where it starts to decelerate (L1080-L1086);
  // an indexed move waits for its input (LSW bit 8, L2473).
  if (words.size() < 10 || words[0] != 0x0002)
    refuse("a relative move (move = \"relative\", MSW 0x0002): an absolute move's length hangs on where the "
           "run stands, a jog or homing move has none");
  if ((words[1] & (bit(2) | bit(8))) != 0)
    refuse("a plain relative move: not an encoder move (LSW bit 2) nor an indexed one (LSW bit 8)");
  const auto offset = multiword(words, 2);
  const auto speed = multiword(words, 4);
  if (!offset || *offset == 0 || *offset < -kMaxSteps || *offset > kMaxSteps)
    refuse(fmt::format("a move of 1 .. {} steps either way (words 2-3, L2508)", kMaxSteps));
  const std::int64_t accel = words[6], decel = words[7];
  if (accel < 1 || accel > kMaxRate || decel < 1 || decel > kMaxRate)
    refuse(
        fmt::format("Acceleration and Deceleration 1 .. {} steps/ms/s (words 6, 7, L2512-L2513)", kMaxRate));
  if (words[9] != 0)
    refuse("Acceleration Jerk 0, linear ramps (word 9, L891): the manual does not define the S-curves of "
           "1 .. 5000 well enough to draw (L901, L908)");
  // The Starting Speed: the last configuration before it (Configuration Mode, control word
  // bit 15, L2284; words 2-3, L2268).
  std::optional<std::int64_t> starting;
  for (const auto& w : earlier)
    if (w.size() >= 4 && (w[0] & bit(15)) != 0) starting = multiword(w, 2);
  if (!starting || *starting < 1 || *starting > 1'999'999)
    refuse("a move after a configuration with its Starting Speed 1 .. 1,999,999 steps/s (L863, L2268)");
  if (!speed || *speed < *starting || *speed > kMaxSpeed)
    refuse(fmt::format("a Programmed Speed of the Starting Speed ({}) .. {} steps/s (words 4-5, L2510)",
                       *starting, kMaxSpeed));
  // Steps/ms/s to steps/s² (L848-L851).
  return PlannedMove{static_cast<double>(*starting), static_cast<double>(*speed),
                     1000.0 * static_cast<double>(accel), 1000.0 * static_cast<double>(decel),
                     static_cast<double>(*offset < 0 ? -*offset : *offset)};
}

std::vector<ProgramBlockInfo> smd23e_programs() {
  using C = Configuration;
  return {
      program_block<C>(
          "configuration", "Configuration Mode: input functions and levels, speeds, motor (L2265-L2341)",
          {
              {"input1", &C::input1, "Input 1's function (control word bits 2-0, L2294)", 0, 0,
               kInputFunctions, true},
              {"input2", &C::input2, "Input 2's function (bits 5-3)", 0, 0, kInputFunctions, true},
              {"input3", &C::input3, "Input 3's function (bits 8-6; general on M12 units)", 0, 0,
               kInputFunctions, true},
              {"input1_active", &C::input1_active, "Input 1 active when current flows or not (word 1 bit 0)",
               0, 0, kActiveLevels, true},
              {"input2_active", &C::input2_active, "Input 2's active level (bit 1)", 0, 0, kActiveLevels,
               true},
              {"input3_active", &C::input3_active, "Input 3's active level (bit 2)", 0, 0, kActiveLevels,
               true},
              {"encoder", &C::encoder, "Quadrature encoder enable (bit 10, E units)"},
              {"stall_detection", &C::stall_detection, "Stall detection (bit 13; needs the encoder)"},
              {"home_proximity", &C::home_proximity, "Home proximity from LSW bit 11 (bit 11)"},
              {"anti_resonance", &C::anti_resonance, "anti-resonance on (bit 14 clear)"},
              {"drive_enable", &C::drive_enable, "Driver enable (word 1 bit 15)"},
              {"save_to_flash", &C::save_to_flash,
               "Save Configuration (word 1 bit 10, on its 0->1 edge): to flash, loaded at power-up; the unit "
               "then answers nothing until power is cycled (L2331)"},
              {"starting_speed", &C::starting_speed, "Starting Speed, steps/s (words 2-3)", 1, 1'999'999},
              {"steps_per_turn", &C::steps_per_turn, "Motor Steps/Turn (word 4)", 200, 32767},
              {"encoder_pulses", &C::encoder_pulses, "Encoder Pulses/Turn (word 6)", 1024, 1024, {}, true},
              {"idle_current_percent", &C::idle_current_percent, "Idle Current, % (word 7)", 0, 100},
              {"motor_current_x10", &C::motor_current_x10, "Motor Current, Arms x 10 (word 8)", 10, 34},
          },
          &configuration),
      program_block<Move>(
          "move", "a move: Absolute, Relative, Jog, Registration, Find Home, Resume (L2487-L2756)",
          {
              {"move",
               &Move::move,
               "the move (MSW bit; LSW bit 7 for a registration)",
               0,
               0,
               {"absolute", "relative", "jog_cw", "jog_ccw", "registration_cw", "registration_ccw", "home_cw",
                "home_ccw", "resume"}},
              {"steps",
               &Move::steps,
               "target, offset or Stopping Distance, steps (words 2-3)",
               -kMaxSteps,
               kMaxSteps,
               {},
               true},
              {"speed", &Move::speed, "Programmed Speed, steps/s (words 4-5; at least the Starting Speed)", 1,
               kMaxSpeed},
              {"accel", &Move::accel, "Acceleration, steps/ms/s (word 6)", 1, kMaxRate},
              {"decel", &Move::decel, "Deceleration, steps/ms/s (word 7)", 1, kMaxRate},
              {"jerk", &Move::jerk, "Acceleration Jerk (word 9, 0 when absent; not with a registration)", 0,
               5000},
              {"min_registration", &Move::min_registration,
               "Minimum Registration Move Distance, steps (words 8-9, 0 when absent; a registration only)", 0,
               kMaxSteps},
              {"encoder_move", &Move::encoder_move, "an encoder move (LSW bit 2, E units)"},
              {"drive_enable", &Move::drive_enable, "DriveEn (LSW bit 15)"},
          },
          &move),
      program_block<Command>(
          "command", "a command without a profile: none, hold, stop, reset errors, presets (L2401-L2481)",
          {
              {"command",
               &Command::command,
               "the command (MSW bit)",
               0,
               0,
               {"none", "hold", "immediate_stop", "reset_errors", "preset_position", "preset_encoder"}},
              {"position", &Command::position,
               "the preset value, steps (words 2-3, 0 when absent; presets only)", -kMaxSteps, kMaxSteps},
              {"drive_enable", &Command::drive_enable, "DriveEn (LSW bit 15)"},
              {"clear_driver_fault", &Command::clear_driver_fault,
               "ClrDrvFlt (LSW bit 10): with reset_errors and drive_enable = false (L2922-L2946)"},
          },
          &command),
  };
}

} // namespace hilrig::duts
