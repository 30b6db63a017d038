// The real rig's ports: libgpiod requests, the Modbus host link and the SocketCAN resolver
// interface, opened from the rig config for one run.
#include "rig/hardware/rig_ports.hpp"

#include <cstring>
#include <ctime>
#include <optional>

#include <fmt/format.h>

#include "drivers/gpiod/input_request.hpp"
#include "drivers/gpiod/output_request.hpp"
#include "drivers/hostlink/modbus_client.hpp"
#include "drivers/socketcan/can_socket.hpp"
#include "rig/hardware/host_words.hpp"

namespace hilrig::hardware {

namespace {

Nanos clock_now(clockid_t clock) {
  timespec ts{};
  clock_gettime(clock, &ts);
  return Nanos{static_cast<std::int64_t>(ts.tv_sec) * 1'000'000'000 + ts.tv_nsec};
}

bool same_settings(const gpiod::LineSettings& a, const gpiod::LineSettings& b) {
  return a.active_low == b.active_low && a.bias == b.bias && a.drive == b.drive && a.debounce == b.debounce;
}

// Lines that share a chip and settings go in one request: one ioctl moves them together.
struct Group {
  std::string chip;
  gpiod::LineSettings settings;
  std::vector<unsigned> offsets;
  std::vector<std::uint16_t> plan_index; // the DrivePlan index of each offset
};

std::vector<Group> group_lines(const std::vector<PlannedLine>& lines,
                               std::vector<std::pair<std::size_t, std::size_t>>* where) {
  std::vector<Group> groups;
  for (std::size_t i = 0; i < lines.size(); ++i) {
    const GpioLine& g = *lines[i].gpio;
    std::size_t k = 0;
    while (k < groups.size() && !(groups[k].chip == g.chip && same_settings(groups[k].settings, g.settings)))
      ++k;
    if (k == groups.size()) groups.push_back(Group{g.chip, g.settings, {}, {}});
    if (where != nullptr) where->emplace_back(k, groups[k].offsets.size());
    groups[k].offsets.push_back(g.offset);
    groups[k].plan_index.push_back(static_cast<std::uint16_t>(i));
  }
  return groups;
}

class GpiodOutputs final : public RtOutputPort {
public:
  explicit GpiodOutputs(const std::vector<PlannedLine>& lines) {
    for (Group& g : group_lines(lines, &where_)) {
      requests_.push_back(std::make_unique<gpiod::OutputRequest>(g.chip, g.offsets, g.settings));
      levels_.emplace_back(g.offsets.size(), Level::Low);
    }
    // Requested inactive; each line goes to its initial level before the run starts.
    for (std::size_t i = 0; i < lines.size(); ++i)
      levels_[where_[i].first][where_[i].second] = lines[i].initial;
    for (std::size_t k = 0; k < requests_.size(); ++k) requests_[k]->write_all(levels_[k]);
  }

  // The whole request is written each time: with the v1 ABI a handle sets all its lines at
  // once, so the others keep their levels only if they are written too. No allocation.
  void write(std::uint16_t line, Level level) noexcept override {
    if (line >= where_.size()) return;
    const auto [k, i] = where_[line];
    levels_[k][i] = level;
    requests_[k]->write_all(levels_[k]);
  }

  [[nodiscard]] std::uint64_t write_errors() const {
    std::uint64_t n = 0;
    for (const auto& r : requests_) n += r->write_errors();
    return n;
  }

private:
  std::vector<std::pair<std::size_t, std::size_t>> where_; // plan index -> (request, line in it)
  std::vector<std::unique_ptr<gpiod::OutputRequest>> requests_;
  std::vector<std::vector<Level>> levels_;
};

class GpiodInputs final : public RtInputPort {
public:
  explicit GpiodInputs(const std::vector<PlannedLine>& lines) {
    for (Group& g : group_lines(lines, &where_)) {
      requests_.push_back(std::make_unique<gpiod::InputRequest>(g.chip, g.offsets, g.settings));
      plan_index_.push_back(std::move(g.plan_index));
    }
  }

  // Kernels before 5.7 stamp v1 line events with CLOCK_REALTIME, later ones with
  // CLOCK_MONOTONIC: a stamp past 2^60 ns (36 years of uptime) is a real-time one.
  void begin() { realtime_minus_monotonic_ = clock_now(CLOCK_REALTIME) - clock_now(CLOCK_MONOTONIC); }

  std::size_t poll(std::span<InputEdge> out) noexcept override {
    std::size_t n = 0;
    for (std::size_t k = 0; k < requests_.size() && n < out.size(); ++k) {
      const std::size_t got = requests_[k]->poll(out.subspan(n));
      for (std::size_t j = n; j < n + got; ++j) {
        out[j].line = plan_index_[k][out[j].line];
        if (out[j].time.count() > (std::int64_t{1} << 60)) out[j].time -= realtime_minus_monotonic_;
      }
      n += got;
    }
    return n;
  }

  [[nodiscard]] Level level(std::size_t plan_index) const {
    const auto [k, i] = where_.at(plan_index);
    return requests_[k]->level(i);
  }

private:
  std::vector<std::pair<std::size_t, std::size_t>> where_;
  std::vector<std::unique_ptr<gpiod::InputRequest>> requests_;
  std::vector<std::vector<std::uint16_t>> plan_index_;
  Nanos realtime_minus_monotonic_{0};
};

class SocketCanResolver final : public ResolverCan {
public:
  // The stream only sends: the socket takes error frames alone, so other nodes' traffic
  // cannot fill its queue.
  explicit SocketCanResolver(const std::string& interface)
      : socket_(interface, errors_only()), bus_(interface) {}

  std::string send(const CanFrame& frame) override {
    // A frame that cannot be queued within a millisecond means nobody takes them off the bus.
    switch (socket_.send(frame, clock_now(CLOCK_MONOTONIC) + Nanos{1'000'000})) {
    case socketcan::SendStatus::Sent:
      return {};
    case socketcan::SendStatus::BusOff:
      return fmt::format("CAN {}: the interface is down or bus-off (ENETDOWN)", bus_);
    case socketcan::SendStatus::DeadlineMissed:
      return fmt::format("CAN {}: transmit queue full for 1 ms (no node acknowledging the resolver frames?)",
                         bus_);
    case socketcan::SendStatus::Failed:
      break;
    }
    return fmt::format("CAN {}: send failed: {}", bus_, std::strerror(socket_.last_errno()));
  }

  std::string check() override {
    while (const auto r = socket_.receive(Nanos{0})) {
      if (!r->is_error) continue;
      tracker_.apply(r->error);
      if (tracker_.state() == socketcan::BusState::BusOff)
        return fmt::format("CAN {}: bus-off ({})", bus_, r->error.describe());
    }
    return {};
  }

  const std::string& bus() const override { return bus_; }

  CanOverruns overruns() const override {
    return CanOverruns{tracker_.rx_overflow_count(), tracker_.tx_overflow_count(), socket_.rx_queue_drops()};
  }

private:
  static socketcan::CanSocketOptions errors_only() {
    socketcan::CanSocketOptions o;
    o.data_frames = false;
    return o;
  }

  socketcan::CanSocket socket_;
  socketcan::BusStateTracker tracker_;
  std::string bus_;
};

class HardwarePorts final : public RigPorts {
public:
  HardwarePorts(const RigConfig& config, const DrivePlan& plan, const campaign::Scenario& s)
      : outputs_(plan.outputs) {
    if (!plan.inputs.empty()) inputs_ = std::make_unique<GpiodInputs>(plan.inputs);
    if (plan.resolver) can_ = std::make_unique<SocketCanResolver>(config.can_resolver);
    if (plan.host) {
      const HostConfig& h = config.host;
      if (h.link == HostLink::ModbusRtu)
        link_ = hostlink::ModbusClient::rtu(hostlink::RtuSettings{h.port, h.format, h.unit, h.timeout});
      else
        link_ = hostlink::ModbusClient::tcp(hostlink::TcpSettings{h.host, h.tcp_port, h.unit, h.timeout});
      words_ = std::make_unique<ModbusHostWords>(*link_, *host_words_of(s.dut.model));
    }
  }

  RtOutputPort& outputs() override { return outputs_; }
  RtInputPort* inputs() override { return inputs_.get(); }
  campaign::HostWords* host() override { return words_.get(); }
  ResolverCan* resolver() override { return can_.get(); }
  std::optional<Level> input_level(std::size_t i) override {
    if (!inputs_) return std::nullopt;
    return inputs_->level(i);
  }
  void begin(Nanos /*start*/) override {
    if (inputs_) inputs_->begin();
  }

private:
  GpiodOutputs outputs_;
  std::unique_ptr<GpiodInputs> inputs_;
  std::unique_ptr<SocketCanResolver> can_;
  std::unique_ptr<hostlink::ModbusClient> link_;
  std::unique_ptr<ModbusHostWords> words_;
};

} // namespace

std::unique_ptr<RigPorts> open_rig_ports(const RigConfig& config, const DrivePlan& plan,
                                         const campaign::Scenario& scenario) {
  return std::make_unique<HardwarePorts>(config, plan, scenario);
}

} // namespace hilrig::hardware
