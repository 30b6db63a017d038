#pragma once
// junit.xml for CI servers: <testsuites> with one <testsuite> per run and one <testcase> per
// check per run, valid against Jenkins' JUnit schema (xunit-plugin junit-10.xsd): testsuite
// name, tests, failures, errors (required), skipped, time, timestamp, hostname, id, package;
// testcase name, classname, time; failure/error/skipped with message and type. Each testsuite's
// <properties> carry the campaign's traceability: tool_version, campaign_file, campaign_sha256,
// campaign_seed, dut_serial and station (when given), backend, host_link.

#include <cstdint>
#include <map>
#include <string>
#include <vector>

#include "rig/results/campaign_result.hpp"
#include "rig/results/run_source.hpp"

namespace hilrig::rig {

// Nominal run: a failed check is a <failure>, an unmeasurable one an <error>.
// Fault run: a must_catch check passes when it failed (the fault was caught), or when
// another must_catch check caught it, and is a <failure> "fault not caught" otherwise; the other checks are
// <skipped> (not judged). A run's rig error is one more testcase "rig" with an <error>. Classnames are
// "<campaign>.<run>" with every other dot made '_' (Jenkins splits the classname at its last dot into package
// and class; sweep keys and values hold dots).
//
// Wall-clock facts (timestamp, hostname, time) come from the clock and nowhere else: they are
// the only attributes that differ between two runs of the same campaign and seed, and the
// determinism tests ignore exactly these three.
struct JunitClock {
  std::string started_at = "1970-01-01T00:00:00Z"; // the campaign's start, ISO 8601 UTC
  std::string hostname = "localhost";
  std::map<std::uint64_t, double> run_seconds; // run index -> wall seconds it took
};
// A testcase's time is an equal share of its run's wall seconds (the run's checks are judged
// from one simulation), so testcase, testsuite and testsuites times add up. A run missing from
// run_seconds (its wall time is not known: `hilrig merge` reads results.json, which holds none)
// writes no time, nor does any element holding it: JUnit's time is optional, a 0 would lie.
[[nodiscard]] std::string to_junit_xml(const CampaignResult& result, const JunitClock& clock = {});
// The same text for `header` (finalized) with the runs `runs` gives, one at a time.
void write_junit_xml(const CampaignResult& header, const RunSource& runs, const JunitClock& clock,
                     const TextSink& out);

// A suite of campaigns (`hilrig run DIR`): one <testsuite> per campaign holding every
// testcase of its runs (classname "<campaign>.<run>"), its file, seed and verdict as properties.
// A campaign's testcases in a suite's junit.xml, made while its runs are at hand (the run log's
// writer holds them), so the suite's junit.xml need not read every run log back: their counts
// (the <testsuite> attributes) and text.
struct JunitCounts {
  std::size_t tests = 0, failed = 0, errored = 0, skipped = 0;
  double seconds = 0.0;
  bool timed = true; // every run's wall time known (JunitClock::run_seconds); else no time is written
  void add(const JunitCounts& o) {
    tests += o.tests;
    failed += o.failed;
    errored += o.errored;
    skipped += o.skipped;
    seconds += o.seconds;
    timed = timed && o.timed;
  }
};
struct JunitSuiteBody {
  JunitCounts counts;
  std::string testcases;
};
[[nodiscard]] JunitSuiteBody junit_suite_body(const CampaignResult& header, const RunSource& runs,
                                              const JunitClock& clock);

struct JunitCampaign {
  // nullptr: a campaign of the suite that has no results (a rig fault before or while it ran,
  // or a stop before it started): a testsuite of one erroring testcase saying `no_result`, so
  // a suite that did not run a campaign never reads green.
  const CampaignResult* result = nullptr;
  std::string file; // the campaign file as given
  JunitClock clock;
  RunSource runs;                       // the campaign's runs when `result` does not hold them (its run log)
  const JunitSuiteBody* body = nullptr; // when given: junit_suite_body(*result, runs, clock), made before
  std::string no_result;                // why there is no result
  std::string campaign{};               // its [campaign] name when there is none ("": the file's stem)
};
[[nodiscard]] std::string to_junit_suite_xml(const std::string& name,
                                             const std::vector<JunitCampaign>& campaigns);
void write_junit_suite_xml(const std::string& name, const std::vector<JunitCampaign>& campaigns,
                           const TextSink& out);

} // namespace hilrig::rig
