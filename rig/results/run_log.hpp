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
// record and throws with the errno text.
// Folding the log (read_run_log, or `hilrig merge OUT.json DIR/runs.jsonl`) gives exactly the
// CampaignResult the runs make, so results.json is byte-identical to an in-memory campaign's.
// The writer also keeps, for the fold at the end of `hilrig run`, what a reader of the file
// would get: the header and the tally of the runs, and the runs themselves while their
// records total at most a budget (reading a run back costs more than running it in most
// shipped campaigns); beyond it it drops them and the fold reads the file, so the memory a
// campaign holds stays bounded however long it is.

#include <cstddef>
#include <cstdint>
#include <filesystem>
#include <optional>
#include <string>
#include <vector>

#include "rig/results/append_file.hpp"
#include "rig/results/campaign_result.hpp"
#include "rig/results/results_json.hpp"
#include "rig/results/run_source.hpp"

namespace hilrig::rig {

inline constexpr const char* kRunLogName = "runs.jsonl";
inline constexpr int kRunLogVersion = 1;
// The record bytes of the runs a RunLog keeps in memory at most (their typed form is of the
// same order): a few thousand runs of a shipped campaign.
inline constexpr std::size_t kRunLogHeldBytes = 32 * 1024 * 1024;

class RunLog {
public:
  // Creates (truncates) path and writes the header: `campaign`'s facts; its runs are not written.
  // It keeps the runs appended while their records total at most `held_bytes`.
  RunLog(const std::filesystem::path& path, const CampaignResult& campaign,
         std::size_t held_bytes = kRunLogHeldBytes);
  void append(const RunResult& run);
  [[nodiscard]] const std::filesystem::path& path() const { return file_.path(); }

  // What read_run_log_summary(path(), interrupted) gives, without reading the file (it does
  // read it when the runs were appended out of run order, to throw as the reader does).
  [[nodiscard]] CampaignResult summary(const std::optional<std::string>& interrupted = std::nullopt) const;
  // The runs appended, judged, in order: from memory while they are held, else what
  // run_log_runs(path()) reads back (the same runs).
  [[nodiscard]] RunSource runs() const;
  // Their results.json objects (RunDumpSource): the JSON each record was made of, dumped once
  // when it was written while the runs are held, else dumps_of(runs()).
  [[nodiscard]] RunDumpSource run_dumps() const;
  // Whether every run appended is still held (none was dropped for the budget).
  [[nodiscard]] bool holds_runs() const { return !dropped_; }

private:
  AppendFile file_;       // one record a block
  CampaignResult header_; // as a reader of the file gets it: finalized, no runs
  RunTally tally_;
  std::optional<std::uint64_t> last_index_;
  bool out_of_order_ = false;
  std::vector<RunResult> held_;         // judged, in the order appended
  std::vector<std::string> held_dumps_; // each one's run_to_json(run).dump(2)
  std::size_t held_bytes_ = 0;
  std::size_t budget_;
  bool dropped_ = false;
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
