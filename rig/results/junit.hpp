#pragma once
// junit.xml for CI servers: <testsuites> with one <testsuite> per run and one <testcase> per
// check per run, valid against Jenkins' JUnit schema (xunit-plugin junit-10.xsd): testsuite
// name, tests, failures, errors (required), skipped, time, timestamp, hostname, id, package;
// testcase name, classname, time; failure/error/skipped with message and type.

#include <string>

#include "rig/results/campaign_result.hpp"

namespace hilrig::rig {

// Nominal run: a failed check is a <failure>, an unmeasurable one an <error>.
// Fault run: a must_catch check passes when it failed (the fault was caught) and is a
// <failure> "fault not caught" otherwise; the other checks are <skipped> (not judged).
// A run's rig error is one more testcase "rig" with an <error>.
// Times are virtual and not recorded: time="0"; timestamp is started_at or the epoch.
[[nodiscard]] std::string to_junit_xml(const CampaignResult& result);

} // namespace hilrig::rig
