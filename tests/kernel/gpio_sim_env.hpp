#pragma once
// The lane's gpio-sim chip as the kernel tests see it: the environment rt-config/vm sets
// (HILRIG_GPIO_CHIP, HILRIG_GPIO_SIM) and the simulator side of each line, read and pulled
// through sysfs as a board on the far side would.

#include <cstdlib>
#include <fstream>
#include <stdexcept>
#include <string>

namespace hilrig::kernel_test {

inline std::string env(const char* name) {
  const char* v = std::getenv(name);
  if (v == nullptr) throw std::runtime_error(std::string(name) + " is not set: run this from rt-config/vm");
  return v;
}

// The level the rig drives on a line, as gpio-sim's far side sees it (-1: unreadable).
inline int sim_value(unsigned line) {
  std::ifstream f(env("HILRIG_GPIO_SIM") + "/sim_gpio" + std::to_string(line) + "/value");
  int v = -1;
  f >> v;
  return v;
}

// The far side pulls a line "pull-up" or "pull-down": the rig reads it as an input.
inline void sim_pull(unsigned line, const char* pull) {
  std::ofstream f(env("HILRIG_GPIO_SIM") + "/sim_gpio" + std::to_string(line) + "/pull");
  f << pull;
}

} // namespace hilrig::kernel_test
