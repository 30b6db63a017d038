#include "rig/campaign/stimulus_kinds.hpp"

#include <array>

namespace hilrig::campaign {

namespace {
constexpr std::array<StimulusKindInfo, 6> kKinds{{
    {"level", StimulusKind::Level, false, "level", "drive a discrete input to a level"},
    {"pulse", StimulusKind::Pulse, false, "width, level (high)", "one pulse of a width, then back"},
    {"bounce", StimulusKind::Bounce, false, "edges, period, level (high)",
     "contact bounce: close at `at`, then `edges` openings each `period` long and `period` apart"},
    {"glitch", StimulusKind::Glitch, true, "width",
     "the line inverted for a width (a spike on a quiet line)"},
    {"stuck", StimulusKind::Stuck, true, "level, until (end)",
     "the line held at a level from at until `until`"},
    {"missing_edges", StimulusKind::MissingEdges, true, "every (1), until (end)",
     "every n-th edge of an encoder line lost from at until `until`"},
}};
} // namespace

std::span<const StimulusKindInfo> stimulus_kinds() { return kKinds; }

const StimulusKindInfo* find_stimulus_kind(std::string_view name) {
  for (const auto& k : kKinds)
    if (k.name == name) return &k;
  return nullptr;
}

} // namespace hilrig::campaign
