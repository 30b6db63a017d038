#include "signals/ssi_slave.hpp"

#include <cmath>
#include <stdexcept>
#include <utility>

namespace hilrig::signals {

SsiSlave::SsiSlave(SsiSlaveParams params, ValueSource source) : params_(params), source_(std::move(source)) {
  params_.format.validate();
  if (params_.monoflop < Nanos{0}) throw std::invalid_argument("SSI monoflop must be >= 0");
  if (params_.output_delay < Nanos{0}) throw std::invalid_argument("SSI output_delay must be >= 0");
  if (!source_) throw std::invalid_argument("SSI slave needs a value source");
}

std::optional<Edge> SsiSlave::set_faults(const SsiSlaveFaults& faults, Nanos now) {
  if (faults.late_response < Nanos{0}) throw std::invalid_argument("SSI late_response must be >= 0");
  if (faults.flip_stream_bit > params_.format.frame_bits)
    throw std::invalid_argument("SSI flip_stream_bit outside the frame");
  faults_ = faults;
  if (faults_.stuck != SsiStuck::None) {
    const Level stuck = faults_.stuck == SsiStuck::High ? Level::High : Level::Low;
    if (stuck != driven_) {
      driven_ = stuck;
      return Edge{now, stuck};
    }
  }
  return std::nullopt;
}

void SsiSlave::emit(SsiDataEdges& out, Nanos t, Level level) {
  if (faults_.stuck == SsiStuck::High) level = Level::High;
  if (faults_.stuck == SsiStuck::Low) level = Level::Low;
  if (level == driven_) return;
  driven_ = level;
  out.edges[out.count++] = Edge{t, level};
}

void SsiSlave::latch(Nanos t) {
  if (params_.latch == SsiLatch::PreviousFrameEnd && have_next_) {
    word_ = next_word_;
  } else {
    word_ = compose_frame(params_.format, source_(t), status_);
  }
  if (faults_.gray_glitch_mask != 0) {
    // The glitch hits the coded field (as the encoder's tracks are read), so with Gray code
    // one flipped track bit corrupts every binary bit below it after decoding.
    const SsiFrameFormat& f = params_.format;
    const unsigned shift = f.frame_bits - (f.data_msb - 1) - f.data_bits;
    const std::uint64_t mask = (static_cast<std::uint64_t>(faults_.gray_glitch_mask) &
                                ((f.data_bits >= 32) ? 0xFFFF'FFFFull : ((1ull << f.data_bits) - 1)))
                               << shift;
    word_ ^= static_cast<std::uint32_t>(mask);
  }
}

Level SsiSlave::wire_bit(unsigned k) const {
  const SsiFrameFormat& f = params_.format;
  if (k > f.frame_bits) return Level::Low; // extra clocks: standard SSI sends 0 [MODEL]
  bool bit = stream_bit(word_, f.frame_bits, k);
  if (faults_.flip_stream_bit == k) bit = !bit;
  return level_of(bit);
}

std::optional<Edge> SsiSlave::advance_to(Nanos t) {
  if (!busy_ || t < expiry_) return std::nullopt;
  busy_ = false;
  const Nanos at = expiry_;
  expiry_ = Nanos::max();
  if (params_.latch == SsiLatch::PreviousFrameEnd) {
    next_word_ = compose_frame(params_.format, source_(at), status_);
    have_next_ = true;
  }
  SsiDataEdges out;
  emit(out, at, Level::High);
  if (out.count == 0) return std::nullopt;
  return out.edges[0];
}

SsiDataEdges SsiSlave::on_clock(const Edge& clock) {
  SsiDataEdges out;
  if (auto idle = advance_to(clock.time)) out.edges[out.count++] = *idle;
  const Nanos at = clock.time + delay();
  if (!busy_) {
    // Only a falling edge starts a frame; a rising edge while idle is ignored.
    if (clock.level != Level::Low) return out;
    busy_ = true;
    bits_sent_ = 0;
    ++frames_;
    latch(clock.time);
    if (params_.low_on_latch) emit(out, at, Level::Low);
  } else if (clock.level == Level::High) {
    ++bits_sent_;
    emit(out, at, wire_bit(bits_sent_));
  }
  expiry_ = clock.time + params_.monoflop; // every clock edge retriggers the monoflop
  return out;
}

Nanos SsiSlave::deadline() const { return busy_ ? expiry_ : Nanos::max(); }

std::vector<Edge> respond(SsiSlave& slave, std::span<const Edge> clock, Nanos until) {
  std::vector<Edge> data;
  data.reserve(clock.size() + 8);
  for (const Edge& e : clock) {
    const SsiDataEdges out = slave.on_clock(e);
    for (const Edge& d : out.view()) data.push_back(d);
  }
  if (auto idle = slave.advance_to(until)) data.push_back(*idle);
  return data;
}

SsiSlave::ValueSource counts_from_turns(std::function<double(Nanos)> turns, std::uint32_t counts_per_turn) {
  if (!turns || counts_per_turn == 0) throw std::invalid_argument("counts_from_turns needs a trajectory");
  return [turns = std::move(turns), counts_per_turn](Nanos t) {
    const double x = turns(t);
    const double frac = x - std::floor(x);
    auto c = static_cast<std::uint64_t>(std::floor(frac * static_cast<double>(counts_per_turn)));
    return static_cast<std::uint32_t>(c % counts_per_turn);
  };
}

} // namespace hilrig::signals
