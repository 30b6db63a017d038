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

#include "models/ssi7361/setup.hpp"
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

// Whole-number options are signed here: CLI11 reads "-1" into an unsigned as 2^64 - 1, and the
// refusal would then quote that instead of what was typed.
struct SsiOptions {
  std::string out;
  std::string name = "rig.ssi";
  unsigned clock_khz = 125;
  std::int64_t frames = 4;
  std::string first = "20us";
  std::int64_t msb = 1;
  std::int64_t bits = 24;
  bool gray = false;
  std::int64_t counts_per_turn = 4096;
  double rpm = 0.0;
  double start_turns = 0.0;
  std::string monoflop = "16us";
  std::string output_delay = "0";
  // Faults.
  std::string stuck = "none";
  std::int64_t flip_bit = 0;
  std::string late = "0";
  std::int64_t glitch_mask = 0;
};

// The data field (--msb, --bits) is what the 7361's Format command can be set to: outside it
// the board raises FMTErr (ssi7361.md §3, L2126-2163), so the rig refuses it too, by the
// model's own rule (models/ssi7361/setup.hpp format_fault), in the manual's order.
void check_fields(const SsiOptions& o) {
  namespace m = models::ssi7361;
  const auto in = [](std::int64_t v, unsigned lo, unsigned hi) {
    return v >= static_cast<std::int64_t>(lo) && v <= static_cast<std::int64_t>(hi);
  };
  // Out of the 5-bit fields' reach the setup cannot even hold the value: judged here first.
  if (!in(o.bits, 0, 31) || !in(o.msb, 0, 31) ||
      m::format_fault(m::SsiSetup{.msb = static_cast<unsigned>(o.msb),
                                  .bits = static_cast<unsigned>(o.bits)}) != m::FormatFault::None) {
    if (!in(o.bits, m::kMinDataBits, m::kMaxDataBits))
      throw CLI::ValidationError("--bits", fmt::format("{} .. {}, the 7361's Number of Data Bits N (got {})",
                                                       m::kMinDataBits, m::kMaxDataBits, o.bits));
    if (!in(o.msb, m::kMinMsb, m::kMaxMsb))
      throw CLI::ValidationError(
          "--msb", fmt::format("{} .. {}, the 7361's MSB Number M (got {})", m::kMinMsb, m::kMaxMsb, o.msb));
    throw CLI::ValidationError(
        "--msb", fmt::format("--msb + --bits at most {} (the 7361's M + N: the field ends by stream bit {}) "
                             "(got {} + {} = {})",
                             m::kMaxMsbPlusBits, kFrameBits, o.msb, o.bits, o.msb + o.bits));
  }
  // A single-turn position is 0 .. counts-per-turn - 1: more than the field holds would wrap.
  const std::int64_t field = std::int64_t{1} << o.bits;
  if (o.counts_per_turn < 1 || o.counts_per_turn > field)
    throw CLI::ValidationError(
        "--counts-per-turn",
        fmt::format("1 .. 2^bits = {}: positions 0 .. counts-per-turn - 1 fit the {}-bit field of --bits "
                    "(got {})",
                    field, o.bits, o.counts_per_turn));
  if (o.glitch_mask < 0 || o.glitch_mask > field - 1)
    throw CLI::ValidationError(
        "--glitch-mask",
        fmt::format("0 .. {} (the {}-bit data field of --bits) (got {})", field - 1, o.bits, o.glitch_mask));
}

// A time of the slave's that may be 0 (monoflop, output delay, a late answer).
Nanos parse_delay(const std::string& option, const std::string& text) { return parse_instant(text, option); }

void check_ssi(const CLI::App& cmd, const SsiOptions& o) {
  check_fields(o);
  // A stuck data line sends no bit: the faults that change the bits it sends would do nothing.
  for (const char* fault : {"--flip-bit", "--late", "--glitch-mask"})
    refuse_unless_applies(cmd, fault, o.stuck == "none",
                          "not with --stuck " + o.stuck + ": a stuck data line sends no bit to change");
  if (o.frames < 1 || o.frames > static_cast<std::int64_t>(kMaxFrames))
    throw CLI::ValidationError("--frames", fmt::format("1 .. {} (got {})", kMaxFrames, o.frames));
  require_within("--rpm", o.rpm, -limits::kMaxRpm, limits::kMaxRpm,
                 fmt::format("-{0} .. {0} rpm", limits::kMaxRpm));
  require_within("--start", o.start_turns, -limits::kMaxTurns, limits::kMaxTurns,
                 fmt::format("-{0} .. {0} turns", limits::kMaxTurns));
}

void run_ssi(const CLI::App& cmd, const SsiOptions& o) {
  using namespace signals;
  check_ssi(cmd, o);
  const SsiMasterParams master_params = ssi7361_master(o.clock_khz == 500);
  const SsiMaster master(master_params);
  // After 0: the clock idles high before the first frame's latching edge.
  const Nanos first = parse_positive_duration(o.first, "--first");
  const Nanos monoflop = parse_delay("--monoflop", o.monoflop);
  const Nanos output_delay = parse_delay("--output-delay", o.output_delay);
  const Nanos late = parse_delay("--late", o.late);
  // The last frame ends within a campaign's run, as quadrature's and discrete's signals do.
  // Exact in Nanos: --frames is at most kMaxFrames, so first + frames x TINT cannot overflow.
  const Nanos tint = master.frame_period();
  const Nanos half_clock = master.clock_period() / 2;
  if (!limits::monoflop_in_range(monoflop, half_clock))
    throw CLI::ValidationError(
        "--monoflop", fmt::format("{} (got {})",
                                  limits::monoflop_range(duration_words(half_clock),
                                                         fmt::format("the {} kHz clock", o.clock_khz)),
                                  o.monoflop));
  // Retriggered by every clock edge, the monoflop runs out TM after a frame's last one: DATA is
  // back at idle before the next frame's latching edge only if TM is shorter than the gap
  // between them (TIDL, L1089-1098: the transducer must have new data within it).
  const Nanos idle = tint - master.clock_schedule(Nanos{0}, 1).back().time;
  if (monoflop >= idle)
    throw CLI::ValidationError(
        "--monoflop",
        fmt::format("shorter than the {} between a frame's last clock edge and the next frame at {} "
                    "kHz, so that DATA is idle before it (got {})",
                    duration_words(idle), o.clock_khz, o.monoflop));
  const Nanos end = first + tint * o.frames;
  if (end > limits::kMaxEnd)
    throw CLI::ValidationError(
        "--frames",
        fmt::format("frames that end by {}: --first {} + {} x {} (one frame at {} kHz) ends at {:.9f} s",
                    duration_words(limits::kMaxEnd), o.first, o.frames, duration_words(tint), o.clock_khz,
                    end.seconds()));
  require_writable("--out", o.out);
  const auto frames = static_cast<std::size_t>(o.frames);

  MotionProfile profile(o.start_turns);
  constant_speed(profile, o.rpm / 60.0, end);

  SsiSlaveParams slave_params;
  slave_params.format = ssi7361_frame(static_cast<unsigned>(o.msb), static_cast<unsigned>(o.bits),
                                      o.gray ? SsiCode::Gray : SsiCode::Binary);
  slave_params.monoflop = monoflop;
  slave_params.output_delay = output_delay;
  SsiSlaveFaults faults;
  if (o.stuck == "high") faults.stuck = SsiStuck::High;
  if (o.stuck == "low") faults.stuck = SsiStuck::Low;
  faults.flip_stream_bit = static_cast<unsigned>(o.flip_bit);
  faults.late_response = late;
  faults.gray_glitch_mask = static_cast<std::uint32_t>(o.glitch_mask);

  std::vector<Edge> clock = master.clock_schedule(first, frames);
  std::vector<Edge> data;
  Level data_initial = Level::High;
  try {
    SsiSlave slave(slave_params, counts_from_turns([&profile](Nanos t) { return profile.position(t); },
                                                   static_cast<std::uint32_t>(o.counts_per_turn)));
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
  for (const SsiReading& r : master.read_frames(line, first, frames)) {
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
  namespace m = models::ssi7361;
  auto o = std::make_shared<SsiOptions>();
  CLI::App* cmd = synth.add_subcommand(
      "ssi", "The 7361's SSI clock and the transducer's data line for N frames (shaft at constant speed)");
  cmd->add_option("--out", o->out, "VCD file to write ('-' for stdout)")->required();
  cmd->add_option("--name", o->name, "signal name prefix");
  cmd->add_option("--clock-khz", o->clock_khz, "SSI clock: 125 (TINT 500 us) or 500 (TINT 250 us)")
      ->check(CLI::IsMember({125U, 500U}));
  cmd->add_option("--frames", o->frames,
                  fmt::format("frames to clock, 1 .. {}, the last ending by 3600s", kMaxFrames));
  cmd->add_option("--first", o->first, "first frame's latching falling edge, e.g. 20us: 1ns .. 3600s");
  cmd->add_option("--msb", o->msb,
                  fmt::format("stream bit of the data MSB (the 7361's MSB Number M): {} .. {}, with --msb + "
                              "--bits <= {} (FMTErr otherwise)",
                              m::kMinMsb, m::kMaxMsb, m::kMaxMsbPlusBits));
  cmd->add_option(
      "--bits", o->bits,
      fmt::format("data bits (the 7361's Number of Data Bits N): {} .. {}, with --msb + --bits <= {}",
                  m::kMinDataBits, m::kMaxDataBits, m::kMaxMsbPlusBits));
  cmd->add_flag("--gray", o->gray, "Gray-coded data (default binary)");
  cmd->add_option("--counts-per-turn", o->counts_per_turn,
                  "transducer counts per turn: 1 .. 2^bits (each position 0 .. counts-per-turn - 1 fits the "
                  "field; more is refused, not wrapped)")
      ->check(positive_number());
  cmd->add_option("--rpm", o->rpm, fmt::format("shaft speed, RPM (signed): -{0} .. {0}", limits::kMaxRpm));
  cmd->add_option("--start", o->start_turns,
                  fmt::format("start position, turns: -{0} .. {0}", limits::kMaxTurns));
  cmd->add_option(
      "--monoflop", o->monoflop,
      "transducer monoflop time TM, e.g. 16us: above half a clock period (4us at 125 kHz, 1us at 500 kHz), "
      "at most 1ms and shorter than the idle gap between frames (TINT less the frame's clock burst, "
      "L1089-1098)");
  cmd->add_option("--output-delay", o->output_delay, "clock edge to data change, e.g. 200ns: 0s .. 3600s");
  cmd->add_option("--stuck", o->stuck, "fault: data line stuck none | high | low")
      ->check(CLI::IsMember({"none", "high", "low"}));
  cmd->add_option("--flip-bit", o->flip_bit, "fault: invert this stream bit (1..25) on the wire")
      ->check(CLI::Range(1, static_cast<int>(kFrameBits)));
  cmd->add_option("--late", o->late, "fault: extra delay of every data change, e.g. 3us: 0s .. 3600s");
  cmd->add_option("--glitch-mask", o->glitch_mask,
                  "fault: XOR this into the coded data field: 0 .. 2^bits - 1 (within --bits)");
  on_run(*cmd, [cmd, o] {
    run_ssi(*cmd, *o);
    return 0;
  });
}

const bool registered = register_synth_kind(&add_synth_ssi);

} // namespace

} // namespace hilrig::cli
