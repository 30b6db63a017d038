#include "rig/hardware/resolver_stream.hpp"

#include <algorithm>

#include "rig/rt/rt_loop.hpp"

namespace hilrig::hardware {

std::string play_resolver_stream(const signals::MotionProfile& profile,
                                 const models::resolver_emulator::AngleStreamParams& params, Nanos end,
                                 ResolverCan& can, Nanos start, rig::SpscRing<SentFrame>& sent,
                                 const std::atomic<bool>& stop, ResolverStreamStats& stats) {
  const Nanos period = params.period;
  Nanos t{0};
  while (t <= end && !stop.load(std::memory_order_relaxed)) {
    (void)rig::sleep_until(start + t);
    std::string why = can.check(); // empty (no allocation) unless the run must stop
    if (!why.empty()) return why;
    const Nanos now = rig::monotonic_now() - start;
    if (now > t + period) {
      const Nanos resume = (now / period + 1) * period;
      const Nanos last = std::min(resume - period, (end / period) * period); // boundaries up to end only
      stats.stale += (last - t) / period + 1;
      t = resume;
      continue;
    }
    const CanFrame frame = models::resolver_emulator::angle_frame(profile, params, t, stats.sent);
    why = can.send(frame);
    if (!why.empty()) return why;
    if (!sent.push(SentFrame{now, frame})) ++stats.ring_overflows;
    ++stats.sent;
    t += period;
  }
  return can.check();
}

} // namespace hilrig::hardware
