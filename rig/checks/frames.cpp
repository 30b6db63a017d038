#include "rig/checks/frames.hpp"

#include <fmt/format.h>

namespace hilrig::checks {

CheckResult check_frames_decode(std::span<const RawFrame> frames, const FrameDecoder& decode,
                                const FrameSpec& spec) {
  CheckResult r;
  r.kind = "frame_decodes";
  std::size_t n = 0;
  std::size_t errors = 0;
  std::string first = "every frame decoded";
  std::optional<TraceWindow> where;
  for (const auto& f : frames) {
    if (spec.id && f.id != *spec.id) continue;
    ++n;
    const std::string err = decode(f);
    if (err.empty()) continue;
    if (errors++ == 0) {
      first = fmt::format("frame {:#x} at {} ns: {}", f.id, f.time.count(), err);
      where = TraceWindow{f.time, f.time};
    }
  }
  if (n == 0 && spec.min_frames == 0) {
    r.measurements.push_back(error(spec.name + ".frames", "nothing judged: no frame captured"));
    return r;
  }
  r.measurements.push_back(measure(
      spec.name + ".frames", static_cast<double>(n), "", static_cast<double>(spec.min_frames), std::nullopt,
      n == 0 ? std::string("missing frame: none captured") : fmt::format("{} frames", n)));
  r.measurements.push_back(
      measure(spec.name + ".errors", static_cast<double>(errors), "", std::nullopt, 0.0, first, where));
  return r;
}

} // namespace hilrig::checks
