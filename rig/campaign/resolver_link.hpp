#pragma once
// The virtual rig's resolver front end, the path a real rig's stators take (DESIGN "Backends"):
// the rig streams a ResolverAngle frame every frame period (models/resolver_emulator/
// angle_streamer.hpp) over a virtual CAN bus (drivers/virtual/can_bus.hpp, 500 kbit/s; its
// frames are in the run's trace and so in can.log) to the resolver-emulator node model, and
// the angle the node holds and interpolates is the angle of the stators the rig synthesizes
// (resolver_stators.hpp). The rig, not the node, forms the carrier: a campaign's excitation may
// be 400 Hz .. 10 kHz (limits.hpp), wider than the node's 2.2 .. 7 kHz.
// A real rig streams the shaft between runs, so the node holds the shaft's start when a run
// begins (the run's first frame arrives a frame time, ~0.23 ms, into it); like the node, the
// stators carry nothing after a frame timeout or an invalid frame.

#include <cstdint>
#include <functional>
#include <memory>
#include <string>
#include <vector>

#include "core/analog.hpp"
#include "core/scheduler.hpp"
#include "drivers/virtual/virtual_bus.hpp"
#include "models/resolver_emulator/angle_streamer.hpp"
#include "models/resolver_emulator/resolver_emulator.hpp"
#include "rig/campaign/campaign.hpp"
#include "rig/campaign/resolver_stators.hpp"

namespace hilrig::campaign {

// The bus's name in the trace and can.log (a real rig's is its [can] resolver interface).
inline constexpr const char* kResolverBus = "can0";
// A frame a millisecond: a real rig's default stream period (rig/hardware/hardware_run.hpp).
inline constexpr Nanos kResolverFramePeriod{1'000'000};

class ResolverLink {
public:
  // shaft: the shaft in encoder counts, counts_per_turn of them a turn. The scheduler and the
  // bus must outlive the link.
  ResolverLink(Scheduler& scheduler, virt::VirtualBus& bus, models::resolver_emulator::ShaftSource shaft,
               double counts_per_turn);

  // Streams from time 0 on, the node holding `at_start` (the shaft at time 0) until the run's
  // first frame arrives.
  void start(const models::resolver_emulator::ShaftSample& at_start);

  // A stator as the board's pin carries it: the resolver's carrier at the node's angle.
  [[nodiscard]] Waveform stator(const ResolverSpec& resolver, Stator which,
                                std::vector<StatorRatioWindow> faults) const;
  // Both stators, each with its own fault windows: a read of one at t forms both (one node angle,
  // one carrier wave, StatorForm::pair) and keeps the other's for its read at t, as the board's
  // read of a peak and the trace's take them.
  struct Stators {
    Waveform sin;
    Waveform cos;
  };
  [[nodiscard]] Stators stators(const ResolverSpec& resolver, std::vector<StatorRatioWindow> sin_faults,
                                std::vector<StatorRatioWindow> cos_faults) const;

  // Called after each frame the node takes: the stators' values from then on may change.
  void on_frame(std::function<void()> handler) { *frame_handler_ = std::move(handler); }

  [[nodiscard]] const models::resolver_emulator::ResolverEmulator& node() const { return *node_; }
  [[nodiscard]] const models::resolver_emulator::AngleStreamer& streamer() const { return streamer_; }

  // The frames the node has taken (each may change a stator's value at any time from its
  // arrival on, nothing else does): a stator's value at t is kept for reading again at t until
  // the next frame (the board reads each peak ahead of time, the trace at the time).
  struct Frames {
    std::uint64_t taken = 0;
  };

private:
  double counts_per_turn_;
  std::shared_ptr<Frames> frames_ = std::make_shared<Frames>();
  std::shared_ptr<std::function<void()>> frame_handler_ = std::make_shared<std::function<void()>>();
  // Shared with the stator waveforms, which the bus holds.
  std::shared_ptr<models::resolver_emulator::ResolverEmulator> node_;
  models::resolver_emulator::AngleStreamer streamer_;
};

} // namespace hilrig::campaign
