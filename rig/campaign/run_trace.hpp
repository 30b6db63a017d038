#pragma once
// What a run's trace carries besides the lines, so a person can see a failure in GTKWave or
// PulseView: the shaft (count and position within the turn, integers), the resolver stators
// as the board reads them (reals), and the host's words (each written and read word, and
// the Transmit / Acknowledge handshake bits as wires). Names, as the VCD shows them:
//   shaft.count, shaft.position          integer, counts (position: 0 .. counts per turn - 1)
//   resolver.sin, resolver.cos            real, volts at each excitation peak
//   host.out<k>, host.in<k>               integer, 16 bits, at each write / each read that changed
//   host.transmit, host.acknowledge       wire, the handshake bits of out0 / in0
// Recording only: nothing here changes what the board sees.

#include <cstdint>
#include <memory>
#include <string_view>
#include <vector>

#include "core/analog.hpp"
#include "core/scheduler.hpp"
#include "core/trace.hpp"
#include "rig/campaign/campaign.hpp"
#include "rig/campaign/host_sequence.hpp"
#include "rig/duts/dut.hpp"

namespace hilrig::campaign {

// The stators' names in the trace.
inline constexpr std::string_view kStatorSin = "resolver.sin";
inline constexpr std::string_view kStatorCos = "resolver.cos";

// The shaft's count as the rig's encoder plays it.
class ShaftTrace {
public:
  ShaftTrace(TraceRecorder& trace, double counts_per_turn, std::int64_t initial_count);
  void count(Nanos t, std::int64_t count);

private:
  [[nodiscard]] std::int64_t position_of(std::int64_t count) const;

  TraceRecorder& trace_;
  std::int64_t per_turn_;
  std::uint32_t count_signal_;
  std::uint32_t position_signal_;
};

// Samples both stators at every peak of the excitation (amplitude * sin(2 pi f t + phase)),
// from time 0 to `end`: there a stator carries ratio * amplitude * sin or cos of the angle.
// The sampler: keep it while the scheduler may run its events (null when nothing is sampled).
[[nodiscard]] std::shared_ptr<void> trace_stators(Scheduler& scheduler, TraceRecorder& trace,
                                                  const ResolverSpec& resolver, Waveform sin, Waveform cos,
                                                  Nanos end);

// The host's words as they pass, around the words the host sequence uses.
class TracedHostWords final : public HostWords {
public:
  TracedHostWords(HostWords& words, const Scheduler& scheduler, TraceRecorder& trace,
                  const duts::HostInterface& host, const std::vector<HostAction>& actions);
  void write(std::size_t word, std::uint16_t value) override;
  std::uint16_t read(std::size_t word) override;

private:
  struct Word {
    std::uint32_t signal = 0;
    bool declared = false;
    bool seen = false; // traced at least once
    std::uint16_t last = 0;
  };
  Word& word_signal(std::vector<Word>& words, const char* direction, std::size_t k);
  void note(Word& w, std::uint16_t value, std::optional<std::uint32_t> bit_signal, unsigned bit);

  HostWords& words_;
  const Scheduler& sched_;
  TraceRecorder& trace_;
  duts::HostInterface host_;
  std::vector<Word> out_, in_;
  std::optional<std::uint32_t> transmit_, acknowledge_;
};

} // namespace hilrig::campaign
