#include "rig/results/junit.hpp"

#include <filesystem>

#include <algorithm>
#include <fmt/format.h>
#include <optional>

#include "rig/results/number_format.hpp"
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

// The first measurement that did not pass, as the one line a CI server shows for the testcase
// (Jenkins' "Error Message", GitLab's summary): what was measured against which limits, then why.
std::string first_bad(const CheckResult& c) {
  const auto limit = [](const std::optional<double>& v) { return v ? format_number(*v) : std::string("-"); };
  for (const auto& m : c.measurements) {
    if (m.outcome == Outcome::Pass) continue;
    const std::string unit = m.unit.empty() ? "" : " " + m.unit;
    return fmt::format("{} = {}{}, limits [{} .. {}]{}, measured {}: {}", m.name,
                       format_number_apart(m.value, limit_beyond(m.value, m.lower, m.upper), 9), unit,
                       limit(m.lower), limit(m.upper), unit, to_string(m.outcome), m.detail);
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
  if (!run.error.empty())
    cases.push_back(Case{std::string(kRigCheckName), Verdict::Errored, run.error, run.error});
  return cases;
}

// Jenkins splits a classname at its last dot into package and class: the campaign is the
// package, the run the class, so neither may hold a dot of its own (sweep keys and values do).
std::string dotless(std::string text) {
  std::replace(text.begin(), text.end(), '.', '_');
  return text;
}

std::string seconds_text(double s) { return fmt::format("{:.3f}", s); }

using Counts = JunitCounts;

// ` time="..."`, or nothing when a run's wall time is not known (`hilrig merge`: results.json
// holds none): JUnit's time is optional, and a 0 would read as a run that took no time.
std::string time_attribute(bool known, double seconds) {
  return known ? fmt::format(" time=\"{}\"", seconds_text(seconds)) : std::string();
}

// The <testcase> elements of one run. The run's checks are judged from one simulation, so
// each of its testcases carries an equal share of the run's wall time: the times add up.
std::string testcases_xml(const CampaignResult& r, const RunResult& run, const JunitClock& clock,
                          Counts& counts) {
  const auto cases = cases_of(run);
  const auto wall = clock.run_seconds.find(run.index);
  const bool timed = wall != clock.run_seconds.end();
  const double run_seconds = timed ? wall->second : 0.0;
  const double share = cases.empty() ? 0.0 : run_seconds / static_cast<double>(cases.size());
  counts.seconds += run_seconds;
  counts.timed = counts.timed && timed;
  const std::string classname = xml_escape(dotless(r.campaign) + "." + dotless(run.name));
  std::string body;
  for (const auto& k : cases) {
    ++counts.tests;
    body += fmt::format("    <testcase name=\"{}\" classname=\"{}\"{}", xml_escape(k.name), classname,
                        time_attribute(timed, share));
    switch (k.verdict) {
    case Verdict::Passed:
      body += k.body.empty() ? "/>\n"
                             : fmt::format(">\n      <system-out>{}</system-out>\n    </testcase>\n",
                                           xml_escape(k.body));
      break;
    case Verdict::Failed:
      ++counts.failed;
      body += fmt::format(">\n      <failure message=\"{}\" type=\"fail\">{}</failure>\n    </testcase>\n",
                          xml_escape(k.message), xml_escape(k.body));
      break;
    case Verdict::Errored:
      ++counts.errored;
      body += fmt::format(">\n      <error message=\"{}\" type=\"error\">{}</error>\n    </testcase>\n",
                          xml_escape(k.message), xml_escape(k.body));
      break;
    case Verdict::Skipped:
      ++counts.skipped;
      body += fmt::format(">\n      <skipped message=\"{}\"/>\n    </testcase>\n", xml_escape(k.message));
      break;
    }
  }
  return body;
}

std::string testsuite_open(const std::string& name, const Counts& c, const JunitClock& clock,
                           const std::string& id, const std::string& package) {
  return fmt::format("  <testsuite name=\"{}\" tests=\"{}\" failures=\"{}\" errors=\"{}\" skipped=\"{}\"{} "
                     "timestamp=\"{}\" hostname=\"{}\" id=\"{}\" package=\"{}\">\n",
                     xml_escape(name), c.tests, c.failed, c.errored, c.skipped,
                     time_attribute(c.timed, c.seconds), xml_escape(clock.started_at),
                     xml_escape(clock.hostname), xml_escape(id), xml_escape(package));
}

std::string property(const std::string& name, const std::string& value) {
  return fmt::format("      <property name=\"{}\" value=\"{}\"/>\n", xml_escape(name), xml_escape(value));
}

// The campaign's traceability facts, one property each (the serial and station when given).
std::string traceability_properties(const CampaignResult& r) {
  std::string s;
  s += property("tool_version", r.tool_version);
  s += property("campaign_sha256", r.campaign_sha256);
  s += property("campaign_seed", std::to_string(r.seed));
  if (!r.dut_serial.empty()) s += property("dut_serial", r.dut_serial);
  if (!r.station.empty()) s += property("station", r.station);
  s += property("backend", r.backend);
  s += property("host_link", r.host_link);
  s += property("trace_policy", to_string(r.trace_policy));
  return s;
}

std::string testsuites_open(const std::string& name, const Counts& all) {
  return fmt::format("<?xml version=\"1.0\" encoding=\"UTF-8\"?>\n"
                     "<testsuites name=\"{}\" tests=\"{}\" failures=\"{}\" errors=\"{}\"{}>\n",
                     xml_escape(name), all.tests, all.failed, all.errored,
                     time_attribute(all.timed, all.seconds));
}

// The counts of a run's testcases, as testcases_xml adds them, without its text.
Counts counts_of(const RunResult& run, const JunitClock& clock) {
  Counts c;
  for (const auto& k : cases_of(run)) {
    ++c.tests;
    c.failed += k.verdict == Verdict::Failed ? 1 : 0;
    c.errored += k.verdict == Verdict::Errored ? 1 : 0;
    c.skipped += k.verdict == Verdict::Skipped ? 1 : 0;
  }
  const auto wall = clock.run_seconds.find(run.index);
  c.timed = wall != clock.run_seconds.end();
  c.seconds = c.timed ? wall->second : 0.0;
  return c;
}

// The runs' counts together: the attributes that open the element before its testcases.
Counts counts_of(const RunSource& runs, const JunitClock& clock) {
  Counts all;
  runs([&](const RunResult& run) { all.add(counts_of(run, clock)); });
  return all;
}

// A campaign that did not run to its end (killed and folded from its run log, or stopped by a
// signal) has runs with no result. Its runs alone could all pass, so the missing ones are one
// <error> testcase: a CI server reading only junit.xml must not show the campaign green.
Counts missing_runs_counts(const CampaignResult& r) {
  Counts c;
  if (!r.complete) c.tests = c.errored = 1;
  return c;
}

std::string missing_runs_testcase(const CampaignResult& r) {
  if (r.complete) return {};
  const std::string message = incomplete_reason(r);
  return fmt::format("    <testcase name=\"complete\" classname=\"{}.campaign\" time=\"0.000\">\n"
                     "      <error message=\"{}\" type=\"error\">{}</error>\n    </testcase>\n",
                     xml_escape(dotless(r.campaign)), xml_escape(message), xml_escape(message));
}

RunSource source_of(const JunitCampaign& c) { return c.runs ? c.runs : runs_of(*c.result); }

} // namespace

JunitSuiteBody junit_suite_body(const CampaignResult& header, const RunSource& runs,
                                const JunitClock& clock) {
  // One pass over the runs: the counts as counts_of(runs, clock) adds them, and the text.
  Counts all;
  std::string text;
  runs([&](const RunResult& run) {
    all.add(counts_of(run, clock));
    Counts counts;
    text += testcases_xml(header, run, clock, counts);
  });
  all.add(missing_runs_counts(header));
  text += missing_runs_testcase(header);
  return JunitSuiteBody{all, std::move(text)};
}

void write_junit_xml(const CampaignResult& r, const RunSource& runs, const JunitClock& clock,
                     const TextSink& out) {
  // Two passes over the runs: the totals the root element opens with, then the text.
  Counts all = counts_of(runs, clock);
  all.add(missing_runs_counts(r));
  out(testsuites_open(r.campaign, all));
  runs([&](const RunResult& run) {
    Counts counts;
    const std::string body = testcases_xml(r, run, clock, counts);
    std::string suite = testsuite_open(dotless(r.campaign) + "." + dotless(run.name), counts, clock,
                                       std::to_string(run.index), dotless(r.campaign));
    suite += "    <properties>\n";
    suite += property("seed", std::to_string(run.seed));
    suite += property("outcome", to_string(run.outcome));
    if (!run.fault.empty()) suite += property("fault", run.fault);
    if (!r.campaign_file.empty()) suite += property("campaign_file", r.campaign_file);
    suite += traceability_properties(r);
    suite += "    </properties>\n";
    suite += body;
    suite += "    <system-out/>\n    <system-err/>\n  </testsuite>\n";
    out(suite);
  });
  if (!r.complete) {
    out(testsuite_open(dotless(r.campaign) + ".campaign", missing_runs_counts(r), clock, "campaign",
                       dotless(r.campaign)) +
        missing_runs_testcase(r) + "    <system-out/>\n    <system-err/>\n  </testsuite>\n");
  }
  out("</testsuites>\n");
}

std::string to_junit_xml(const CampaignResult& r, const JunitClock& clock) {
  std::string text;
  write_junit_xml(r, runs_of(r), clock, [&](std::string_view piece) { text += piece; });
  return text;
}

void write_junit_suite_xml(const std::string& name, const std::vector<JunitCampaign>& campaigns,
                           const TextSink& out) {
  const auto counts_of_campaign = [](const JunitCampaign& c) {
    if (c.result == nullptr) {
      Counts none;
      none.tests = none.errored = 1;
      return none;
    }
    if (c.body) return c.body->counts;
    Counts counts = counts_of(source_of(c), c.clock);
    counts.add(missing_runs_counts(*c.result));
    return counts;
  };
  Counts all;
  for (const auto& c : campaigns) all.add(counts_of_campaign(c));
  out(testsuites_open(name, all));
  for (std::size_t i = 0; i < campaigns.size(); ++i) {
    if (campaigns[i].result == nullptr) {
      // Named as its results would be, so a CI's history of the campaign stays one series.
      const std::string stem = campaigns[i].campaign.empty()
                                   ? std::filesystem::path(campaigns[i].file).stem().string()
                                   : campaigns[i].campaign;
      out(testsuite_open(stem, counts_of_campaign(campaigns[i]), campaigns[i].clock, std::to_string(i),
                         dotless(stem)));
      out("    <properties>\n" + property("campaign_file", campaigns[i].file) + "    </properties>\n");
      out(fmt::format("    <testcase name=\"results\" classname=\"{}.campaign\" time=\"0.000\">\n"
                      "      <error message=\"{}\" type=\"error\">{}</error>\n    </testcase>\n",
                      xml_escape(dotless(stem)), xml_escape(campaigns[i].no_result),
                      xml_escape(campaigns[i].no_result)));
      out("    <system-out/>\n    <system-err/>\n  </testsuite>\n");
      continue;
    }
    const CampaignResult& r = *campaigns[i].result;
    out(testsuite_open(r.campaign, counts_of_campaign(campaigns[i]), campaigns[i].clock, std::to_string(i),
                       dotless(r.campaign)));
    std::string props = "    <properties>\n";
    props += property("campaign_file", campaigns[i].file);
    props += property("seed", std::to_string(r.seed));
    props += property("verdict", to_string(r.verdict));
    props += traceability_properties(r);
    props += "    </properties>\n";
    out(props);
    if (campaigns[i].body) {
      out(campaigns[i].body->testcases);
    } else {
      source_of(campaigns[i])([&](const RunResult& run) {
        Counts counts;
        out(testcases_xml(r, run, campaigns[i].clock, counts));
      });
      out(missing_runs_testcase(r));
    }
    out("    <system-out/>\n    <system-err/>\n  </testsuite>\n");
  }
  out("</testsuites>\n");
}

std::string to_junit_suite_xml(const std::string& name, const std::vector<JunitCampaign>& campaigns) {
  std::string text;
  write_junit_suite_xml(name, campaigns, [&](std::string_view piece) { text += piece; });
  return text;
}

} // namespace hilrig::rig
