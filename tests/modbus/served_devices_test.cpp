// Every device in `hilrig serve`'s table can be served over Modbus RTU (pty) and answers
// the rig's client: input register 0 reads, an input register far outside every map
// (1000) is Illegal Data Address, and an unknown fault variant or device is refused.
#include <gtest/gtest.h>

#include <algorithm>
#include <span>
#include <stdexcept>
#include <string>
#include <vector>

#include "drivers/hostlink/modbus_client.hpp"
#include "rig/cli/serve_devices.hpp"
#include "tests/modbus/serve_thread.hpp"

namespace hilrig::test {
namespace {

// The host word maps as each model's README documents them: ANS1 "Host register map"
// (command words at 1024 + k, status words at k, 20 each, L1699-L1701, L2288-L2290);
// SMD23E spec §6.1 (input registers 0-9, output words at 1024-1033); 4501 README "Register
// map" (O:s.0-7 at holding 0-7, I:s.0-7 at input 0-7); 7361 README "Register map" (%Q,
// %AQ1-6 at holding 0-6; %I, %AI1-6 at input 0-6).
TEST(ServedDevices, TableNamesTheModelsWithRegisterMaps) {
  struct Expected {
    const char* name;
    cli::HostWordMap words;
  };
  for (const Expected& e : {Expected{"amci4501", {0, 8, 0, 8}}, Expected{"ans1", {1024, 20, 0, 20}},
                            Expected{"smd23e", {1024, 10, 0, 10}}, Expected{"ssi7361", {0, 7, 0, 7}}}) {
    const cli::ServedDevice* d = cli::find_served_device(e.name);
    ASSERT_NE(d, nullptr) << e.name;
    EXPECT_FALSE(d->description.empty());
    EXPECT_NE(std::string(d->faults).find("none"), std::string::npos) << e.name;
    EXPECT_EQ(d->words.command_base, e.words.command_base) << e.name;
    EXPECT_EQ(d->words.command_words, e.words.command_words) << e.name;
    EXPECT_EQ(d->words.status_base, e.words.status_base) << e.name;
    EXPECT_EQ(d->words.status_words, e.words.status_words) << e.name;
  }
  EXPECT_EQ(cli::find_served_device("pls9999"), nullptr);
}

TEST(ServedDevices, EachIsServedOverModbusRtu) {
  for (const cli::ServedDevice& d : cli::served_devices()) {
    cli::ServeOptions o;
    o.device = std::string(d.name);
    o.link = cli::ServeLink::Pty;
    ServeThread server(o);
    hostlink::RtuSettings s;
    s.device = server.endpoint().serial_path;
    auto client = hostlink::ModbusClient::rtu(s);
    std::array<std::uint16_t, 1> w{};
    EXPECT_EQ(client->read_input_registers(1000, w), RegisterStatus::IllegalDataAddress) << d.name;
    // The whole host word map reads, and the word after each block is outside the map.
    const cli::HostWordMap& m = d.words;
    std::vector<std::uint16_t> words(std::max(m.status_words, m.command_words));
    const std::span<std::uint16_t> status(words.data(), m.status_words);
    const std::span<std::uint16_t> command(words.data(), m.command_words);
    EXPECT_EQ(client->read_input_registers(m.status_base, status), RegisterStatus::Ok) << d.name;
    EXPECT_EQ(client->read_holding_registers(m.command_base, command), RegisterStatus::Ok) << d.name;
    EXPECT_EQ(client->read_input_registers(static_cast<std::uint16_t>(m.status_base + m.status_words), w),
              RegisterStatus::IllegalDataAddress)
        << d.name;
    EXPECT_EQ(client->read_holding_registers(static_cast<std::uint16_t>(m.command_base + m.command_words), w),
              RegisterStatus::IllegalDataAddress)
        << d.name;
  }
}

TEST(ServedDevices, UnknownDeviceOrFaultIsRefused) {
  cli::ServeOptions o;
  o.link = cli::ServeLink::Pty;
  o.device = "nosuchboard";
  EXPECT_THROW(ServeThread{o}, std::invalid_argument);
  for (const cli::ServedDevice& d : cli::served_devices()) {
    o.device = std::string(d.name);
    o.fault = "no-such-fault";
    EXPECT_THROW(ServeThread{o}, std::invalid_argument) << d.name;
  }
}

} // namespace
} // namespace hilrig::test
