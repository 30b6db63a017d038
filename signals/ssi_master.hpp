#pragma once
// The SSI master side: clock bursts as an edge schedule, and the reading of a data line
// (as the 7361 does it, ssi7361.md §2.1). The clock idles high; with t = 0 at the latching
// falling edge F1 and period T, F_j = (j-1)T and R_k = (k-1/2)T (50 % duty, [MODEL]). The
// master samples bit k at k*T, half a period after R_k ([MODEL], digest §2.1); for the last
// bit that instant lies inside the transducer's monoflop time.

#include <cstddef>
#include <cstdint>
#include <span>
#include <vector>

#include "core/line.hpp"
#include "core/time.hpp"

namespace hilrig::signals {

struct SsiMasterParams {
  double clock_hz = 125'000.0;            // 125 kHz or 500 kHz on the 7361 (L1123)
  unsigned frame_bits = 25;               // rising edges per frame, 1..32 (25 on the 7361, L967)
  Nanos frame_period = microseconds(500); // TINT, start to start (L1090)
  // Added to the clock period 1/clock_hz: a master whose clock runs off its nominal rate (a
  // detection-power knob of the 7361 model; 0 = the manual's clock).
  Nanos clock_period_error{0};
};

// The 7361's clock: 125 kHz / TINT 500 us, or 500 kHz / TINT 250 us (L1090, L1096-1098).
[[nodiscard]] SsiMasterParams ssi7361_master(bool clock_500khz = false);

// The level of a line over time, from its level before the first edge and its edges in
// time order. An edge at t has taken effect at t.
class LineHistory {
public:
  LineHistory(Level initial, std::span<const Edge> edges) : initial_(initial), edges_(edges) {}
  [[nodiscard]] Level level_at(Nanos t) const;

private:
  Level initial_;
  std::span<const Edge> edges_;
};

// What the master read in one frame, and what it saw of the handshake.
struct SsiReading {
  Nanos frame_start;      // F1
  std::uint32_t word = 0; // frame_bits wide, first bit sent = MSB
  bool ready = true;      // DATA was high (idle) just before F1; a line stuck low fails this
  bool released = true;   // DATA back high before the next frame's F1 (monoflop expired)
};

class SsiMaster {
public:
  // Throws std::invalid_argument for a clock outside 1 kHz..10 MHz, frame_bits outside
  // 1..32, or a frame period shorter than the burst.
  explicit SsiMaster(SsiMasterParams params);

  [[nodiscard]] Nanos clock_period() const { return period_; }
  [[nodiscard]] Nanos frame_period() const { return params_.frame_period; }
  [[nodiscard]] const SsiMasterParams& params() const { return params_; }
  [[nodiscard]] Nanos falling_edge(Nanos frame_start, unsigned j) const; // F_j, j = 1..frame_bits
  [[nodiscard]] Nanos rising_edge(Nanos frame_start, unsigned k) const;  // R_k, k = 1..frame_bits
  [[nodiscard]] Nanos sample_time(Nanos frame_start, unsigned k) const;  // bit k, k = 1..frame_bits
  // The burst: F1, R1, F2, ..., F_n, R_n (2 * frame_bits edges), appended to `out`.
  void append_burst(Nanos frame_start, std::vector<Edge>& out) const;
  // `frames` bursts, the first F1 at `first`, one frame period apart.
  [[nodiscard]] std::vector<Edge> clock_schedule(Nanos first, std::size_t frames) const;

  [[nodiscard]] SsiReading read_frame(const LineHistory& data, Nanos frame_start) const;
  [[nodiscard]] std::vector<SsiReading> read_frames(const LineHistory& data, Nanos first,
                                                    std::size_t frames) const;

private:
  SsiMasterParams params_;
  Nanos period_;
  Nanos half_;
};

} // namespace hilrig::signals
