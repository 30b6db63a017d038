#pragma once
// Shared by the check tests: find a measurement by name in a result.

#include <gtest/gtest.h>

#include <string>

#include "rig/results/measurement.hpp"

namespace hilrig::checks::test {

inline const rig::Measurement& find(const rig::CheckResult& r, const std::string& name) {
  for (const auto& m : r.measurements) {
    if (m.name == name) return m;
  }
  ADD_FAILURE() << "no measurement named " << name;
  static const rig::Measurement none;
  return none;
}

} // namespace hilrig::checks::test
