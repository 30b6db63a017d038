#pragma once
// The run log: a campaign's results as they happen, one JSON Lines record per run, so a
// campaign costs the same per run however long it is and a kill leaves every finished run.
//
//   line 1:    {"run_log": 1, "results": <results.json object of the campaign with no runs>}
//   line 2...: {"run": <the run's results.json object>}
//
// Each record is one write() of a whole line on an O_APPEND descriptor followed by
// fdatasync(): a SIGKILL or a crash of hilrig leaves whole records only; a power loss loses at
// most the record in flight, which the reader sees as a last line without its newline and
// ignores. A write that fails (ENOSPC, EFBIG, EIO) truncates the log back to its last whole
// record and throws with the errno text. Nothing per run is held in memory.
// Folding the log (read_run_log, or `hilrig merge OUT.json DIR/runs.jsonl`) gives exactly the
// CampaignResult the runs make, so results.json is byte-identical to an in-memory campaign's.

#include <filesystem>
#include <optional>
#include <string>

#include "rig/results/append_file.hpp"
#include "rig/results/campaign_result.hpp"
#include "rig/results/run_source.hpp"

namespace hilrig::rig {

inline constexpr const char* kRunLogName = "runs.jsonl";
inline constexpr int kRunLogVersion = 1;

class RunLog {
public:
  // Creates (truncates) path and writes the header: `campaign`'s facts; its runs are not written.
  RunLog(const std::filesystem::path& path, const CampaignResult& campaign);
  void append(const RunResult& run);
  [[nodiscard]] const std::filesystem::path& path() const { return file_.path(); }

private:
  AppendFile file_; // one record a block
};

// The campaign the log holds: its header with every whole record, finalized. Throws
// std::runtime_error naming the file and line of a record that is not a run.
[[nodiscard]] CampaignResult read_run_log(const std::filesystem::path& path);

// The same without its runs: the header finalized over every whole record read one at a time
// (faults, totals, verdict, complete), holding one run at a time; `interrupted` is the stop
// the campaign ended with (it is not in the log). Throws as read_run_log does, and when a
// record's run index is not above the one before (this writer writes runs in run order).
[[nodiscard]] CampaignResult
read_run_log_summary(const std::filesystem::path& path,
                     const std::optional<std::string>& interrupted = std::nullopt);
// The log's runs, read back one record at a time on each pass (the file must stay as it is).
[[nodiscard]] RunSource run_log_runs(const std::filesystem::path& path);

} // namespace hilrig::rig
