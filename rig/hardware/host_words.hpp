#pragma once
// A board's host words over a Modbus link: command word k is holding register
// command_base + k and status word k is input register status_base + k, the map
// `hilrig serve` serves for each device (rig/cli/serve_devices.hpp). An exception reply is
// a rig fault here: the campaign's words are the device's own, so the link is at fault.

#include <cstddef>
#include <cstdint>
#include <string>
#include <string_view>

#include "core/register_map.hpp"
#include "rig/campaign/host_sequence.hpp"
#include "rig/cli/serve_devices.hpp"

namespace hilrig::hardware {

// The word map of a device model; nullptr when the rig cannot address its host words.
[[nodiscard]] const cli::HostWordMap* host_words_of(std::string_view model);
[[nodiscard]] std::string host_device_names();

class ModbusHostWords final : public campaign::HostWords {
public:
  ModbusHostWords(RegisterMap& link, const cli::HostWordMap& map) : link_(link), map_(map) {}
  void write(std::size_t word, std::uint16_t value) override;
  [[nodiscard]] std::uint16_t read(std::size_t word) override;

private:
  RegisterMap& link_;
  cli::HostWordMap map_;
};

} // namespace hilrig::hardware
