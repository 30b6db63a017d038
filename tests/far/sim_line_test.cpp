// gpio-sim's simulator-side files (Documentation/admin-guide/gpio/gpio-sim.rst): sim_gpioN/value
// holds "0" or "1" with a newline, sim_gpioN/pull takes "pull-up" or "pull-down".
#include <gtest/gtest.h>

#include <string>

#include "drivers/gpiosim/sim_line.hpp"
#include "tests/far/fake_sim_chip.hpp"

namespace hilrig::test {
namespace {

TEST(SimLine, PathsFollowTheSysfsLayout) {
  EXPECT_EQ(gpiosim::sim_line_path("/sys/devices/platform/gpio-sim.0/gpiochip0", 3, "value"),
            "/sys/devices/platform/gpio-sim.0/gpiochip0/sim_gpio3/value");
  EXPECT_EQ(gpiosim::sim_line_path("/chip/", 12, "pull"), "/chip/sim_gpio12/pull");
}

TEST(SimLine, ReadsTheLevelTheUserDrivesEachTimeAnew) {
  FakeSimChip chip(4);
  gpiosim::SimLineReader line(chip.dir(), 2);
  EXPECT_EQ(line.read(), Level::Low);
  chip.set_value(2, Level::High);
  EXPECT_EQ(line.read(), Level::High); // the same open file, read again from the start
  chip.set_value(2, Level::Low);
  EXPECT_EQ(line.read(), Level::Low);
}

TEST(SimLine, PullWritesTheWordsTheKernelTakes) {
  FakeSimChip chip(2);
  gpiosim::SimLinePull line(chip.dir(), 1);
  line.pull(Level::High);
  EXPECT_EQ(chip.take_pull(1), "pull-up");
  line.pull(Level::Low);
  EXPECT_EQ(chip.take_pull(1), "pull-down");
  EXPECT_EQ(chip.take_pull(0), ""); // the other line untouched
}

TEST(SimLine, AMissingLineNamesItsPath) {
  FakeSimChip chip(2);
  try {
    gpiosim::SimLineReader line(chip.dir(), 7);
    FAIL() << "opened a line the chip does not have";
  } catch (const gpiosim::GpioSimError& e) {
    EXPECT_NE(std::string(e.what()).find("sim_gpio7/value"), std::string::npos) << e.what();
  }
  EXPECT_THROW(gpiosim::SimLinePull(chip.dir(), 9), gpiosim::GpioSimError);
}

TEST(SimLine, AValueOtherThanZeroOrOneIsAnError) {
  FakeSimChip chip(1);
  gpiosim::SimLineReader line(chip.dir(), 0);
  chip.write_raw_value(0, "x\n");
  EXPECT_THROW((void)line.read(), gpiosim::GpioSimError);
}

} // namespace
} // namespace hilrig::test
