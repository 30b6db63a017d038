#include "sample_campaign.hpp"

#include <fmt/format.h>

namespace hilrig::rig::test {

namespace {

Measurement m(std::string name, double value, std::string unit, std::optional<double> lower,
              std::optional<double> upper) {
  Measurement out;
  out.name = std::move(name);
  out.value = value;
  out.unit = std::move(unit);
  out.lower = lower;
  out.upper = upper;
  out.outcome = judge(value, lower, upper);
  out.detail = "hand-made";
  return out;
}

CheckResult throughput(double max_us) {
  CheckResult c;
  c.check = "ls1-throughput";
  c.kind = "throughput";
  c.measurements.push_back(m("ls1-throughput.count", 3, "", 1.0, std::nullopt));
  c.measurements.push_back(m("ls1-throughput.max", max_us, "us", std::nullopt, 20.0));
  c.measurements.back().window =
      TraceWindow{Nanos{1'000'000}, Nanos{1'000'000 + static_cast<std::int64_t>(max_us * 1e3)}};
  c.series.push_back(Series{"latency", "us", {12.0, 15.0, max_us}});
  return c;
}

CheckResult advance() {
  CheckResult c;
  c.check = "ls1-advance";
  c.kind = "advance_counts";
  c.measurements.push_back(m("ls1-advance.edge0", 94.0, "counts", 93.0, 95.0));
  c.measurements.back().window = TraceWindow{Nanos{155'000'000}, Nanos{158'333'333}};
  c.measurements.back().at = Nanos{156'666'667};
  return c;
}

} // namespace

RunResult nominal_run(std::uint64_t index, double max_us) {
  RunResult r;
  r.index = index;
  r.name = fmt::format("ls1/run{}", index);
  r.seed = 1000 + index;
  r.checks = {throughput(max_us), advance()};
  r.observations.push_back(Observation{"dut.speed", 100.0, "rpm", Nanos{14'600'000}});
  return r;
}

RunResult fault_run(std::uint64_t index, const std::string& fault, bool caught) {
  RunResult r = nominal_run(index, caught ? 35.0 : 15.0);
  r.fault = fault;
  r.must_catch = {"ls1-throughput"};
  return r;
}

CampaignResult sample_campaign(std::size_t n) {
  CampaignResult c;
  c.campaign = "ans1-sample";
  c.device = "ans1";
  c.seed = 42;
  c.planned_runs = n;
  for (std::uint64_t i = 0; i < n; ++i) {
    c.runs.push_back(i % 3 == 2 ? fault_run(i, "slow_output", true)
                                : nominal_run(i, 10.0 + static_cast<double>(i)));
  }
  finalize(c);
  return c;
}

} // namespace hilrig::rig::test
