#include "rig/campaign/motion.hpp"

#include <cmath>
#include <exception>

#include <fmt/format.h>

#include "signals/move_builders.hpp"

namespace hilrig::campaign {

BuiltMotion build_motion(const std::string& file, const MotionSpec& motion, const EncoderSpec& encoder) {
  const double cpt = encoder.counts_per_turn();
  const auto per_s = [cpt](double rpm) {
    return rpm / 60.0 * cpt;
  }; // rpm -> counts/s (and rpm/s -> counts/s²)
  BuiltMotion out{signals::MotionProfile(motion.start_turns * cpt, Nanos{0}), {}};
  signals::MotionProfile& p = out.profile;
  for (std::size_t i = 0; i < motion.moves.size(); ++i) {
    const Move& m = motion.moves[i];
    try {
      switch (m.kind) {
      case MoveKind::Constant:
        signals::constant_speed(p, per_s(m.speed_rpm), m.duration);
        break;
      case MoveKind::Accelerate:
        p.accelerate((per_s(m.to_rpm) - p.end_velocity()) / m.duration.seconds(), m.duration);
        break;
      case MoveKind::Dwell:
        p.dwell(m.duration);
        break;
      case MoveKind::Trapezoid: {
        const double a = per_s(m.accel_rpm_s);
        (void)signals::trapezoid_move(p, m.turns * cpt, signals::MoveLimits{per_s(m.speed_rpm), a, a});
        break;
      }
      case MoveKind::PressStroke: {
        // Run to the crank angle of the braking stroke: after `strokes` full turns, the next
        // time the angle reaches brake_at_deg (strictly ahead of where the shaft is).
        const double here = p.end_position() / cpt; // turns
        double target = std::floor(here) + static_cast<double>(m.strokes) + m.brake_at_deg / 360.0;
        if (target <= here) target += 1.0;
        const double speed = per_s(m.speed_rpm);
        const Nanos run = std::max(Nanos{1}, Nanos::from_seconds((target - here) * cpt / speed));
        const signals::PressStroke s = signals::press_stroke(p, speed, run, per_s(m.decel_rpm_s));
        out.brakes.push_back(BrakeApplied{s.brake_applied, m.brake_line});
        break;
      }
      }
    } catch (const std::exception& e) {
      throw CampaignError(file, m.where, fmt::format("motion.move[{}]", i),
                          fmt::format("a move that can follow the one before it ({})", e.what()));
    }
  }
  return out;
}

} // namespace hilrig::campaign
