#include "rig/campaign/motion_record.hpp"

#include <algorithm>

namespace hilrig::campaign {

rig::MotionRecord record_motion(const signals::MotionProfile& profile, Nanos end,
                                std::vector<rig::MotionEvent> events) {
  rig::MotionRecord r;
  const Nanos begin = profile.start_time();
  if (end <= begin) return r;
  std::vector<Nanos> times;
  const auto& segments = profile.segments();
  if (segments.size() <= kMotionKnotsKept) {
    for (const auto& s : segments)
      if (s.start < end) times.push_back(s.start);
    if (profile.end_time() < end) times.push_back(profile.end_time());
  }
  // Even samples as well: a plotted position curves between knots.
  const std::int64_t step = (end - begin).count() / static_cast<std::int64_t>(kMotionSamples);
  for (std::int64_t i = 0; i < static_cast<std::int64_t>(kMotionSamples); ++i)
    times.push_back(begin + Nanos{step * i});
  times.push_back(begin);
  times.push_back(end);
  for (const auto& e : events)
    if (e.time >= begin && e.time <= end) times.push_back(e.time);
  std::sort(times.begin(), times.end());
  times.erase(std::unique(times.begin(), times.end()), times.end());
  for (const Nanos t : times) r.points.push_back({t, profile.position(t), profile.velocity(t)});
  std::stable_sort(events.begin(), events.end(),
                   [](const auto& a, const auto& b) { return a.time < b.time; });
  r.events = std::move(events);
  return r;
}

} // namespace hilrig::campaign
