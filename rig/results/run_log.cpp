#include "rig/results/run_log.hpp"

#include <fstream>
#include <functional>
#include <optional>
#include <stdexcept>
#include <string>

#include <fmt/format.h>
#include <nlohmann/json.hpp>

#include "rig/results/results_json.hpp"

namespace hilrig::rig {

using nlohmann::json;

RunLog::RunLog(const std::filesystem::path& path, const CampaignResult& campaign, std::size_t held_bytes)
    : file_(path), budget_(held_bytes) {
  CampaignResult header = campaign;
  header.runs.clear();
  finalize(header);
  const json record = to_json(header);
  file_.append(json{{"run_log", kRunLogVersion}, {"results", record}}.dump() + "\n");
  header_ = campaign_from_json(record); // what the reader's header is: only the facts written
}

void RunLog::append(const RunResult& run) {
  // The record carries the words finalize() would derive, so a log read on its own agrees.
  RunResult judged = run;
  judge(judged);
  // The record is {"run":<the run's object, compact>}: while the runs are held, its text is
  // made from the indented dump results.json takes (compact_json_text), one dump, not two.
  const json run_json = run_to_json(judged);
  std::string dump = dropped_ ? run_json.dump() : run_json.dump(2);
  file_.append("{\"run\":" + (dropped_ ? dump : compact_json_text(dump)) + "}\n");
  if (last_index_ && judged.index <= *last_index_) out_of_order_ = true;
  last_index_ = judged.index;
  tally_.add(judged);
  if (dropped_) return;
  held_bytes_ += 2 * dump.size(); // the text and about as much again for the typed run
  if (held_bytes_ > budget_) {
    dropped_ = true;
    std::vector<RunResult>().swap(held_);
    std::vector<std::string>().swap(held_dumps_);
    return;
  }
  held_.push_back(std::move(judged));
  held_dumps_.push_back(std::move(dump));
}

namespace {

// Calls on_header with the header, then on_run with each whole record's run, one at a time.
void read_records(const std::filesystem::path& path, const std::function<void(CampaignResult)>& on_header,
                  const std::function<void(RunResult)>& on_run) {
  std::ifstream in(path, std::ios::binary);
  if (!in) throw std::runtime_error(fmt::format("cannot read {}", path.string()));
  std::string line;
  std::size_t number = 0;
  bool header = false;
  while (std::getline(in, line)) {
    ++number;
    if (in.eof()) break; // no newline: a record cut short by a power loss, not a whole run
    try {
      const json j = json::parse(line);
      if (!header) {
        if (!j.is_object() || !j.contains("run_log"))
          throw std::runtime_error(fmt::format("not a hilrig run log (version {})", kRunLogVersion));
        if (j.at("run_log") != kRunLogVersion)
          throw std::runtime_error(fmt::format("run log: unsupported version {}: hilrig {} reads version {}",
                                               j.at("run_log").dump(), tool_version(), kRunLogVersion));
        on_header(campaign_from_json(j.at("results")));
        header = true;
      } else {
        on_run(run_from_json(j.at("run")));
      }
    } catch (const std::exception& e) {
      throw std::runtime_error(fmt::format("{}:{}: {}", path.string(), number, e.what()));
    }
  }
  if (!header) throw std::runtime_error(fmt::format("{}: empty run log", path.string()));
}

} // namespace

CampaignResult read_run_log(const std::filesystem::path& path) {
  CampaignResult result;
  read_records(
      path, [&](CampaignResult header) { result = std::move(header); },
      [&](RunResult run) { result.runs.push_back(std::move(run)); });
  finalize(result);
  return result;
}

CampaignResult read_run_log_summary(const std::filesystem::path& path,
                                    const std::optional<std::string>& interrupted) {
  CampaignResult result;
  RunTally tally;
  std::optional<std::uint64_t> last;
  read_records(
      path, [&](CampaignResult header) { result = std::move(header); },
      [&](RunResult run) {
        if (last && run.index <= *last)
          throw std::runtime_error(fmt::format("run {} after run {}: not in run order", run.index, *last));
        last = run.index;
        tally.add(run);
      });
  result.interrupted = interrupted;
  tally.apply(result);
  return result;
}

CampaignResult RunLog::summary(const std::optional<std::string>& interrupted) const {
  if (out_of_order_) return read_run_log_summary(path(), interrupted); // throws with file:line
  CampaignResult result = header_;
  result.interrupted = interrupted;
  RunTally tally = tally_;
  tally.apply(result);
  return result;
}

RunSource RunLog::runs() const {
  if (dropped_) return run_log_runs(path());
  return [this](const RunVisitor& visit) {
    for (const RunResult& run : held_) visit(run);
  };
}

RunDumpSource RunLog::run_dumps() const {
  if (dropped_) return dumps_of(runs());
  return [this](const RunDumpVisitor& visit) {
    for (const std::string& dump : held_dumps_) visit(dump);
  };
}

RunSource run_log_runs(const std::filesystem::path& path) {
  return [path](const RunVisitor& visit) {
    read_records(
        path, [](const CampaignResult&) {},
        [&](RunResult run) {
          judge(run);
          visit(run);
        });
  };
}

} // namespace hilrig::rig
