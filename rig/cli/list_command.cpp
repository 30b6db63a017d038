#include "rig/cli/list_command.hpp"

#include <iostream>
#include <string>
#include <variant>

#include <fmt/format.h>

#include "rig/campaign/limits.hpp"

#include "rig/campaign/stimulus_kinds.hpp"
#include "rig/checks/registry.hpp"
#include "rig/duts/dut.hpp"

namespace hilrig::cli {

namespace {

std::string value_text(const duts::ParamValue& v) {
  struct Text {
    std::string operator()(std::int64_t i) const { return std::to_string(i); }
    std::string operator()(double d) const { return fmt::format("{}", d); }
    std::string operator()(Nanos n) const { return fmt::format("\"{}us\"", n.micros()); }
    std::string operator()(bool b) const { return b ? "true" : "false"; }
    std::string operator()(const std::string& s) const { return "\"" + s + "\""; }
  };
  return std::visit(Text{}, v);
}

} // namespace

void write_listing(std::ostream& out) {
  out << "devices (model = ...):\n";
  for (const duts::DutInfo& d : duts::dut_registry()) {
    out << fmt::format("  {}: {}\n", d.name, d.description);
    std::string inputs;
    std::string outputs;
    for (const auto& p : d.pins) {
      std::string& list = p.direction == duts::PinDirection::Input ? inputs : outputs;
      list += (list.empty() ? "" : " ") + p.name + (p.analog ? "(analog)" : "");
    }
    out << fmt::format("    input pins: {}\n    output pins: {}\n", inputs, outputs);
    for (const auto& p : d.params)
      out << fmt::format("    param {} ({}, default {}{}): {}\n", p.name, duts::to_string(p.kind),
                         value_text(p.default_value),
                         p.kind == duts::ParamKind::Boolean ? ""
                                                            : ", " + campaign::range_text(p.kind, p.range),
                         p.description);
    out << fmt::format("    host words: {} out, {} in{}\n", d.host.output_words, d.host.input_words,
                       d.host.handshake ? " (Transmit/Acknowledge handshake)" : "");
  }
  out << "  external: a real board (pins declared in the campaign)\n";

  out << "device variants (variant = ..., or a [[fault]]'s variant):\n";
  for (const duts::DutInfo& d : duts::dut_registry())
    for (const auto& v : d.variants) out << fmt::format("  {}/{}: {}\n", d.name, v.name, v.description);

  out << "device faults ([[device_fault]] fault = ..., at, until):\n";
  for (const duts::DutInfo& d : duts::dut_registry())
    for (const auto& f : d.faults) out << fmt::format("  {}/{}: {}\n", d.name, f.name, f.description);

  out << "checks ([[check]] kind = ...):\n";
  for (const checks::CheckKind& k : checks::check_kinds()) {
    out << fmt::format("  {}: {}\n", k.name, k.summary);
    for (const auto& p : k.params)
      out << fmt::format("    {} ({}{}): {}\n", p.name, checks::expected_text(p.type, p.range),
                         p.required ? ", required" : "", p.help);
  }

  out << "signal faults ([[fault]] signal = { kind = ... }, or a [[stimulus]]):\n";
  for (const auto& s : campaign::stimulus_kinds())
    if (s.signal_fault) out << fmt::format("  {}: {} (keys: {})\n", s.name, s.summary, s.keys);
  out << "stimuli ([[stimulus]] kind = ...):\n";
  for (const auto& s : campaign::stimulus_kinds())
    if (!s.signal_fault) out << fmt::format("  {}: {} (keys: {})\n", s.name, s.summary, s.keys);
}

void add_list_command(CLI::App& app) {
  CLI::App* cmd = app.add_subcommand(
      "list", "name the devices, checks, signal faults, device faults and device variants");
  cmd->callback([] { write_listing(std::cout); });
}

} // namespace hilrig::cli
