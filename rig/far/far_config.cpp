#include "rig/far/far_config.hpp"

#include <fstream>
#include <sstream>

#include <toml++/toml.h>

#include "rig/campaign/toml_file.hpp"
#include "rig/campaign/toml_reader.hpp"

namespace hilrig::far {

namespace {

using campaign::CampaignError;
using campaign::TableReader;

FarPin read_pin(const std::string& file, const toml::table& t, std::size_t i) {
  TableReader r(file, t, "pin[" + std::to_string(i) + "]");
  FarPin p;
  p.where = r.where();
  p.board = r.string("board");
  if (p.board.empty()) r.fail("board", "a pin name of the served board");
  const std::int64_t offset = r.integer("offset");
  if (offset < 0 || offset > 65535) r.fail("offset", "a gpio-sim line offset in 0..65535");
  p.offset = static_cast<unsigned>(offset);
  r.finish();
  return p;
}

FarResolver read_resolver(const std::string& file, const toml::table& t) {
  TableReader r(file, t, "resolver");
  FarResolver x;
  x.where = r.where();
  x.sin_pin = r.opt_string("sin").value_or(x.sin_pin);
  x.cos_pin = r.opt_string("cos").value_or(x.cos_pin);
  if (x.sin_pin == x.cos_pin) r.fail("cos", "a pin other than sin's");
  const std::int64_t channel = r.opt_integer("channel").value_or(0);
  if (channel < 0 || channel > 15) r.fail("channel", "a ResolverAngle channel in 0..15");
  x.channel = static_cast<std::uint8_t>(channel);
  x.frame_period = r.opt_duration("frame_period").value_or(x.frame_period);
  if (x.frame_period <= Nanos{0}) r.fail("frame_period", "a duration > 0");
  const std::int64_t timeout = r.opt_integer("timeout_periods").value_or(x.timeout_periods);
  if (timeout < 1 || timeout > 100000) r.fail("timeout_periods", "an integer in 1..100000");
  x.timeout_periods = static_cast<unsigned>(timeout);
  x.ratio = r.opt_number("ratio").value_or(x.ratio);
  if (x.ratio <= 0.0) r.fail("ratio", "a transformation ratio > 0");
  x.excitation_hz = r.opt_number("excitation_hz").value_or(x.excitation_hz);
  if (x.excitation_hz < 2200.0 || x.excitation_hz > 7000.0)
    r.fail("excitation_hz", "a reference frequency in 2200..7000 Hz");
  x.amplitude = r.opt_number("amplitude").value_or(x.amplitude);
  if (x.amplitude <= 0.0) r.fail("amplitude", "a reference amplitude > 0");
  r.finish();
  return x;
}

} // namespace

FarConfig parse_far_config(std::string_view text, const std::string& file_name) {
  const toml::table root = campaign::parse_toml(text, file_name);
  TableReader r(file_name, root, "");
  FarConfig c;
  c.file = file_name;
  const auto pins = r.tables("pin");
  for (std::size_t i = 0; i < pins.size(); ++i) {
    FarPin p = read_pin(file_name, *pins[i], i);
    const std::string path = "pin[" + std::to_string(i) + "]";
    for (const FarPin& q : c.pins) {
      if (q.board == p.board)
        throw CampaignError(file_name, p.where, path + ".board", "a pin not given before (" + p.board + ")");
      if (q.offset == p.offset)
        throw CampaignError(file_name, p.where, path + ".offset",
                            "a line no other pin uses (" + q.board + " is on " + std::to_string(q.offset) +
                                ")");
    }
    c.pins.push_back(std::move(p));
  }
  if (const toml::table* t = r.opt_table("resolver")) {
    FarResolver x = read_resolver(file_name, *t);
    for (const FarPin& p : c.pins)
      if (p.board == x.sin_pin || p.board == x.cos_pin)
        throw CampaignError(file_name, p.where, "pin.board",
                            "a digital pin: " + p.board + " is fed by [resolver]");
    c.resolver = std::move(x);
  }
  if (c.pins.empty() && !c.resolver)
    throw CampaignError(file_name, r.where(), "pin", "at least one [[pin]] or a [resolver] table");
  r.finish();
  return c;
}

FarConfig load_far_config(const std::string& path) {
  return parse_far_config(campaign::read_toml_text(path, "far-side config file"), path);
}

} // namespace hilrig::far
