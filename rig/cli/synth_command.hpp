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
// "10ms", "24.414us", "1.5s", "250ns", "3" (seconds); throws CLI::ValidationError naming
// `option` unless the text is a finite time within +-3600 s (a campaign's longest run,
// rig/campaign/limits.hpp kMaxEnd: beyond it Nanos would overflow or a run never end).
[[nodiscard]] Nanos parse_duration(const std::string& text, const std::string& option = "duration");
// Bad input unless lo <= value <= hi (NaN and infinities are outside): throws
// CLI::ValidationError "OPTION: RANGE (got VALUE)", RANGE as a person writes it ("0 .. 32767 rpm").
void require_within(const std::string& option, double value, double lo, double hi, const std::string& range);
// The same for a duration: "--late: 0s .. 3600s (got -1us)".
void require_duration_within(const std::string& option, const std::string& text, Nanos value, Nanos lo,
                             Nanos hi);
// A whole number lo..hi from one field of a list option ("--train: a count 1 .. 5000000 (got 0)").
[[nodiscard]] std::int64_t parse_whole(const std::string& text, const std::string& option,
                                       const std::string& what, std::int64_t lo, std::int64_t hi);
// "3600s", "250us", "0s": the largest unit that writes the duration exactly.
[[nodiscard]] std::string duration_words(Nanos d);
// Writes the trace as VCD to `path` ("-" for stdout); throws std::runtime_error on I/O failure.
void write_vcd_file(const TraceRecorder& trace, const std::string& path);

} // namespace hilrig::cli
