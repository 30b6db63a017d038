#include "rig/checks/brake_application.hpp"

#include "rig/checks/support.hpp"

namespace hilrig::checks {
namespace {

constexpr Nanos kSampleStart{16'000'000}; // L1039: sampling begins 16 ms after the transition
constexpr Nanos kSampleTick{1'000'000};   // L1039: every millisecond
constexpr int kSamples = 16;              // L1039-L1040: the next sixteen
constexpr int kNoiseReleased = 8;         // L1039: released for 8 of them: noise
constexpr int kQualifyApplied = 12;       // L1040: applied for 12 of the 16, else noise

std::optional<Nanos> next_application(std::span<const Edge> line, Level applied_level, Nanos from) {
  const auto e = next_edge(line, from, Nanos::max(), applied_level);
  return e ? std::optional<Nanos>{e->time} : std::nullopt;
}

} // namespace

BrakeApplication brake_application(std::span<const Edge> line, Level before, Level applied_level, Nanos from,
                                   Nanos end, BrakeDebounce rule) {
  BrakeApplication out;
  std::optional<Nanos> start = next_application(line, applied_level, from);
  if (rule == BrakeDebounce::None) {
    if (start && *start <= end) out.applied = start;
    return out;
  }
  while (start) {
    const Nanos t0 = *start;
    int released = 0;
    std::optional<Nanos> abort_at;
    for (int k = 0; k < kSamples && !abort_at; ++k) {
      const Nanos at = t0 + kSampleStart + k * kSampleTick;
      if (at > end) return out;
      if (level_at(line, at, before) != applied_level && ++released >= kNoiseReleased) abort_at = at;
    }
    if (!abort_at) {
      const Nanos decision = t0 + kSampleStart + kSamples * kSampleTick;
      if (decision > end) return out;
      if (kSamples - released >= kQualifyApplied) {
        out.applied = t0;
        return out;
      }
      abort_at = decision;
    }
    out.rejected.push_back(t0);
    start = level_at(line, *abort_at, before) == applied_level
                ? std::optional<Nanos>{*abort_at}
                : next_application(line, applied_level, *abort_at);
  }
  return out;
}

} // namespace hilrig::checks
