#pragma once
// Resolver stator signals synthesized from the shaft the rig turns (a motion profile or a
// plant), for boards that read a resolver (the ANS1's SIN/COS pins, the Series 2700's): the
// rotor is excited with amplitude * sin(2 pi f t) and each stator carries it times the
// transformation ratio and sin or cos of the shaft angle. Stimuli are data: the waveforms
// are pure functions of virtual time.

#include <functional>
#include <memory>

#include "core/analog.hpp"
#include "rig/campaign/campaign.hpp"
#include "signals/motion_profile.hpp"

namespace hilrig::campaign {

enum class Stator : std::uint8_t { Sine, Cosine };

// The shaft's position at a time, in encoder counts.
using ShaftPosition = std::function<double(Nanos)>;

// position: the shaft in encoder counts, counts_per_turn of them per shaft turn.
[[nodiscard]] Waveform stator_waveform(ShaftPosition position, double counts_per_turn,
                                       const ResolverSpec& resolver, Stator stator);
// The same over a motion profile in counts.
[[nodiscard]] Waveform stator_waveform(std::shared_ptr<const signals::MotionProfile> profile,
                                       double counts_per_turn, const ResolverSpec& resolver, Stator stator);

} // namespace hilrig::campaign
