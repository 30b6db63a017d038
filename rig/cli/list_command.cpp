#include "rig/cli/list_command.hpp"

#include <CLI/CLI.hpp>
#include <iostream>
#include <string>
#include <variant>

#include <fmt/format.h>

#include "rig/campaign/limits.hpp"

#include "rig/campaign/stimulus_kinds.hpp"
#include "rig/checks/registry.hpp"
#include "rig/duts/device_programs.hpp"
#include "rig/duts/dut.hpp"

namespace hilrig::cli {

namespace {

// A block field's kind, range and what its absence means, e.g. "integer 1 .. 16, required".
std::string program_field_text(const duts::ProgramFieldInfo& f) {
  std::string kind;
  switch (f.kind) {
  case duts::ProgramFieldKind::Integer:
    kind = fmt::format("integer {} .. {}", f.min, f.max);
    break;
  case duts::ProgramFieldKind::Boolean:
    kind = "boolean";
    break;
  case duts::ProgramFieldKind::Choice:
    for (const auto& c : f.choices) kind += (kind.empty() ? "one of " : ", ") + c;
    break;
  }
  switch (f.absent) {
  case duts::ProgramFieldInfo::Absent::Required:
    return kind + ", required";
  case duts::ProgramFieldInfo::Absent::Default:
    return kind + ", default " +
           (f.kind == duts::ProgramFieldKind::Choice    ? f.choices[static_cast<std::size_t>(f.default_value)]
            : f.kind == duts::ProgramFieldKind::Boolean ? std::string(f.default_value != 0 ? "true" : "false")
                                                        : std::to_string(f.default_value));
  case duts::ProgramFieldInfo::Absent::Optional:
    break;
  }
  return kind + ", optional: left as it is when absent";
}

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

  out << "programming blocks ([[host]] program = ... with its fields, written as the words its manual "
         "gives):\n";
  for (const duts::DutInfo& d : duts::dut_registry())
    for (const auto& b : duts::device_programs(d.name)) {
      out << fmt::format("  {}/{}: {}\n", d.name, b.name, b.description);
      for (const auto& f : b.fields)
        out << fmt::format("    {} ({}): {}\n", f.name, program_field_text(f), f.description);
    }

  out << "power cycles ([[power_cycle]] at, off):\n";
  for (const duts::DutInfo& d : duts::dut_registry())
    out << fmt::format("  {}: {}\n", d.name,
                       d.power_cycle.empty() ? std::string("none (the model has no power cycle)")
                                             : d.power_cycle);

  out << "front-panel actions ([[panel]] action = ..., at):\n";
  for (const duts::DutInfo& d : duts::dut_registry())
    for (const auto& a : d.panel) out << fmt::format("  {}/{}: {}\n", d.name, a.name, a.description);

  out << "checks ([[check]] kind = ...):\n";
  for (const checks::CheckKind& k : checks::check_kinds()) {
    out << fmt::format("  {}: {}\n", k.name, k.summary);
    for (const auto& p : k.params)
      out << fmt::format("    {} ({}{}): {}\n", p.name, checks::expected_text(p),
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
