#pragma once
// The hilrig program run as a person types it, for the tests of the command line: `hilrig ARGS`
// (plain words, no quoting) with stdout captured and stderr to a file of the running test's own
// (ctest runs a file's tests in parallel processes: a shared file would hand one test another's
// messages). Needs HILRIG_EXE, the built program's path.

#include <sys/wait.h>

#include <gtest/gtest.h>

#include <array>
#include <cstdio>
#include <filesystem>
#include <string>

#include "tests/tools/scratch_files.hpp"

namespace hilrig::test {

struct ProcessResult {
  int status = -1;
  std::string out; // stdout
  std::string err; // stderr
};

// `wrap` goes before the program: "timeout 20 " bounds a server a missing check leaves serving.
inline ProcessResult run_hilrig(const std::string& args, const std::string& wrap = "") {
  const ::testing::TestInfo* test = ::testing::UnitTest::GetInstance()->current_test_info();
  const std::filesystem::path dir =
      scratch_dir("campaign", std::string("hilrig_io_") + test->test_suite_name() + "." + test->name());
  const std::filesystem::path err = dir / "stderr";
  const std::string command = wrap + std::string(HILRIG_EXE) + " " + args + " 2>" + err.string();
  ProcessResult r;
  FILE* pipe = ::popen(command.c_str(), "r");
  if (pipe == nullptr) return r;
  std::array<char, 4096> buf{};
  std::size_t n = 0;
  while ((n = std::fread(buf.data(), 1, buf.size(), pipe)) > 0) r.out.append(buf.data(), n);
  const int status = ::pclose(pipe);
  r.status = WIFEXITED(status) ? WEXITSTATUS(status) : -1;
  r.err = read_file(err);
  return r;
}

} // namespace hilrig::test
