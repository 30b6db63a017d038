// The rig config (docs/rig-config.md): a good file gives every value as written, and each
// bad key is refused at its own line and column. Line numbers are counted by hand in each
// case's text (line 1 is the first line of the raw string).

#include <gtest/gtest.h>

#include <string>

#include "rig/hardware/rig_config.hpp"

namespace hilrig::hardware {
namespace {

using campaign::CampaignError;

// 19 lines.
const std::string kGood = R"([rt]
priority = 70
cpu = 1
edge_tolerance = "40us"
[gpio]
chip = "gpiochip0"
[[gpio.line]]
rig = "enc.A"
offset = 0
[[gpio.line]]
rig = "ls1"
offset = 8
chip = "gpiochip1"
active_low = true
bias = "pull-down"
drive = "open-drain"
debounce = "0us"
[can]
resolver = "can0"
)";

// The error's text, or "" when the text was accepted.
std::string error_of(const std::string& text) {
  try {
    (void)parse_rig_config(text, "rig.toml");
  } catch (const CampaignError& e) {
    return e.what();
  }
  return "";
}

bool starts_with(const std::string& s, const std::string& prefix) { return s.rfind(prefix, 0) == 0; }

TEST(RigConfig, GoodFileGivesEveryValue) {
  const RigConfig c = parse_rig_config(kGood, "rig.toml");
  EXPECT_EQ(c.file, "rig.toml");
  EXPECT_EQ(c.rt.priority, 70);
  ASSERT_TRUE(c.rt.cpu.has_value());
  EXPECT_EQ(*c.rt.cpu, 1);
  EXPECT_EQ(c.rt.edge_tolerance, Nanos{40'000});
  ASSERT_EQ(c.lines.size(), 2U);
  EXPECT_EQ(c.lines[0].rig, "enc.A");
  EXPECT_EQ(c.lines[0].chip, "gpiochip0"); // the [gpio] default
  EXPECT_EQ(c.lines[0].offset, 0U);
  EXPECT_FALSE(c.lines[0].settings.active_low);
  EXPECT_EQ(c.lines[0].settings.bias, gpiod::Bias::AsIs);
  EXPECT_EQ(c.lines[0].settings.drive, gpiod::Drive::PushPull);
  EXPECT_EQ(c.lines[0].where.line, 7U);
  EXPECT_EQ(c.lines[1].chip, "gpiochip1");
  EXPECT_EQ(c.lines[1].offset, 8U);
  EXPECT_TRUE(c.lines[1].settings.active_low);
  EXPECT_EQ(c.lines[1].settings.bias, gpiod::Bias::PullDown);
  EXPECT_EQ(c.lines[1].settings.drive, gpiod::Drive::OpenDrain);
  EXPECT_FALSE(c.lines[1].settings.debounce.has_value()); // 0us: no debounce
  EXPECT_EQ(c.can_resolver, "can0");
  EXPECT_EQ(c.host.link, HostLink::None);
  EXPECT_EQ(c.line_for("ls1"), &c.lines[1]);
  EXPECT_EQ(c.line_for("ls2"), nullptr);
}

TEST(RigConfig, DefaultsWhenTablesAreLeftOut) {
  const RigConfig c = parse_rig_config("", "rig.toml");
  EXPECT_EQ(c.rt.priority, 80);
  EXPECT_FALSE(c.rt.cpu.has_value());
  EXPECT_EQ(c.rt.edge_tolerance, Nanos{50'000});
  EXPECT_TRUE(c.lines.empty());
  EXPECT_TRUE(c.can_resolver.empty());
  // cpu = -1: not pinned.
  EXPECT_FALSE(parse_rig_config("[rt]\ncpu = -1\n", "rig.toml").rt.cpu.has_value());
}

TEST(RigConfig, ResolverStreamThreadHasItsOwnPriorityAndCpu) {
  const RigConfig d = parse_rig_config("", "rig.toml");
  EXPECT_EQ(d.rt.resolver_priority, 70); // below the edge loop's 80
  EXPECT_FALSE(d.rt.resolver_cpu.has_value());
  const RigConfig c = parse_rig_config("[rt]\nresolver_priority = 60\nresolver_cpu = 2\n", "rig.toml");
  EXPECT_EQ(c.rt.resolver_priority, 60);
  EXPECT_EQ(c.rt.resolver_cpu.value_or(-1), 2);
  // The ranges, swept across each limit: priority 0..99, cpu -1..4095.
  for (int p : {-1, 0, 1, 98, 99, 100}) {
    const std::string e = error_of("[rt]\nresolver_priority = " + std::to_string(p) + "\n");
    EXPECT_EQ(e.empty(), p >= 0 && p <= 99) << p << ": " << e;
    if (!e.empty()) {
      EXPECT_NE(e.find("rt.resolver_priority"), std::string::npos) << e;
    }
  }
  for (int cpu : {-2, -1, 0, 4095, 4096}) {
    const std::string e = error_of("[rt]\nresolver_cpu = " + std::to_string(cpu) + "\n");
    EXPECT_EQ(e.empty(), cpu >= -1 && cpu <= 4095) << cpu << ": " << e;
  }
  EXPECT_FALSE(parse_rig_config("[rt]\nresolver_cpu = -1\n", "rig.toml").rt.resolver_cpu.has_value());
}

TEST(RigConfig, ModbusRtuHost) {
  const RigConfig c = parse_rig_config(R"([host]
link = "modbus-rtu"
port = "/dev/ttyS1"
baud = 38400
format = "8N2"
unit = 7
timeout = "150ms"
)",
                                       "rig.toml");
  EXPECT_EQ(c.host.link, HostLink::ModbusRtu);
  EXPECT_EQ(c.host.port, "/dev/ttyS1");
  EXPECT_EQ(c.host.format.baud, 38400U);
  EXPECT_EQ(c.host.format.data_bits, 8);
  EXPECT_EQ(c.host.format.parity, Parity::None);
  EXPECT_EQ(c.host.format.stop_bits, 2);
  EXPECT_EQ(c.host.unit, 7);
  EXPECT_EQ(c.host.timeout, Nanos{150'000'000});
}

TEST(RigConfig, ModbusTcpHost) {
  const RigConfig c =
      parse_rig_config("[host]\nlink = \"modbus-tcp\"\naddress = \"127.0.0.1:1502\"\n", "rig.toml");
  EXPECT_EQ(c.host.link, HostLink::ModbusTcp);
  EXPECT_EQ(c.host.host, "127.0.0.1");
  EXPECT_EQ(c.host.tcp_port, 1502);
  EXPECT_EQ(c.host.unit, 1);
  EXPECT_EQ(c.host.timeout, Nanos{200'000'000}); // 200 ms unless written
}

TEST(RigConfig, ShippedExampleParses) {
  const RigConfig c = load_rig_config(HILRIG_SOURCE_DIR "/rt-config/rig.example.toml");
  EXPECT_EQ(c.rt.priority, 80);
  ASSERT_NE(c.line_for("enc.B"), nullptr);
  EXPECT_EQ(c.line_for("enc.B")->offset, 1U);
  EXPECT_EQ(c.can_resolver, "can0");
  EXPECT_EQ(c.host.link, HostLink::ModbusRtu);
  EXPECT_EQ(c.host.format.parity, Parity::Even);
}

struct BadCase {
  std::string text;
  std::string prefix; // file:line:column: key
};

TEST(RigConfig, EachBadKeyAtItsLine) {
  const BadCase cases[] = {
      {"[rt]\npriority = 100\n", "rig.toml:2:12: rt.priority:"},
      {"[rt]\npriority = \"high\"\n", "rig.toml:2:12: rt.priority:"},
      {"[rt]\ncpu = -2\n", "rig.toml:2:7: rt.cpu:"},
      {"[rt]\nedge_tolerance = 50\n", "rig.toml:2:18: rt.edge_tolerance:"},
      {"[rt]\nedge_tolerance = \"0us\"\n", "rig.toml:2:18: rt.edge_tolerance:"},
      {"[rt]\nperiod = \"1ms\"\n", "rig.toml:2:1: rt.period: unknown key"},
      {"[gpio]\nchip = \"gpiochip0\"\n[[gpio.line]]\nrig = \"enc.A\"\n",
       "rig.toml:3:1: gpio.line[0].offset: missing"},
      {"[gpio]\nchip = \"c\"\n[[gpio.line]]\nrig = \"a\"\noffset = -1\n",
       "rig.toml:5:10: gpio.line[0].offset:"},
      {"[gpio]\nchip = \"c\"\n[[gpio.line]]\nrig = \"a\"\noffset = 0\nbias = \"up\"\n",
       "rig.toml:6:8: gpio.line[0].bias: one of \"as-is\""},
      {"[gpio]\nchip = \"c\"\n[[gpio.line]]\nrig = \"a\"\noffset = 0\ndrive = \"totem\"\n",
       "rig.toml:6:9: gpio.line[0].drive:"},
      {"[gpio]\nchip = \"c\"\n[[gpio.line]]\nrig = \"a\"\noffset = 0\nactive_low = 1\n",
       "rig.toml:6:14: gpio.line[0].active_low:"},
      {"[gpio]\nchip = \"c\"\n[[gpio.line]]\nrig = \"a\"\noffset = 0\ndebounce = \"5us\"\n",
       "rig.toml:6:12: gpio.line[0].debounce:"},
      {"[gpio]\nchip = \"c\"\n[[gpio.line]]\nrig = \"a\"\noffset = 0\nwire = \"x\"\n",
       "rig.toml:6:1: gpio.line[0].wire: unknown key"},
      // Two lines for one rig line, and one GPIO line twice.
      {"[gpio]\nchip = \"c\"\n[[gpio.line]]\nrig = \"a\"\noffset = 0\n[[gpio.line]]\nrig = \"a\"\noffset = "
       "1\n",
       "rig.toml:7:7: gpio.line[1].rig:"},
      {"[gpio]\nchip = \"c\"\n[[gpio.line]]\nrig = \"a\"\noffset = 3\n[[gpio.line]]\nrig = \"b\"\noffset = "
       "3\n",
       "rig.toml:8:10: gpio.line[1].offset:"},
      // No chip here and no [gpio] default.
      {"[[gpio.line]]\nrig = \"a\"\noffset = 0\n", "rig.toml:2:7: gpio.line[0].rig: a chip"},
      {"[can]\nresolver = 0\n", "rig.toml:2:12: can.resolver:"},
      {"[host]\nlink = \"rs485\"\n", "rig.toml:2:8: host.link:"},
      {"[host]\nlink = \"modbus-rtu\"\n", "rig.toml:1:1: host.port: missing"},
      {"[host]\nlink = \"modbus-rtu\"\nport = \"/dev/ttyS1\"\nformat = \"8X1\"\n",
       "rig.toml:4:10: host.format:"},
      {"[host]\nlink = \"modbus-rtu\"\nport = \"/dev/ttyS1\"\nbaud = 0\n", "rig.toml:4:8: host.baud:"},
      {"[host]\nlink = \"modbus-rtu\"\nport = \"/dev/ttyS1\"\nunit = 0\n", "rig.toml:4:8: host.unit:"},
      {"[host]\nlink = \"modbus-rtu\"\nport = \"/dev/ttyS1\"\naddress = \"h:1\"\n",
       "rig.toml:4:11: host.address: not a key of link"},
      {"[host]\nlink = \"modbus-tcp\"\naddress = \"127.0.0.1\"\n", "rig.toml:3:11: host.address:"},
      {"[host]\nlink = \"modbus-tcp\"\naddress = \"h:1502\"\ntimeout = \"0ms\"\n",
       "rig.toml:4:11: host.timeout:"},
      {"[host]\nlink = \"modbus-tcp\"\naddress = \"h:1502\"\nport = \"/dev/ttyS1\"\n",
       "rig.toml:4:8: host.port: not a key of link"},
      {"chip = \"gpiochip0\"\n", "rig.toml:1:1: chip: unknown key"}, // belongs in [gpio]
      {"[rt\n", "rig.toml:1:"},                                      // not TOML at all
  };
  for (const BadCase& c : cases) {
    const std::string e = error_of(c.text);
    EXPECT_TRUE(starts_with(e, c.prefix)) << "text:\n" << c.text << "\ngot: " << e << "\nwant: " << c.prefix;
  }
}

TEST(RigConfig, MissingFileNamesIt) {
  try {
    (void)load_rig_config("no-such-dir/rig.toml");
    FAIL() << "accepted a missing file";
  } catch (const CampaignError& e) {
    EXPECT_EQ(e.file(), "no-such-dir/rig.toml");
    EXPECT_EQ(e.key(), "file");
  }
}

// The same file checks as a campaign: a directory or a FIFO is not read (a FIFO would block).
TEST(RigConfig, OnlyARegularFileIsRead) {
  for (const char* path : {HILRIG_SOURCE_DIR "/rt-config", "/dev/zero"}) {
    try {
      (void)load_rig_config(path);
      FAIL() << "accepted " << path;
    } catch (const CampaignError& e) {
      EXPECT_EQ(e.key(), "file");
      EXPECT_NE(e.expected().find("a regular rig config file"), std::string::npos) << e.what();
    }
  }
}

} // namespace
} // namespace hilrig::hardware
