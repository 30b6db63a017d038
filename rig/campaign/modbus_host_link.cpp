#include "rig/campaign/modbus_host_link.hpp"

#include <unistd.h>

#include <cerrno>
#include <cstring>
#include <span>
#include <stdexcept>

#include <fmt/format.h>

#include "drivers/hostlink/modbus_client.hpp"

namespace hilrig::campaign {

namespace {

const char* exception_name(RegisterStatus s) {
  switch (s) {
  case RegisterStatus::IllegalFunction:
    return "illegal function";
  case RegisterStatus::IllegalDataAddress:
    return "illegal data address";
  case RegisterStatus::IllegalDataValue:
    return "illegal data value";
  case RegisterStatus::DeviceFailure:
    return "device failure";
  case RegisterStatus::Ok:
    break;
  }
  return "ok";
}

void check(RegisterStatus s, const std::string& transaction) {
  if (s == RegisterStatus::Ok) return;
  throw std::runtime_error(fmt::format("host link: {}: the board answered exception {} ({})", transaction,
                                       static_cast<int>(s), exception_name(s)));
}

} // namespace

// Releases the turn for one transaction and takes it back however the transaction ends.
class ModbusHostLink::InFlight {
public:
  explicit InFlight(std::unique_lock<std::mutex>& held) : held_(held) {
    if (held_.owns_lock()) held_.unlock();
  }
  ~InFlight() {
    if (held_.mutex() != nullptr) held_.lock();
  }
  InFlight(const InFlight&) = delete;
  InFlight& operator=(const InFlight&) = delete;

private:
  std::unique_lock<std::mutex>& held_;
};

ModbusHostLink::ModbusHostLink(std::unique_ptr<RegisterMap> client, const HostRegisters& at,
                               std::shared_ptr<std::mutex> turn, std::shared_ptr<void> board)
    : at_(at), turn_(std::move(turn)), board_(std::move(board)), client_(std::move(client)) {
  if (turn_) held_ = std::unique_lock<std::mutex>(*turn_);
}

ModbusHostLink::~ModbusHostLink() {
  // A board still answering a request the client gave up on waits for the turn: give it
  // back for good before the board is stopped (the simulation touches the DUT no more).
  if (held_.owns_lock()) held_.unlock();
  client_.reset();
  board_.reset();
}

void ModbusHostLink::write(std::size_t word, std::uint16_t value) {
  const auto address = static_cast<std::uint16_t>(at_.command_base + word);
  RegisterStatus s = RegisterStatus::Ok;
  {
    const InFlight turn(held_);
    s = client_->write_holding_registers(address, std::span<const std::uint16_t>(&value, 1));
  }
  check(s, fmt::format("write holding register {} (command word {})", address, word));
}

std::uint16_t ModbusHostLink::read(std::size_t word) {
  const auto address = static_cast<std::uint16_t>(at_.status_base + word);
  std::uint16_t value = 0;
  RegisterStatus s = RegisterStatus::Ok;
  {
    const InFlight turn(held_);
    s = client_->read_input_registers(address, std::span<std::uint16_t>(&value, 1));
  }
  check(s, fmt::format("read input register {} (status word {})", address, word));
  return value;
}

namespace {

drivers::modbus::RtuServerOptions board_options() {
  drivers::modbus::RtuServerOptions o;
  o.unit = 1;
  return o;
}

int dup_or_throw(int fd) {
  const int copy = ::dup(fd);
  if (copy < 0) throw std::runtime_error(std::string("pty board: dup: ") + std::strerror(errno));
  return copy;
}

} // namespace

PtyBoard::PtyBoard(duts::Dut& dut, const HostRegisters& at, std::mutex& turn)
    : registers_(dut, at, turn), server_(registers_, pty_.master_fd(), board_options()),
      master_(io_, dup_or_throw(pty_.master_fd())) {
  wait_for_frame();
  thread_ = std::thread([this] { io_.run(); });
}

PtyBoard::~PtyBoard() {
  io_.stop();
  if (thread_.joinable()) thread_.join();
}

void PtyBoard::wait_for_frame() {
  master_.async_wait(
      boost::asio::posix::stream_descriptor::wait_read, [this](const boost::system::error_code& ec) {
        if (ec) return;
        server_.serve_once(); // the frame is there: poll returns at once and the server answers it
        wait_for_frame();
      });
}

std::unique_ptr<HostWords> modbus_rtu_pty_link(duts::Dut& dut, const HostRegisters& at,
                                               Nanos response_timeout) {
  auto turn = std::make_shared<std::mutex>();
  auto board = std::make_shared<PtyBoard>(dut, at, *turn);
  hostlink::RtuSettings settings;
  settings.device = board->device();
  settings.response_timeout = response_timeout;
  return std::make_unique<ModbusHostLink>(hostlink::ModbusClient::rtu(settings), at, std::move(turn),
                                          std::move(board));
}

} // namespace hilrig::campaign
