#pragma once
// A board's programming blocks in its own words: each block (an ANS1 setpoint pair, an SMD23E
// move, a 7361 setup) names its fields with their kind and range, and compiles the values to
// the command words its manual gives. A campaign writes `program = "setpoints"` with the
// fields in a [[host]] entry; the parser checks every field against the block's declaration
// and stores only the compiled words, so nothing downstream sees a field name.
//
// A device declares a block as a struct of its fields and a compile function of that struct
// (program_block<B>): the rows name the struct's members, so the declaration `hilrig list`
// shows, the parser's ranges and the compiler's inputs are one table.

#include <cstddef>
#include <cstdint>
#include <functional>
#include <optional>
#include <span>
#include <stdexcept>
#include <string>
#include <type_traits>
#include <utility>
#include <variant>
#include <vector>

namespace hilrig::duts {

enum class ProgramFieldKind : std::uint8_t { Integer, Boolean, Choice };

struct ProgramFieldInfo {
  std::string name;
  ProgramFieldKind kind = ProgramFieldKind::Integer;
  std::int64_t min = 0; // Integer: the closed range the manual gives
  std::int64_t max = 0;
  std::vector<std::string> choices; // Choice: the words, stored as their index
  // What an absent field means: Required (bad input), Default (default_value) or Optional
  // (nullopt: the block leaves that setting as it is, e.g. an Apply bit left clear).
  enum class Absent : std::uint8_t { Required, Default, Optional };
  Absent absent = Absent::Required;
  std::int64_t default_value = 0;
  std::string description;
};

// The fields' values in declaration order: an integer, a choice's index, a boolean as 0/1, or
// nullopt for an Optional field not given.
using ProgramValues = std::vector<std::optional<std::int64_t>>;

// The words the campaign wrote before a block, in order (blocks as compiled, raw writes as
// given): what a block that leaves a setting "as it is" keeps when the board has no way to
// read the setting back (the 7361's Format word is written whole, L2126-L2152).
using EarlierWrites = std::span<const std::vector<std::uint16_t>>;

struct ProgramBlockInfo {
  std::string name;        // as a campaign names it: program = "setpoints"
  std::string description; // what it programs, with the manual lines
  std::vector<ProgramFieldInfo> fields;
  // The output words 0.. the block is written as (word 0 without Transmit; on a board
  // without the handshake, exactly what `write = [...]` would hold).
  std::function<std::vector<std::uint16_t>(const ProgramValues&, EarlierWrites)> compile;
};

// A compiler's refusal of values that are each in range but do not go together (a rule across
// fields, e.g. the 7361's M + N <= 26): bad input at `field`, saying what is expected.
struct ProgramFieldError : std::invalid_argument {
  ProgramFieldError(std::string field_name, const std::string& expected)
      : std::invalid_argument(expected), field(std::move(field_name)) {}
  std::string field;
};

// --- Declaring a block as a struct ------------------------------------------------------

template <typename B>
using BlockMember = std::variant<std::int64_t B::*, bool B::*, std::optional<std::int64_t> B::*>;

// One row: a member of the block's struct. An int64 member with `choices` is a Choice (its
// index); without, an Integer in [min, max]; so is an optional member. An int64 or bool member is Required
// unless `given_default` (then its default is the struct's initializer); an optional member is Optional.
template <typename B> struct BlockField {
  // A constructor, not default member initializers: GCC 12 fails on those in this template.
  BlockField(const char* field_name, BlockMember<B> field_member, const char* field_description,
             std::int64_t lo = 0, std::int64_t hi = 0,
             std::vector<std::string> field_choices = std::vector<std::string>(), bool has_default = false)
      : name(field_name), member(field_member), description(field_description), min(lo), max(hi),
        choices(std::move(field_choices)), given_default(has_default) {}
  const char* name;
  BlockMember<B> member;
  const char* description;
  std::int64_t min;
  std::int64_t max;
  std::vector<std::string> choices;
  bool given_default;
};

// GCC 12 at -O2 instantiates every member-pointer alternative of the visits below for every
// block and then warns about accesses on paths that never run (a bool member read of a struct
// that has none, any member of an empty block): false positives, silenced here only.
#if defined(__GNUC__) && !defined(__clang__)
#pragma GCC diagnostic push
#pragma GCC diagnostic ignored "-Warray-bounds"
#pragma GCC diagnostic ignored "-Wmaybe-uninitialized"
#endif
template <typename B>
[[nodiscard]] ProgramBlockInfo
program_block(std::string name, std::string description, std::vector<BlockField<B>> fields,
              std::function<std::vector<std::uint16_t>(const B&, EarlierWrites)> compile) {
  ProgramBlockInfo info;
  info.name = std::move(name);
  info.description = std::move(description);
  const B defaults{};
  for (const BlockField<B>& f : fields) {
    ProgramFieldInfo fi;
    fi.name = f.name;
    fi.description = f.description;
    fi.min = f.min;
    fi.max = f.max;
    fi.choices = f.choices;
    std::visit(
        [&](auto member) {
          using T = std::remove_cvref_t<decltype(defaults.*member)>;
          if constexpr (std::is_same_v<T, bool>) {
            fi.kind = ProgramFieldKind::Boolean;
            fi.min = 0;
            fi.max = 1;
            fi.absent = ProgramFieldInfo::Absent::Default;
            fi.default_value = (defaults.*member) ? 1 : 0;
          } else if constexpr (std::is_same_v<T, std::int64_t>) {
            fi.kind = f.choices.empty() ? ProgramFieldKind::Integer : ProgramFieldKind::Choice;
            if (!f.choices.empty()) fi.max = static_cast<std::int64_t>(f.choices.size()) - 1;
            fi.absent =
                f.given_default ? ProgramFieldInfo::Absent::Default : ProgramFieldInfo::Absent::Required;
            fi.default_value = defaults.*member;
          } else {
            fi.kind = f.choices.empty() ? ProgramFieldKind::Integer : ProgramFieldKind::Choice;
            if (!f.choices.empty()) fi.max = static_cast<std::int64_t>(f.choices.size()) - 1;
            fi.absent = ProgramFieldInfo::Absent::Optional;
          }
        },
        f.member);
    info.fields.push_back(std::move(fi));
  }
  info.compile = [fields = std::move(fields), compile](const ProgramValues& values, EarlierWrites earlier) {
    B b{};
    for (std::size_t i = 0; i < fields.size() && i < values.size(); ++i) {
      std::visit(
          [&](auto member) {
            using T = std::remove_cvref_t<decltype(b.*member)>;
            if constexpr (std::is_same_v<T, bool>) {
              if (values[i]) b.*member = *values[i] != 0;
            } else if constexpr (std::is_same_v<T, std::int64_t>) {
              if (values[i]) b.*member = *values[i];
            } else {
              b.*member = values[i];
            }
          },
          fields[i].member);
    }
    return compile(b, earlier);
  };
  return info;
}

// A block whose words depend on its fields only.
template <typename B>
[[nodiscard]] ProgramBlockInfo program_block(std::string name, std::string description,
                                             std::vector<BlockField<B>> fields,
                                             std::vector<std::uint16_t> (*compile)(const B&)) {
  return program_block<B>(std::move(name), std::move(description), std::move(fields),
                          std::function<std::vector<std::uint16_t>(const B&, EarlierWrites)>(
                              [compile](const B& b, EarlierWrites) { return compile(b); }));
}

// A block whose words also depend on what the campaign wrote before it.
template <typename B>
[[nodiscard]] ProgramBlockInfo program_block(std::string name, std::string description,
                                             std::vector<BlockField<B>> fields,
                                             std::vector<std::uint16_t> (*compile)(const B&, EarlierWrites)) {
  return program_block<B>(std::move(name), std::move(description), std::move(fields),
                          std::function<std::vector<std::uint16_t>(const B&, EarlierWrites)>(compile));
}

#if defined(__GNUC__) && !defined(__clang__)
#pragma GCC diagnostic pop
#endif

// Helpers the devices' compilers share.
[[nodiscard]] inline std::uint16_t word(std::int64_t v) { return static_cast<std::uint16_t>(v); }
[[nodiscard]] inline std::uint16_t bit(unsigned n, bool on = true) {
  return on ? static_cast<std::uint16_t>(1U << n) : std::uint16_t{0};
}

} // namespace hilrig::duts
