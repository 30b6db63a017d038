#pragma once
// One Programming Cycle (digest §5.3-5.4): the command words latched at TRMT's 0->1 edge
// are checked in the manual's fixed order and, only if everything is valid, committed
// together; on the first error the module sets that one error bit and keeps its old setup,
// including the linear offset LO (L1961-1962).
//
// Order (reference processing, digest §5.4):
//   1. must-be-zero bits of %Q / %AQ1, CntDir without PgmDir       -> CMDErr
//   2. E2Err present: E2CLR clears it and loads the defaults (committed at once: it is the
//      remedy, not a parameter); without E2CLR                     -> CMDErr
//   3. no command bit 07-01 (E2CLR alone without E2Err has no effect, L2121) -> CMDErr
//   4. a parameter error pending and this cycle does not reprogram it -> MsgIgn
//   5. N, M, M+N -> FMTErr; MUL, DIV, MUL<=DIV -> SCLErr; Preset -> PSTErr; RUT -> RUTErr
//   6. commit; clear FMT/SCL/PST/RUT/CMD/MsgIgn; Format that changes the setup clears LO;
//      Apply Preset last: LO = Preset - scaled(latest raw).

#include <cstdint>

#include "models/ssi7361/host_words.hpp"
#include "models/ssi7361/params.hpp"
#include "models/ssi7361/setup.hpp"

namespace hilrig::models::ssi7361 {

// What the programming cycle keeps between cycles (the module's EEPROM and error bits).
struct ProgramState {
  Setup setup{};
  std::int64_t offset = 0;         // LO
  std::uint16_t errors = 0;        // %I error bits this cycle owns (not ROVErr, not ACK)
  std::uint64_t eeprom_writes = 0; // accepted changes and applied presets (L1307-1313)
};

struct CycleOutcome {
  bool accepted = false;       // committed (no error bit set by this cycle)
  bool rut_programmed = false; // the rate window restarts
  bool preset_applied = false;
  bool defaults_loaded = false; // E2CLR with E2Err: committed even if a later check fails
};

// Runs one cycle on `state`. `latest_raw` is the raw word of the last complete frame.
CycleOutcome run_cycle(ProgramState& state, const CommandWords& words, std::uint32_t latest_raw,
                       const Params& params);

} // namespace hilrig::models::ssi7361
