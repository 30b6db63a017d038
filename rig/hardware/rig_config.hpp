#pragma once
// The rig config: which driver and line each of the campaign's rig lines uses on this
// rig, the RT loop's settings, the CAN interface of the resolver stream and the host link.
// One rig config serves every campaign; the campaign file stays the same on the virtual
// bus. docs/rig-config.md describes every key. Errors are "file:line:column: key: what
// was expected", as for campaign files.

#include <cstdint>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "core/serial.hpp"
#include "core/time.hpp"
#include "drivers/gpiod/line_settings.hpp"
#include "rig/campaign/campaign_error.hpp"

namespace hilrig::hardware {

using campaign::SourcePos;

struct RtConfig {
  int priority = 80;      // SCHED_FIFO priority of the RT loop (0: left SCHED_OTHER)
  std::optional<int> cpu; // the CPU the RT loop is pinned to; none: not pinned
  // The resolver angle stream's own thread: below the edge loop by default (its deadline is
  // a 1 ms period, the loop's an edge tolerance of microseconds).
  int resolver_priority = 70;
  std::optional<int> resolver_cpu;
  Nanos edge_tolerance{50'000}; // an output edge later than this is a rig fault
};

struct GpioLine {
  std::string rig;  // the campaign's rig line name ("enc.A")
  std::string chip; // /dev path, name or label (the [gpio] default when not given)
  unsigned offset = 0;
  gpiod::LineSettings settings;
  SourcePos where;
};

enum class HostLink : std::uint8_t { None, ModbusRtu, ModbusTcp };

struct HostConfig {
  HostLink link = HostLink::None;
  std::string port; // modbus-rtu: the serial device
  SerialFormat format{19200, 8, Parity::Even, 1};
  int unit = 1;
  std::string host = "127.0.0.1"; // modbus-tcp
  int tcp_port = 502;
  Nanos timeout{200'000'000};
  SourcePos where;
};

struct RigConfig {
  std::string file; // as given, for messages
  RtConfig rt;
  std::string gpio_chip;
  std::vector<GpioLine> lines;
  std::string can_resolver; // "" when the rig has no resolver CAN interface
  SourcePos can_where;
  HostConfig host;

  [[nodiscard]] const GpioLine* line_for(std::string_view rig) const; // nullptr: not on this rig
};

// Throws campaign::CampaignError naming the file, line, column and key.
[[nodiscard]] RigConfig parse_rig_config(std::string_view text, const std::string& file_name);
[[nodiscard]] RigConfig load_rig_config(const std::string& path);

} // namespace hilrig::hardware
