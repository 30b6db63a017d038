#include "rig/results/run_log.hpp"

#include <fstream>
#include <stdexcept>
#include <string>

#include <fmt/format.h>
#include <nlohmann/json.hpp>

#include "rig/results/results_json.hpp"

namespace hilrig::rig {

using nlohmann::json;

RunLog::RunLog(const std::filesystem::path& path, const CampaignResult& campaign) : file_(path) {
  CampaignResult header = campaign;
  header.runs.clear();
  finalize(header);
  file_.append(json{{"run_log", kRunLogVersion}, {"results", to_json(header)}}.dump() + "\n");
}

void RunLog::append(const RunResult& run) {
  // The record carries the words finalize() would derive, so a log read on its own agrees.
  RunResult judged = run;
  judged.outcome = run_outcome(judged);
  for (auto& c : judged.checks) c.judgement = judgement_in(judged, c);
  file_.append(json{{"run", run_to_json(judged)}}.dump() + "\n");
}

CampaignResult read_run_log(const std::filesystem::path& path) {
  std::ifstream in(path, std::ios::binary);
  if (!in) throw std::runtime_error(fmt::format("cannot read {}", path.string()));
  CampaignResult result;
  std::string line;
  std::size_t number = 0;
  bool header = false;
  while (std::getline(in, line)) {
    ++number;
    if (in.eof()) break; // no newline: a record cut short by a power loss, not a whole run
    try {
      const json j = json::parse(line);
      if (!header) {
        if (!j.is_object() || !j.contains("run_log") || j.at("run_log") != kRunLogVersion)
          throw std::runtime_error("not a hilrig run log (version 1)");
        result = campaign_from_json(j.at("results"));
        header = true;
      } else {
        result.runs.push_back(run_from_json(j.at("run")));
      }
    } catch (const std::exception& e) {
      throw std::runtime_error(fmt::format("{}:{}: {}", path.string(), number, e.what()));
    }
  }
  if (!header) throw std::runtime_error(fmt::format("{}: empty run log", path.string()));
  finalize(result);
  return result;
}

} // namespace hilrig::rig
