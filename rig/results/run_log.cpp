#include "rig/results/run_log.hpp"

#include <fcntl.h>
#include <unistd.h>

#include <cerrno>
#include <cstring>
#include <fstream>
#include <stdexcept>
#include <string>

#include <fmt/format.h>
#include <nlohmann/json.hpp>

#include "rig/results/results_json.hpp"

namespace hilrig::rig {

using nlohmann::json;

RunLog::RunLog(const std::filesystem::path& path, const CampaignResult& campaign) : path_(path) {
  fd_ = ::open(path.c_str(), O_WRONLY | O_CREAT | O_TRUNC | O_APPEND | O_CLOEXEC, 0644);
  if (fd_ < 0)
    throw std::runtime_error(fmt::format("cannot write {}: {}", path.string(), std::strerror(errno)));
  CampaignResult header = campaign;
  header.runs.clear();
  finalize(header);
  try {
    write_record(json{{"run_log", kRunLogVersion}, {"results", to_json(header)}}.dump() + "\n");
  } catch (...) {
    ::close(fd_);
    throw;
  }
}

RunLog::~RunLog() {
  if (fd_ >= 0) ::close(fd_);
}

void RunLog::append(const RunResult& run) {
  // The record carries the words finalize() would derive, so a log read on its own agrees.
  RunResult judged = run;
  judged.outcome = run_outcome(judged);
  for (auto& c : judged.checks) c.judgement = judgement_in(judged, c);
  write_record(json{{"run", run_to_json(judged)}}.dump() + "\n");
}

void RunLog::write_record(const std::string& line) {
  // One write() of the whole line: a short write only happens at a size limit or a full disk,
  // and then the partial record is cut off again so the log ends on a whole record.
  ssize_t n = -1;
  do n = ::write(fd_, line.data(), line.size());
  while (n < 0 && errno == EINTR);
  int err = 0;
  if (n < 0)
    err = errno;
  else if (static_cast<std::size_t>(n) != line.size())
    err = EFBIG;
  else if (::fdatasync(fd_) != 0)
    err = errno;
  if (err != 0) {
    if (::ftruncate(fd_, size_) != 0) { /* the reader ignores a torn last line */
    }
    throw std::runtime_error(fmt::format("cannot write {}: {}", path_.string(), std::strerror(err)));
  }
  size_ += static_cast<off_t>(line.size());
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
