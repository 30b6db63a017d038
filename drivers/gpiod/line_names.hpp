#pragma once
// How both libgpiod backends name a request's lines in an error: "CHIP lines 3 4 7".

#include <span>
#include <string>

namespace hilrig::gpiod {

inline std::string line_names(const std::string& chip, std::span<const unsigned> offsets) {
  std::string s = chip + " lines";
  // Appended piecewise: GCC 12 at -O3 warns falsely (-Wrestrict) on " " + std::to_string(o).
  for (unsigned o : offsets) {
    s += ' ';
    s += std::to_string(o);
  }
  return s;
}

} // namespace hilrig::gpiod
