#include "rig/results/campaign_result.hpp"

#include <algorithm>

#include <fmt/format.h>

namespace hilrig::rig {
namespace {

bool is_must_catch(const RunResult& run, const std::string& check) {
  return std::find(run.must_catch.begin(), run.must_catch.end(), check) != run.must_catch.end();
}

} // namespace

bool caught(const RunResult& run) {
  return std::any_of(run.checks.begin(), run.checks.end(), [&](const CheckResult& c) {
    return is_must_catch(run, c.check) && c.outcome() == Outcome::Fail;
  });
}

Judgement judgement_in(const RunResult& run, const CheckResult& check) {
  const Outcome o = check.outcome();
  if (run.fault.empty())
    return o == Outcome::Pass ? Judgement::Pass : o == Outcome::Fail ? Judgement::Fail : Judgement::Error;
  if (!is_must_catch(run, check.check)) return Judgement::NotJudged;
  if (caught(run)) return o == Outcome::Fail ? Judgement::Caught : Judgement::NotJudged;
  return o == Outcome::Error ? Judgement::Error : Judgement::Fail; // passed: the fault went unnoticed
}

Outcome run_outcome(const RunResult& run) {
  if (!run.error.empty()) return Outcome::Error;
  if (!run.fault.empty()) {
    if (caught(run)) return Outcome::Pass;
    const bool erred = std::any_of(run.checks.begin(), run.checks.end(), [&](const CheckResult& c) {
      return is_must_catch(run, c.check) && c.outcome() == Outcome::Error;
    });
    return erred ? Outcome::Error : Outcome::Fail;
  }
  Outcome o = Outcome::Pass;
  for (const auto& c : run.checks) {
    const Outcome co = c.outcome();
    if (co == Outcome::Error) return Outcome::Error;
    if (co == Outcome::Fail) o = Outcome::Fail;
  }
  return o;
}

void judge(RunResult& run) {
  run.outcome = run_outcome(run);
  for (auto& c : run.checks) c.judgement = judgement_in(run, c);
}

void RunTally::add(RunResult& run) {
  Totals& t = totals_;
  ++t.runs;
  judge(run);
  switch (run.outcome) {
  case Outcome::Pass:
    ++t.runs_passed;
    break;
  case Outcome::Fail:
    ++t.runs_failed;
    break;
  case Outcome::Error:
    ++t.runs_errored;
    break;
  }
  for (const auto& c : run.checks) {
    ++t.checks;
    t.measurements += c.measurements.size();
    switch (c.judgement) {
    case Judgement::Pass:
      ++t.checks_passed;
      break;
    case Judgement::Fail:
      ++t.checks_failed;
      break;
    case Judgement::Caught:
      ++t.checks_caught;
      break;
    case Judgement::NotJudged:
      ++t.checks_not_judged;
      break;
    case Judgement::Error:
      ++t.checks_errored;
      break;
    }
  }
  if (!run.fault.empty()) {
    FaultRow& row = faults_[run.fault];
    row.fault = run.fault;
    for (const auto& m : run.must_catch) {
      if (std::find(row.must_catch.begin(), row.must_catch.end(), m) == row.must_catch.end()) {
        row.must_catch.push_back(m);
      }
    }
    row.runs.push_back(run.index);
    if (caught(run)) ++row.caught_runs;
  }
  any_interrupted_ = any_interrupted_ || run.interrupted;
  last_interrupted_ = run.interrupted;
}

void RunTally::apply(CampaignResult& r) {
  Totals t = totals_;
  r.faults.clear();
  for (const auto& [name, row] : faults_) {
    ++t.faults;
    if (row.caught()) ++t.faults_caught;
    r.faults.push_back(row);
  }
  r.totals = t;
  r.last_run_interrupted = last_interrupted_;
  // A run stopped by a stop request did not run to its end: the result is not complete.
  r.complete = t.runs == r.planned_runs && !r.interrupted && !any_interrupted_;
  if (t.runs_errored > 0 || !r.complete) {
    r.verdict = Outcome::Error;
  } else if (t.runs_failed > 0 || t.faults_caught < t.faults) {
    r.verdict = Outcome::Fail;
  } else {
    r.verdict = Outcome::Pass;
  }
}

std::string incomplete_reason(const CampaignResult& r) {
  if (r.complete) return {};
  const std::size_t missing = r.planned_runs > r.totals.runs ? r.planned_runs - r.totals.runs : 0;
  return fmt::format(
      "incomplete: {} of {} planned runs have no result, the campaign did not run to its end{}", missing,
      r.planned_runs, r.interrupted ? fmt::format(" (stopped by {})", *r.interrupted) : "");
}

void finalize(CampaignResult& r) {
  std::stable_sort(r.runs.begin(), r.runs.end(),
                   [](const RunResult& a, const RunResult& b) { return a.index < b.index; });
  RunTally tally;
  for (auto& run : r.runs) tally.add(run);
  tally.apply(r);
}

} // namespace hilrig::rig
