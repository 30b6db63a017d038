#pragma once
// The tests' one VCD reader (IEEE 1364-2005 §18.2), written from the format and not from
// hilrig's writer, so a test reads trace.vcd (or synth's output) as GTKWave would. The file is
// read as whitespace-separated tokens: the header's $scope/$upscope nesting gives each $var
// its dotted name, and after $enddefinitions "#t" sets the time, "0!", "1!", "x!", "z!" change
// a scalar, "b101 #" a vector and "r1.25 $" a real; the values inside $dumpvars ... $end are
// the initial ones. Other sections ($comment, $date, ...) are skipped to their $end.

#include <cstddef>
#include <cstdint>
#include <fstream>
#include <istream>
#include <map>
#include <optional>
#include <sstream>
#include <stdexcept>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

namespace hilrig::test {

struct VcdChange {
  std::int64_t time = 0;
  std::string value; // as written, without the identifier: "0", "1", "x", "z", "b0101", "r1.25"

  // A scalar's level or a vector's bits (an x or z bit reads 0).
  [[nodiscard]] std::uint64_t bits() const {
    if (value.empty()) return 0;
    if (value[0] != 'b' && value[0] != 'B') return value[0] == '1' ? 1U : 0U;
    std::uint64_t v = 0;
    for (std::size_t i = 1; i < value.size(); ++i) v = v << 1U | (value[i] == '1' ? 1U : 0U);
    return v;
  }
  // A real's number; a scalar's or a vector's bits as a number.
  [[nodiscard]] double number() const {
    if (!value.empty() && (value[0] == 'r' || value[0] == 'R')) return std::stod(value.substr(1));
    return static_cast<double>(bits());
  }
};

struct VcdVar {
  std::string type; // wire, integer, real, ...
  int width = 0;
  std::string id;                   // the identifier code
  std::string name;                 // dotted, from the $scope nesting: "enc.A"
  std::string leaf;                 // the $var's own reference: "A"
  std::size_t index = 0;            // declaration order
  std::optional<VcdChange> initial; // its $dumpvars value, when it has one
  std::vector<VcdChange> changes;   // after $dumpvars, in file order

  // Every value it takes in file order, the initial one first ("0", "b101", "r1.5", ...).
  [[nodiscard]] std::vector<std::string> values() const {
    std::vector<std::string> out;
    if (initial) out.push_back(initial->value);
    for (const VcdChange& c : changes) out.push_back(c.value);
    return out;
  }
  // Its bits at t: the last change at or before t, else the initial value (0 without one).
  [[nodiscard]] std::uint64_t bits_at(std::int64_t t) const {
    std::uint64_t v = initial ? initial->bits() : 0U;
    for (const VcdChange& c : changes)
      if (c.time <= t) v = c.bits();
    return v;
  }
};

struct Vcd {
  std::vector<VcdVar> vars;           // in declaration order
  std::vector<std::int64_t> times;    // every "#t" after $enddefinitions, in file order
  std::vector<std::size_t> change_of; // the var of each change after $dumpvars, in file order

  // The var of this dotted name, or null.
  [[nodiscard]] const VcdVar* find(std::string_view name) const {
    for (const VcdVar& v : vars)
      if (v.name == name) return &v;
    return nullptr;
  }
  // The var of this reference (the last part of its name); throws std::out_of_range when there
  // is none or when two scopes hold one.
  [[nodiscard]] const VcdVar& leaf(std::string_view leaf) const {
    const VcdVar* found = nullptr;
    for (const VcdVar& v : vars) {
      if (v.leaf != leaf) continue;
      if (found != nullptr) throw std::out_of_range("VCD: two variables named " + std::string(leaf));
      found = &v;
    }
    if (found == nullptr) throw std::out_of_range("VCD: no variable " + std::string(leaf));
    return *found;
  }
  [[nodiscard]] bool has_leaf(std::string_view leaf) const {
    for (const VcdVar& v : vars)
      if (v.leaf == leaf) return true;
    return false;
  }
};

inline Vcd parse_vcd(std::istream& in) {
  Vcd vcd;
  std::map<std::string, std::size_t> ids; // id code -> var
  const auto var_of = [&](const std::string& id) -> std::size_t {
    const auto it = ids.find(id);
    if (it == ids.end()) throw std::out_of_range("VCD: a change of an undeclared identifier " + id);
    return it->second;
  };
  const auto skip_section = [&] {
    for (std::string t; in >> t && t != "$end";) {}
  };
  std::vector<std::string> scopes;
  std::string token;
  while (in >> token && token != "$enddefinitions") {
    if (token == "$scope") {
      std::string kind, name;
      in >> kind >> name;
      scopes.push_back(name);
      skip_section();
    } else if (token == "$upscope") {
      if (!scopes.empty()) scopes.pop_back();
      skip_section();
    } else if (token == "$var") {
      VcdVar v;
      in >> v.type >> v.width >> v.id >> v.leaf;
      skip_section(); // an optional bit range, then $end
      for (const std::string& s : scopes) v.name += s + ".";
      v.name += v.leaf;
      v.index = vcd.vars.size();
      ids.emplace(v.id, v.index);
      vcd.vars.push_back(std::move(v));
    } else if (token.starts_with("$")) {
      skip_section();
    }
  }
  skip_section(); // $enddefinitions' own $end
  bool dumpvars = false;
  std::int64_t now = 0;
  while (in >> token) {
    if (token == "$dumpvars") {
      dumpvars = true;
    } else if (token == "$end") {
      dumpvars = false;
    } else if (token.starts_with("$")) {
      if (token == "$comment") skip_section();
    } else if (token[0] == '#') {
      now = std::stoll(token.substr(1));
      vcd.times.push_back(now);
    } else {
      VcdChange c{now, token};
      std::string id;
      if (token[0] == 'b' || token[0] == 'B' || token[0] == 'r' || token[0] == 'R') {
        in >> id;
      } else {
        c.value = token.substr(0, 1);
        id = token.substr(1);
      }
      const std::size_t var = var_of(id);
      if (dumpvars) {
        vcd.vars[var].initial = std::move(c);
      } else {
        vcd.vars[var].changes.push_back(std::move(c));
        vcd.change_of.push_back(var);
      }
    }
  }
  return vcd;
}

// The file at `path` (no variable at all when it cannot be read), or a text in memory.
inline Vcd read_vcd_file(const std::string& path) {
  std::ifstream in(path);
  return parse_vcd(in);
}
inline Vcd parse_vcd_text(const std::string& text) {
  std::istringstream in(text);
  return parse_vcd(in);
}

} // namespace hilrig::test
