#pragma once
// Frame decodes: every captured CAN frame (or serial message) decodes with no named error.
// The decoder is the device's own (a DBC message, a Modbus reply parser): the check only counts.

#include <cstddef>
#include <cstdint>
#include <functional>
#include <optional>
#include <span>
#include <string>
#include <vector>

#include "rig/checks/support.hpp"

namespace hilrig::checks {

// A frame as captured: a CAN frame (id = CAN identifier) or one serial message (id = 0 or
// the address the link's framing gives).
struct RawFrame {
  Nanos time;
  std::uint32_t id = 0;
  std::vector<std::uint8_t> bytes{};
};

// Returns "" when the frame decodes, otherwise the error's name ("crc", "length", ...).
using FrameDecoder = std::function<std::string(const RawFrame&)>;

struct FrameSpec {
  std::string name = "frames";
  std::optional<std::uint32_t> id{}; // only frames with this id; default all
  std::size_t min_frames = 1;
};

// "<name>.frames" (count, lower min_frames) and "<name>.errors" (upper 0; the detail names
// the first error, the window is its frame).
[[nodiscard]] CheckResult check_frames_decode(std::span<const RawFrame> frames, const FrameDecoder& decode,
                                              const FrameSpec& spec);

} // namespace hilrig::checks
