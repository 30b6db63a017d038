#include "rig/campaign/program_reader.hpp"

#include <string>

#include <fmt/format.h>

#include "rig/duts/device_programs.hpp"

namespace hilrig::campaign {

namespace {

using duts::ProgramFieldInfo;
using duts::ProgramFieldKind;

std::string names_of(const std::vector<std::string>& names) {
  std::string out;
  for (const auto& n : names) out += (out.empty() ? "" : ", ") + n;
  return out;
}

std::string expected_of(const ProgramFieldInfo& f) {
  switch (f.kind) {
  case ProgramFieldKind::Boolean:
    return fmt::format("{}: true or false", f.description);
  case ProgramFieldKind::Choice:
    return fmt::format("{}: one of {}", f.description, names_of(f.choices));
  case ProgramFieldKind::Integer:
    break;
  }
  return fmt::format("{}: an integer in {} .. {}", f.description, f.min, f.max);
}

// The field's value as the block stores it (a choice's index, a boolean as 0/1), in range.
std::optional<std::int64_t> field_value(TableReader& r, const ProgramFieldInfo& f) {
  const toml::node* n = r.node(f.name);
  if (n == nullptr) {
    switch (f.absent) {
    case ProgramFieldInfo::Absent::Required:
      r.fail(f.name, "missing: " + expected_of(f));
    case ProgramFieldInfo::Absent::Default:
      return f.default_value;
    case ProgramFieldInfo::Absent::Optional:
      return std::nullopt;
    }
  }
  switch (f.kind) {
  case ProgramFieldKind::Boolean:
    if (const auto* b = n->as_boolean()) return b->get() ? 1 : 0;
    break;
  case ProgramFieldKind::Choice:
    if (const auto* s = n->as_string())
      for (std::size_t i = 0; i < f.choices.size(); ++i)
        if (f.choices[i] == s->get()) return static_cast<std::int64_t>(i);
    break;
  case ProgramFieldKind::Integer:
    if (const auto* v = n->as_integer(); v != nullptr && v->get() >= f.min && v->get() <= f.max)
      return v->get();
    break;
  }
  r.fail(f.name, expected_of(f));
}

} // namespace

std::vector<std::uint16_t> read_program(TableReader& r, const duts::DutInfo* info,
                                        duts::EarlierWrites earlier) {
  const std::string block_name = r.string("program");
  if (info == nullptr)
    r.fail("program",
           "a block of a virtual board's model: an external board's words are written with write = [...]");
  const duts::ProgramBlockInfo* block = duts::find_program(info->name, block_name);
  if (block == nullptr) {
    std::vector<std::string> names;
    for (const auto& b : duts::device_programs(info->name)) names.push_back(b.name);
    r.fail("program", names.empty()
                          ? fmt::format("none: {} declares no programming blocks (write = [...])", info->name)
                          : fmt::format("a programming block of {}: one of {}", info->name, names_of(names)));
  }
  duts::ProgramValues values;
  for (const ProgramFieldInfo& f : block->fields) values.push_back(field_value(r, f));
  try {
    return block->compile(values, earlier);
  } catch (const duts::ProgramFieldError& e) {
    r.fail(e.field, e.what());
  }
}

} // namespace hilrig::campaign
