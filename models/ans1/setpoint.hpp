#pragma once
// Setpoint pairs (spec §4.4), stitching (§4.5) and advanced edges (§4.6), as pure functions
// of a limit switch position. [MODEL] for A17: a pair is the half-open interval [From, To):
// on at From, off at To; From > To wraps through zero; From == To != 0 is on everywhere;
// From == To == 0 is unused.
#include <array>
#include <cstdint>

#include "models/ans1/output_setup.hpp"

namespace hilrig::models::ans1 {

// How far each edge of a pair moves against the direction of travel, in counts: positive
// moves the edge to a lower position (earlier when GMP increases). The device takes them
// from the advances with the sign of the speed (OutputChannel::edge_shift says which
// advance goes with which edge).
struct EdgeShift {
  std::int32_t from = 0; // the From edge
  std::int32_t to = 0;   // the To edge
  // How far a stitched pair's pattern moves as a whole: the lead advance's shift ([MODEL], A38).
  std::int32_t stitch = 0;
};

// (To - From) mod FSC; FSC when From == To != 0; 0 for an unused pair.
[[nodiscard]] std::int32_t pair_length(const SetpointPair& pair, std::uint16_t fsc);

// Plain membership of position p, no advance.
[[nodiscard]] bool in_pair(std::uint16_t p, const SetpointPair& pair, std::uint16_t fsc);

// L >= 2 On + Off: at least two Ons and one Off fit (L868). Unstitched pairs are valid.
[[nodiscard]] bool stitch_fits(const SetpointPair& pair, std::uint16_t fsc);

// The stitch pattern at distance d (0 <= d < length) from From (§4.5, [MODEL] for A16).
[[nodiscard]] bool stitch_on(std::int32_t d, std::int32_t length, std::int32_t on, std::int32_t off);

// The run [first, last] of distances around d (0 <= d < FSC) over which stitch_on's pattern
// (off from length on) keeps its value at d: one On or Off of the pattern, the short remainder,
// or the rest of the cycle. It never crosses d = 0, where the pattern starts again. Exact scan
// skipping narrows its quiet interval to it.
struct StitchRun {
  std::int32_t first = 0;
  std::int32_t last = 0;
};
[[nodiscard]] StitchRun stitch_run(std::int32_t d, std::int32_t length, std::int32_t on, std::int32_t off,
                                   std::int32_t fsc);

// The pair's state at p with advanced edges. A stitched pair moves as a whole by the stitch
// shift ([MODEL], A38). When the trail edge is advanced to or past the lead edge the pair is
// off (L890); when the advanced pair covers a whole cycle it is on everywhere.
// late_wrap_to is the SetpointOffByOneAtWrap fault: a wrapping pair keeps To itself on.
[[nodiscard]] bool pair_on(std::uint16_t p, const SetpointPair& pair, std::uint16_t fsc, EdgeShift shift,
                           bool late_wrap_to = false);

// Where an unstitched pair is on with advanced edges: at p with (p - start) mod FSC < length;
// length <= 0: nowhere, length >= FSC: everywhere. pair_on's rule, as an arc of positions
// (exact scan skipping asks where the state can change).
struct PairArc {
  std::int64_t start = 0;
  std::int32_t length = 0;
};
[[nodiscard]] PairArc pair_arc(const SetpointPair& pair, std::uint16_t fsc, EdgeShift shift,
                               bool late_wrap_to = false);

// Pairs on one output that share a position (Setpoint Overlap Error 1100, L1898).
[[nodiscard]] bool pairs_overlap(const std::array<SetpointPair, kPairsPerOutput>& pairs, std::uint16_t fsc);

} // namespace hilrig::models::ans1
