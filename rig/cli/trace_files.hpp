#pragma once
// A run's trace as files a person opens in GTKWave or PulseView: STEM.vcd, with a wire per
// check (check.<name>) high over every window the check judged, and for each check that
// failed (or erred) STEM.<check>.gtkw, a GTKWave save file that opens the VCD zoomed on the
// first failed measurement's window, markers A and B at its edges and the primary marker at
// the edge it captured (docs/campaigns.md, "Traces").

#include <filesystem>
#include <optional>
#include <string>

#include "core/trace.hpp"
#include "rig/results/campaign_result.hpp"

namespace hilrig::cli {

// Writes STEM.vcd (and, when gtkw_for_failures, a .gtkw per failed check) atomically: a crash
// leaves a whole file or none. Declares the check.<name> wires on `trace`. `end`: the run's
// end (campaign.end of a run that ran to it), written as a final "#<end>" when later than the
// last change; none for a run cut short, whose trace ends where it stopped.
void write_trace_files(const std::filesystem::path& dir, const std::string& stem, TraceRecorder& trace,
                       const rig::RunResult& run, bool gtkw_for_failures, std::optional<Nanos> end);
// The same run's trace under a second stem: STEM.vcd a hard link to WRITTEN_STEM.vcd (written by
// write_trace_files for this run, so the same bytes), and the .gtkw files of its failed checks.
void link_trace_files(const std::filesystem::path& dir, const std::string& written_stem,
                      const std::string& stem, const TraceRecorder& trace, const rig::RunResult& run);

// The window a save file opens on (exposed for tests): [begin, end] in ns.
struct GtkwView {
  Nanos begin;
  Nanos end;
  std::optional<Nanos> at; // the primary marker (default: begin)
};
// GTKWave's save-file text for `vcd_name`, showing `signals`, zoomed on `view` with its edges
// as markers A and B (primary marker at A).
[[nodiscard]] std::string gtkw_text(const std::string& vcd_name, const std::string& title,
                                    const GtkwView& view, const std::vector<SignalInfo>& signals);

} // namespace hilrig::cli
