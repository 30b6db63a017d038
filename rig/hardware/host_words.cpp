#include "rig/hardware/host_words.hpp"

#include <array>

#include <fmt/format.h>

#include "rig/campaign/executive.hpp"

namespace hilrig::hardware {

namespace {

[[noreturn]] void refused(const char* what, std::size_t word, std::uint16_t reg, RegisterStatus status) {
  throw campaign::RigFault(fmt::format("host link: {} word {} (register {}) refused: exception {}", what,
                                       word, reg, static_cast<int>(status)));
}

} // namespace

const cli::HostWordMap* host_words_of(std::string_view model) {
  const cli::ServedDevice* d = cli::find_served_device(model);
  return d == nullptr ? nullptr : &d->words;
}

std::string host_device_names() { return cli::served_device_names(); }

void ModbusHostWords::write(std::size_t word, std::uint16_t value) {
  if (word >= map_.command_words)
    throw campaign::RigFault(
        fmt::format("host link: no command word {} ({} words)", word, map_.command_words));
  const auto reg = static_cast<std::uint16_t>(map_.command_base + word);
  const std::array<std::uint16_t, 1> v{value};
  const RegisterStatus st = link_.write_holding_registers(reg, v);
  if (st != RegisterStatus::Ok) refused("writing command", word, reg, st);
}

std::uint16_t ModbusHostWords::read(std::size_t word) {
  if (word >= map_.status_words)
    throw campaign::RigFault(fmt::format("host link: no status word {} ({} words)", word, map_.status_words));
  const auto reg = static_cast<std::uint16_t>(map_.status_base + word);
  std::array<std::uint16_t, 1> v{};
  const RegisterStatus st = link_.read_input_registers(reg, v);
  if (st != RegisterStatus::Ok) refused("reading status", word, reg, st);
  return v[0];
}

} // namespace hilrig::hardware
