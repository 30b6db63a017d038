// `hilrig serve pls2700 --model M --motion constant:<rpm>rpm --param KEY=VALUE` as a PLC sees
// it: the hilrig program serves Modbus TCP on a port the OS chooses (--modbus-tcp
// 127.0.0.1:0, told back through --port-file) and this test talks to it with libmodbus.
// Waits are polls with a bounded deadline, never a fixed sleep standing for a time.

#include <arpa/inet.h>
#include <fcntl.h>
#include <modbus.h>
#include <netinet/in.h>
#include <spawn.h>
#include <sys/socket.h>
#include <sys/wait.h>
#include <unistd.h>

#include <gtest/gtest.h>

#include <array>
#include <cerrno>
#include <chrono>
#include <csignal>
#include <cstdint>
#include <filesystem>
#include <optional>
#include <string>
#include <thread>
#include <vector>

#include "tests/tools/scratch_files.hpp"

extern char** environ;

namespace hilrig {
namespace {

namespace fs = std::filesystem;
using Clock = std::chrono::steady_clock;

// Long enough for a loaded CI machine to start a process; a pass takes well under a second.
constexpr auto kDeadline = std::chrono::seconds(30);

// One `hilrig serve pls2700 ...` child process, stopped with SIGTERM when the test is done.
class Served {
public:
  Served(const std::string& name, const std::vector<std::string>& options,
         const std::string& device = "pls2700") {
    dir_ = test::scratch_dir("campaign", "serve_cli_" + name);
    const fs::path port_file = dir_ / "port";
    std::vector<std::string> args{HILRIG_EXE, "serve", device};
    args.insert(args.end(), options.begin(), options.end());
    for (const char* a : {"--modbus-tcp", "127.0.0.1:0", "--port-file"}) args.emplace_back(a);
    args.push_back(port_file.string());
    std::vector<char*> argv;
    for (auto& a : args) argv.push_back(a.data());
    argv.push_back(nullptr);
    posix_spawn_file_actions_t io;
    posix_spawn_file_actions_init(&io);
    posix_spawn_file_actions_addopen(&io, 1, (dir_ / "stdout").c_str(), O_WRONLY | O_CREAT | O_TRUNC, 0644);
    posix_spawn_file_actions_addopen(&io, 2, (dir_ / "stderr").c_str(), O_WRONLY | O_CREAT | O_TRUNC, 0644);
    if (posix_spawn(&pid_, argv[0], &io, nullptr, argv.data(), environ) != 0) pid_ = -1;
    posix_spawn_file_actions_destroy(&io);
    // The port file is complete once it holds a line.
    for (const auto until = Clock::now() + kDeadline; pid_ > 0 && Clock::now() < until;) {
      const std::string text = fs::exists(port_file) ? test::read_file(port_file) : std::string();
      if (text.find('\n') != std::string::npos) {
        port_ = std::stoi(text);
        break;
      }
      int status = 0;
      if (waitpid(pid_, &status, WNOHANG) == pid_) {
        pid_ = -1; // it ended: stderr says why
        break;
      }
      std::this_thread::sleep_for(std::chrono::milliseconds(5));
    }
  }
  Served(const Served&) = delete;
  Served& operator=(const Served&) = delete;
  ~Served() {
    if (ctx_ != nullptr) {
      modbus_close(ctx_);
      modbus_free(ctx_);
    }
    if (pid_ > 0) {
      kill(pid_, SIGTERM);
      int status = 0;
      waitpid(pid_, &status, 0);
    }
  }

  [[nodiscard]] std::string why_not() const { return test::read_file(dir_ / "stderr"); }
  [[nodiscard]] int port() const { return port_; }

  // Sends `signal` and waits (bounded) for the server to end: its wait status, or nullopt if it
  // had not started or was still running at the deadline (then it is killed).
  std::optional<int> stop_with(int signal) {
    if (pid_ <= 0) return std::nullopt;
    kill(pid_, signal);
    for (const auto until = Clock::now() + kDeadline; Clock::now() < until;) {
      int status = 0;
      if (waitpid(pid_, &status, WNOHANG) == pid_) {
        pid_ = -1;
        return status;
      }
      std::this_thread::sleep_for(std::chrono::milliseconds(5));
    }
    return std::nullopt; // the destructor's SIGTERM and wait end it
  }

  // A connected client, or null (then why_not() says why).
  modbus_t* client() {
    if (ctx_ != nullptr || port_ <= 0) return ctx_;
    ctx_ = modbus_new_tcp("127.0.0.1", port_);
    if (ctx_ != nullptr && modbus_connect(ctx_) != 0) {
      modbus_free(ctx_);
      ctx_ = nullptr;
    }
    return ctx_;
  }

  // Input registers [address, address + n): the words, or the Modbus exception's errno.
  struct Read {
    std::vector<std::uint16_t> words;
    int error = 0;
  };
  Read input_registers(int address, int n) {
    Read r;
    r.words.assign(static_cast<std::size_t>(n), 0);
    if (client() == nullptr) {
      r.error = -1;
      return r;
    }
    if (modbus_read_input_registers(ctx_, address, n, r.words.data()) != n) r.error = errno;
    return r;
  }

  Read holding_registers(int address, int n) {
    Read r;
    r.words.assign(static_cast<std::size_t>(n), 0);
    if (client() == nullptr) {
      r.error = -1;
      return r;
    }
    if (modbus_read_registers(ctx_, address, n, r.words.data()) != n) r.error = errno;
    return r;
  }
  // FC16: 0, or the Modbus exception's errno.
  int write(int address, const std::vector<std::uint16_t>& words) {
    if (client() == nullptr) return -1;
    const int n = static_cast<int>(words.size());
    return modbus_write_registers(ctx_, address, n, words.data()) == n ? 0 : errno;
  }

private:
  fs::path dir_;
  pid_t pid_ = -1;
  int port_ = 0;
  modbus_t* ctx_ = nullptr;
};

// pls2700 manual (seeds/002_46e90574ec92805f.txt:1257-1260): the BTR is 3 words on the
// 1-channel modules (2731, 2731-04, 2741), 5 on the 2-channel ones (2732, 2732-04, 2742,
// 2742-18); the served map has exactly those input registers (models/pls2700/README.md).
TEST(ServeCli, ModelChoosesTheRegisterMap) {
  for (const auto& [model, words] :
       {std::pair{"2731", 3}, std::pair{"2741", 3}, std::pair{"2742", 5}, std::pair{"2742-18", 5}}) {
    Served s(std::string("model_") + model, {"--model", model});
    const auto all = s.input_registers(0, words);
    ASSERT_EQ(all.error, 0) << model << ": " << s.why_not();
    const auto past = s.input_registers(words, 1);
    EXPECT_EQ(past.error, EMBXILADD) << model; // one word past the BTR
    const auto longer = s.input_registers(0, words + 1);
    EXPECT_EQ(longer.error, EMBXILADD) << model;
  }
}

// The position word of channel 1 once it is no longer the power-up 0: polled until it has
// taken `distinct` different values (the module updating), or the deadline.
std::vector<std::uint16_t> positions(Served& s, std::size_t distinct) {
  std::vector<std::uint16_t> seen;
  for (const auto until = Clock::now() + kDeadline; Clock::now() < until && seen.size() < distinct;) {
    const auto r = s.input_registers(0, 1);
    if (r.error != 0) break;
    if (seen.empty() || seen.back() != r.words[0]) seen.push_back(r.words[0]);
    std::this_thread::sleep_for(std::chrono::milliseconds(2));
  }
  return seen;
}

// With --motion a built-in transducer turns the stators: the position word moves through
// valid positions (bit 15 clear; 8000h is the transducer-fault pattern, seeds/002:1315).
// --param min_stator_ratio=1.1 puts the same transducer's ratio (1.0) below the fault limit:
// a transducer fault, 8000h in position and tach (L1315), while the nominal server moves.
// Without --motion the stators are open: 8000h as well.
TEST(ServeCli, MotionTurnsTheTransducerAndAParamFaultsIt) {
  Served faulted("faulted",
                 {"--model", "2731", "--motion", "constant:300rpm", "--param", "min_stator_ratio=1.1"});
  Served open("open", {"--model", "2731"});
  Served nominal("nominal", {"--model", "2731", "--motion", "constant:300rpm"});
  const std::vector<std::uint16_t> moved = positions(nominal, 4);
  ASSERT_EQ(moved.size(), 4U) << nominal.why_not();
  for (std::size_t i = 1; i < moved.size(); ++i) EXPECT_EQ(moved[i] & 0x8000, 0) << moved[i];
  // Both others started before the nominal one moved through three updates.
  for (Served* s : {&faulted, &open}) {
    const auto r = s->input_registers(0, 2);
    ASSERT_EQ(r.error, 0) << s->why_not();
    EXPECT_EQ(r.words[0], 0x8000);
    EXPECT_EQ(r.words[1], 0x8000);
  }
}

// Polls input register `address` until `pred` holds for it, or the deadline; the last word read.
template <class Pred> std::uint16_t input_until(Served& s, int address, Pred pred) {
  std::uint16_t last = 0;
  for (const auto until = Clock::now() + kDeadline; Clock::now() < until;) {
    const auto r = s.input_registers(address, 1);
    if (r.error != 0) break;
    last = r.words[0];
    if (pred(last)) break;
    std::this_thread::sleep_for(std::chrono::milliseconds(2));
  }
  return last;
}

// docs/serve.md "Rig controls": holding 9000 the supply (1 on, 0 off), 9001 a timed power cycle
// (off now, on that many ms later), 9002 the Program switch (1 Program, 0 Display), 9003 CLEAR
// on an output's last pair.
constexpr int kSupply = 9000;
constexpr int kPowerCycle = 9001;
constexpr int kProgramSwitch = 9002;
constexpr int kClearPair = 9003;

// pls2700 manual (seeds/002_46e90574ec92805f.txt): the keyboard lock 8100h is "retained through
// power loss" (L1356-1357) and the setpoints are in nvRAM (L776); the resolver is absolute. A 2741
// (BTR: position, tach, status; BTW at holding 0, error byte at 64) turning at 300 rpm: output 1
// programmed 0..SF-1 (ON 0 OFF 359 at SF 360) is on; with the supply off every word reads 0 and
// the outputs are off; back on, the output is on again without reprogramming.
TEST(ServeCli, APlcPowersTheServedBoardOffAndOnThroughTheRigControls) {
  Served s("power", {"--model", "2741", "--motion", "constant:300rpm"});
  ASSERT_EQ(s.holding_registers(kSupply, 1).words, std::vector<std::uint16_t>{1}) << s.why_not();
  ASSERT_EQ(s.write(0, {0xC011, 0x0000, 0x0000, 0x0359}), 0);
  ASSERT_EQ(s.holding_registers(64, 1).words[0], 0);
  EXPECT_EQ(input_until(s, 2, [](std::uint16_t w) { return (w & 1) != 0; }) & 1, 1);
  ASSERT_EQ(s.write(kSupply, {0}), 0);
  EXPECT_EQ(s.holding_registers(kSupply, 1).words, std::vector<std::uint16_t>{0});
  EXPECT_EQ(s.input_registers(0, 3).words, std::vector<std::uint16_t>(3, 0));
  ASSERT_EQ(s.write(kSupply, {1}), 0);
  EXPECT_EQ(input_until(s, 2, [](std::uint16_t w) { return (w & 1) != 0; }) & 1, 1);
  // A timed cycle: off at once, back on 50 ms later by itself.
  ASSERT_EQ(s.write(kPowerCycle, {50}), 0);
  EXPECT_EQ(s.holding_registers(kSupply, 1).words, std::vector<std::uint16_t>{0});
  EXPECT_EQ(input_until(s, 2, [](std::uint16_t w) { return (w & 1) != 0; }) & 1, 1);
  EXPECT_EQ(s.holding_registers(kSupply, 1).words, std::vector<std::uint16_t>{1});
  // Values a control does not take are refused; a write across the board's and the controls'
  // addresses too.
  EXPECT_EQ(s.write(kSupply, {2}), EMBXILVAL);
  EXPECT_EQ(s.write(kPowerCycle, {0}), EMBXILVAL);
  EXPECT_EQ(s.write(kSupply - 1, {1, 1}), EMBXILADD);
}

// L543: the Program switch toward the back is Program Mode, toward the front Display Mode, where
// "the keyboard cannot modify parameters" (L535); CLEAR on a pair deletes it (L1078). The shaft
// stands at 0 (constant:0rpm): output 1 programmed ON 0 OFF 100 is on (status word, input 2,
// bit 0). CLEAR on its pair (9003 = 1) in Display Mode: ignored, still on; the switch to Program
// (9002 = 1), CLEAR again: the pair is gone, output 1 off.
TEST(ServeCli, TheProgramSwitchDecidesWhetherTheKeyboardMayDeleteAPair) {
  Served s("switch", {"--model", "2741", "--motion", "constant:0rpm", "--param", "program_switch=display"});
  ASSERT_EQ(s.holding_registers(kProgramSwitch, 1).words, std::vector<std::uint16_t>{0}) << s.why_not();
  ASSERT_EQ(s.write(0, {0xC011, 0x0000, 0x0000, 0x0100}), 0);
  ASSERT_EQ(input_until(s, 2, [](std::uint16_t w) { return (w & 1) != 0; }) & 1, 1);
  ASSERT_EQ(s.write(kClearPair, {1}), 0);
  // Ignored in Display Mode: still on at every read for 10 ms, 50 of the module's 200 us updates
  // (the server advances the board to the clock before each request).
  for (const auto until = Clock::now() + std::chrono::milliseconds(10); Clock::now() < until;) {
    const auto r = s.input_registers(2, 1);
    ASSERT_EQ(r.error, 0);
    ASSERT_EQ(r.words[0] & 1, 1);
  }
  ASSERT_EQ(s.write(kProgramSwitch, {1}), 0);
  EXPECT_EQ(s.holding_registers(kProgramSwitch, 1).words, std::vector<std::uint16_t>{1});
  ASSERT_EQ(s.write(kClearPair, {1}), 0);
  EXPECT_EQ(input_until(s, 2, [](std::uint16_t w) { return (w & 1) == 0; }) & 1, 0);
  EXPECT_EQ(s.write(kProgramSwitch, {3}), EMBXILVAL);
  EXPECT_EQ(s.write(kClearPair, {9}), EMBXILVAL); // outputs 1..8
}

// smd23e manual (seeds/003_7a93cebfafae55cd.txt L2331): after Save Configuration the unit
// "stops responding to commands and you must cycle power"; L2235: the saved configuration is
// used "on every power up". Served: Configuration Mode words with Config Word bit 10 (0x0400)
// at holding 1024, input word 9 = 0xAAAA; a power cycle through 9001; then SW1 (input 0) shows
// Command Mode without Configuration Error (bit 13), no configuration written since.
TEST(ServeCli, AServedSmd23eLockedByAFlashSaveComesBackAfterAPowerCycle) {
  Served s("smd23e_power", {}, "smd23e");
  // v_s 100 (words 2-3), 2048 steps/turn, encoder 1024, 50 % idle, 2.0 A (L2265-L2341).
  const std::vector<std::uint16_t> config{0x8000, 0x8000, 0, 100, 2048, 0, 1024, 50, 20, 0};
  ASSERT_EQ(s.write(1024, config), 0) << s.why_not();
  std::vector<std::uint16_t> save = config;
  save[1] = 0x8400;
  ASSERT_EQ(s.write(1024, save), 0);
  ASSERT_EQ(s.input_registers(9, 1).words[0], 0xAAAA);
  ASSERT_EQ(s.write(1024, {0x0000, 0x8000}), 0); // Command Mode: not answered (locked)
  EXPECT_EQ(s.input_registers(9, 1).words[0], 0xAAAA);
  ASSERT_EQ(s.write(kPowerCycle, {20}), 0);
  const std::uint16_t sw1 = input_until(s, 0, [](std::uint16_t w) { return w != 0; });
  EXPECT_EQ(sw1 & 0xA000, 0) << std::hex << sw1; // Command Mode, Configuration Error 0
  EXPECT_NE(sw1 & 0x4000, 0) << std::hex << sw1; // Controller OK
  // The SMD23E has no Program switch and no keyboard: those controls are not its addresses.
  EXPECT_EQ(s.holding_registers(kProgramSwitch, 1).error, EMBXILADD);
  EXPECT_EQ(s.write(kProgramSwitch, {1}), EMBXILADD);
  EXPECT_EQ(s.write(kClearPair, {1}), EMBXILADD);
  EXPECT_EQ(s.holding_registers(kSupply, 1).words, std::vector<std::uint16_t>{1});
}

// SIGTERM and SIGINT are stop requests (StopSignals, as for `hilrig run`): the server leaves its
// loop, closes its clients and exits 0, with a client still connected.
TEST(ServeCli, SigtermOrSigintStopsTheServerCleanly) {
  for (const int signal : {SIGTERM, SIGINT}) {
    Served s(std::string("stop_") + std::to_string(signal), {"--model", "2741"});
    ASSERT_EQ(s.input_registers(0, 3).error, 0) << s.why_not();
    const std::optional<int> status = s.stop_with(signal);
    ASSERT_TRUE(status.has_value()) << "still serving after signal " << signal;
    EXPECT_TRUE(WIFEXITED(*status)) << "killed by signal " << (WIFSIGNALED(*status) ? WTERMSIG(*status) : 0);
    EXPECT_EQ(WIFEXITED(*status) ? WEXITSTATUS(*status) : -1, 0) << s.why_not();
  }
}

// A connection the server closes itself is named on stderr with its reason: here a length
// field of 0x300 = 768, where a Modbus TCP frame's MBAP length (unit id + PDU) is 2 .. 254, a
// PDU being at most 253 bytes (Modbus Application Protocol V1.1b3, §4.1; Messaging on TCP/IP
// Implementation Guide, §3.1.3).
TEST(ServeCli, AConnectionTheServerClosesIsNamedWithItsReason) {
  Served served("close_reason", {}, "ans1");
  ASSERT_GT(served.port(), 0) << served.why_not();
  const int fd = ::socket(AF_INET, SOCK_STREAM, 0);
  ASSERT_GE(fd, 0);
  sockaddr_in at{};
  at.sin_family = AF_INET;
  at.sin_port = htons(static_cast<std::uint16_t>(served.port()));
  at.sin_addr.s_addr = htonl(INADDR_LOOPBACK);
  ASSERT_EQ(::connect(fd, reinterpret_cast<const sockaddr*>(&at), sizeof at), 0);
  const std::array<std::uint8_t, 8> bad{0, 8, 0, 0, 0x03, 0x00, 1, 4}; // tid 8, protocol 0, length 768
  ASSERT_EQ(::send(fd, bad.data(), bad.size(), 0), static_cast<ssize_t>(bad.size()));
  std::array<std::uint8_t, 16> none{};
  EXPECT_EQ(::recv(fd, none.data(), none.size(), 0), 0); // the server closed it
  ::close(fd);
  const std::string said = "MBAP length 768 outside 2 .. 254 (unit id + a PDU of at most 253 bytes)";
  for (const auto until = Clock::now() + kDeadline;
       served.why_not().find(said) == std::string::npos && Clock::now() < until;)
    std::this_thread::sleep_for(std::chrono::milliseconds(5));
  EXPECT_NE(served.why_not().find("hilrig serve: closed 127.0.0.1:"), std::string::npos) << served.why_not();
  EXPECT_NE(served.why_not().find(said), std::string::npos) << served.why_not();
}

TEST(ServeCli, BadMotionOrParamIsRefusedBeforeServing) {
  for (const auto& opts : {std::vector<std::string>{"--motion", "300rpm"},
                           std::vector<std::string>{"--param", "min_stator_ratio=11"},
                           std::vector<std::string>{"--model", "2750"}}) {
    Served s("refused_" + opts[0].substr(2), opts);
    EXPECT_EQ(s.client(), nullptr);
    EXPECT_NE(s.why_not().find("hilrig serve"), std::string::npos) << s.why_not();
  }
}

} // namespace
} // namespace hilrig
