#include "rig/far/far_lines.hpp"

#include <algorithm>
#include <stdexcept>

namespace hilrig::far {

PolledInput::PolledInput(Scheduler& scheduler, const std::string& chip_dir, unsigned offset)
    : scheduler_(scheduler), line_(chip_dir, offset), level_(line_.read()), last_read_(level_) {}

bool PolledInput::poll(Nanos t) {
  const Level now_read = line_.read();
  if (now_read == last_read_) return false;
  last_read_ = now_read;
  ++edges_;
  const Edge edge{std::max(t, scheduler_.now()), now_read};
  // The model's clock is behind t until the tick runs it forward: the edge waits for it.
  scheduler_.at(edge.time, [this, edge] {
    level_ = edge.level;
    for (const EdgeHandler& h : handlers_) h(edge);
  });
  return true;
}

PullOutput::PullOutput(const std::string& chip_dir, unsigned offset) : line_(chip_dir, offset) {
  line_.pull(Level::Low);
}

void PullOutput::set(Level level) {
  if (level == level_) return;
  line_.pull(level);
  level_ = level;
  ++edges_;
}

FarLine::FarLine(Scheduler& scheduler, std::string chip_dir, std::string pin, unsigned offset)
    : scheduler_(scheduler), chip_dir_(std::move(chip_dir)), pin_(std::move(pin)), offset_(offset) {}

LineInput& FarLine::reader() {
  if (output_)
    throw std::invalid_argument("far side: pin " + pin_ + " is an output of the board, not an input");
  if (!input_) input_ = std::make_unique<PolledInput>(scheduler_, chip_dir_, offset_);
  return *input_;
}

LineOutput& FarLine::driver() {
  if (input_)
    throw std::invalid_argument("far side: pin " + pin_ + " is an input of the board, not an output");
  if (!output_) output_ = std::make_unique<PullOutput>(chip_dir_, offset_);
  return *output_;
}

} // namespace hilrig::far
