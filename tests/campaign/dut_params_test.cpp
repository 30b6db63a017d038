// Every [MODEL] choice the ANS1 and SMD23E READMEs list (models/*/README.md, "Parameters" /
// "[MODEL] parameters") is a DUT parameter a campaign's dut.params sets, `hilrig list` shows
// with its meaning and default, and that reaches the model's Params field the README names.
// The name -> field table below is written from the READMEs, independently of the adapters'.
#include <gtest/gtest.h>

#include <fstream>
#include <functional>
#include <map>
#include <set>
#include <sstream>
#include <string>
#include <vector>

#include "campaign_text.hpp"
#include "rig/campaign/campaign_error.hpp"
#include "rig/campaign/campaign_parser.hpp"
#include "rig/duts/ans1_adapter.hpp"
#include "rig/duts/smd23e_dut.hpp"

namespace hilrig::duts {
namespace {

using campaign::test::error_of;

using namespace hilrig::literals;

template <typename P> using Reader = std::function<ParamValue(const P&)>;

// A value of the same kind that differs from v and lies in the parameter's range.
ParamValue other_than(const ParamInfo& p) {
  const ParamValue& v = p.default_value;
  std::vector<ParamValue> candidates;
  if (const auto* b = std::get_if<bool>(&v)) candidates = {!*b};
  if (const auto* i = std::get_if<std::int64_t>(&v)) candidates = {*i + 1, *i - 1};
  if (const auto* d = std::get_if<double>(&v)) candidates = {*d * 0.75, *d * 1.25, *d + 0.5};
  if (const auto* n = std::get_if<Nanos>(&v)) candidates = {*n + 1_us, *n - 1_us};
  for (const ParamValue& c : candidates)
    if (c != v && in_range(p.range, c)) return c;
  ADD_FAILURE() << p.name << ": no other value in range";
  return v;
}

template <typename P, typename Make>
void expect_every_readme_choice_reaches_its_field(const DutInfo& info,
                                                  const std::map<std::string, Reader<P>>& readme, Make make) {
  std::set<std::string> listed;
  for (const ParamInfo& p : info.params) listed.insert(p.name);
  for (const auto& [name, read] : readme) {
    const ParamInfo* p = info.param(name);
    ASSERT_NE(p, nullptr) << info.name << " has no parameter " << name;
    EXPECT_FALSE(p->description.empty()) << name;
    EXPECT_EQ(p->default_value, read(P{})) << name << ": `hilrig list` default differs from the model's";
    const ParamValue v = other_than(*p);
    EXPECT_TRUE(in_range(p->range, p->default_value)) << name << ": the default is outside its own range";
    const P made = make(info.with_defaults({{name, v}}));
    EXPECT_EQ(read(made), v) << name << " does not reach its field";
    listed.erase(name);
  }
  EXPECT_TRUE(listed.empty()) << info.name << " lists a parameter the README does not: " << *listed.begin();
}

TEST(DutParams, EverySmd23eReadmeChoiceIsSettableAndListed) {
  using P = models::smd23e::Params;
  // models/smd23e/README.md "[MODEL] parameters" and "Fault variants" (the variants' knobs).
  const std::map<std::string, Reader<P>> readme{
      {"has_encoder", [](const P& p) { return ParamValue{p.has_encoder}; }},
      {"m12", [](const P& p) { return ParamValue{p.m12}; }},
      {"heartbeat_half_period", [](const P& p) { return ParamValue{p.heartbeat_half_period}; }},
      {"homing_pause", [](const P& p) { return ParamValue{p.homing_pause}; }},
      {"idle_current_delay", [](const P& p) { return ParamValue{p.idle_current_delay}; }},
      {"input_delay", [](const P& p) { return ParamValue{p.input_delay}; }},
      {"scurve_linear_fraction", [](const P& p) { return ParamValue{p.scurve_linear_fraction}; }},
      {"stop_input_level_sensitive", [](const P& p) { return ParamValue{p.stop_input_level_sensitive}; }},
      {"capture_on_any_transition", [](const P& p) { return ParamValue{p.capture_on_any_transition}; }},
      {"stall_threshold_counts", [](const P& p) { return ParamValue{p.stall_threshold_counts}; }},
      {"dwell_after_last_segment", [](const P& p) { return ParamValue{p.dwell_after_last_segment}; }},
      {"report_present_current", [](const P& p) { return ParamValue{p.report_present_current}; }},
      {"sw2_bit13_as_figure", [](const P& p) { return ParamValue{p.sw2_bit13_as_figure}; }},
      {"netloss_at_powerup", [](const P& p) { return ParamValue{p.netloss_at_powerup}; }},
      {"flash_config_valid", [](const P& p) { return ParamValue{p.flash_config_valid}; }},
      {"wrong_accel_factor", [](const P& p) { return ParamValue{p.wrong_accel_factor}; }},
      {"lost_step_interval", [](const P& p) { return ParamValue{p.lost_step_interval}; }},
      {"late_stop_delay", [](const P& p) { return ParamValue{p.late_stop_delay}; }},
      {"step_clock_error", [](const P& p) { return ParamValue{p.step_clock_error}; }},
  };
  expect_every_readme_choice_reaches_its_field(*find_dut("smd23e"), readme,
                                               [](const DutParams& v) { return smd23e_params(v); });
}

TEST(DutParams, EveryAns1ReadmeChoiceIsSettableAndListed) {
  using P = models::ans1::Params;
  // models/ans1/README.md "Parameters": the rows whose "Where" is a Params field.
  const std::map<std::string, Reader<P>> readme{
      {"scan", [](const P& p) { return ParamValue{p.master_scan_period}; }},
      {"slave_scan", [](const P& p) { return ParamValue{p.slave_scan_period}; }},
      {"output_delay", [](const P& p) { return ParamValue{p.output_delay}; }},
      {"speed_update", [](const P& p) { return ParamValue{p.speed_update_period}; }},
      {"excitation_hz", [](const P& p) { return ParamValue{p.excitation_hz}; }},
      {"excitation_amplitude", [](const P& p) { return ParamValue{p.excitation_amplitude}; }},
      {"resolver_min_ratio", [](const P& p) { return ParamValue{p.resolver_min_ratio}; }},
      {"resolver_max_ratio", [](const P& p) { return ParamValue{p.resolver_max_ratio}; }},
      {"time_only_retrigger_restarts", [](const P& p) { return ParamValue{p.time_only_retrigger_restarts}; }},
      {"brake_sample_start", [](const P& p) { return ParamValue{p.brake_sample_start}; }},
      {"timer_error", [](const P& p) { return ParamValue{p.timer_error}; }},
      {"output_off_skew", [](const P& p) { return ParamValue{p.output_off_skew}; }},
  };
  expect_every_readme_choice_reaches_its_field(*find_dut("ans1"), readme,
                                               [](const DutParams& v) { return ans1_params(v); });
}

TEST(DutParams, EveryVariantOfEveryDeviceSaysWhatItDoesWrong) {
  for (const DutInfo& d : dut_registry()) {
    for (const VariantInfo& v : d.variants) {
      EXPECT_FALSE(v.description.empty()) << d.name << "/" << v.name;
      EXPECT_EQ(v.description.find("wrong on purpose"), std::string::npos) << d.name << "/" << v.name;
      if (v.name != "nominal") {
        EXPECT_NE(v.description, "as specified") << d.name << "/" << v.name;
      }
    }
  }
}

// The shipped homing campaign with a [dut.params] table appended (TOML lets a sub-table of
// [dut] be defined after other tables).
std::string homing_campaign_with(const std::string& params) {
  std::ifstream in(std::string(HILRIG_SOURCE_DIR) + "/campaigns/smd23e/smd23e_homing.toml");
  std::stringstream text;
  text << in.rdbuf();
  return text.str() + "\n[dut.params]\n" + params;
}

TEST(DutParams, CampaignSetsTheSmd23eSwitchesAndRefusesOutOfRange) {
  EXPECT_EQ(
      error_of(homing_campaign_with("m12 = false\nstall_threshold_counts = 8.5\n"
                                    "stop_input_level_sensitive = false\nidle_current_delay = \"1s\"\n")),
      "accepted");
  // Sweep the S-curve fraction across its 0..1 range: both ends in, a hair beyond out.
  for (const auto& [value, ok] : std::map<std::string, bool>{
           {"-0.001", false}, {"0.0", true}, {"0.5", true}, {"1.0", true}, {"1.001", false}}) {
    const std::string e = error_of(homing_campaign_with("scurve_linear_fraction = " + value + "\n"));
    if (ok) {
      EXPECT_EQ(e, "accepted") << value;
    } else {
      EXPECT_NE(e.find("dut.params.scurve_linear_fraction: a value in 0 .. 1"), std::string::npos)
          << value << ": " << e;
    }
  }
  const std::string e = error_of(homing_campaign_with("lost_step_interval = 0\n"));
  EXPECT_NE(e.find("dut.params.lost_step_interval: a value in 1 .. "), std::string::npos) << e;
}

} // namespace
} // namespace hilrig::duts
