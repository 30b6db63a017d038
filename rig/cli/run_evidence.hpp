#pragma once
// The files `hilrig run` writes into its --out directory (docs/campaigns.md, "Outputs"): what a
// new campaign there may remove, and what no other command may write over in a run's directory.

#include <string>

namespace hilrig::cli {

// Whether hilrig run writes a file of this name: results.json, junit.xml, report.html,
// runs.jsonl, trace*.vcd, can.log, *.gtkw, the lock, and each of them with ".tmp".
[[nodiscard]] bool is_run_evidence(const std::string& name);

} // namespace hilrig::cli
