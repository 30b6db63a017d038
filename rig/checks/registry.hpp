#pragma once
// The registry of check kinds: name -> parameter table + builder. The campaign parser builds
// each check's typed parameters once with build_check_params() (every range and finiteness
// rule checked there); the executive runs them with run_check() on the run's Capture;
// `hilrig list` names the kinds and their parameters from check_kinds(). Units are in the
// parameter names (limit_us, advance_ms, tolerance_counts).

#include <functional>
#include <map>
#include <optional>
#include <set>
#include <stdexcept>
#include <string>
#include <string_view>
#include <vector>

#include <nlohmann/json_fwd.hpp>

#include "rig/checks/check_params.hpp"
#include "rig/checks/support.hpp"

namespace hilrig::checks {

// What one run captured, as plain data the executive fills from its trace.
struct Capture {
  std::map<std::string, std::vector<Edge>, std::less<>> lines; // every captured line, by trace name
  // Each captured line's level at the capture's start, where it is known (the trace's initial
  // value): where a line starts is no edge, so a check that needs the level before the first
  // edge (shaft_move's direction) reads it here.
  std::map<std::string, Level, std::less<>> initial{};
  // The lines the rig drives into the board (its stimuli): an edge missing there is the
  // campaign's, and a check waiting for it judged nothing (an error, not the board's fail).
  std::set<std::string, std::less<>> rig_driven{};
  PositionFn position; // stimulus position, counts (e.g. the motion profile)
  PositionFn speed;    // counts/s
  // When the rig knows the trajectory (virtual time): how long `position` holds still from a
  // time, so a crossing scan steps over a standstill (empty: sample every step).
  HeldFn held{};
  std::vector<PositionSample> motion{}; // the shaft's position trace (brake checks)
  // The encoder count's changes as the board saw them (append_motion-compacted; brake report
  // window). Empty: `motion` is the count changes.
  std::vector<PositionSample> counts{};
  // When the rig knows the trajectory (virtual time): the exact standstill at or after a
  // time (nullopt: still moving at the end). Empty on hardware, where only count changes
  // are evidence (checks/standstill.hpp: an interval).
  std::function<std::optional<Nanos>(Nanos)> standstill{};
  std::vector<rig::Observation> observations{};
  std::map<std::string, std::vector<RawFrame>, std::less<>> frames; // by bus or link name
  std::map<std::string, FrameDecoder, std::less<>> decoders;        // by decoder name
  Nanos begin{0};
  Nanos end{0};
  // Debounce only: the bisections the executive ran with bisect_boundary() and the check's
  // plan, one per probe start (DebounceParams::probe_starts), in that order.
  std::vector<PhaseBisection> bisections{};
};

enum class ParamType { Number, Integer, Boolean, String, Level, NumberList };
[[nodiscard]] const char* to_string(ParamType t);

// The valid range of a number (every number must be finite besides).
struct ParamRange {
  std::optional<double> min{};
  bool min_open = false; // min itself is out of range ("> 0")
  std::optional<double> max{};
};
// "a finite number > 0", "an integer 1 .. 65535", "\"high\" or \"low\"", ...
[[nodiscard]] std::string expected_text(ParamType t, const ParamRange& range);

struct ParamSpec {
  std::string name{};
  ParamType type = ParamType::Number;
  bool required = false;
  std::string help{}; // one line, with the default
  ParamRange range{};
  // An instant of the run (from_us, at_ms, crossings_us, ...), in ns per unit of the number;
  // 0 for a number that is not one (a limit, a width). The campaign reader holds an instant
  // to 0 .. campaign.end, so a window past the run's end is refused before anything runs.
  double instant_ns = 0.0;
  // A duration that must last (a timeout, a step, a probe width, a tick), in ns per unit of
  // the number; 0 for any other. Rounded to whole ns as the check rounds it, it must be at
  // least 1 ns: 0.0004 us is 0 ns, a timeout or probe of no time at all.
  double duration_ns = 0.0;
};
// The same for a parameter: a duration (ParamSpec::duration_ns) reads "a finite number >=
// 0.0005 (at least 1 ns once rounded to whole ns)".
[[nodiscard]] std::string expected_text(const ParamSpec& p);

// A problem with one check parameter: the key ("" for the check as a whole) and the valid
// range, for the campaign parser's file:line:col: key: expected.
class ParamError : public std::invalid_argument {
public:
  ParamError(std::string key, const std::string& expected)
      : std::invalid_argument(expected), key_(std::move(key)) {}
  [[nodiscard]] const std::string& key() const { return key_; }

private:
  std::string key_;
};

struct CheckKind {
  std::string name{};    // "throughput", "debounce", "advance_counts", ...
  std::string summary{}; // one line for `hilrig list`
  std::vector<ParamSpec> params{};
  // Typed parameters from a table whose keys and types already match `params`; throws
  // ParamError for a rule across parameters.
  std::function<CheckParams(std::string_view check, const nlohmann::json& table)> build;
  bool needs_bisection = false; // the executive runs the plan's probes before run_check (debounce)
};

[[nodiscard]] const std::vector<CheckKind>& check_kinds();
[[nodiscard]] const CheckKind* find_check_kind(std::string_view name);

// The typed parameters of check `check` of `kind` from its table as written (the TOML table
// converted to JSON). Throws ParamError for the first problem: an unknown or missing key, a
// wrong type, a number not finite or out of its range, a rule across parameters.
[[nodiscard]] CheckParams build_check_params(const CheckKind& kind, std::string_view check,
                                             const nlohmann::json& table);

// Runs check `check`; sets CheckResult::check and ::kind. A line, observation or decoder the
// capture lacks gives a result whose only measurement is an Error naming it.
[[nodiscard]] CheckResult run_check(std::string_view check, const CheckParams& params,
                                    const Capture& capture);

} // namespace hilrig::checks
