#include "rig/results/junit.hpp"

#include <algorithm>
#include <fmt/format.h>

#include "rig/results/xml_escape.hpp"

namespace hilrig::rig {
namespace {

enum class Verdict { Passed, Failed, Errored, Skipped };

struct Case {
  std::string name;
  Verdict verdict = Verdict::Passed;
  std::string message;
  std::string body;
};

// Every measurement as one line: the failure body a person reads in the CI view.
std::string measurements_text(const CheckResult& c) {
  std::string out;
  for (const auto& m : c.measurements) {
    out += fmt::format("{} = {} {} [{} .. {}] measured {}: {}\n", m.name, m.value, m.unit,
                       m.lower ? fmt::format("{}", *m.lower) : "-",
                       m.upper ? fmt::format("{}", *m.upper) : "-", to_string(m.outcome), m.detail);
  }
  return out;
}

std::string first_bad(const CheckResult& c) {
  for (const auto& m : c.measurements) {
    if (m.outcome != Outcome::Pass) return fmt::format("{}: {}", m.name, m.detail);
  }
  return {};
}

// The checks of a run that caught its fault, named for the skipped checks' message.
std::string catchers(const RunResult& run) {
  std::string out;
  for (const auto& c : run.checks)
    if (c.judgement == Judgement::Caught) out += (out.empty() ? "" : ", ") + c.check;
  return out;
}

// One testcase per check, from the word results.json holds for it (CheckResult::judgement).
std::vector<Case> cases_of(const RunResult& run) {
  std::vector<Case> cases;
  bool any_must_catch = false;
  for (const auto& c : run.checks) {
    Case k{c.check, Verdict::Passed, {}, measurements_text(c)};
    any_must_catch = any_must_catch ||
                     std::find(run.must_catch.begin(), run.must_catch.end(), c.check) != run.must_catch.end();
    switch (c.judgement) {
    case Judgement::Pass:
      break;
    case Judgement::Caught:
      k.body = fmt::format("caught fault '{}'\n{}", run.fault, k.body);
      break;
    case Judgement::NotJudged:
      k.verdict = Verdict::Skipped;
      k.message = run.outcome == Outcome::Pass
                      ? fmt::format("not judged: fault '{}' was caught by {}", run.fault, catchers(run))
                      : fmt::format("not judged in the run of fault '{}'", run.fault);
      break;
    case Judgement::Fail:
      k.verdict = Verdict::Failed;
      k.message = run.fault.empty() ? first_bad(c)
                                    : fmt::format("fault '{}' not caught: the check passed", run.fault);
      break;
    case Judgement::Error:
      k.verdict = Verdict::Errored;
      k.message = first_bad(c);
      if (k.message.empty()) k.message = "nothing judged: the check has no measurement";
      break;
    }
    cases.push_back(std::move(k));
  }
  if (!run.fault.empty() && !any_must_catch) {
    cases.push_back(Case{"catch " + run.fault,
                         Verdict::Failed,
                         fmt::format("fault '{}' not caught: none of its must_catch checks ran", run.fault),
                         {}});
  }
  if (!run.error.empty()) cases.push_back(Case{"rig", Verdict::Errored, run.error, run.error});
  return cases;
}

} // namespace

std::string to_junit_xml(const CampaignResult& r) {
  const std::string stamp = r.started_at.value_or("1970-01-01T00:00:00");
  const std::string host = r.host.value_or("localhost");
  std::string suites;
  std::size_t all = 0, all_failed = 0, all_errored = 0;
  for (const auto& run : r.runs) {
    const auto cases = cases_of(run);
    std::size_t failed = 0, errored = 0, skipped = 0;
    std::string body;
    const std::string classname = xml_escape(fmt::format("{}.{}", r.campaign, run.name));
    for (const auto& k : cases) {
      body +=
          fmt::format("    <testcase name=\"{}\" classname=\"{}\" time=\"0\"", xml_escape(k.name), classname);
      switch (k.verdict) {
      case Verdict::Passed:
        body += k.body.empty() ? "/>\n"
                               : fmt::format(">\n      <system-out>{}</system-out>\n    </testcase>\n",
                                             xml_escape(k.body));
        break;
      case Verdict::Failed:
        ++failed;
        body += fmt::format(">\n      <failure message=\"{}\" type=\"fail\">{}</failure>\n    </testcase>\n",
                            xml_escape(k.message), xml_escape(k.body));
        break;
      case Verdict::Errored:
        ++errored;
        body += fmt::format(">\n      <error message=\"{}\" type=\"error\">{}</error>\n    </testcase>\n",
                            xml_escape(k.message), xml_escape(k.body));
        break;
      case Verdict::Skipped:
        ++skipped;
        body += fmt::format(">\n      <skipped message=\"{}\"/>\n    </testcase>\n", xml_escape(k.message));
        break;
      }
    }
    suites +=
        fmt::format("  <testsuite name=\"{}\" tests=\"{}\" failures=\"{}\" errors=\"{}\" skipped=\"{}\" "
                    "time=\"0\" timestamp=\"{}\" hostname=\"{}\" id=\"{}\" package=\"{}\">\n",
                    classname, cases.size(), failed, errored, skipped, xml_escape(stamp), xml_escape(host),
                    run.index, xml_escape(r.campaign));
    suites += "    <properties>\n";
    suites += fmt::format("      <property name=\"seed\" value=\"{}\"/>\n", run.seed);
    suites += fmt::format("      <property name=\"outcome\" value=\"{}\"/>\n", to_string(run.outcome));
    if (!run.fault.empty())
      suites += fmt::format("      <property name=\"fault\" value=\"{}\"/>\n", xml_escape(run.fault));
    suites += "    </properties>\n";
    suites += body;
    suites += "    <system-out/>\n    <system-err/>\n  </testsuite>\n";
    all += cases.size();
    all_failed += failed;
    all_errored += errored;
  }
  return fmt::format("<?xml version=\"1.0\" encoding=\"UTF-8\"?>\n"
                     "<testsuites name=\"{}\" tests=\"{}\" failures=\"{}\" errors=\"{}\" time=\"0\">\n"
                     "{}</testsuites>\n",
                     xml_escape(r.campaign), all, all_failed, all_errored, suites);
}

} // namespace hilrig::rig
