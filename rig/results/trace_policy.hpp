#pragma once
// Which runs of a campaign keep their trace files (`hilrig run --trace`), recorded in the
// results so a reader knows whether a run without a trace link passed or was never kept:
//   all     the shard's first run (trace.vcd) and every run that did not pass (the default)
//   failed  only the runs that did not pass: a passing run formats and writes nothing
//   none    no trace file at all
// The trace is recorded in every case: the checks judge from it (docs/campaigns.md, "Traces").

#include <cstdint>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

namespace hilrig::rig {

enum class TracePolicy : std::uint8_t { All, Failed, None };

[[nodiscard]] const char* to_string(TracePolicy policy);
// The policy of this name, nullopt when there is none.
[[nodiscard]] std::optional<TracePolicy> trace_policy_named(std::string_view name);
// Every policy's name, in the order above.
[[nodiscard]] std::vector<std::string> trace_policy_names();
// Whether a run keeps its trace file: `first` is the shard's first run, `passed` its outcome.
[[nodiscard]] bool keeps_trace(TracePolicy policy, bool first, bool passed);

} // namespace hilrig::rig
