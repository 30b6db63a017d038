#pragma once
// A served board's digital pins on gpio-sim's simulator side, as core line interfaces the
// model takes (ans1_pins.hpp's wire_pins_by_map asks a bus for line(name).reader() or
// .driver()):
//   - a board input is a PolledInput: poll(t) reads sim_gpioN/value (the level the rig
//     drives) and a change becomes an edge at t, scheduled so the model sees it in time order;
//   - a board output is a PullOutput: set() pulls the line up or down at once, so the rig's
//     gpiod request sees an edge event.
// A line becomes one or the other when the model first asks for it.

#include <cstdint>
#include <memory>
#include <string>
#include <vector>

#include "core/line.hpp"
#include "core/scheduler.hpp"
#include "drivers/gpiosim/sim_line.hpp"

namespace hilrig::far {

class PolledInput final : public LineInput {
public:
  // Reads the line's level now: that is the level before the first edge.
  PolledInput(Scheduler& scheduler, const std::string& chip_dir, unsigned offset);

  [[nodiscard]] Level level() const override { return level_; }
  void on_edge(EdgeHandler handler) override { handlers_.push_back(std::move(handler)); }

  // Reads the line; a level other than the last one read is an edge at t (not before the
  // scheduler's now). Returns true when it found one.
  bool poll(Nanos t);
  [[nodiscard]] std::uint64_t edges() const { return edges_; }

private:
  Scheduler& scheduler_;
  gpiosim::SimLineReader line_;
  Level level_;     // what the model sees (changes when the edge's event runs)
  Level last_read_; // what the last poll read
  std::vector<EdgeHandler> handlers_;
  std::uint64_t edges_ = 0;
};

class PullOutput final : public LineOutput {
public:
  // Pulls the line down: an output is off until the model drives it.
  PullOutput(const std::string& chip_dir, unsigned offset);

  void set(Level level) override;
  [[nodiscard]] Level driven() const override { return level_; }
  [[nodiscard]] std::uint64_t edges() const { return edges_; }

private:
  gpiosim::SimLinePull line_;
  Level level_ = Level::Low;
  std::uint64_t edges_ = 0;
};

// One board pin on one gpio-sim line.
class FarLine {
public:
  FarLine(Scheduler& scheduler, std::string chip_dir, std::string pin, unsigned offset);

  // The pin as a board input (the rig drives it). Throws std::invalid_argument when the
  // model already took it as an output.
  LineInput& reader();
  // The pin as a board output. Throws std::invalid_argument when taken as an input.
  LineOutput& driver();

  [[nodiscard]] const std::string& pin() const { return pin_; }
  [[nodiscard]] unsigned offset() const { return offset_; }
  [[nodiscard]] bool claimed() const { return input_ != nullptr || output_ != nullptr; }
  [[nodiscard]] PolledInput* input() { return input_.get(); }
  [[nodiscard]] const PolledInput* input() const { return input_.get(); }
  [[nodiscard]] const PullOutput* output() const { return output_.get(); }

private:
  Scheduler& scheduler_;
  std::string chip_dir_;
  std::string pin_;
  unsigned offset_;
  std::unique_ptr<PolledInput> input_;
  std::unique_ptr<PullOutput> output_;
};

} // namespace hilrig::far
