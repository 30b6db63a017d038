#include "rig/results/trace_policy.hpp"

#include <array>

namespace hilrig::rig {

namespace {
constexpr std::array kPolicies{TracePolicy::All, TracePolicy::Failed, TracePolicy::None};
} // namespace

const char* to_string(TracePolicy policy) {
  switch (policy) {
  case TracePolicy::All:
    return "all";
  case TracePolicy::Failed:
    return "failed";
  case TracePolicy::None:
    return "none";
  }
  return "all";
}

std::optional<TracePolicy> trace_policy_named(std::string_view name) {
  for (const TracePolicy p : kPolicies)
    if (name == to_string(p)) return p;
  return std::nullopt;
}

std::vector<std::string> trace_policy_names() {
  std::vector<std::string> names;
  for (const TracePolicy p : kPolicies) names.emplace_back(to_string(p));
  return names;
}

bool keeps_trace(TracePolicy policy, bool first, bool passed) {
  switch (policy) {
  case TracePolicy::All:
    return first || !passed;
  case TracePolicy::Failed:
    return !passed;
  case TracePolicy::None:
    return false;
  }
  return false;
}

} // namespace hilrig::rig
