#pragma once
// The probes of the last bisection over whole nanoseconds, by depth. Two bisections of the
// same interval for nearby targets take the same first probes (each halving depends only on
// the ones before), so a caller asking for one step after another re-evaluates only the
// probes below where their paths part. A remembered value is used only at its own point, so
// a bisection gives the plain bisection's answer whatever the function probed.

#include <array>
#include <cstddef>
#include <cstdint>

namespace hilrig::models::smd23e {

class BisectionPath {
public:
  // Depths a bisection over int64 points can reach.
  static constexpr std::size_t kDepths = 64;

  // Whether probe number `depth` at `point` is remembered (probe() would not evaluate it).
  [[nodiscard]] bool knows(std::size_t depth, std::int64_t point) const {
    return depth < kDepths && probes_[depth].known && probes_[depth].point == point;
  }

  // f(point), probe number `depth` of a bisection: remembered when the last probe at that
  // depth was at the same point, else evaluated (and remembered for the next bisection).
  template <class F> double probe(std::size_t depth, std::int64_t point, F&& f) {
    if (depth >= kDepths) return f(point);
    Probe& p = probes_[depth];
    if (!p.known || p.point != point) {
      p.point = point;
      p.value = f(point);
      p.known = true;
    }
    return p.value;
  }

private:
  struct Probe {
    std::int64_t point = 0;
    double value = 0.0;
    bool known = false;
  };
  std::array<Probe, kDepths> probes_{};
};

} // namespace hilrig::models::smd23e
