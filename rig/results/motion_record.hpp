#pragma once
// The shaft's motion over one run, kept in the results for the report's speed and position
// plot: points of the trajectory the encoder played and the events that acted on the shaft
// (a board output driving a plant's valve or motor, a located standstill). Recorded for runs
// with a plant or a brake check; empty otherwise.

#include <string>
#include <vector>

#include "core/time.hpp"

namespace hilrig::rig {

struct MotionPoint {
  Nanos time;
  double position = 0.0; // encoder counts
  double speed = 0.0;    // counts/s
};

struct MotionEvent {
  Nanos time;
  std::string what; // e.g. "valve off: brake applied, clutch released"
};

struct MotionRecord {
  std::vector<MotionPoint> points; // in time order
  std::vector<MotionEvent> events; // in time order
  [[nodiscard]] bool empty() const { return points.empty(); }
};

} // namespace hilrig::rig
