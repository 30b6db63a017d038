#pragma once
// SocketCAN error frames decoded into what a test engineer asks: which state is the
// controller in (error-active, warning, passive, bus-off), did it restart, and what kind
// of bus error was seen. Pure: decoded from the frame's ID and data (linux/can/error.h).

#include <array>
#include <cstdint>
#include <optional>
#include <string>

namespace hilrig::socketcan {

enum class BusState : std::uint8_t { ErrorActive, ErrorWarning, ErrorPassive, BusOff };

[[nodiscard]] constexpr const char* to_string(BusState s) {
  switch (s) {
  case BusState::ErrorActive:
    return "error-active";
  case BusState::ErrorWarning:
    return "error-warning";
  case BusState::ErrorPassive:
    return "error-passive";
  case BusState::BusOff:
    return "bus-off";
  }
  return "?";
}

struct ErrorReport {
  std::optional<BusState> state; // a state the controller entered, when the frame says so
  bool restarted = false;        // the controller left bus-off (restart-ms or manual)
  bool tx_timeout = false;
  bool lost_arbitration = false;
  bool protocol_violation = false; // bit, form, stuff error...
  bool no_ack = false;             // nobody acknowledged our frame
  bool transceiver = false;
  bool rx_overflow = false;
  bool tx_overflow = false;
  std::optional<std::uint8_t> tx_errors;      // TEC, when the frame carries counters
  std::optional<std::uint8_t> rx_errors;      // REC
  [[nodiscard]] std::string describe() const; // "bus-off; no ACK; TEC 255"
};

// Decodes an error frame: can_id with CAN_ERR_FLAG set, and its 8 data bytes.
[[nodiscard]] ErrorReport decode_error_frame(std::uint32_t can_id, const std::array<std::uint8_t, 8>& data);

// The controller's state as a sequence of error reports leaves it.
class BusStateTracker {
public:
  void apply(const ErrorReport& r);
  [[nodiscard]] BusState state() const { return state_; }
  [[nodiscard]] std::uint32_t bus_off_count() const { return bus_offs_; }
  [[nodiscard]] std::uint32_t restart_count() const { return restarts_; }
  // Error frames that said the controller lost frames (CAN_ERR_CRTL_RX/TX_OVERFLOW): one
  // report each, as the driver raises one per overrun it sees.
  [[nodiscard]] std::uint32_t rx_overflow_count() const { return rx_overflows_; }
  [[nodiscard]] std::uint32_t tx_overflow_count() const { return tx_overflows_; }

private:
  BusState state_ = BusState::ErrorActive;
  std::uint32_t bus_offs_ = 0;
  std::uint32_t restarts_ = 0;
  std::uint32_t rx_overflows_ = 0;
  std::uint32_t tx_overflows_ = 0;
};

} // namespace hilrig::socketcan
