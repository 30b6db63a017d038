#pragma once
// The rig's own controls of a served board (`hilrig serve`, docs/serve.md "Rig controls"):
// holding registers past every served device's map that switch the board's supply and move
// its front-panel Program switch, so a lab operator or a test harness works them with the
// same Modbus client that programs the board. Every other address goes to the board's map.

#include <cstdint>
#include <functional>
#include <span>

#include "core/register_map.hpp"
#include "core/scheduler.hpp"

namespace hilrig::cli {

inline constexpr std::uint16_t kSupplyRegister = 9000;        // 1 on, 0 off (reads the state)
inline constexpr std::uint16_t kPowerCycleRegister = 9001;    // write T: off now, on T ms later
inline constexpr std::uint16_t kProgramSwitchRegister = 9002; // 1 Program, 0 Display (2700)
inline constexpr std::uint16_t kClearPairRegister = 9003;     // write N: CLEAR on output N's last pair
inline constexpr std::uint16_t kFirstControl = kSupplyRegister;
inline constexpr std::uint16_t kControlCount = 4;

// What the served model offers; an empty function: the board has no such control.
struct BoardControls {
  std::function<void(bool on)> power;
  std::function<void(bool program)> set_program_switch;
  std::function<bool()> program_switch; // where the switch stands
  // The keyboard's CLEAR on output N's last setpoint pair (1..outputs); ignored in Display Mode.
  std::function<void(int output)> clear_last_pair;
  int outputs = 0;
};

class ControlledRegisters final : public RegisterMap {
public:
  // The board's map and controls; power cycles are timed on the scheduler the server advances.
  ControlledRegisters(RegisterMap& board, BoardControls controls, Scheduler& scheduler);
  ~ControlledRegisters() override;
  ControlledRegisters(const ControlledRegisters&) = delete;
  ControlledRegisters& operator=(const ControlledRegisters&) = delete;

  RegisterStatus read_input_registers(std::uint16_t address, std::span<std::uint16_t> out) override;
  RegisterStatus read_holding_registers(std::uint16_t address, std::span<std::uint16_t> out) override;
  RegisterStatus write_holding_registers(std::uint16_t address,
                                         std::span<const std::uint16_t> values) override;

  [[nodiscard]] bool powered() const { return powered_; }

private:
  // Whether the served model has the control at this address (else exception 02).
  [[nodiscard]] bool offers(std::uint16_t address) const;
  RegisterStatus write_control(std::uint16_t address, std::uint16_t value);
  void set_power(bool on);

  RegisterMap& board_;
  BoardControls controls_;
  Scheduler& scheduler_;
  bool powered_ = true;
  EventId back_on_{};
};

} // namespace hilrig::cli
