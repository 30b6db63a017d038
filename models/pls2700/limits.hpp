#pragma once
// Limit windows with advances (pls2700.md §4.5, §4.6). Positions are machine positions in
// counts of the owning channel; shifts are advance distances in counts (speed x time).
#include <bitset>

#include "models/pls2700/setup.hpp"

namespace hilrig::models::pls2700 {

struct WindowRules {
  bool wrap_pairs = true;            // R-LS-3
  bool equal_pair_full_turn = false; // R-LS-4
};

// R-ADV-4: ON iff MP lies in the circular window [ON - s_on, OFF - s_off) of length
// (OFF - ON) mod SF + s_on - s_off; a window of length <= 0 is never on, >= SF always on.
[[nodiscard]] bool pair_on(const SetpointPair& pair, int mp, int scale_factor, double s_on, double s_off,
                           const WindowRules& rules);

// Any pair of the output on.
[[nodiscard]] bool output_on(const OutputSetup& output, int mp, int scale_factor, double s_on, double s_off,
                             const WindowRules& rules);

// 2742-18 (R-18-2, R-18-6): pairs are linear in the cycle's LS Position (ON <= OFF < CL);
// with `anticipate` (level mode, another cycle follows) an ON point moved below zero by its
// advance turns on at CL + ON - s_on, near the end of the current cycle.
[[nodiscard]] bool cycle_output_on(const OutputSetup& output, int ls, int cycle_length, double s_on,
                                   double s_off, bool anticipate);

// R-LS-5: the per-position ON table of one output, kept as the positions a deleted pair
// cleared while another pair still covered them ("holes"). Entering a pair re-sets its range;
// a power cycle rebuilds the table from the stored pairs (no holes).
class HoleTable {
public:
  static constexpr int kPositions = 4096;
  void clear_range(const SetpointPair& pair, int scale_factor) { mark(pair, scale_factor, true); }
  void set_range(const SetpointPair& pair, int scale_factor) { mark(pair, scale_factor, false); }
  void rebuild() { holes_.reset(); }
  [[nodiscard]] bool hole(int mp) const {
    return mp >= 0 && mp < kPositions && holes_.test(static_cast<std::size_t>(mp));
  }

private:
  void mark(const SetpointPair& pair, int scale_factor, bool value);
  std::bitset<kPositions> holes_;
};

} // namespace hilrig::models::pls2700
