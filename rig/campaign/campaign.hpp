#pragma once
// A campaign, as read from its TOML file: the DUT and its wiring, the motion and the
// encoder, stimuli and host actions in time, the checks with their limits, the fault
// entries, and how many runs (repetitions, sweeps). Every entry keeps where it was
// written so a later error can point at it. docs/campaigns.md describes every key.

#include <cstddef>
#include <cstdint>
#include <map>
#include <optional>
#include <string>
#include <vector>

#include "core/line.hpp"
#include "core/time.hpp"
#include "rig/campaign/campaign_error.hpp"
#include "rig/campaign/plant_spec.hpp"
#include "rig/checks/check_params.hpp"
#include "rig/duts/dut.hpp"
#include "signals/ssi_frame.hpp"

namespace hilrig::campaign {

using duts::ParamValue;

// A parameter as written: its value (of the declared kind) and where.
struct Param {
  ParamValue value;
  SourcePos where;
};
using ParamMap = std::map<std::string, Param, std::less<>>;

struct DutSpec {
  std::string model; // a registry name, or "external" (a real board)
  std::string variant = "nominal";
  std::string backend = "virtual";
  std::string serial; // [dut] serial: the board's serial number, for the outputs; "" when not given
  ParamMap params;    // every declared parameter (defaults filled in)
  std::map<std::string, duts::PinDirection, std::less<>> external_pins; // "external" only
  SourcePos where;
};

// One wire: a rig line <-> a board pin. Rig line names are the bus line names and the
// names checks and stimuli use ("enc.A", "ls1").
struct Wire {
  std::string rig;
  std::string board;
  duts::PinDirection direction = duts::PinDirection::Input; // the board pin's direction
  bool analog = false;                                      // an analog pin (resolver stator)
  SourcePos where;
};

struct EncoderSpec {
  std::int64_t lines = 1000; // lines per turn; X4 quadrature gives 4 counts per line
  SourcePos where;
  [[nodiscard]] double counts_per_turn() const { return 4.0 * static_cast<double>(lines); }
};

// Resolver stators driven from the motion (boards with analog stator pins). The rig
// excites with amplitude * sin(2 pi f t), phase-locked to the board's reference from time 0;
// each stator is ratio * that * sin/cos(shaft angle). No sin_line: no resolver.
struct ResolverSpec {
  std::string sin_line; // rig line wired to the sine stator pin
  std::string cos_line; // rig line wired to the cosine stator pin
  double excitation_hz = 5000.0;
  double amplitude = 1.0;
  double ratio = 1.0;
  // The reference's phase at time 0, degrees: amplitude * sin(2 pi f t + phase). A board
  // whose reference is a cosine (the Series 2700 model) takes 90.
  double phase_deg = 0.0;
  SourcePos where;
};

// [ssi]: the SSI transducer the rig plays for a board that is the SSI master (the 7361): it
// answers the board's clock on clock_line with the shaft's position on data_line, latched at
// each frame's first falling clock edge (signals/ssi_slave.hpp). The shaft is the [plant]'s
// where there is one, else the [motion]'s: a single-turn transducer of counts_per_turn counts,
// floor(turns x counts_per_turn) wrapped to one turn. No data_line: no transducer.
struct SsiSpec {
  std::string clock_line; // rig line wired to the board's clock output
  std::string data_line;  // rig line wired to the board's data input
  std::uint32_t counts_per_turn = 4096;
  signals::SsiFrameFormat format{}; // frame_bits, data_msb, data_bits, code
  Nanos monoflop = microseconds(16);
  SourcePos where;
};

enum class MoveKind : std::uint8_t { Constant, Accelerate, Dwell, Trapezoid, PressStroke };

// A move of the motion profile. Speeds in rpm, accelerations in rpm/s, distances in turns.
struct Move {
  MoveKind kind = MoveKind::Constant;
  Nanos duration{0};         // constant, accelerate, dwell
  double speed_rpm = 0.0;    // constant, trapezoid (cruise), press_stroke (running)
  double to_rpm = 0.0;       // accelerate: speed at the end
  double accel_rpm_s = 0.0;  // trapezoid: acceleration and deceleration
  double turns = 0.0;        // trapezoid: distance
  std::int64_t strokes = 0;  // press_stroke: full strokes before the braking one
  double brake_at_deg = 0.0; // press_stroke: crank angle at which the brake is applied
  double decel_rpm_s = 0.0;  // press_stroke: brake deceleration
  std::string brake_line;    // press_stroke: rig line driven to brake_level when the brake is applied
  Level brake_level = Level::Low;
  SourcePos where;
};

struct MotionSpec {
  double start_turns = 0.0;
  std::vector<Move> moves;
  SourcePos where;
};

enum class StimulusKind : std::uint8_t {
  Level,        // line to a level
  Pulse,        // line to level for width, then back
  Bounce,       // contact bounce: `edges` toggles `period` apart, then settle at level
  Glitch,       // (signal fault) the line inverted for width
  Stuck,        // (signal fault) the line held at level from `at` until `until`
  MissingEdges, // (signal fault) every `every`-th edge of an encoder line lost in [at, until)
};

struct Stimulus {
  StimulusKind kind = StimulusKind::Level;
  Nanos at{0};
  std::string line;
  Level level = Level::High;
  Nanos width{0};
  Nanos period{0};
  std::int64_t edges = 0;
  std::int64_t every = 1;
  Nanos until = Nanos::max();
  SourcePos where;
};

// A host action: write command words (with the handshake) or read one input word.
struct HostAction {
  enum class Kind : std::uint8_t { Write, Read };
  Kind kind = Kind::Write;
  Nanos at{0};
  std::vector<std::uint16_t> words; // write: output words 0.. (the rig drives Transmit)
  // write: the words alone, no Transmit handshake (the 4501's control bits 0 and 1 act
  // without a programming cycle, seeds/001 L167).
  bool raw = false;
  std::size_t word = 0; // read: input word index
  // read: inside the handshake of the write above, once Acknowledge is set and before
  // Transmit is cleared (the 7361's error bits are valid only then, seeds/004 L1298-1299).
  bool while_acknowledged = false;
  std::string name; // read: the observation's name; write: optional label
  std::string unit;
  bool is_signed = false;     // read: the word is two's complement
  Nanos timeout{100'000'000}; // write: how long to wait for Acknowledge
  SourcePos where;
};

// A fault the device's manual describes ([[device_fault]]), in place from `at` until `until`:
// a board fault raised in the model, or a resolver fault the rig makes on the stators.
struct DeviceFaultEvent {
  std::size_t fault = 0; // index into the DUT's DutInfo::faults
  std::string name;      // the fault's name (messages, traces)
  duts::FaultSite site = duts::FaultSite::Board;
  Nanos at{0};
  Nanos until = Nanos::max(); // the condition ends here (the board may keep it latched)
  double ratio = 0.0;         // site StatorRatio: the stators' transformation ratio meanwhile
  SourcePos where;
};

// The board's supply off at `at` and back on `off` later ([[power_cycle]]): the model keeps
// what its manual says survives power loss (DutInfo::power_cycle) and powers up again.
struct PowerCycleEvent {
  Nanos at{0};
  Nanos off{0};
  SourcePos where;
  [[nodiscard]] Nanos on_at() const { return at + off; }
};

// A front-panel action at `at` ([[panel]]): a switch or key of the board (DutInfo::panel).
struct PanelEvent {
  std::size_t action = 0; // index into the DUT's DutInfo::panel
  std::string name;
  Nanos at{0};
  SourcePos where;
};

// A check: its kind and name, and its typed parameters, built and range-checked once by the
// parser (rig/checks/registry.hpp: build_check_params).
struct CheckSpec {
  std::string kind;
  std::string name;
  checks::CheckParams params;
  std::vector<std::string> tags; // `tags = [...]`: what `hilrig run --tag T` selects by
  Nanos probe_at{0};             // bisection checks (debounce): when each probe pulse starts
  SourcePos where;
};

// A fault-injection entry: a device variant and/or a signal fault, and the checks of
// which at least one must fail (catch it). A fault nobody catches fails the campaign.
struct FaultSpec {
  std::string name;
  std::optional<std::string> variant;
  std::optional<Stimulus> signal;
  std::vector<std::string> caught_by;
  // Scenario keys the fault run replaces (paths as in [[sweep]]), from `set = { ... }`: the
  // scenario is wrong on purpose, not the board (e.g. a brake too slow for its limit).
  std::vector<std::string> set_keys;
  SourcePos where;
};

// One point of the scenario: everything a single run needs.
struct Scenario {
  DutSpec dut;
  std::vector<Wire> wiring;
  EncoderSpec encoder;
  ResolverSpec resolver;
  SsiSpec ssi;
  MotionSpec motion;
  std::optional<PlantSpec> plant; // a plant turns the shaft instead of the motion
  std::vector<Stimulus> stimuli;
  std::vector<HostAction> host;
  std::vector<DeviceFaultEvent> device_faults;
  std::vector<PowerCycleEvent> power_cycles;
  std::vector<PanelEvent> panel;
  std::vector<CheckSpec> checks;
  Nanos end{0};
  Nanos host_poll{1'000'000}; // how often the host polls Acknowledge
  // On a rig: an output edge later than this is a rig fault. Unset: the rig config's
  // rt.edge_tolerance. The virtual bus plays every edge exactly on time.
  std::optional<Nanos> edge_tolerance;

  [[nodiscard]] const Wire* wire_for_rig(std::string_view rig_line) const;
  [[nodiscard]] const CheckSpec* check(std::string_view name) const;
};

struct SweepAxis {
  std::string key; // dotted path into the file, e.g. "dut.params.delay"
  std::size_t values = 0;
  SourcePos where;
};

// One run: which scenario point, which repetition, which seed, which fault.
struct RunSpec {
  std::size_t index = 0;
  std::size_t point = 0;
  std::size_t repetition = 0;
  std::uint64_t seed = 0;
  std::optional<std::size_t> fault; // index into Campaign::faults
  std::string label;                // "point 2 rep 0", "fault late", with the sweep values
};

struct Campaign {
  std::string file;
  std::string sha256; // of the file's bytes, lower-case hex: written into results.json
  std::string name;
  std::string description;
  std::uint64_t seed = 1;
  std::int64_t repeat = 1;
  std::vector<SweepAxis> sweep;
  std::vector<Scenario> points; // one per sweep point (one when there is no sweep)
  std::vector<std::string> point_labels;
  std::vector<FaultSpec> faults;
  // [fault][point]: the scenario of a fault that sets keys; empty for a fault that does not.
  std::vector<std::vector<Scenario>> fault_points;
  std::vector<RunSpec> runs;

  // The scenario a run runs: its sweep point's, or its fault's when the fault sets keys.
  [[nodiscard]] const Scenario& scenario_of(const RunSpec& run) const;
};

// Seed of run `index` for a base seed: splitmix64, so neighbouring runs differ widely.
[[nodiscard]] std::uint64_t run_seed(std::uint64_t base, std::size_t index);
// The campaign's runs for a base seed: nominal runs (each point x repeat) then one run
// per fault at each point. Index order is the file's order.
[[nodiscard]] std::vector<RunSpec> plan_runs(const Campaign& campaign, std::uint64_t base_seed);
// Shard k of n (0-based k): the runs whose index mod n is k.
[[nodiscard]] std::vector<RunSpec> shard(const std::vector<RunSpec>& runs, std::size_t k, std::size_t n);

} // namespace hilrig::campaign
