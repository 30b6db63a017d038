#pragma once
// A directory laid out as a gpio-sim chip's simulator side in sysfs
// (/sys/devices/platform/<dev>/<chip>/sim_gpioN/{value,pull}), in a fresh temporary folder.
// The test plays the kernel: set_value() is the level the chip's user drives; pull() reads
// and consumes what was last written to pull (the kernel takes each write whole).
#include <gtest/gtest.h>

#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>

#include "core/line.hpp"

namespace hilrig::test {

class FakeSimChip {
public:
  explicit FakeSimChip(unsigned lines) {
    std::string templ = (std::filesystem::temp_directory_path() / "hilrig-gpiosim-XXXXXX").string();
    if (::mkdtemp(templ.data()) == nullptr) ADD_FAILURE() << "mkdtemp failed";
    dir_ = templ;
    for (unsigned i = 0; i < lines; ++i) {
      std::filesystem::create_directory(line_dir(i));
      set_value(i, Level::Low);
      std::ofstream(line_dir(i) / "pull").flush(); // nothing written yet
    }
  }
  ~FakeSimChip() { std::filesystem::remove_all(dir_); }
  FakeSimChip(const FakeSimChip&) = delete;
  FakeSimChip& operator=(const FakeSimChip&) = delete;

  [[nodiscard]] std::string dir() const { return dir_.string(); }
  void set_value(unsigned line, Level level) const {
    std::ofstream(line_dir(line) / "value", std::ios::trunc) << (is_high(level) ? "1\n" : "0\n");
  }
  void write_raw_value(unsigned line, const std::string& text) const {
    std::ofstream(line_dir(line) / "value", std::ios::trunc) << text;
  }
  // What the far side last wrote to the line's pull ("" when nothing since the last call).
  [[nodiscard]] std::string take_pull(unsigned line) const {
    const auto path = line_dir(line) / "pull";
    std::stringstream text;
    text << std::ifstream(path).rdbuf();
    std::ofstream(path, std::ios::trunc).flush();
    return text.str();
  }

private:
  [[nodiscard]] std::filesystem::path line_dir(unsigned i) const {
    return dir_ / ("sim_gpio" + std::to_string(i));
  }
  std::filesystem::path dir_;
};

} // namespace hilrig::test
