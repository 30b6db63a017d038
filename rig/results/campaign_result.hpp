#pragma once
// A campaign's results as data: every run with its checks and observations, the fault
// detection matrix, totals and the verdict. The executive fills runs; finalize() derives the
// rest, so a shard, a merged set of shards and an unsharded run compute them the same way.

#include <cstddef>
#include <cstdint>
#include <map>
#include <optional>
#include <string>
#include <vector>

#include "rig/results/measurement.hpp"
#include "rig/results/motion_record.hpp"
#include "rig/results/trace_policy.hpp"

namespace hilrig::rig {

struct RunResult {
  std::uint64_t index = 0;             // position of the run in the whole (unsharded) campaign
  std::string name;                    // e.g. "ls1-throughput/600rpm"
  std::uint64_t seed = 0;              // the run's own seed
  std::string fault;                   // the fault injected in this run; "" for a nominal run
  std::vector<std::string> must_catch; // checks that must fail when `fault` is injected
  std::string error;                   // a rig fault that stopped the run ("" when none)
  bool interrupted = false;            // stopped by a stop request (SIGINT/SIGTERM); error says when
  std::vector<CheckResult> checks;
  std::vector<Observation> observations;
  MotionRecord motion; // the shaft's speed and position with its events (plant and brake runs)
  std::string trace;   // the run's trace file beside the results (e.g. "trace-run3.vcd"); "" when none kept
  Outcome outcome = Outcome::Error; // derived by finalize(): run_outcome()
};

// Nominal run: passes when every check passes. Fault run: passes when a must_catch check
// failed (the fault was caught); its other checks are not judged. Error when the run has a
// rig error, or (nominal) a check could not be measured, or (fault) a must_catch check erred.
[[nodiscard]] Outcome run_outcome(const RunResult& run);
// Whether a fault run's fault was caught: a must_catch check has outcome Fail.
[[nodiscard]] bool caught(const RunResult& run);
// The word a check of `run` reads (Judgement); finalize() stores it in CheckResult::judgement.
[[nodiscard]] Judgement judgement_in(const RunResult& run, const CheckResult& check);

// One row of the fault detection matrix: fault -> the checks that must catch it -> caught?
struct FaultRow {
  std::string fault;
  std::vector<std::string> must_catch;
  std::vector<std::uint64_t> runs; // indices of the runs that injected it
  std::size_t caught_runs = 0;
  [[nodiscard]] bool caught() const { return !runs.empty() && caught_runs == runs.size(); }
};

struct Totals {
  std::size_t runs = 0, runs_passed = 0, runs_failed = 0, runs_errored = 0;
  // Checks counted by the word they read: passed + failed + caught + not_judged + errored = checks.
  std::size_t checks = 0, checks_passed = 0, checks_failed = 0, checks_caught = 0, checks_not_judged = 0,
              checks_errored = 0;
  std::size_t measurements = 0;
  std::size_t faults = 0, faults_caught = 0;
  friend bool operator==(const Totals&, const Totals&) = default;
};

struct Shard {
  std::uint32_t index = 0;
  std::uint32_t count = 1;
};

struct CampaignResult {
  std::string campaign;        // the campaign's name
  std::string device;          // "ans1", "pls2700", ...
  std::string campaign_sha256; // SHA-256 of the campaign file's bytes (hex): merge refuses a mismatch
  std::string tool_version;    // the hilrig that ran it (kToolVersion): merge refuses a mismatch
  std::uint64_t seed = 0;
  Shard shard;
  // Traceability: the campaign file as given, the board's serial ([dut] serial) and the test
  // station (--station), "" when not given; how host actions reached the board and where it ran.
  std::string campaign_file;
  std::string dut_serial;
  std::string station;
  std::string host_link = "in-process";        // or "modbus-rtu-pty" (hilrig run --host-link)
  std::string backend = "virtual";             // or "hardware" (hilrig run --backend)
  TracePolicy trace_policy = TracePolicy::All; // which runs kept their trace files (hilrig run --trace)
  std::size_t planned_runs = 0;                // runs this result should hold when complete
  std::vector<RunResult> runs;                 // in run-index order
  // The campaign was stopped early by this signal ("SIGTERM"); nullopt when it was not.
  std::optional<std::string> interrupted;
  // Derived by finalize():
  std::vector<FaultRow> faults; // sorted by fault name
  Totals totals;
  Outcome verdict = Outcome::Error;
  bool complete = false;             // runs.size() == planned_runs
  bool last_run_interrupted = false; // the last run was cut short by a stop request (not written)
  // Wall-clock facts (start time, host). Never compared or merged; written under "wall_clock".
  std::optional<std::string> started_at;
  std::optional<std::string> host;
};

// Sorts runs by index and derives each run's outcome and each check's judgement, faults,
// totals, verdict and complete. The verdict is Pass
// when the result is complete, every run passes and every fault is caught; Error when any
// run erred (or the result is incomplete); Fail otherwise.
void finalize(CampaignResult& result);

// Why an incomplete result's verdict is an error, for junit.xml and report.html alike:
// "incomplete: 7 of 10 planned runs have no result, the campaign did not run to its end" (and
// the stop, when a signal stopped it). Empty when the result is complete.
[[nodiscard]] std::string incomplete_reason(const CampaignResult& result);

// Derives a run's outcome and each of its checks' judgement (what finalize() does per run).
void judge(RunResult& run);

// finalize() one run at a time, for runs that are not all held (a run log folded record by
// record): add() each run in index order (it derives the run's outcome and judgements), then
// apply() to a result whose `runs` are not held, or are exactly the runs added.
class RunTally {
public:
  void add(RunResult& run);
  void apply(CampaignResult& result);

private:
  std::map<std::string, FaultRow> faults_;
  Totals totals_;
  bool any_interrupted_ = false;
  bool last_interrupted_ = false;
};

} // namespace hilrig::rig
