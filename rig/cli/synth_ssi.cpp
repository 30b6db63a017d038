// `hilrig synth ssi`: the 7361's SSI clock (125 or 500 kHz, 25 clocks a frame) and the data
// line of the transducer the rig plays, for N frames, binary or Gray, with optional slave
// faults; the words the master reads (and their decoded positions) as integer signals.
//
// The shaft turns at constant speed from a start angle: synth_command.hpp does not expose
// the quadrature kind's profile options, so they are not copied here.

#include <CLI/CLI.hpp>
#include <fmt/core.h>

#include <cstdint>
#include <memory>
#include <stdexcept>
#include <string>
#include <vector>

#include "rig/campaign/limits.hpp"
#include "rig/cli/number_checks.hpp"
#include "rig/cli/synth_command.hpp"
#include "signals/move_builders.hpp"
#include "signals/ssi_frame.hpp"
#include "signals/ssi_master.hpp"
#include "signals/ssi_slave.hpp"

namespace hilrig::cli {

namespace limits = campaign::limits;

namespace {

// The 7361's frame: 25 clocks (signals/ssi_master.cpp ssi7361_master).
constexpr unsigned kFrameBits = 25;
// Each frame is 50 clock edges and up to 50 data edges: kMaxSynthEdges in all.
constexpr std::size_t kMaxFrames = static_cast<std::size_t>(kMaxSynthEdges) / 100;

struct SsiOptions {
  std::string out;
  std::string name = "rig.ssi";
  unsigned clock_khz = 125;
  std::size_t frames = 4;
  std::string first = "20us";
  unsigned msb = 1;
  unsigned bits = 24;
  bool gray = false;
  std::uint32_t counts_per_turn = 4096;
  double rpm = 0.0;
  double start_turns = 0.0;
  std::string monoflop = "16us";
  std::string output_delay = "0";
  // Faults.
  std::string stuck = "none";
  unsigned flip_bit = 0;
  std::string late = "0";
  std::uint32_t glitch_mask = 0;
};

// The data field (--msb, --bits) lies inside the frame, stream bits 1 .. 25.
void check_fields(const SsiOptions& o) {
  if (o.msb < 1 || o.msb + o.bits - 1 > kFrameBits)
    throw CLI::ValidationError("--msb", fmt::format("1 .. {0} with --msb + --bits - 1 <= {0} (got {1} + {2})",
                                                    kFrameBits, o.msb, o.bits));
  const std::uint64_t max_mask = (std::uint64_t{1} << o.bits) - 1;
  if (o.glitch_mask > max_mask)
    throw CLI::ValidationError(
        "--glitch-mask",
        fmt::format("0 .. {} (the {}-bit data field of --bits) (got {})", max_mask, o.bits, o.glitch_mask));
}

// A time of the slave's that may be 0 (monoflop, output delay, a late answer).
Nanos parse_delay(const std::string& option, const std::string& text) {
  const Nanos d = parse_duration(text, option);
  require_duration_within(option, text, d, Nanos::zero(), limits::kMaxEnd);
  return d;
}

void check_ssi(const SsiOptions& o) {
  check_fields(o);
  if (o.frames < 1 || o.frames > kMaxFrames)
    throw CLI::ValidationError("--frames", fmt::format("1 .. {} (got {})", kMaxFrames, o.frames));
  require_within("--rpm", o.rpm, -limits::kMaxRpm, limits::kMaxRpm,
                 fmt::format("-{0} .. {0} rpm", limits::kMaxRpm));
  require_within("--start", o.start_turns, -limits::kMaxTurns, limits::kMaxTurns,
                 fmt::format("-{0} .. {0} turns", limits::kMaxTurns));
}

void run_ssi(const SsiOptions& o) {
  using namespace signals;
  check_ssi(o);
  const SsiMasterParams master_params = ssi7361_master(o.clock_khz == 500);
  const SsiMaster master(master_params);
  const Nanos first = parse_duration(o.first, "--first");
  if (first <= Nanos::zero())
    throw CLI::ValidationError("--first", "must be > 0 (the clock idles high before), got " + o.first);
  const Nanos monoflop = parse_delay("--monoflop", o.monoflop);
  const Nanos output_delay = parse_delay("--output-delay", o.output_delay);
  const Nanos late = parse_delay("--late", o.late);
  const Nanos end = first + master.frame_period() * static_cast<std::int64_t>(o.frames);

  MotionProfile profile(o.start_turns);
  constant_speed(profile, o.rpm / 60.0, end);

  SsiSlaveParams slave_params;
  slave_params.format = ssi7361_frame(o.msb, o.bits, o.gray ? SsiCode::Gray : SsiCode::Binary);
  slave_params.monoflop = monoflop;
  slave_params.output_delay = output_delay;
  SsiSlaveFaults faults;
  if (o.stuck == "high") faults.stuck = SsiStuck::High;
  if (o.stuck == "low") faults.stuck = SsiStuck::Low;
  faults.flip_stream_bit = o.flip_bit;
  faults.late_response = late;
  faults.gray_glitch_mask = o.glitch_mask;

  std::vector<Edge> clock = master.clock_schedule(first, o.frames);
  std::vector<Edge> data;
  Level data_initial = Level::High;
  try {
    SsiSlave slave(slave_params,
                   counts_from_turns([&profile](Nanos t) { return profile.position(t); }, o.counts_per_turn));
    // A stuck line is stuck from the start: it is the line's initial level, not an edge.
    static_cast<void>(slave.set_faults(faults, Nanos{0}));
    data_initial = slave.data();
    data = respond(slave, clock, end);
  } catch (const std::invalid_argument& e) {
    throw CLI::ValidationError("ssi", e.what());
  }

  TraceRecorder trace;
  const std::uint32_t clk = trace.declare(o.name + ".clock");
  const std::uint32_t dat = trace.declare(o.name + ".data");
  const auto frame_bits = static_cast<std::uint8_t>(master_params.frame_bits);
  const std::uint32_t word = trace.declare(o.name + ".word", SignalKind::Integer, frame_bits);
  const std::uint32_t value =
      trace.declare(o.name + ".value", SignalKind::Integer, static_cast<std::uint8_t>(o.bits));
  trace.set_initial(clk, 1); // SSI clock idles high
  trace.set_initial(dat, is_high(data_initial) ? 1 : 0);
  trace.set_initial(word, 0);
  trace.set_initial(value, 0);
  for (const Edge& e : clock) trace.edge(clk, e);
  for (const Edge& e : data) trace.edge(dat, e);
  // Each word appears when the master has sampled its last bit.
  const LineHistory line(data_initial, data);
  for (const SsiReading& r : master.read_frames(line, first, o.frames)) {
    const Nanos read_at = master.sample_time(r.frame_start, master_params.frame_bits);
    trace.value(word, read_at, static_cast<std::int64_t>(r.word));
    trace.value(value, read_at,
                static_cast<std::int64_t>(decompose_frame(slave_params.format, r.word).value));
  }
  write_vcd_file(trace, o.out);
  if (o.out != "-")
    fmt::print("{}: {} frames at {} kHz, {} clock edges, {} data edges, {} code\n", o.out, o.frames,
               o.clock_khz, clock.size(), data.size(), o.gray ? "Gray" : "binary");
}

void add_synth_ssi(CLI::App& synth) {
  auto o = std::make_shared<SsiOptions>();
  CLI::App* cmd = synth.add_subcommand(
      "ssi", "The 7361's SSI clock and the transducer's data line for N frames (shaft at constant speed)");
  cmd->add_option("--out", o->out, "VCD file to write ('-' for stdout)")->required();
  cmd->add_option("--name", o->name, "signal name prefix");
  cmd->add_option("--clock-khz", o->clock_khz, "SSI clock: 125 (TINT 500 us) or 500 (TINT 250 us)")
      ->check(CLI::IsMember({125U, 500U}));
  cmd->add_option("--frames", o->frames, fmt::format("frames to clock, 1 .. {}", kMaxFrames));
  cmd->add_option("--first", o->first, "first frame's latching falling edge, e.g. 20us: 1ns .. 3600s");
  cmd->add_option("--msb", o->msb,
                  "stream bit of the data MSB (the 7361's M): 1 .. 25, with --msb + --bits - 1 <= 25");
  cmd->add_option("--bits", o->bits, "data bits (the 7361's N)")->check(CLI::Range(1U, 25U));
  cmd->add_flag("--gray", o->gray, "Gray-coded data (default binary)");
  cmd->add_option("--counts-per-turn", o->counts_per_turn, "transducer counts per turn")
      ->check(positive_number());
  cmd->add_option("--rpm", o->rpm, fmt::format("shaft speed, RPM (signed): -{0} .. {0}", limits::kMaxRpm));
  cmd->add_option("--start", o->start_turns,
                  fmt::format("start position, turns: -{0} .. {0}", limits::kMaxTurns));
  cmd->add_option("--monoflop", o->monoflop, "transducer monoflop time TM, e.g. 16us: 0 .. 3600s");
  cmd->add_option("--output-delay", o->output_delay, "clock edge to data change, e.g. 200ns: 0 .. 3600s");
  cmd->add_option("--stuck", o->stuck, "fault: data line stuck none | high | low")
      ->check(CLI::IsMember({"none", "high", "low"}));
  cmd->add_option("--flip-bit", o->flip_bit, "fault: invert this stream bit (1..25) on the wire")
      ->check(CLI::Range(1U, kFrameBits));
  cmd->add_option("--late", o->late, "fault: extra delay of every data change, e.g. 3us: 0 .. 3600s");
  cmd->add_option("--glitch-mask", o->glitch_mask,
                  "fault: XOR this into the coded data field: 0 .. 2^bits - 1 (within --bits)");
  on_run(*cmd, [o] {
    run_ssi(*o);
    return 0;
  });
}

const bool registered = register_synth_kind(&add_synth_ssi);

} // namespace

} // namespace hilrig::cli
