#include "rig/campaign/resolver_link.hpp"

#include <utility>

#include "signals/resolver_frames.hpp"

namespace hilrig::campaign {

namespace {

using models::resolver_emulator::AngleStreamParams;
using models::resolver_emulator::ResolverEmulatorParams;

ResolverEmulatorParams node_params() {
  ResolverEmulatorParams p; // its own carrier is not used (the rig forms the stators)
  p.frame_period = kResolverFramePeriod;
  return p;
}

AngleStreamParams stream_params(double counts_per_turn) {
  AngleStreamParams p;
  p.period = kResolverFramePeriod;
  p.units_per_turn = counts_per_turn;
  return p;
}

} // namespace

ResolverLink::ResolverLink(Scheduler& scheduler, virt::VirtualBus& bus,
                           models::resolver_emulator::ShaftSource shaft, double counts_per_turn)
    : counts_per_turn_(counts_per_turn),
      node_(std::make_shared<models::resolver_emulator::ResolverEmulator>(
          scheduler, bus.can(kResolverBus).attach("resolver_emulator"), node_params())),
      streamer_(scheduler, bus.can(kResolverBus).attach("rig"), std::move(shaft),
                stream_params(counts_per_turn)) {
  // The bus knows each frame's time to the node's end of frame, stuff bits and all: every
  // frame carries the shaft at the instant the node holds it, so the node's angle follows the
  // shaft to the frame's resolution (1/2^24 turn, speed 1/4096 turn/s) plus what its
  // interpolation at constant speed misses between frames (a/2 * period^2 under acceleration a).
  const virt::CanBitTiming timing = bus.can(kResolverBus).timing();
  streamer_.lead_by_transport(
      [timing](const CanFrame& frame) { return virt::can_end_of_frame(virt::can_frame_bits(frame), timing); },
      virt::can_end_of_frame_range(signals::encode(signals::ResolverAngleFrame{}), timing));
}

void ResolverLink::start(const models::resolver_emulator::ShaftSample& at_start) {
  // The stream before the run: its last frame (sequence 15, the one before the run's first)
  // holds the shaft's start from time 0 on, so the board reads a resolver from its first scan.
  node_->hold(models::resolver_emulator::angle_frame(at_start, streamer_.params(), 15));
  streamer_.start(Nanos{0});
}

Waveform ResolverLink::stator(const ResolverSpec& resolver, Stator which,
                              std::vector<StatorRatioWindow> faults) const {
  const Waveform carried =
      stator_waveform([node = node_, per_turn = counts_per_turn_](
                          Nanos t) { return node->angle_turns(t).value_or(0.0) * per_turn; },
                      counts_per_turn_, resolver, which, std::move(faults));
  return [node = node_, carried](Nanos t) { return node->angle_turns(t) ? carried(t) : 0.0; };
}

} // namespace hilrig::campaign
