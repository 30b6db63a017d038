#pragma once
// The registry of check kinds: name -> function + parameter schema. The campaign parser
// validates a check's parameters with validate_check_params(); the executive runs it with
// run_check() on the run's Capture; `hilrig list` names them from check_kinds().
// Parameters are a JSON object (the campaign's TOML table converted); units are in the names
// (limit_us, advance_ms, tolerance_counts).

#include <functional>
#include <map>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include <nlohmann/json_fwd.hpp>

#include "rig/checks/brake.hpp"
#include "rig/checks/debounce.hpp"
#include "rig/checks/frames.hpp"
#include "rig/checks/support.hpp"

namespace hilrig::checks {

// What one run captured, as plain data the executive fills from its trace.
struct Capture {
  std::map<std::string, std::vector<Edge>, std::less<>> lines; // every captured line, by trace name
  PositionFn position;                  // stimulus position, counts (e.g. the motion profile)
  PositionFn speed;                     // counts/s
  std::vector<PositionSample> motion{}; // the shaft's position trace (brake checks)
  std::vector<rig::Observation> observations{};
  std::map<std::string, std::vector<RawFrame>, std::less<>> frames; // by bus or link name
  std::map<std::string, FrameDecoder, std::less<>> decoders;        // by decoder name
  Nanos begin{0};
  Nanos end{0};
  // Debounce only: the bisection the executive ran with bisect_boundary() and debounce_plan().
  std::optional<Bisection> bisection{};
};

enum class ParamType { Number, Integer, Boolean, String, Level, NumberList };
[[nodiscard]] const char* to_string(ParamType t);

struct ParamSpec {
  std::string name{};
  ParamType type = ParamType::Number;
  bool required = false;
  std::string help{}; // one line, with the default
};

using CheckFn = std::function<CheckResult(const Capture& capture, const nlohmann::json& params)>;

struct CheckKind {
  std::string name{};    // "throughput", "debounce", "advance_counts", ...
  std::string summary{}; // one line for `hilrig list`
  std::vector<ParamSpec> params{};
  CheckFn run;
  bool needs_bisection = false; // the executive runs debounce_plan() probes before run()
  // Rules across parameters (e.g. "crossings_us or setpoint"); returns error sentences.
  std::function<std::vector<std::string>(const nlohmann::json&)> cross_check;
};

[[nodiscard]] const std::vector<CheckKind>& check_kinds();
[[nodiscard]] const CheckKind* find_check_kind(std::string_view name);

// Every problem with the parameters, one sentence each: unknown names, missing required
// ones, wrong types, cross-parameter rules. Empty when valid.
[[nodiscard]] std::vector<std::string> validate_check_params(const CheckKind& kind,
                                                             const nlohmann::json& params);

// Runs the check named `check` of kind `kind`; sets CheckResult::check. Unknown kinds and
// invalid parameters give a result whose only measurement is an Error naming the problem.
[[nodiscard]] CheckResult run_check(std::string_view check, std::string_view kind, const Capture& capture,
                                    const nlohmann::json& params);

// Debounce: the probe plan from a check's parameters (narrow_us, wide_us, resolution_us,
// input, output) for the executive's bisect_boundary() call.
struct BisectionPlan {
  Nanos narrow{0};
  Nanos wide{0};
  Nanos resolution{0};
  std::string input{};       // the line the pulse is driven on
  std::string output{};      // the line whose edge means "accepted"
  Level level = Level::High; // the pulse's active level on the input
};
[[nodiscard]] BisectionPlan debounce_plan(const nlohmann::json& params);

} // namespace hilrig::checks
