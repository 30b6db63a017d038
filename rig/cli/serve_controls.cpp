#include "rig/cli/serve_controls.hpp"

namespace hilrig::cli {

namespace {

enum class Span : std::uint8_t { Board, Controls, Straddles };

// Whether [address, address + n) lies among the board's addresses, the controls', or both.
Span span_of(std::uint16_t address, std::size_t n) {
  const std::size_t first = address;
  const std::size_t end = first + n;
  const std::size_t controls_end = std::size_t{kFirstControl} + kControlCount;
  if (end <= kFirstControl || first >= controls_end) return Span::Board;
  if (first >= kFirstControl && end <= controls_end) return Span::Controls;
  return Span::Straddles;
}

} // namespace

bool ControlledRegisters::offers(std::uint16_t address) const {
  if (address == kSupplyRegister || address == kPowerCycleRegister) return static_cast<bool>(controls_.power);
  if (address == kClearPairRegister) return static_cast<bool>(controls_.clear_last_pair);
  return controls_.program_switch && controls_.set_program_switch;
}

ControlledRegisters::ControlledRegisters(RegisterMap& board, BoardControls controls, Scheduler& scheduler)
    : board_(board), controls_(std::move(controls)), scheduler_(scheduler) {}

ControlledRegisters::~ControlledRegisters() { scheduler_.cancel(back_on_); }

RegisterStatus ControlledRegisters::read_input_registers(std::uint16_t address,
                                                         std::span<std::uint16_t> out) {
  return board_.read_input_registers(address, out);
}

RegisterStatus ControlledRegisters::read_holding_registers(std::uint16_t address,
                                                           std::span<std::uint16_t> out) {
  switch (span_of(address, out.size())) {
  case Span::Board:
    return board_.read_holding_registers(address, out);
  case Span::Straddles:
    return RegisterStatus::IllegalDataAddress;
  case Span::Controls:
    break;
  }
  for (std::size_t i = 0; i < out.size(); ++i) {
    const auto a = static_cast<std::uint16_t>(address + i);
    if (!offers(a)) return RegisterStatus::IllegalDataAddress;
    if (a == kSupplyRegister)
      out[i] = powered_ ? 1 : 0;
    else if (a == kProgramSwitchRegister)
      out[i] = controls_.program_switch() ? 1 : 0;
    else
      out[i] = 0; // a command, not a state
  }
  return RegisterStatus::Ok;
}

RegisterStatus ControlledRegisters::write_holding_registers(std::uint16_t address,
                                                            std::span<const std::uint16_t> values) {
  switch (span_of(address, values.size())) {
  case Span::Board:
    return board_.write_holding_registers(address, values);
  case Span::Straddles:
    return RegisterStatus::IllegalDataAddress;
  case Span::Controls:
    break;
  }
  // Judged whole before any acts, as one transaction.
  for (std::size_t i = 0; i < values.size(); ++i) {
    const auto a = static_cast<std::uint16_t>(address + i);
    const std::uint16_t v = values[i];
    if (!offers(a)) return RegisterStatus::IllegalDataAddress;
    const bool valid = a == kPowerCycleRegister  ? v >= 1
                       : a == kClearPairRegister ? v >= 1 && v <= controls_.outputs
                                                 : v <= 1;
    if (!valid) return RegisterStatus::IllegalDataValue;
  }
  for (std::size_t i = 0; i < values.size(); ++i) {
    const RegisterStatus s = write_control(static_cast<std::uint16_t>(address + i), values[i]);
    if (s != RegisterStatus::Ok) return s;
  }
  return RegisterStatus::Ok;
}

RegisterStatus ControlledRegisters::write_control(std::uint16_t address, std::uint16_t value) {
  if (address == kSupplyRegister) {
    set_power(value == 1);
  } else if (address == kPowerCycleRegister) {
    set_power(false);
    back_on_ = scheduler_.after(milliseconds(value), [this] {
      back_on_ = {};
      set_power(true);
    });
  } else if (address == kClearPairRegister) {
    controls_.clear_last_pair(value);
  } else {
    controls_.set_program_switch(value == 1);
  }
  return RegisterStatus::Ok;
}

void ControlledRegisters::set_power(bool on) {
  scheduler_.cancel(back_on_); // the operator's own switch wins over a timed cycle
  back_on_ = {};
  if (on == powered_) return;
  powered_ = on;
  controls_.power(on);
}

} // namespace hilrig::cli
