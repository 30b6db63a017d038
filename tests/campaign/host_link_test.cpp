// The host link as a user meets it: `hilrig run --host-link modbus-rtu-pty` programs and reads
// a virtual ANS1 through Modbus RTU on a pty pair and gets the same results, byte for byte, as
// the in-process link; a peer that corrupts a reply's CRC or stops answering is a rig fault
// (exit 3) naming the lost transaction, and what was captured before it is kept.

#include <modbus/modbus.h>
#include <poll.h>
#include <unistd.h>

#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <atomic>
#include <filesystem>
#include <fstream>
#include <map>
#include <mutex>
#include <sstream>
#include <thread>

#include <nlohmann/json.hpp>

#include "drivers/hostlink/modbus_client.hpp"
#include "drivers/modbus/pdu_handler.hpp"
#include "drivers/modbus/pty.hpp"
#include "rig/campaign/campaign_parser.hpp"
#include "rig/campaign/dut_registers.hpp"
#include "rig/campaign/executive.hpp"
#include "rig/campaign/modbus_host_link.hpp"
#include "rig/cli/run_command.hpp"
#include "rig/results/results_json.hpp"
#include "tests/tools/scratch_files.hpp"
#include "tests/tools/vcd_reader.hpp"

namespace hilrig::campaign {
namespace {

namespace fs = std::filesystem;

// ANS1 production counters: four programming writes at 0 and 1010 ms, five status reads at
// 1020 ms; the campaign's comments derive the expected counts from the manual.
const std::string kCounters = std::string(HILRIG_SOURCE_DIR) + "/campaigns/ans1/ans1_counters.toml";

// The ANS1's host words on Modbus (models/ans1/README.md "Host register map", manual L1699):
// command word k = holding register 1024 + k, status word k = input register k.
const HostRegisters kAns1Registers{1024, 20, 0, 20};

fs::path scratch(const std::string& name) {
  const fs::path dir = fs::path(HILRIG_BINARY_DIR) / "tests" / "campaign" / "scratch" / ("host_link_" + name);
  fs::remove_all(dir);
  fs::create_directories(dir);
  return dir;
}

int run(cli::RunOptions o, const fs::path& out, std::string* err_text = nullptr) {
  if (o.file.empty()) o.file = kCounters;
  o.out = out;
  o.handle_signals = false;
  std::ostringstream err;
  const int status = cli::run_campaign(o, err);
  if (err_text != nullptr) *err_text = err.str();
  return status;
}

const rig::Observation* observation(const rig::RunResult& r, const std::string& name) {
  for (const auto& o : r.observations)
    if (o.name == name) return &o;
  return nullptr;
}

TEST(HostLink, ModbusRtuOverAPtyGivesTheSameResultsAsInProcess) {
  const fs::path in_process = scratch("in_process");
  const fs::path modbus = scratch("modbus");
  cli::RunOptions o;
  o.epoch = 1'767'225'600; // 2026-01-01T00:00:00Z: both runs' wall_clock.started_at
  std::string err;
  ASSERT_EQ(run(o, in_process, &err), 0) << err;
  o.host_link = "modbus-rtu-pty";
  ASSERT_EQ(run(o, modbus, &err), 0) << err;

  // Byte for byte (the start time pinned by --epoch, the host this machine in both) but for
  // the link each names (traceability).
  const auto without_host_link = [](const fs::path& file) {
    nlohmann::json j = nlohmann::json::parse(hilrig::test::read_file(file));
    j.erase("host_link");
    return j.dump();
  };
  EXPECT_EQ(nlohmann::json::parse(hilrig::test::read_file(in_process / "results.json"))["host_link"],
            "in-process");
  EXPECT_EQ(nlohmann::json::parse(hilrig::test::read_file(modbus / "results.json"))["host_link"],
            "modbus-rtu-pty");
  EXPECT_EQ(without_host_link(in_process / "results.json"), without_host_link(modbus / "results.json"));
  EXPECT_EQ(hilrig::test::read_file(in_process / "trace.vcd"), hilrig::test::read_file(modbus / "trace.vcd"));
  // And they are the right results: the counts the campaign derives from the manual, read
  // over the link (part cycles floor(10 * 3 / 2) = 15, ten revolutions).
  const rig::CampaignResult r = rig::read_results_file(modbus / "results.json");
  ASSERT_EQ(r.runs.size(), 1U);
  for (const auto& [name, value] : std::map<std::string, double>{{"part_cycles_high", 0},
                                                                 {"part_cycles", 15},
                                                                 {"batch1", 15},
                                                                 {"revolutions", 10},
                                                                 {"good_parts", 15}}) {
    const rig::Observation* obs = observation(r.runs[0], name);
    ASSERT_NE(obs, nullptr) << name;
    EXPECT_EQ(obs->value, value) << name;
  }
  EXPECT_EQ(r.verdict, rig::Outcome::Pass);
}

// Host words straight to the DUT, counted.
class CountedDirectWords final : public HostWords {
public:
  CountedDirectWords(duts::Dut& dut, std::uint64_t& count) : dut_(dut), count_(count) {}
  void write(std::size_t word, std::uint16_t value) override {
    ++count_;
    dut_.host_write(word, value);
  }
  std::uint16_t read(std::size_t word) override {
    ++count_;
    return dut_.host_read(word);
  }

private:
  duts::Dut& dut_;
  std::uint64_t& count_;
};

// A Modbus link whose board's request count is added to `requests` when the run ends.
class CountedModbusLink final : public HostWords {
public:
  CountedModbusLink(duts::Dut& dut, std::uint64_t& requests)
      : turn_(std::make_shared<std::mutex>()),
        board_(std::make_shared<PtyBoard>(dut, kAns1Registers, *turn_)), requests_(requests) {
    hostlink::RtuSettings s;
    s.device = board_->device();
    link_ = std::make_unique<ModbusHostLink>(hostlink::ModbusClient::rtu(s), kAns1Registers, turn_, board_);
  }
  ~CountedModbusLink() override {
    link_.reset(); // the client is closed: no request is in flight
    requests_ += board_->stats().requests.load();
  }
  CountedModbusLink(const CountedModbusLink&) = delete;
  CountedModbusLink& operator=(const CountedModbusLink&) = delete;
  void write(std::size_t word, std::uint16_t value) override { link_->write(word, value); }
  std::uint16_t read(std::size_t word) override { return link_->read(word); }

private:
  std::shared_ptr<std::mutex> turn_;
  std::shared_ptr<PtyBoard> board_;
  std::uint64_t& requests_;
  std::unique_ptr<ModbusHostLink> link_;
};

TEST(HostLink, EachHostWordIsOneModbusTransaction) {
  const Campaign c = load_campaign(kCounters);
  std::vector<RunSpec> runs = plan_runs(c, c.seed);
  std::uint64_t words = 0;
  std::uint64_t requests = 0;
  Executive direct(c);
  direct.use_host_link([&](duts::Dut& dut, const duts::DutInfo&) -> std::unique_ptr<HostWords> {
    return std::make_unique<CountedDirectWords>(dut, words);
  });
  Executive modbus(c);
  modbus.use_host_link([&](duts::Dut& dut, const duts::DutInfo&) -> std::unique_ptr<HostWords> {
    return std::make_unique<CountedModbusLink>(dut, requests);
  });
  const rig::CampaignResult a = direct.run_all(runs, c.seed, {});
  const rig::CampaignResult b = modbus.run_all(runs, c.seed, {});
  EXPECT_EQ(rig::to_json_text(a), rig::to_json_text(b));
  // Four writes of 4, 4, 7 and 4 words (each word once, then Transmit set and cleared) and
  // five reads, plus the Acknowledge polls: at least 19 + 4 * 2 + 5 word accesses.
  EXPECT_GE(words, 32U);
  EXPECT_EQ(requests, words);
}

// CRC-16/MODBUS (poly 0xA001 reflected, init 0xFFFF), low byte first on the wire.
std::uint16_t crc16_modbus(const std::vector<std::uint8_t>& bytes) {
  std::uint16_t crc = 0xFFFF;
  for (std::uint8_t b : bytes) {
    crc = static_cast<std::uint16_t>(crc ^ b);
    for (int i = 0; i < 8; ++i)
      crc = (crc & 1U) != 0 ? static_cast<std::uint16_t>((crc >> 1) ^ 0xA001)
                            : static_cast<std::uint16_t>(crc >> 1);
  }
  return crc;
}

// A board on a pty that answers from the DUT's words like PtyBoard, until the rig reads
// input register `trigger`: then it answers with a corrupted CRC (BadCrc), or never answers
// again (Silent).
class FaultyBoard {
public:
  enum class Fault { BadCrc, Silent };
  FaultyBoard(duts::Dut& dut, std::mutex& turn, std::uint16_t trigger, Fault fault)
      : registers_(dut, kAns1Registers, turn), trigger_(trigger), fault_(fault) {
    thread_ = std::thread([this] { serve(); });
  }
  ~FaultyBoard() {
    stop_ = true;
    thread_.join();
  }
  FaultyBoard(const FaultyBoard&) = delete;
  FaultyBoard& operator=(const FaultyBoard&) = delete;
  [[nodiscard]] const std::string& device() const { return pty_.slave_path(); }

private:
  void serve() {
    modbus_t* ctx = modbus_new_rtu("fd", 19200, 'E', 8, 1);
    modbus_set_slave(ctx, 1);
    modbus_set_socket(ctx, pty_.master_fd());
    bool silent = false;
    while (!stop_) {
      pollfd p{pty_.master_fd(), POLLIN, 0};
      if (::poll(&p, 1, 10) <= 0) continue; // bounded, so the destructor's stop is seen
      std::array<std::uint8_t, MODBUS_RTU_MAX_ADU_LENGTH> req{};
      const int n = modbus_receive(ctx, req.data());
      if (n <= 3) continue;
      const std::span<const std::uint8_t> pdu(req.data() + 1, static_cast<std::size_t>(n) - 3);
      const bool hit = pdu[0] == 4 && ((pdu[1] << 8) | pdu[2]) == trigger_;
      if (hit && fault_ == Fault::Silent) silent = true;
      if (silent) continue;
      const drivers::modbus::PduResult r = drivers::modbus::handle_pdu(registers_, pdu);
      std::vector<std::uint8_t> frame{req[0]};
      frame.insert(frame.end(), r.response.begin(), r.response.end());
      const std::uint16_t crc = crc16_modbus(frame);
      frame.push_back(static_cast<std::uint8_t>(crc & 0xFF));
      frame.push_back(static_cast<std::uint8_t>((crc >> 8) ^ (hit ? 0xFF : 0x00)));
      if (::write(pty_.master_fd(), frame.data(), frame.size()) != static_cast<ssize_t>(frame.size())) break;
    }
    modbus_set_socket(ctx, -1);
    modbus_free(ctx);
  }

  drivers::modbus::Pty pty_;
  DutRegisters registers_;
  std::uint16_t trigger_;
  Fault fault_;
  std::atomic<bool> stop_{false};
  std::thread thread_;
};

HostLinkFactory faulty_link(FaultyBoard::Fault fault, std::uint16_t trigger) {
  return [=](duts::Dut& dut, const duts::DutInfo&) -> std::unique_ptr<HostWords> {
    auto turn = std::make_shared<std::mutex>();
    auto board = std::make_shared<FaultyBoard>(dut, *turn, trigger, fault);
    hostlink::RtuSettings s;
    s.device = board->device();
    s.response_timeout = milliseconds(250);
    return std::make_unique<ModbusHostLink>(hostlink::ModbusClient::rtu(s), kAns1Registers, turn, board);
  };
}

// What a link failure at the read of status word 5 (batch1, the third read at 1020 ms) must
// leave: exit 3, the failure named, the two reads before it and every handshake kept, the
// trace written with the batch-limit pulse (750..850 ms) in it and the rig's lines inactive.
void expect_named_failure_and_captured_data(FaultyBoard::Fault fault, const std::string& what) {
  const fs::path out = scratch(what == "bad CRC" ? "bad_crc" : "silent");
  cli::RunOptions o;
  o.host_link_factory = faulty_link(fault, 5);
  std::string err;
  ASSERT_EQ(run(o, out, &err), 3) << err;
  EXPECT_NE(err.find("rig fault"), std::string::npos) << err;

  const rig::CampaignResult r = rig::read_results_file(out / "results.json");
  ASSERT_EQ(r.runs.size(), 1U);
  const rig::RunResult& run0 = r.runs[0];
  EXPECT_NE(run0.error.find("read input registers 5..5: " + what), std::string::npos) << run0.error;
  EXPECT_FALSE(run0.interrupted);
  EXPECT_EQ(r.verdict, rig::Outcome::Error);
  ASSERT_EQ(run0.observations.size(), 2U);
  EXPECT_EQ(run0.observations[0].name, "part_cycles_high");
  EXPECT_EQ(run0.observations[0].value, 0);
  EXPECT_EQ(run0.observations[1].name, "part_cycles");
  EXPECT_EQ(run0.observations[1].value, 15);
  ASSERT_EQ(run0.checks.size(), 1U);
  EXPECT_EQ(run0.checks[0].check, "host");
  EXPECT_EQ(run0.checks[0].measurements.size(), 4U); // cb2, cb10, cb11, cb1 acknowledged

  const hilrig::test::Vcd vcd = hilrig::test::read_vcd_file((out / "trace.vcd").string());
  const hilrig::test::VcdVar* done = vcd.find("batch1_done");
  ASSERT_NE(done, nullptr) << "no batch1_done in the trace";
  const std::vector<std::string> pulse = done->values();
  EXPECT_EQ(std::count(pulse.begin(), pulse.end(), "1"), 1); // on once, at the 8th part cycle
  for (const char* line : {"enc.A", "enc.B"}) {
    const hilrig::test::VcdVar* wire = vcd.find(line);
    ASSERT_NE(wire, nullptr) << line;
    EXPECT_EQ(wire->values().back(), "0") << line << " not left inactive";
  }
}

TEST(HostLink, CorruptedCrcIsANamedRigFaultAndLosesNoCapturedData) {
  expect_named_failure_and_captured_data(FaultyBoard::Fault::BadCrc, "bad CRC");
}

TEST(HostLink, SilentPeerIsANamedRigFaultAndLosesNoCapturedData) {
  expect_named_failure_and_captured_data(FaultyBoard::Fault::Silent, "timeout");
}

TEST(HostLink, UnknownLinkOrDeviceWithoutARegisterMapIsBadInput) {
  cli::RunOptions o;
  o.host_link = "modbus-carrier-pigeon";
  std::string err;
  EXPECT_EQ(run(o, scratch("unknown"), &err), 2);
  EXPECT_NE(err.find("--host-link modbus-carrier-pigeon"), std::string::npos) << err;
  // The reference PLS is a campaign model only: `hilrig serve` has no register map for it.
  o.host_link = "modbus-rtu-pty";
  o.file = std::string(HILRIG_SOURCE_DIR) + "/campaigns/reference/reference_pls_pass.toml";
  EXPECT_EQ(run(o, scratch("unserved"), &err), 2);
  EXPECT_NE(err.find("reference_pls has no Modbus register map"), std::string::npos) << err;
  EXPECT_FALSE(fs::exists(scratch("unserved") / "results.json"));
}

} // namespace
} // namespace hilrig::campaign
