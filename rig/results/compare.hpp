#pragma once
// Nightly regression: every measurement of a new results file against a baseline, each read
// by what its run is (docs/campaigns.md "hilrig compare"). A drift beyond its threshold, a
// measurement that disappeared, one that newly fails (a nominal run's pass -> fail or error) or,
// in a fault run, a check that no longer catches the injected fault is a regression; a nominal
// measurement that passes again and a check that now catches its fault are improvements.
// Measurements are matched by run name and measurement name.

#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "rig/results/campaign_result.hpp"

namespace hilrig::rig {

// "NAME=VALUE" (absolute, in the measurement's unit) or "NAME=VALUE%" (relative). NAME is a
// measurement name or a dotted suffix of one ("p99" matches "ls1.p99"); the longest match wins.
struct Threshold {
  std::string name;
  double value = 0.0;
  bool relative = false;
};
// Throws std::invalid_argument on a malformed threshold.
[[nodiscard]] Threshold parse_threshold(std::string_view text);
// Whether `t` names `measurement`: its name, or a dotted suffix of it.
[[nodiscard]] bool threshold_matches(const Threshold& t, const std::string& measurement);

struct CompareOptions {
  std::vector<Threshold> thresholds;
  double default_rel = 0.05; // for measurements no threshold names
};

enum class Drift { Same, Within, Beyond, Missing, Added, NewlyFails, NowPasses, NowCatches, NoLongerCatches };
[[nodiscard]] const char* to_string(Drift d);

struct DriftRow {
  std::string run;         // the run's name
  std::string measurement; // the measurement's name
  std::string unit;
  std::optional<double> base;
  std::optional<double> now;
  std::optional<double> lower, upper; // the new result's limits (a newly failing value is read against them)
  // The measurement's word in its run (measurement_judgement()): "caught" in a fault run is
  // the fault's evidence, not a failure.
  Judgement base_word = Judgement::Error;
  Judgement now_word = Judgement::Error;
  Threshold threshold; // the one applied (name empty: the default)
  Drift drift = Drift::Same;
  [[nodiscard]] bool regression() const {
    return drift == Drift::Beyond || drift == Drift::Missing || drift == Drift::NewlyFails ||
           drift == Drift::NoLongerCatches;
  }
  [[nodiscard]] bool improvement() const { return drift == Drift::NowPasses || drift == Drift::NowCatches; }
};

struct Comparison {
  std::vector<DriftRow> rows; // baseline order, then added measurements
  Outcome base_verdict = Outcome::Error;
  Outcome now_verdict = Outcome::Error;
  [[nodiscard]] std::size_t regressions() const;
  [[nodiscard]] std::size_t improvements() const;
  [[nodiscard]] bool regression() const; // any row regressed, or the verdict got worse
};

[[nodiscard]] Comparison compare_results(const CampaignResult& base, const CampaignResult& now,
                                         const CompareOptions& options);

// A fixed-width table: every regression and drift, plus every row when `all`; then a summary.
[[nodiscard]] std::string format_comparison(const Comparison& c, bool all = false);

} // namespace hilrig::rig
