// The hilrig program loads as few shared libraries as Debian allows (deps/CMakeLists.txt):
// fmt, toml++ and nettle are linked in, libgpiod from its archive (unless built against a private
// libgpiod prefix), and libstdc++ and libgcc when HILRIG_STATIC_RUNTIME applies (not under the
// sanitizers). Each shared library is a start-up cost of every `hilrig run`
// (docs/PERFORMANCE.md, "Fixed cost of a run").

#include <gtest/gtest.h>

#include <array>
#include <cstdio>
#include <string>
#include <vector>

namespace hilrig {
namespace {

// The DT_NEEDED entries of the program, as readelf (binutils) lists them.
std::vector<std::string> needed_libraries() {
  const std::string command = std::string("readelf -d ") + HILRIG_EXE + " 2>/dev/null";
  std::string text;
  FILE* pipe = ::popen(command.c_str(), "r");
  if (pipe == nullptr) return {};
  std::array<char, 4096> buf{};
  std::size_t n = 0;
  while ((n = std::fread(buf.data(), 1, buf.size(), pipe)) > 0) text.append(buf.data(), n);
  ::pclose(pipe);
  std::vector<std::string> names;
  const std::string marker = "Shared library: [";
  for (std::size_t at = text.find(marker); at != std::string::npos; at = text.find(marker, at)) {
    at += marker.size();
    names.push_back(text.substr(at, text.find(']', at) - at));
  }
  return names;
}

bool loads(const std::vector<std::string>& needed, const std::string& stem) {
  for (const std::string& name : needed) {
    if (name.rfind(stem + ".so", 0) == 0) return true;
  }
  return false;
}

TEST(ProgramLinkage, LoadsNoLibraryItCanLinkIn) {
  const std::vector<std::string> needed = needed_libraries();
  ASSERT_FALSE(needed.empty()) << "readelf -d " << HILRIG_EXE << " listed no shared library";
  EXPECT_TRUE(loads(needed, "libc"));
  for (const char* stem : {"libfmt", "libtomlplusplus", "libnettle", "libcrypto"}) {
    EXPECT_FALSE(loads(needed, stem)) << stem;
  }
  EXPECT_EQ(loads(needed, "libgpiod"), HILRIG_EXPECT_SHARED_GPIOD != 0);
  EXPECT_EQ(loads(needed, "libstdc++"), HILRIG_EXPECT_STATIC_RUNTIME == 0);
  EXPECT_EQ(loads(needed, "libgcc_s"), HILRIG_EXPECT_STATIC_RUNTIME == 0);
}

} // namespace
} // namespace hilrig
