#include "rig/hardware/rig_config.hpp"

#include <array>
#include <charconv>
#include <fstream>
#include <span>
#include <sstream>

#include <fmt/format.h>
#include <toml++/toml.h>

#include "drivers/gpiod/input_request.hpp"
#include "rig/campaign/toml_file.hpp"
#include "rig/campaign/toml_reader.hpp"

namespace hilrig::hardware {

namespace {

using campaign::CampaignError;
using campaign::TableReader;

// "8E1": data bits, parity (N/E/O), stop bits.
std::optional<SerialFormat> parse_format(std::string_view text, std::uint32_t baud) {
  if (text.size() != 3) return std::nullopt;
  SerialFormat f;
  f.baud = baud;
  if (text[0] < '5' || text[0] > '8') return std::nullopt;
  f.data_bits = static_cast<std::uint8_t>(text[0] - '0');
  switch (text[1]) {
  case 'N':
    f.parity = Parity::None;
    break;
  case 'E':
    f.parity = Parity::Even;
    break;
  case 'O':
    f.parity = Parity::Odd;
    break;
  default:
    return std::nullopt;
  }
  if (text[2] != '1' && text[2] != '2') return std::nullopt;
  f.stop_bits = static_cast<std::uint8_t>(text[2] - '0');
  return f;
}

class Reader {
public:
  Reader(const std::string& file, const toml::table& root) : file_(file), root_(file, root, "") {}

  RigConfig read() {
    RigConfig c;
    c.file = file_;
    read_rt(c.rt);
    read_gpio(c);
    read_can(c);
    read_host(c.host);
    root_.finish();
    return c;
  }

private:
  void read_rt(RtConfig& rt) {
    const toml::table* t = root_.opt_table("rt");
    if (t == nullptr) return;
    TableReader r(file_, *t, "rt");
    read_priority(r, "priority", rt.priority);
    read_cpu(r, "cpu", rt.cpu);
    read_priority(r, "resolver_priority", rt.resolver_priority);
    read_cpu(r, "resolver_cpu", rt.resolver_cpu);
    if (auto d = r.opt_duration("edge_tolerance")) {
      if (*d <= Nanos{0}) r.fail("edge_tolerance", "a duration > 0");
      rt.edge_tolerance = *d;
    }
    r.finish();
  }

  static void read_priority(TableReader& r, std::string_view key, int& priority) {
    if (auto p = r.opt_integer(key)) {
      if (*p < 0 || *p > 99) r.fail(key, "a SCHED_FIFO priority in 1..99 (0: not real-time)");
      priority = static_cast<int>(*p);
    }
  }

  static void read_cpu(TableReader& r, std::string_view key, std::optional<int>& cpu) {
    if (auto c = r.opt_integer(key)) {
      if (*c < -1 || *c > 4095) r.fail(key, "a CPU number >= 0, or -1 for not pinned");
      if (*c >= 0) cpu = static_cast<int>(*c);
    }
  }

  template <typename E>
  E choice(TableReader& r, std::string_view key, E fallback,
           std::initializer_list<std::pair<const char*, E>> names) {
    const auto text = r.opt_string(key);
    if (!text) return fallback;
    std::string expected;
    for (const auto& [name, value] : names) {
      if (*text == name) return value;
      expected += fmt::format("{}\"{}\"", expected.empty() ? "" : ", ", name);
    }
    r.fail(key, "one of " + expected);
  }

  void read_gpio(RigConfig& c) {
    const toml::table* t = root_.opt_table("gpio");
    if (t == nullptr) return;
    TableReader r(file_, *t, "gpio");
    c.gpio_chip = r.opt_string("chip").value_or("");
    if (r.has("chip") && c.gpio_chip.empty()) r.fail("chip", "a chip: a /dev path, name or label");
    std::size_t i = 0;
    for (const toml::table* lt : r.tables("line")) {
      TableReader l(file_, *lt, fmt::format("gpio.line[{}]", i++));
      GpioLine g;
      g.where = l.where();
      g.rig = l.string("rig");
      if (g.rig.empty()) l.fail("rig", "a rig line name, as the campaign's [[wiring]] rig keys use");
      const std::int64_t offset = l.integer("offset");
      if (offset < 0 || offset > 65535) l.fail("offset", "a line offset on its chip, >= 0");
      g.offset = static_cast<unsigned>(offset);
      g.chip = l.opt_string("chip").value_or(c.gpio_chip);
      if (g.chip.empty())
        l.fail(l.has("chip") ? "chip" : "rig", l.has("chip")
                                                   ? "a chip: a /dev path, name or label"
                                                   : "a chip: give chip here or a default in [gpio] chip");
      g.settings.active_low = l.opt_boolean("active_low").value_or(false);
      g.settings.bias = choice(l, "bias", gpiod::Bias::AsIs,
                               {{"as-is", gpiod::Bias::AsIs},
                                {"disabled", gpiod::Bias::Disabled},
                                {"pull-up", gpiod::Bias::PullUp},
                                {"pull-down", gpiod::Bias::PullDown}});
      g.settings.drive = choice(l, "drive", gpiod::Drive::PushPull,
                                {{"push-pull", gpiod::Drive::PushPull},
                                 {"open-drain", gpiod::Drive::OpenDrain},
                                 {"open-source", gpiod::Drive::OpenSource}});
      if (auto d = l.opt_duration("debounce")) {
        if (*d < Nanos{0}) l.fail("debounce", "a duration >= 0");
        if (*d > Nanos{0} && !gpiod::supports_debounce())
          l.fail("debounce", "\"0us\": this build's libgpiod (1.6) cannot set a debounce period");
        if (*d > Nanos{0}) g.settings.debounce = *d;
      }
      for (const GpioLine& other : c.lines) {
        if (other.rig == g.rig)
          l.fail("rig",
                 fmt::format("each rig line once; \"{}\" is already at line {}", g.rig, other.where.line));
        if (other.chip == g.chip && other.offset == g.offset)
          l.fail("offset", fmt::format("each GPIO line once; {} line {} is already \"{}\"", g.chip, g.offset,
                                       other.rig));
      }
      l.finish();
      c.lines.push_back(std::move(g));
    }
    r.finish();
  }

  void read_can(RigConfig& c) {
    const toml::table* t = root_.opt_table("can");
    if (t == nullptr) return;
    TableReader r(file_, *t, "can");
    c.can_where = r.where();
    if (auto iface = r.opt_string("resolver")) {
      if (iface->empty() || iface->size() >= 16)
        r.fail("resolver", "a CAN interface name (e.g. \"can0\"), at most 15 characters");
      c.can_resolver = *iface;
    }
    r.finish();
  }

  void read_host(HostConfig& h) {
    const toml::table* t = root_.opt_table("host");
    if (t == nullptr) return;
    TableReader r(file_, *t, "host");
    h.where = r.where();
    const std::string link = r.string("link");
    if (link == "modbus-rtu")
      h.link = HostLink::ModbusRtu;
    else if (link == "modbus-tcp")
      h.link = HostLink::ModbusTcp;
    else
      r.fail("link", "\"modbus-rtu\" or \"modbus-tcp\"");
    const bool rtu = h.link == HostLink::ModbusRtu;
    // Keys of the other link are mistakes, not defaults.
    static constexpr std::array<const char*, 3> kRtuKeys{"port", "baud", "format"};
    static constexpr std::array<const char*, 1> kTcpKeys{"address"};
    for (const char* key :
         rtu ? std::span<const char* const>(kTcpKeys) : std::span<const char* const>(kRtuKeys))
      if (r.has(key)) r.fail(key, fmt::format("not a key of link = \"{}\"", link));
    if (rtu) {
      h.port = r.string("port");
      if (h.port.empty()) r.fail("port", "a serial device");
      const std::int64_t baud = r.opt_integer("baud").value_or(19200);
      if (baud < 50 || baud > 4'000'000) r.fail("baud", "a baud rate in 50..4000000");
      const std::string format = r.opt_string("format").value_or("8E1");
      const auto f = parse_format(format, static_cast<std::uint32_t>(baud));
      if (!f) r.fail("format", "data bits, parity and stop bits, like \"8E1\" or \"8N2\"");
      h.format = *f;
    } else {
      const std::string address = r.string("address");
      const auto colon = address.rfind(':');
      int port = 0;
      const char* b = address.data();
      const auto [end, ec] = colon == std::string::npos
                                 ? std::from_chars_result{b, std::errc::invalid_argument}
                                 : std::from_chars(b + colon + 1, b + address.size(), port);
      if (colon == std::string::npos || colon == 0 || ec != std::errc{} || end != b + address.size() ||
          port < 1 || port > 65535)
        r.fail("address", "host:port, like \"127.0.0.1:1502\"");
      h.host = address.substr(0, colon);
      h.tcp_port = port;
    }
    const std::int64_t unit = r.opt_integer("unit").value_or(1);
    if (unit < (rtu ? 1 : 0) || unit > (rtu ? 247 : 255))
      r.fail("unit", rtu ? "a Modbus RTU address in 1..247" : "a Modbus TCP unit id in 0..255");
    h.unit = static_cast<int>(unit);
    if (auto d = r.opt_duration("timeout")) {
      if (*d <= Nanos{0}) r.fail("timeout", "a duration > 0");
      h.timeout = *d;
    }
    r.finish();
  }

  const std::string& file_;
  TableReader root_;
};

} // namespace

const GpioLine* RigConfig::line_for(std::string_view rig) const {
  for (const GpioLine& l : lines)
    if (l.rig == rig) return &l;
  return nullptr;
}

RigConfig parse_rig_config(std::string_view text, const std::string& file_name) {
  const toml::table root = campaign::parse_toml(text, file_name);
  // A campaign given as --rig by mistake is named as one, not by the first of its tables that a
  // rig config has otherwise ([[host]] actions where a rig's [host] link would be).
  if (const toml::node* c = root.get("campaign"))
    throw CampaignError(file_name, campaign::pos_of(*c), "campaign",
                        "a campaign file's table, in a file read as a rig config: --rig takes the rig "
                        "config (docs/rig-config.md), the campaign is the file given before it");
  return Reader(file_name, root).read();
}

RigConfig load_rig_config(const std::string& path) {
  return parse_rig_config(campaign::read_toml_text(path, "rig config file"), path);
}

} // namespace hilrig::hardware
