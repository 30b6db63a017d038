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

#include <functional>
#include <string>

#include "core/time.hpp"
#include "core/trace.hpp"

namespace hilrig::cli {

void add_synth_command(CLI::App& app);

using SynthKindAdder = void (*)(CLI::App& synth);
// Registers a `hilrig synth <kind>` adder; returns true so it can initialise a static.
bool register_synth_kind(SynthKindAdder add);

// Helpers shared by the synth kinds.
// Makes `run` the kind's callback: its status other than 0 is the exit status, and a value the
// signal library refuses (std::invalid_argument: an SSI frame too short for its fields, a pulse
// as wide as its period, a motion of no duration) is bad input, exit 2, as CLI11's own checks.
void on_run(CLI::App& kind, std::function<int()> run);
// "10ms", "24.414us", "1.5s", "250ns", "3" (seconds); throws CLI::ValidationError.
[[nodiscard]] Nanos parse_duration(const std::string& text);
// Writes the trace as VCD to `path` ("-" for stdout); throws std::runtime_error on I/O failure.
void write_vcd_file(const TraceRecorder& trace, const std::string& path);

} // namespace hilrig::cli
