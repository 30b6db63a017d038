// Writes results.json, junit.xml and report.html of the sample campaign into a directory, for
// the independent Python checks of the JUnit structure (check_junit.py).

#include <cstdio>
#include <filesystem>

#include "rig/results/junit.hpp"
#include "rig/results/report_html.hpp"
#include "rig/results/results_json.hpp"
#include "sample_campaign.hpp"

int main(int argc, char** argv) {
  if (argc != 2) {
    std::fprintf(stderr, "usage: write_sample_results DIR\n");
    return 2;
  }
  namespace fs = std::filesystem;
  const fs::path dir = argv[1];
  fs::create_directories(dir);
  using namespace hilrig::rig;
  CampaignResult c = test::sample_campaign(6);
  // One of each testcase verdict: a failure, an error, skips (fault run 2), passes.
  c.runs.push_back(test::nominal_run(6, 25.0));
  c.runs.push_back(test::fault_run(7, "glitch & bounce", false));
  c.runs.push_back(test::nominal_run(8, 10.0));
  c.runs.back().error = "CAN bus-off <node 3>";
  c.planned_runs = c.runs.size();
  finalize(c);
  write_results_file(dir / "results.json", c);
  write_file_atomically(dir / "junit.xml", to_junit_xml(c));
  write_file_atomically(dir / "report.html", to_report_html(c));
  return 0;
}
