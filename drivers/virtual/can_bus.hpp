#pragma once
// A virtual CAN bus: frame durations from bitrate and bit stuffing, arbitration by
// identifier when nodes start together, error-frame and frame-loss injection hooks.
//
// Timing of one frame that starts (SOF) at t with duration d (can_frame_bits, actual stuffing):
//  - receivers get it at t + d - 3 nominal bits (end of EOF), stamped with that time, and it
//    is recorded in the trace under the bus name then;
//  - the bus is idle again at t + d (after the 3-bit intermission); the heads of all nodes'
//    queues that are pending then arbitrate, and the winner's SOF is at that instant.
// A send() on an idle bus starts an arbitration round at the current time (as a scheduled
// event, so every node that sends at that same instant takes part).
// Arbitration compares the arbitration fields bit by bit as the bus does (dominant 0 wins):
// lower base ID wins; a standard data frame beats a standard remote frame (RTR) which beats
// an extended frame with the same base ID (SRR/IDE recessive); then the 18-bit extension,
// then RTR. FD frames send a dominant RRS in place of RTR. Identical arbitration fields from
// two nodes (a misconfigured network) go to the node attached first.
// Each node's own queue is first in, first out (as a SocketCAN socket's is).
// Error injection: the frame is sent up to its ACK delimiter, then receivers signal a CRC
// error (ISO 11898-1: the error flag starts at the bit after the ACK delimiter): an error
// frame of 6 dominant bits + 8-bit delimiter + 3-bit intermission = 17 nominal bits. Nobody
// receives the frame; the sender retransmits it automatically, arbitrating again. Each error
// adds 8 to the sender's transmit error counter and each success subtracts 1; above 255 the
// node goes bus-off: its queue is dropped and later sends are ignored (no auto-recovery).
// Frame loss: the frame takes its time on the bus, the sender sees success, nobody receives
// it, and it is not in the trace. The bus must outlive the scheduler's pending events.

#include <cstdint>
#include <functional>
#include <memory>
#include <string>
#include <vector>

#include "core/can_frame.hpp"
#include "core/scheduler.hpp"
#include "core/trace.hpp"

namespace hilrig::virt {

struct CanBitTiming {
  std::uint32_t nominal_bitrate = 500'000; // arbitration phase, bit/s
  std::uint32_t data_bitrate = 2'000'000;  // FD data phase when BRS is set, bit/s
};

// Bits a frame occupies on the wire, from SOF to the end of the intermission (3 bits),
// with the bits sent at the nominal and at the data bitrate counted apart.
// Field layout (ISO 11898-1:2015), unstuffed bits:
//   classic base:  SOF 1, ID 11, RTR 1, IDE 1, r0 1, DLC 4, data 8n, CRC 15       = 34 + 8n
//   classic ext.:  SOF 1, ID 11, SRR 1, IDE 1, ID 18, RTR 1, r1 1, r0 1, DLC 4, data, CRC 15
//                                                                                 = 54 + 8n
//   then (not stuffed) CRC delimiter 1, ACK 1, ACK delimiter 1, EOF 7, intermission 3 = 13.
//   FD base:       SOF 1, ID 11, RRS 1, IDE 1, FDF 1, res 1, BRS 1, ESI 1, DLC 4, data 8n
//   FD ext.:       SOF 1, ID 11, SRR 1, IDE 1, ID 18, RRS 1, FDF 1, res 1, BRS, ESI, DLC 4, data
//   then stuff count 4 (Gray-coded dynamic stuff count mod 8 + even parity), CRC 17 (n <= 16)
//   or 21, with fixed stuff bits: one before the stuff count and one after every 4 bits of
//   stuff count + CRC (6 for CRC-17, 7 for CRC-21); then the same 13 bits as classic.
// Dynamic stuffing (a complement bit after 5 equal bits) runs from SOF to the end of the CRC
// (classic) or of the data field (FD; a dynamic stuff bit due right after the last data bit is
// not sent, the fixed stuff bit stands in its place). The FD CRC covers the dynamic stuff bits
// and the stuff count; its value cannot change the frame's length (fixed stuffing only).
// Data phase (BRS set): the bits after the BRS bit up to the end of the CRC sequence (ESI, DLC,
// data, stuff count, CRC and their stuff bits); BRS and the CRC delimiter count as nominal
// (the rate switches at their sample points, which we round to whole bits).
struct CanFrameBits {
  std::uint32_t nominal = 0;
  std::uint32_t data = 0;  // bits sent at the data bitrate (only FD with BRS)
  std::uint32_t stuff = 0; // stuff bits included in the two counts above
};

// Throws std::invalid_argument for a frame no bus can send (identifier out of range, a length
// or bits its format does not have): the check every function below makes first.
void can_check_frame(const CanFrame& frame);
// Actual: stuff bits worked out from the frame's real bit stream (including its CRC).
[[nodiscard]] CanFrameBits can_frame_bits(const CanFrame& frame);
// Worst case: the maximum stuff bits any frame of this format and length could need.
[[nodiscard]] CanFrameBits can_frame_bits_worst(const CanFrame& frame);
[[nodiscard]] Nanos can_frame_duration(const CanFrameBits& bits, const CanBitTiming& timing);
// From SOF to the end of EOF (the duration less the 3-bit intermission): when receivers take
// the frame, so a frame sent on an idle bus reaches them this long after its send.
[[nodiscard]] Nanos can_end_of_frame(const CanFrameBits& bits, const CanBitTiming& timing);
// Every end of frame a classic frame of this one's format and length can have, shortest first:
// its bits with no stuff bits up to can_frame_bits_worst's. Throws std::invalid_argument for FD.
[[nodiscard]] std::vector<Nanos> can_end_of_frame_range(const CanFrame& frame, const CanBitTiming& timing);

// CRC of a bit sequence (one bit per element, 0/1, first sent first), as ISO 11898-1
// specifies for the CRC field: CRC-15 (classic), CRC-17 and CRC-21 (FD, register starting
// with its top bit set).
struct CanCrc {
  std::uint32_t width;
  std::uint32_t poly; // without the x^width term
  std::uint32_t init;
};
inline constexpr CanCrc kCanCrc15{15, 0x4599, 0};
inline constexpr CanCrc kCanCrc17{17, 0x1'685B, 1U << 16};
inline constexpr CanCrc kCanCrc21{21, 0x10'2899, 1U << 20};
[[nodiscard]] std::uint32_t can_crc(const std::uint8_t* bits, std::size_t count, const CanCrc& crc);

// Payload length for a DLC (0..15) and the DLC for a length (FD lengths round up).
[[nodiscard]] std::uint8_t can_dlc_to_len(std::uint8_t dlc, bool fd);
[[nodiscard]] std::uint8_t can_len_to_dlc(std::uint8_t len);

class CanBus;

// One node on a virtual CAN bus (implements core CanPort).
class CanNode; // defined by the implementation; see can_bus.cpp

class CanBus {
public:
  CanBus(Scheduler& scheduler, std::string name, CanBitTiming timing, TraceRecorder* trace);
  ~CanBus();

  [[nodiscard]] const std::string& name() const;
  [[nodiscard]] const CanBitTiming& timing() const;

  // Attaches a new node; the port stays valid for the bus's lifetime.
  [[nodiscard]] CanPort& attach(std::string node_name);

  // Fault hooks, asked for each frame as it wins arbitration:
  // drop -> nobody receives it (frame loss); error -> an error frame replaces it and the
  // sender retransmits automatically (as a CAN controller does).
  using FrameFilter = std::function<bool(const CanFrame&)>;
  void set_drop(FrameFilter drop);
  void set_error(FrameFilter error);

  [[nodiscard]] std::uint64_t frames_delivered() const;
  [[nodiscard]] std::uint64_t error_frames() const;
  [[nodiscard]] std::uint64_t frames_dropped() const;
  // A port this bus handed out: its transmit error counter and bus-off state.
  [[nodiscard]] std::uint32_t transmit_errors(const CanPort& port) const;
  [[nodiscard]] bool bus_off(const CanPort& port) const;

private:
  friend class CanNode;
  struct Impl;
  std::unique_ptr<Impl> impl_;
};

} // namespace hilrig::virt
