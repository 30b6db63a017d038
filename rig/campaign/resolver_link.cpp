#include "rig/campaign/resolver_link.hpp"

#include <array>
#include <cstdint>
#include <optional>
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
  node_->on_frame([frames = frames_, handler = frame_handler_] {
    ++frames->taken;
    if (*handler) (*handler)();
  });
}

void ResolverLink::start(const models::resolver_emulator::ShaftSample& at_start) {
  // The stream before the run: its last frame (sequence 15, the one before the run's first)
  // holds the shaft's start from time 0 on, so the board reads a resolver from its first scan.
  node_->hold(models::resolver_emulator::angle_frame(at_start, streamer_.params(), 15));
  streamer_.start(Nanos{0});
}

Waveform ResolverLink::stator(const ResolverSpec& resolver, Stator which,
                              std::vector<StatorRatioWindow> faults) const {
  Stators both = which == Stator::Sine ? stators(resolver, std::move(faults), {})
                                       : stators(resolver, {}, std::move(faults));
  return which == Stator::Sine ? std::move(both.sin) : std::move(both.cos);
}

ResolverLink::Stators ResolverLink::stators(const ResolverSpec& resolver,
                                            std::vector<StatorRatioWindow> sin_faults,
                                            std::vector<StatorRatioWindow> cos_faults) const {
  // The node's angle read once a sample time for both stators: nothing when the node drives no
  // stators. The pairs read since the node's last frame are kept (a few, by time): the same t
  // reads the same values until the next frame.
  struct Kept {
    Nanos t{0};
    std::uint64_t frames = 0;
    StatorForm::Pair value;
    bool held = false;
  };
  constexpr std::size_t kKept = 64;
  struct Shared {
    std::shared_ptr<models::resolver_emulator::ResolverEmulator> node;
    std::shared_ptr<Frames> frames;
    double per_turn;
    StatorForm sin_form;
    StatorForm cos_form;
    std::array<Kept, kKept> kept{};

    StatorForm::Pair at(Nanos t) {
      const auto ns = static_cast<std::uint64_t>(t.count());
      Kept& k = kept[((ns ^ (ns >> 7U) ^ (ns >> 17U)) * 0x9E37'79B9'7F4A'7C15ULL >> 58U) % kKept];
      if (k.held && k.t == t && k.frames == frames->taken) return k.value;
      const std::optional<double> turns = node->angle_turns(t);
      const StatorForm::Pair value =
          turns ? StatorForm::pair(sin_form, cos_form, t, *turns * per_turn) : StatorForm::Pair{};
      k = Kept{t, frames->taken, value, true};
      return value;
    }
  };
  auto shared = std::make_shared<Shared>(
      Shared{node_, frames_, counts_per_turn_,
             StatorForm(counts_per_turn_, resolver, Stator::Sine, std::move(sin_faults)),
             StatorForm(counts_per_turn_, resolver, Stator::Cosine, std::move(cos_faults))});
  return {[shared](Nanos t) { return shared->at(t).sin; }, [shared](Nanos t) { return shared->at(t).cos; }};
}

} // namespace hilrig::campaign
