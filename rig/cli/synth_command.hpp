#pragma once
// `hilrig synth <kind>`: writes synthesized sensor signals for a profile given on the
// command line to a VCD file, without a rig or a board. Kinds here: quadrature, discrete.
//
// Other signal kinds (resolver, SSI) add their own subcommand from their own file,
// rig/cli/synth_<kind>.cpp (globbed into hilrig_cli_synth, an object library so static
// registrations are linked in):
//
//   namespace { const bool registered = hilrig::cli::register_synth_kind(&add_synth_resolver); }
//
// where add_synth_resolver(CLI::App& synth) calls synth.add_subcommand("resolver", ...).

#include "rig/cli/cli_fwd.hpp"

#include <cstdint>
#include <functional>
#include <ostream>
#include <string>

#include "core/time.hpp"
#include "core/trace.hpp"

namespace hilrig::cli {

void add_synth_command(CLI::App& app);

using SynthKindAdder = void (*)(CLI::App& synth);
// Registers a `hilrig synth <kind>` adder; returns true so it can initialise a static.
bool register_synth_kind(SynthKindAdder add);

// The most edges one `synth` writes: a trace holds ~92 bytes an edge while it is built (the
// solved edge, the recorder's copy), so 10 million is ~0.9 GB, and a VCD of ~150 MB. Every kind
// counts what its options make, in closed form, and refuses more (exit 2) before solving.
inline constexpr std::int64_t kMaxSynthEdges = 10'000'000;

// Helpers shared by the synth kinds.
// Makes `run` the kind's callback: its status other than 0 is the exit status, and a value the
// signal library refuses (std::invalid_argument: an SSI frame too short for its fields, a pulse
// as wide as its period, a motion of no duration) is bad input, exit 2, as CLI11's own checks.
void on_run(CLI::App& kind, std::function<int()> run);
// Times: "10ms", "24.414us", "1.5s", "250ns", "3" (seconds). The one parser of every synth
// time option: bad input (CLI::ValidationError) naming `option` and its own range,
// "--first: 1ns .. 3600s (got nan)", unless the text is a time within lo .. hi, both as written
// and rounded to the nanosecond ("1e-10" is refused by a 1ns minimum, not rounded to 0).
[[nodiscard]] Nanos parse_duration(const std::string& text, const std::string& option, Nanos lo, Nanos hi);
// A time on the trace: 0 .. 3600 s (the VCD starts at 0; rig/campaign/limits.hpp kMaxEnd is a
// campaign's longest run: beyond it Nanos would overflow or a run never end).
[[nodiscard]] Nanos parse_instant(const std::string& text, const std::string& option);
// A width, a period or a run time: 1 ns .. 3600 s.
[[nodiscard]] Nanos parse_positive_duration(const std::string& text, const std::string& option);
// Bad input unless lo <= value <= hi (NaN and infinities are outside): throws
// CLI::ValidationError "OPTION: RANGE (got VALUE)", RANGE as a person writes it ("0 .. 32767 rpm").
void require_within(const std::string& option, double value, double lo, double hi, const std::string& range);
// A whole number lo..hi from one field of a list option ("--train: a count 1 .. 5000000 (got 0)").
[[nodiscard]] std::int64_t parse_whole(const std::string& text, const std::string& option,
                                       const std::string& what, std::int64_t lo, std::int64_t hi);
// "3600s", "250us", "0s": the largest unit that writes the duration exactly.
[[nodiscard]] std::string duration_words(Nanos d);
// An option that does nothing unless `applies` is bad input when given: "--duration: only with
// --profile constant or press (this is --profile trapezoid)", `needs` saying what it needs.
void refuse_unless_applies(const CLI::App& kind, const std::string& option, bool applies,
                           const std::string& needs);
// Bad input before anything is written unless `path` ("-": stdout) can be written: not a
// directory, in a directory that exists and may be written ("--out /nowhere/x.vcd: cannot write
// in /nowhere: No such file or directory"). Every output of a kind is checked first, so a
// refused one leaves no other behind.
void require_writable(const std::string& option, const std::string& path);
// Writes the trace as VCD to `path` ("-" for stdout): a new or regular file through a
// temporary renamed over it (a crash leaves the old file or the whole new one), a device, pipe
// or symlink written through; throws std::runtime_error on I/O failure.
void write_vcd_file(const TraceRecorder& trace, const std::string& path);
// The same, any text: `write` formats into the temporary (a candump log).
void write_output_file(const std::string& path, const std::function<void(std::ostream&)>& write);
// Whether two output paths name one file (./x.vcd and x.vcd, a link and its target).
[[nodiscard]] bool same_file(const std::string& a, const std::string& b);

} // namespace hilrig::cli
