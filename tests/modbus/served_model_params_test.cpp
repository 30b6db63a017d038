// `hilrig serve ans1|smd23e --param NAME=VALUE` sets the same model parameters as a campaign's
// dut.params (rig/duts, `hilrig list`), checked by kind and range before the model is built.
// Models are built directly from the serve table (no network): what a parameter changes is
// read from the host words.
#include <gtest/gtest.h>

#include <array>
#include <stdexcept>
#include <string>
#include <vector>

#include "core/scheduler.hpp"
#include "rig/cli/serve_devices.hpp"
#include "rig/cli/serve_params.hpp"
#include "rig/duts/dut.hpp"

namespace hilrig::test {
namespace {

using namespace hilrig::literals;

cli::ServedModel build(Scheduler& s, const char* device, std::vector<std::string> params) {
  cli::ServeModelOptions o;
  o.params = cli::serve_params(*duts::find_dut(device), params); // what serve_device does
  o.params_given = !params.empty();
  return cli::find_served_device(device)->build(s, o);
}

std::uint16_t input_register(const cli::ServedModel& m, std::uint16_t address) {
  std::array<std::uint16_t, 1> w{};
  EXPECT_EQ(m.registers->read_input_registers(address, w), RegisterStatus::Ok);
  return w[0];
}

TEST(ServedModelParams, Smd23eFlashConfigurationSwitch) {
  // smd23e manual (seeds/003_7a93cebfafae55cd.txt:2830, SW1 bit 13): Configuration Error is
  // 1 at power-up until a valid configuration exists -- unless one is loaded from flash.
  constexpr std::uint16_t kConfigurationError = 1U << 13;
  Scheduler a;
  Scheduler b;
  const auto plain = build(a, "smd23e", {});
  const auto flash = build(b, "smd23e", {"flash_config_valid=true"});
  EXPECT_NE(input_register(plain, 0) & kConfigurationError, 0);
  EXPECT_EQ(input_register(flash, 0) & kConfigurationError, 0);
}

TEST(ServedModelParams, Smd23eHeartbeatPeriod) {
  // SW2 bit 11 toggles every half period in Command Mode (T3, about 500 ms, :2888): at 150 ms
  // it has toggled once with a 100 ms half period, not yet with the default.
  constexpr std::uint16_t kHeartbeat = 1U << 11;
  Scheduler a;
  Scheduler b;
  const auto nominal = build(a, "smd23e", {});
  const auto fast = build(b, "smd23e", {"heartbeat_half_period=100ms"});
  a.run_until(150_ms);
  b.run_until(150_ms);
  EXPECT_NE(input_register(nominal, 1) & kHeartbeat, input_register(fast, 1) & kHeartbeat);
}

TEST(ServedModelParams, BadParametersAreRefusedBeforeServing) {
  Scheduler s;
  for (const char* bad : {"no_such_knob=1", "m12", "m12=yes", "homing_pause=2", "homing_pause=-1s",
                          "scurve_linear_fraction=1.001", "lost_step_interval=0", "lost_step_interval=1.5"}) {
    EXPECT_THROW((void)build(s, "smd23e", {bad}), std::invalid_argument) << bad;
  }
  for (const char* good : {"scurve_linear_fraction=1", "scurve_linear_fraction=0", "lost_step_interval=1",
                           "homing_pause=0s", "m12=true"}) {
    EXPECT_NO_THROW((void)build(s, "smd23e", {good})) << good;
  }
  EXPECT_THROW((void)build(s, "ans1", {"excitation_hz=fast"}), std::invalid_argument);
  EXPECT_NO_THROW((void)build(s, "ans1", {"excitation_hz=2200", "resolver_min_ratio=0.5", "scan=20us"}));
}

TEST(ServedModelParams, MessageNamesTheRange) {
  Scheduler s;
  try {
    (void)build(s, "smd23e", {"scurve_linear_fraction=2"});
    FAIL() << "accepted";
  } catch (const std::invalid_argument& e) {
    EXPECT_NE(std::string(e.what()).find("0 .. 1"), std::string::npos) << e.what();
  }
}

} // namespace
} // namespace hilrig::test
