#pragma once
// results.json: the campaign's results as JSON (schema: docs/results.schema.json).
// Deterministic: object keys sorted, runs in index order, absent limits written as null, no
// wall-clock time outside the "wall_clock" object (which compare and merge ignore).

#include <filesystem>
#include <functional>
#include <string>
#include <string_view>

#include <nlohmann/json_fwd.hpp>

#include "rig/results/atomic_file.hpp" // write_file_atomically, which write_results_file uses
#include "rig/results/campaign_result.hpp"
#include "rig/results/run_source.hpp"

namespace hilrig::rig {

inline constexpr const char* kResultsFormat = "hilrig-results";
inline constexpr int kResultsVersion = 2; // 2: outcome words, campaign_sha256, tool_version

// The hilrig version (the CMake project's), written into every results.json.
[[nodiscard]] const char* tool_version();

[[nodiscard]] nlohmann::json to_json(const CampaignResult& result);
// Throws std::runtime_error naming the first missing or mistyped field. Derived fields
// (faults, totals, verdict, complete) are recomputed with finalize(), not trusted.
[[nodiscard]] CampaignResult campaign_from_json(const nlohmann::json& j);

// One run as its results.json object, and back (the run log, rig/results/run_log.hpp, holds these).
[[nodiscard]] nlohmann::json run_to_json(const RunResult& run);
[[nodiscard]] RunResult run_from_json(const nlohmann::json& j);

[[nodiscard]] std::string to_json_text(const CampaignResult& result); // 2-space indent, trailing newline
// The same text for `header` (finalized, its runs not used) with the runs `runs` gives, one at a
// time: to_json_text(r) is write_json_text(r, runs_of(r), ...).
void write_json_text(const CampaignResult& header, const RunSource& runs, const TextSink& out);
// Each run's object as write_json_text writes it, run_to_json(run).dump(2), in index order:
// a writer that has already built a run's JSON (the run log's) dumps it once, not again here.
using RunDumpVisitor = std::function<void(std::string_view)>;
using RunDumpSource = std::function<void(const RunDumpVisitor&)>;
[[nodiscard]] RunDumpSource dumps_of(const RunSource& runs);
// The compact text (nlohmann's dump()) of the JSON whose indented text (dump(n), any n) is
// `indented`: the spaces and line breaks outside its strings dropped (the writer puts none
// anywhere else), so a writer holding an indented dump gets the compact one without a second.
[[nodiscard]] std::string compact_json_text(std::string_view indented);
void write_json_dumps(const CampaignResult& header, const RunDumpSource& runs, const TextSink& out);

// Writes to "<path>.tmp", then renames over path: a crash leaves either the previous
// complete file or the new one, never half a file. Call it again as runs finish to keep a
// readable partial-progress file (complete = false until the last run).
void write_results_file(const std::filesystem::path& path, const CampaignResult& result);
void write_results_file(const std::filesystem::path& path, const CampaignResult& header,
                        const RunSource& runs);
void write_results_dumps(const std::filesystem::path& path, const CampaignResult& header,
                         const RunDumpSource& runs);
// Throws std::runtime_error when the file cannot be read or is not a results file. A run log
// (*.jsonl, rig/results/run_log.hpp) is folded: its header and whole records, finalized.
[[nodiscard]] CampaignResult read_results_file(const std::filesystem::path& path);

} // namespace hilrig::rig
