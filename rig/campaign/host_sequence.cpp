#include "rig/campaign/host_sequence.hpp"

#include <algorithm>
#include <optional>
#include <string>

#include <fmt/format.h>

#include "rig/checks/support.hpp"

namespace hilrig::campaign {

HostSequence::HostSequence(Scheduler& scheduler, const Scenario& scenario, const duts::HostInterface& host,
                           HostWords& words)
    : sched_(scheduler), s_(scenario), host_(host), words_(words) {}

void HostSequence::start() {
  if (!s_.host.empty()) sched_.at(s_.host.front().at, [this] { step(); });
}

void HostSequence::step() {
  const HostAction& h = s_.host[next_];
  if (h.kind == HostAction::Kind::Read) {
    read(h);
    done();
    return;
  }
  for (std::size_t w = h.words.size(); w-- > 1;) words_.write(w, h.words[w]);
  words_.write(0, h.words[0]);
  if (!host_.handshake || h.raw) {
    done();
    return;
  }
  write_started_ = sched_.now();
  words_.write(0, static_cast<std::uint16_t>(h.words[0] | (1U << host_.transmit_bit)));
  sched_.after(s_.host_poll, [this] { poll_ack(true); });
}

bool HostSequence::ack() {
  return ((static_cast<unsigned>(words_.read(0)) >> host_.acknowledge_bit) & 1U) != 0U;
}

void HostSequence::read(const HostAction& h) {
  const std::uint16_t raw = words_.read(h.word);
  const double value =
      h.is_signed ? static_cast<double>(static_cast<std::int16_t>(raw)) : static_cast<double>(raw);
  observations_.push_back(rig::Observation{h.name, value, h.unit, sched_.now(), h.at});
}

void HostSequence::poll_ack(bool want) {
  const HostAction& h = s_.host[next_];
  const Nanos waited = sched_.now() - write_started_;
  const std::string name =
      fmt::format("host.{}.ack", h.name.empty() ? fmt::format("write{}", next_) : h.name);
  if (ack() == want) {
    if (want) {
      handshakes_.push_back(checks::measure(name, checks::to_us(waited), "us", std::nullopt,
                                            checks::to_us(h.timeout),
                                            fmt::format("Acknowledge {} after Transmit (polled every {} us)",
                                                        "set", checks::to_us(s_.host_poll)),
                                            rig::TraceWindow{write_started_, sched_.now()}));
      for (std::size_t k = next_ + 1; k < s_.host.size() && s_.host[k].while_acknowledged; ++k)
        read(s_.host[k]);
      words_.write(0, h.words[0]);
      write_started_ = sched_.now();
      sched_.after(s_.host_poll, [this] { poll_ack(false); });
    } else {
      done();
    }
    return;
  }
  if (waited >= h.timeout) {
    handshakes_.push_back(
        checks::failure(want ? name : name + "_clear",
                        fmt::format("no Acknowledge {} within {} us of {} Transmit", want ? "set" : "clear",
                                    checks::to_us(h.timeout), want ? "setting" : "clearing"),
                        rig::TraceWindow{write_started_, sched_.now()}));
    if (want) words_.write(0, h.words[0]);
    done();
    return;
  }
  sched_.after(s_.host_poll, [this, want] { poll_ack(want); });
}

// Reads while Acknowledge was set belong to their write's handshake: done with it (or lost
// with it when Acknowledge never came).
void HostSequence::done() {
  ++next_;
  while (next_ < s_.host.size() && s_.host[next_].while_acknowledged) ++next_;
  if (next_ >= s_.host.size()) return;
  const Nanos at = std::max(sched_.now(), s_.host[next_].at);
  if (at > s_.end) return;
  sched_.at(at, [this] { step(); });
}

} // namespace hilrig::campaign
