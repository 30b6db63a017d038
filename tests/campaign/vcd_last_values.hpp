#pragma once
// Reads a VCD file (IEEE 1364 §18) just far enough to tell each 1-bit signal's values: full
// names from the $scope nesting ("enc.A"), and every value change in file order. Written from
// the format, not from hilrig's writer, so a test reads the trace as GTKWave would.

#include <fstream>
#include <map>
#include <sstream>
#include <string>
#include <vector>

namespace hilrig::campaign::test {

struct VcdSignal {
  std::vector<char> values; // '0', '1', 'x', 'z' in file order (the $dumpvars one first)
};

// Full signal name -> its values. Empty when the file cannot be read.
inline std::map<std::string, VcdSignal> read_vcd_wires(const std::string& path) {
  std::ifstream in(path);
  std::map<std::string, std::string> name_of; // id code -> full name
  std::map<std::string, VcdSignal> out;
  std::vector<std::string> scopes;
  std::string token;
  bool definitions = true;
  while (definitions && in >> token) {
    if (token == "$scope") {
      std::string kind, name;
      in >> kind >> name >> token;
      scopes.push_back(name);
    } else if (token == "$upscope") {
      in >> token;
      if (!scopes.empty()) scopes.pop_back();
    } else if (token == "$var") {
      std::string type, width, id, leaf;
      in >> type >> width >> id >> leaf;
      while (in >> token && token != "$end") {}
      if (width != "1") continue;
      std::string full;
      for (const std::string& s : scopes) full += s + ".";
      name_of[id] = full + leaf;
      out[full + leaf];
    } else if (token == "$enddefinitions") {
      definitions = false;
    }
  }
  std::string line;
  while (std::getline(in, line)) {
    if (line.empty() || line[0] == '#' || line[0] == '$' || line[0] == 'b' || line[0] == 'r') continue;
    const char v = line[0];
    if (v != '0' && v != '1' && v != 'x' && v != 'z') continue;
    const auto it = name_of.find(line.substr(1));
    if (it != name_of.end()) out[it->second].values.push_back(v);
  }
  return out;
}

} // namespace hilrig::campaign::test
