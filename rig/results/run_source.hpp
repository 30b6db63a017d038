#pragma once
// The runs of a campaign, each visited once in index order, wherever they are: in memory, or
// read back one record at a time from a run log (rig/results/run_log.hpp). The writers of
// results.json, junit.xml and report.html take a source and a sink, so a campaign of any
// length is written holding one run at a time, and the in-memory and folded files are the same
// bytes because one routine writes both.

#include <functional>
#include <ostream>
#include <string_view>

#include "rig/results/campaign_result.hpp"

namespace hilrig::rig {

using RunVisitor = std::function<void(const RunResult&)>;
// Calls the visitor with each run, judged (judge()), in index order. A writer may call it
// more than once (a pass for its totals, a pass for its text).
using RunSource = std::function<void(const RunVisitor&)>;

// The runs `result` holds (finalized). The result must outlive the source.
[[nodiscard]] inline RunSource runs_of(const CampaignResult& result) {
  return [&result](const RunVisitor& visit) {
    for (const RunResult& run : result.runs) visit(run);
  };
}

// Where a writer puts its text, piece by piece.
using TextSink = std::function<void(std::string_view)>;

// A sink that writes to `out` (write_file_atomically's stream, rig/results/atomic_file.hpp).
[[nodiscard]] inline TextSink sink_to(std::ostream& out) {
  return
      [&out](std::string_view piece) { out.write(piece.data(), static_cast<std::streamsize>(piece.size())); };
}

} // namespace hilrig::rig
