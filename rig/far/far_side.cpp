#include "rig/far/far_side.hpp"

#include <stdexcept>

#include <fmt/format.h>

namespace hilrig::far {

FarSide::FarSide(Scheduler& scheduler, const FarConfig& config, std::string chip_dir, CanPort* resolver_port)
    : scheduler_(scheduler), config_(config), chip_dir_(std::move(chip_dir)) {
  if (!config_.pins.empty() && chip_dir_.empty())
    throw std::invalid_argument(config_.file +
                                ": [[pin]] entries need a gpio-sim chip directory (--gpio-sim)");
  for (const FarPin& p : config_.pins) {
    lines_.push_back(std::make_unique<FarLine>(scheduler_, chip_dir_, p.board, p.offset));
    pin_map_.emplace(p.board, p.board);
  }
  if (config_.resolver) {
    if (resolver_port == nullptr)
      throw std::invalid_argument(config_.file + ": [resolver] needs a CAN interface for its node (--can)");
    const FarResolver& r = *config_.resolver;
    models::resolver_emulator::ResolverEmulatorParams p;
    p.channel = r.channel;
    p.excitation_hz = r.excitation_hz;
    p.excitation_amplitude = r.amplitude;
    p.transformation_ratio = r.ratio;
    p.frame_period = r.frame_period;
    p.timeout_periods = r.timeout_periods;
    node_ = std::make_unique<models::resolver_emulator::ResolverEmulator>(scheduler_, *resolver_port, p);
    sin_ = std::make_unique<WaveformInput>(node_->sin_waveform());
    cos_ = std::make_unique<WaveformInput>(node_->cos_waveform());
    pin_map_.emplace(r.sin_pin, r.sin_pin);
    pin_map_.emplace(r.cos_pin, r.cos_pin);
  }
}

FarSide::~FarSide() = default;

FarLine& FarSide::line(std::string_view pin) {
  for (const auto& l : lines_)
    if (l->pin() == pin) return *l;
  throw std::invalid_argument(fmt::format("far side: {} has no [[pin]] board = \"{}\"", config_.file, pin));
}

AnalogInput& FarSide::analog(std::string_view pin) {
  if (config_.resolver && pin == config_.resolver->sin_pin) return *sin_;
  if (config_.resolver && pin == config_.resolver->cos_pin) return *cos_;
  throw std::invalid_argument(fmt::format("far side: {} does not feed analog pin {}", config_.file, pin));
}

void FarSide::check_all_taken(std::string_view device) const {
  for (std::size_t i = 0; i < lines_.size(); ++i)
    if (!lines_[i]->claimed())
      throw campaign::CampaignError(config_.file, config_.pins[i].where, fmt::format("pin[{}].board", i),
                                    fmt::format("a pin of {} ({} is not one)", device, lines_[i]->pin()));
}

void FarSide::poll(Nanos t) {
  ++polls_;
  for (const auto& l : lines_)
    if (PolledInput* in = l->input()) (void)in->poll(t);
}

FarSideCounters FarSide::counters() const {
  FarSideCounters c;
  c.polls = polls_;
  for (const auto& l : lines_) {
    if (l->input() != nullptr) c.input_edges += l->input()->edges();
    if (l->output() != nullptr) c.output_edges += l->output()->edges();
  }
  return c;
}

std::string FarSide::describe() const {
  std::string s;
  std::size_t ins = 0;
  std::size_t outs = 0;
  for (const auto& l : lines_) {
    if (l->input() != nullptr) ++ins;
    if (l->output() != nullptr) ++outs;
  }
  if (!lines_.empty()) s = fmt::format("{} input and {} output pin(s) on gpio-sim {}", ins, outs, chip_dir_);
  if (config_.resolver) {
    const FarResolver& r = *config_.resolver;
    s += fmt::format("{}resolver node channel {} feeding {}/{}", s.empty() ? "" : "; ", r.channel, r.sin_pin,
                     r.cos_pin);
  }
  return s;
}

} // namespace hilrig::far
