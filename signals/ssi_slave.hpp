#pragma once
// The SSI transducer the rig plays for a master such as the 7361: a state machine fed
// clock edges with their times, producing data-line edges with their times. No backend.
//
// Protocol (ssi7361.md §2.1-2.2, manual L1083-1093):
// - clock and data idle high; the first falling clock edge after a quiet period (monoflop
//   expired) latches the position (L1085) and, as the L1083 figure suggests, pulls DATA low;
// - each following rising edge R_k drives stream bit k, MSB first (L1088);
// - the monoflop is retriggered by every clock edge; TM after the last one it expires and
//   DATA returns to idle high (L1091-1092), so bit N stays valid for TM.
// The master samples each bit half a period after R_k ([MODEL], digest §2.1), so the data
// may change up to half a period late and still be read correctly. Rising edges beyond
// frame_bits (a master clocking too many bits) send 0, as standard SSI does [MODEL].

#include <array>
#include <cstddef>
#include <cstdint>
#include <functional>
#include <optional>
#include <span>
#include <vector>

#include "core/line.hpp"
#include "core/time.hpp"
#include "signals/ssi_frame.hpp"

namespace hilrig::signals {

enum class SsiLatch : std::uint8_t {
  FirstFallingEdge, // latch at F1 (L1085)
  PreviousFrameEnd  // latch when the previous frame's monoflop expires (L1085-1086)
};

struct SsiSlaveParams {
  SsiFrameFormat format{};
  Nanos monoflop = microseconds(16); // TM, "typically 12 to 20 us" (L1091-1092); [MODEL] mid value
  SsiLatch latch = SsiLatch::FirstFallingEdge;
  bool low_on_latch = true;      // [MODEL] DATA drops at F1 (L1083 figure, digest §2.1)
  Nanos output_delay = Nanos{0}; // clock edge to data change (line driver and opto delay)
};

enum class SsiStuck : std::uint8_t { None, High, Low };

// Signal faults the transducer side can inject (DESIGN "SSI bit errors").
struct SsiSlaveFaults {
  SsiStuck stuck = SsiStuck::None;
  unsigned flip_stream_bit = 0;       // 1..frame_bits: invert that stream bit on the wire; 0 = none
  Nanos late_response = Nanos{0};     // added to output_delay: data changes later after each edge
  std::uint32_t gray_glitch_mask = 0; // XOR into the coded data field (Gray or binary) before sending
};

// The data-line edges caused by one input (at most two: a latch drop can coincide with an
// expiry). No allocation per clock edge.
struct SsiDataEdges {
  std::array<Edge, 2> edges{};
  std::size_t count = 0;
  [[nodiscard]] std::span<const Edge> view() const& { return {edges.data(), count}; }
  // A view of a temporary would dangle in a range-for: keep the result in a variable.
  std::span<const Edge> view() const&& = delete;
};

class SsiSlave {
public:
  // Position in counts at the latch instant; only the low data_bits bits are sent.
  using ValueSource = std::function<std::uint32_t(Nanos)>;

  // Throws std::invalid_argument for an invalid frame format or a negative monoflop.
  SsiSlave(SsiSlaveParams params, ValueSource source);

  // Status bits sent in the frames latched from now on.
  void set_status(std::uint32_t status) { status_ = status; }
  // Applies faults from `now`; a stuck line changes level at once (the returned edge).
  std::optional<Edge> set_faults(const SsiSlaveFaults& faults, Nanos now);
  [[nodiscard]] const SsiSlaveFaults& faults() const { return faults_; }

  // Feeds one clock edge (edges in time order). Expires the monoflop first if it ran out
  // before the edge, then reacts to the edge.
  SsiDataEdges on_clock(const Edge& clock);
  // Lets time pass to t: returns the return-to-idle edge if the monoflop expired by then.
  std::optional<Edge> advance_to(Nanos t);
  // When the monoflop expires (DATA returns to idle), or Nanos::max() while idle.
  [[nodiscard]] Nanos deadline() const;

  [[nodiscard]] Level data() const { return driven_; } // level after the last emitted edge
  [[nodiscard]] bool busy() const { return busy_; }
  [[nodiscard]] std::uint32_t latched_word() const { return word_; } // frame word before wire faults
  [[nodiscard]] std::uint64_t frames() const { return frames_; }
  [[nodiscard]] const SsiSlaveParams& params() const { return params_; }

private:
  void latch(Nanos t);
  void emit(SsiDataEdges& out, Nanos t, Level level);
  [[nodiscard]] Level wire_bit(unsigned k) const;
  [[nodiscard]] Nanos delay() const { return params_.output_delay + faults_.late_response; }

  SsiSlaveParams params_;
  ValueSource source_;
  SsiSlaveFaults faults_{};
  std::uint32_t status_ = 0;
  std::uint32_t word_ = 0;
  std::uint32_t next_word_ = 0; // PreviousFrameEnd mode: latched at the last expiry
  bool have_next_ = false;
  bool busy_ = false;
  unsigned bits_sent_ = 0;
  Nanos expiry_ = Nanos::max();
  Level driven_ = Level::High;
  std::uint64_t frames_ = 0;
};

// Convenience for whole schedules: feeds every clock edge (sorted), lets time run to
// `until`, and returns all data edges in time order.
[[nodiscard]] std::vector<Edge> respond(SsiSlave& slave, std::span<const Edge> clock, Nanos until);

// Value sources: angle in turns -> counts per turn (floor, wrapped to one turn).
[[nodiscard]] SsiSlave::ValueSource counts_from_turns(std::function<double(Nanos)> turns,
                                                      std::uint32_t counts_per_turn);

} // namespace hilrig::signals
