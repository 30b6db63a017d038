#pragma once
// Runs `hilrig synth ARGS...` in-process, as the command line would, so a test can read the
// VCD it writes. Defined in run_synth.cpp: the tests that call it do not compile CLI11.

#include <string>
#include <vector>

namespace hilrig::test {

void synth(std::vector<std::string> args);
// Where the synth tests write their VCD files: the build tree.
inline const std::string kSynthDir = HILRIG_BINARY_DIR;

} // namespace hilrig::test
