#pragma once
// Command blocks (spec §5.2/§5.3, manual L1699-L2250): the 20 words a host writes, decoded and
// validated into a new Ans1Setup plus the one-shot actions the block asks for. Pure: no device,
// no time. HostInterface calls decode_command_block() on each Transmit 0->1 edge.
//
// Validation order [MODEL]: undefined block number (1000), reserved bits (1010), incompatible
// Apply bits (1011), values out of range (1001), incompatible values (1011), setpoint overlap
// (1100). The whole block is checked before anything is applied; a rejected block leaves the
// setup unchanged and asks for no action except Clear Errors (bit 4).
#include <array>
#include <cstdint>
#include <optional>

#include "models/ans1/error_codes.hpp"
#include "models/ans1/setup.hpp"

namespace hilrig::models::ans1 {

inline constexpr int kHostWords = 20;
using HostWords = std::array<std::uint16_t, kHostWords>;

// Command word 0 (and status word 0) fields common to every block.
inline constexpr std::uint16_t kTransmitBit = 0x8000;     // command w0 bit 15
inline constexpr std::uint16_t kAcknowledgeBit = 0x8000;  // status w0 bit 15
inline constexpr std::uint16_t kClearErrorsBit = 0x0010;  // command w0 bit 4
inline constexpr std::uint16_t kBlockNumberMask = 0x000F; // command w0 bits 3..0

// The command block numbers (w0 bits 3..0). 12..14 are undefined.
enum class CommandBlock : std::uint8_t {
  ClearErrors = 0,
  ReturnDataAndForces = 1,
  GlobalConfiguration = 2,
  Setpoints = 3,
  AdjustSetpoints = 4,
  Timing = 5,
  Enabling = 6,
  DieProtection = 7,
  BrakeMonitor = 8,
  ShiftRegister = 9,
  ProductionCycle = 10,
  ProductionCounters = 11,
  SaveRestore = 15,
};

// CB1 words 1..3: which data attribute block the status words carry, and the output and
// input point the point-specific blocks report on.
struct DataSelection {
  std::uint8_t attribute = 0; // 0..8, 16..20
  std::uint8_t output = 1;    // 1..16 (DA1, DA2, DA3, DA16, DA19)
  std::uint8_t input = 1;     // 1..16 (DA4, DA16, DA18)
  friend bool operator==(const DataSelection&, const DataSelection&) = default;
};

[[nodiscard]] constexpr bool is_data_attribute(unsigned n) { return n <= 8 || (n >= 16 && n <= 20); }

struct Forces {
  std::uint16_t enable = 0; // bit n-1 = point n forced
  std::uint16_t state = 0;  // bit n-1 = forced ON (1) or OFF (0)
  friend bool operator==(const Forces&, const Forces&) = default;
};

struct CounterPreset {
  CounterId counter = CounterId::PartCycle;
  std::uint32_t value = 0;
};

inline constexpr int kProgramSlots = 39;   // stored programs 1..39
inline constexpr int kFactoryProgram = 40; // load-only: factory defaults (L2229)

// CB15 (L2222-L2250).
struct ProgramCommand {
  bool save_global = false;   // bit 10: CB2 + CB8 parameters to flash
  bool save_program = false;  // bit 9
  bool load_program = false;  // bit 8
  bool delete_stored = false; // bit 5: erase every stored program (RAM copy stays)
  std::uint8_t slot = 0;      // w1: 0 = active program, 1..39, 40 = factory defaults (load only)
};

struct BlockActions {
  bool clear_errors = false;                   // bit 4 of any block
  std::optional<DataSelection> selection;      // CB1 bit 8
  std::optional<Forces> output_forces;         // CB1 bit 9 (w4, w5)
  std::optional<Forces> input_forces;          // CB1 bit 10 (w6, w7)
  bool machine_preset = false;                 // CB2 bit 14: after applying the setup, GMP := MPV
  bool factory_defaults = false;               // CB2 bit 5: setup and stored programs to default
  int ls_preset_output = 0;                    // CB3 bit 14: after applying, LSO := LSPV - GMP
  std::optional<CounterPreset> counter_preset; // CB11 bit 12
  ProgramCommand program{};                    // CB15
};

// What the decoder needs to know besides the setup.
struct HostContext {
  std::uint8_t active_program = 0;                          // 0 = none loaded yet
  std::array<const Ans1Setup*, kProgramSlots + 1> stored{}; // stored[k]: slot k's program (1..39), or null
};

struct DecodedBlock {
  int block = 0;
  ErrorCode error = ErrorCode::None;
  Ans1Setup setup{}; // the setup after the block; equal to the current one when rejected
  BlockActions actions{};
};

[[nodiscard]] DecodedBlock decode_command_block(const HostWords& words, const Ans1Setup& current,
                                                const HostContext& context);

} // namespace hilrig::models::ans1
