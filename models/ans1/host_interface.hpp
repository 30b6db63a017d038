#pragma once
// The ANS1's host interface (spec §5, manual L536, L1699-L2663): 20 command words the host
// writes, 20 status words it reads, and the Transmit/Acknowledge handshake.
//
// Host side (a Modbus server, the virtual host link, a test):
//   host.write(k, value) / host.write_block(words)   command word k = 0..19
//                                                     (Modbus holding register 1024 + k)
//   host.read(k) / host.status()                      status word k = 0..19
//                                                     (Modbus input register k)
//   Handshake (L1705, L2296): write words 1..19 and word 0 with Transmit (bit 15) = 0; then
//   set Transmit = 1; the device acts on the 0->1 edge at its next scan, and the scan after it,
//   the first to run with the block in force, writes the response and sets Acknowledge (status
//   w0 bit 15); read the result; clear Transmit; Acknowledge drops at the next scan.
//   Status word 0: 15 Ack, 14 Heartbeat, 13 Hardware Fault, 12 Resolver Fault, 11..8 error
//   code (error_codes.hpp), 7 RPM Clamped, 6 Output Forced, 4..0 data block number.
//
// Device side: Ans1 owns one (Ans1::host(), `HostInterface host_{*this}`) and calls scan() at
// the end of every position scan; a block's programming takes effect from the next scan. The
// interface programs the device only through Ans1's public API (configure_*, preset_*,
// force_*, clear_errors) and reads it through its getters, Ans1::monitors() and
// data_block.hpp. This header only forward-declares Ans1, so ans1.hpp can include it.
#include <array>
#include <cstdint>
#include <optional>

#include "models/ans1/command_block.hpp"
#include "models/ans1/error_codes.hpp"
#include "models/ans1/setup.hpp"

namespace hilrig::models::ans1 {

class Ans1;

inline constexpr int kModbusCommandBase = 1024; // holding register of command word 0 (L1701)
inline constexpr int kModbusStatusBase = 0;     // input register of status word 0 (L2290)

class HostInterface {
public:
  explicit HostInterface(Ans1& device);

  // ---- host side ----
  void write(int word, std::uint16_t value);
  void write_block(const HostWords& words);
  [[nodiscard]] std::uint16_t command(int word) const { return commands_[static_cast<std::size_t>(word)]; }
  [[nodiscard]] std::uint16_t read(int word) const {
    return word < 0 || word >= kHostWords ? 0 : status()[static_cast<std::size_t>(word)];
  }
  [[nodiscard]] HostWords status() const;

  // ---- device side ----
  void scan();
  // Power-up: the handshake and errors start again (a Transmit the host already holds is no
  // edge [MODEL]); returns the setup flash gives: the global parameters Save Global stored
  // (CB2, CB8, L2239) and the program last saved or loaded (L2236) [MODEL], else factory defaults.
  [[nodiscard]] Ans1Setup power_up();

  // ---- state, for reports and tests ----
  [[nodiscard]] ErrorCode error() const { return error_; }
  [[nodiscard]] bool acknowledge() const { return ack_; }
  [[nodiscard]] bool transmit_seen() const { return transmit_seen_; }
  // A block was executed; the next scan writes its response and sets Acknowledge.
  [[nodiscard]] bool responding() const { return responding_; }
  [[nodiscard]] const DataSelection& selection() const { return selection_; }
  [[nodiscard]] std::uint8_t active_program() const { return active_program_; }
  [[nodiscard]] bool hardware_fault() const { return hardware_fault_; }
  [[nodiscard]] bool program_stored(int slot) const {
    return programs_[static_cast<std::size_t>(slot)].has_value();
  }
  // What Save Global (CB15 bit 10) last stored: CB2 and CB8 parameters.
  [[nodiscard]] const std::optional<Ans1Setup>& saved_global() const { return saved_global_; }

  // Fault injection: a stored program whose checksum fails. Loading it is refused and sets
  // Hardware Fault (status bit 13, L2298) until Clear Errors.
  void corrupt_program(int slot);

private:
  struct StoredProgram {
    Ans1Setup setup;
    bool checksum_ok = true;
  };
  void execute(const HostWords& words);
  void apply_setup(const Ans1Setup& next, const Ans1Setup& current);
  void run_program_command(const ProgramCommand& cmd, const Ans1Setup& current, Ans1Setup& next);

  Ans1& device_;
  HostWords commands_{};
  bool transmit_seen_ = false; // Transmit level at the previous scan
  bool ack_ = false;
  bool responding_ = false; // executed at the last scan: Acknowledge at this one
  ErrorCode error_ = ErrorCode::None;
  ErrorCode latched_ = ErrorCode::None; // the last 1001-1100, until Clear Errors (L2306-L2309)
  bool hardware_fault_ = false;
  DataSelection selection_{};
  std::uint8_t active_program_ = 0;
  std::array<std::optional<StoredProgram>, kProgramSlots + 1> programs_{}; // index 1..39
  std::optional<Ans1Setup> saved_global_;
};

} // namespace hilrig::models::ans1
