#pragma once

#include <optional>
#include <string>

#include <nlohmann/json.hpp>

#include "rig/campaign/campaign.hpp"
#include "rig/checks/registry.hpp"

namespace hilrig::campaign {

// A check parameter the campaign cannot run as written: its key and what it expects.
struct CheckTimeProblem {
  std::string key;
  std::string expected;
};

// The instants a check names (ParamSpec::instant_ns: from_us, to_us, crossings_us, at_ms,
// applied_ms, from_ms, to_ms) lie within the run, 0 .. campaign.end, each rounded to whole ns
// as the check rounds it; a word check's at_ms is not before the first [[host]] read of its
// observation. Either would judge nothing, found only after the whole run: this finds it
// before anything runs. `table` holds the check's keys, already typed and ranged by
// build_check_params().
[[nodiscard]] std::optional<CheckTimeProblem>
check_time_problem(const Scenario& s, const checks::CheckKind& kind, const nlohmann::json& table);

} // namespace hilrig::campaign
