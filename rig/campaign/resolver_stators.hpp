#pragma once
// Resolver stator signals synthesized from the shaft the rig turns (a motion profile or a
// plant), for boards that read a resolver (the ANS1's SIN/COS pins, the Series 2700's): the
// rotor is excited with amplitude * sin(2 pi f t) and each stator carries it times the
// transformation ratio and sin or cos of the shaft angle. Stimuli are data: the waveforms
// are pure functions of virtual time.
// A resolver device fault ([[device_fault]] of a stator site) changes a stator's amplitude
// for its window: 0 for an open coil or a lost transducer, the fault's ratio for a ratio
// out of range, so the board detects it from the signal.

#include <functional>
#include <memory>
#include <vector>

#include "core/analog.hpp"
#include "rig/campaign/campaign.hpp"
#include "signals/motion_profile.hpp"

namespace hilrig::campaign {

enum class Stator : std::uint8_t { Sine, Cosine };

// The shaft's position at a time, in encoder counts.
using ShaftPosition = std::function<double(Nanos)>;

// One stator's transformation ratio from `at` until `until` (instead of the resolver's).
struct StatorRatioWindow {
  Nanos at{0};
  Nanos until = Nanos::max();
  double ratio = 0.0;
};

// The windows of the scenario's resolver faults that act on this stator, in file order (a
// later one wins where two overlap).
[[nodiscard]] std::vector<StatorRatioWindow> stator_fault_windows(const Scenario& scenario, Stator stator);

// A stator at t with the shaft at `position` counts: the excitation times the ratio in force
// at t (a fault window's, else the resolver's) times sin or cos of the shaft angle. A reader
// that has the position at hand (the resolver front end's node) calls it with no
// ShaftPosition between.
class StatorForm {
public:
  StatorForm(double counts_per_turn, const ResolverSpec& resolver, Stator stator,
             std::vector<StatorRatioWindow> faults = {});
  [[nodiscard]] double operator()(Nanos t, double position) const;

  // Both stators at t with the shaft at `position`, one carrier wave and one angle between them:
  // the values sine(t, position) and cosine(t, position) give (forms of one resolver and
  // counts_per_turn, each with its own fault windows; sine's carrier and angle are used).
  struct Pair {
    double sin = 0.0;
    double cos = 0.0;
  };
  [[nodiscard]] static Pair pair(const StatorForm& sine, const StatorForm& cosine, Nanos t, double position);

private:
  [[nodiscard]] double ratio_at(Nanos t) const;

  double ratio_;
  double amplitude_;
  double omega_;
  double phase_;
  double radians_per_count_;
  Stator stator_;
  std::vector<StatorRatioWindow> faults_;
};

// position: the shaft in encoder counts, counts_per_turn of them per shaft turn.
[[nodiscard]] Waveform stator_waveform(ShaftPosition position, double counts_per_turn,
                                       const ResolverSpec& resolver, Stator stator,
                                       std::vector<StatorRatioWindow> faults = {});
// The same over a motion profile in counts.
[[nodiscard]] Waveform stator_waveform(std::shared_ptr<const signals::MotionProfile> profile,
                                       double counts_per_turn, const ResolverSpec& resolver, Stator stator,
                                       std::vector<StatorRatioWindow> faults = {});

} // namespace hilrig::campaign
