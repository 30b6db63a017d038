#include "rig/cli/run_evidence.hpp"

#include "rig/cli/directory_lock.hpp"

namespace hilrig::cli {

namespace {

bool ends_with(const std::string& s, const std::string& tail) {
  return s.size() >= tail.size() && s.compare(s.size() - tail.size(), tail.size(), tail) == 0;
}

} // namespace

bool is_run_evidence(const std::string& name) {
  if (ends_with(name, ".tmp")) return is_run_evidence(name.substr(0, name.size() - 4));
  return name == "results.json" || name == "junit.xml" || name == "report.html" || name == "runs.jsonl" ||
         name == "can.log" || name == kDirectoryLockName ||
         (name.starts_with("trace") && ends_with(name, ".vcd")) || ends_with(name, ".gtkw");
}

} // namespace hilrig::cli
