#include "drivers/socketcan/bus_state.hpp"

#include <linux/can.h>
#include <linux/can/error.h>

namespace hilrig::socketcan {

ErrorReport decode_error_frame(std::uint32_t can_id, const std::array<std::uint8_t, 8>& data) {
  ErrorReport r;
  const std::uint32_t cls = can_id & CAN_ERR_MASK;
  r.tx_timeout = (cls & CAN_ERR_TX_TIMEOUT) != 0;
  r.lost_arbitration = (cls & CAN_ERR_LOSTARB) != 0;
  r.protocol_violation = (cls & CAN_ERR_PROT) != 0;
  r.transceiver = (cls & CAN_ERR_TRX) != 0;
  r.no_ack = (cls & CAN_ERR_ACK) != 0;
  r.restarted = (cls & CAN_ERR_RESTARTED) != 0;
  if ((cls & CAN_ERR_CRTL) != 0) {
    const std::uint8_t c = data[1];
    r.rx_overflow = (c & CAN_ERR_CRTL_RX_OVERFLOW) != 0;
    r.tx_overflow = (c & CAN_ERR_CRTL_TX_OVERFLOW) != 0;
    // The most severe state the byte names wins.
    if ((c & (CAN_ERR_CRTL_RX_PASSIVE | CAN_ERR_CRTL_TX_PASSIVE)) != 0) {
      r.state = BusState::ErrorPassive;
    } else if ((c & (CAN_ERR_CRTL_RX_WARNING | CAN_ERR_CRTL_TX_WARNING)) != 0) {
      r.state = BusState::ErrorWarning;
    } else if ((c & CAN_ERR_CRTL_ACTIVE) != 0) {
      r.state = BusState::ErrorActive;
    }
  }
  if ((cls & CAN_ERR_BUSOFF) != 0) r.state = BusState::BusOff;
  if ((cls & CAN_ERR_CNT) != 0) {
    r.tx_errors = data[6];
    r.rx_errors = data[7];
  }
  return r;
}

std::string ErrorReport::describe() const {
  std::string s;
  auto add = [&s](const std::string& part) { s += (s.empty() ? "" : "; ") + part; };
  if (state) add(to_string(*state));
  if (restarted) add("restarted");
  if (no_ack) add("no ACK");
  if (protocol_violation) add("protocol violation");
  if (lost_arbitration) add("lost arbitration");
  if (tx_timeout) add("TX timeout");
  if (transceiver) add("transceiver fault");
  if (rx_overflow) add("RX overflow");
  if (tx_overflow) add("TX overflow");
  if (tx_errors) add("TEC " + std::to_string(*tx_errors));
  if (rx_errors) add("REC " + std::to_string(*rx_errors));
  return s.empty() ? "error frame" : s;
}

void BusStateTracker::apply(const ErrorReport& r) {
  if (r.rx_overflow) ++rx_overflows_;
  if (r.tx_overflow) ++tx_overflows_;
  if (r.restarted) {
    // After a restart the controller is error-active again.
    ++restarts_;
    state_ = BusState::ErrorActive;
  }
  if (r.state) {
    if (*r.state == BusState::BusOff && state_ != BusState::BusOff) ++bus_offs_;
    state_ = *r.state;
  }
}

} // namespace hilrig::socketcan
