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

#include "rig/cli/number_checks.hpp"
#include "rig/cli/synth_command.hpp"
#include "signals/move_builders.hpp"
#include "signals/ssi_frame.hpp"
#include "signals/ssi_master.hpp"
#include "signals/ssi_slave.hpp"

namespace hilrig::cli {

namespace {

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

void run_ssi(const SsiOptions& o) {
  using namespace signals;
  const SsiMasterParams master_params = ssi7361_master(o.clock_khz == 500);
  const SsiMaster master(master_params);
  const Nanos first = parse_duration(o.first);
  if (first <= Nanos::zero())
    throw CLI::ValidationError("--first", "must be > 0 (the clock idles high before)");
  if (o.frames == 0) throw CLI::ValidationError("--frames", "must be > 0");
  const Nanos end = first + master.frame_period() * static_cast<std::int64_t>(o.frames);

  MotionProfile profile(o.start_turns);
  constant_speed(profile, o.rpm / 60.0, end);

  SsiSlaveParams slave_params;
  slave_params.format = ssi7361_frame(o.msb, o.bits, o.gray ? SsiCode::Gray : SsiCode::Binary);
  slave_params.monoflop = parse_duration(o.monoflop);
  slave_params.output_delay = parse_duration(o.output_delay);
  SsiSlaveFaults faults;
  if (o.stuck == "high") faults.stuck = SsiStuck::High;
  if (o.stuck == "low") faults.stuck = SsiStuck::Low;
  faults.flip_stream_bit = o.flip_bit;
  faults.late_response = parse_duration(o.late);
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
  cmd->add_option("--frames", o->frames, "frames to clock");
  cmd->add_option("--first", o->first, "first frame's latching falling edge, e.g. 20us");
  cmd->add_option("--msb", o->msb, "stream bit of the data MSB (the 7361's M)");
  cmd->add_option("--bits", o->bits, "data bits (the 7361's N)")->check(CLI::Range(1U, 25U));
  cmd->add_flag("--gray", o->gray, "Gray-coded data (default binary)");
  cmd->add_option("--counts-per-turn", o->counts_per_turn, "transducer counts per turn")
      ->check(positive_number());
  cmd->add_option("--rpm", o->rpm, "shaft speed, RPM (signed)");
  cmd->add_option("--start", o->start_turns, "start position, turns");
  cmd->add_option("--monoflop", o->monoflop, "transducer monoflop time TM, e.g. 16us");
  cmd->add_option("--output-delay", o->output_delay, "clock edge to data change, e.g. 200ns");
  cmd->add_option("--stuck", o->stuck, "fault: data line stuck none | high | low")
      ->check(CLI::IsMember({"none", "high", "low"}));
  cmd->add_option("--flip-bit", o->flip_bit, "fault: invert this stream bit (1..25) on the wire");
  cmd->add_option("--late", o->late, "fault: extra delay of every data change, e.g. 3us");
  cmd->add_option("--glitch-mask", o->glitch_mask, "fault: XOR this into the coded data field");
  on_run(*cmd, [o] {
    run_ssi(*o);
    return 0;
  });
}

const bool registered = register_synth_kind(&add_synth_ssi);

} // namespace

} // namespace hilrig::cli
