#pragma once
// A host-link transaction that failed on the wire (not an exception reply, which is the
// device's own answer and comes back as a RegisterStatus). The message names the
// transaction, so a report can say which register access was lost.

#include <stdexcept>
#include <string>

namespace hilrig::hostlink {

enum class LinkFailure {
  Timeout,        // no (complete) reply within the response timeout: a silent peer
  BadCrc,         // RTU reply whose CRC did not match: corruption on the line
  BadReply,       // reply of the wrong length, function or unit: a confused peer
  ConnectionLost, // the TCP connection or the serial device went away
  Other,
};

[[nodiscard]] constexpr const char* to_string(LinkFailure f) {
  switch (f) {
  case LinkFailure::Timeout:
    return "timeout";
  case LinkFailure::BadCrc:
    return "bad CRC";
  case LinkFailure::BadReply:
    return "bad reply";
  case LinkFailure::ConnectionLost:
    return "connection lost";
  case LinkFailure::Other:
    break;
  }
  return "link error";
}

class HostLinkError : public std::runtime_error {
public:
  HostLinkError(LinkFailure failure, const std::string& transaction, const std::string& detail)
      : std::runtime_error(transaction + ": " + to_string(failure) +
                           (detail.empty() ? "" : " (" + detail + ")")),
        failure_(failure), transaction_(transaction) {}
  [[nodiscard]] LinkFailure failure() const { return failure_; }
  [[nodiscard]] const std::string& transaction() const { return transaction_; }

private:
  LinkFailure failure_;
  std::string transaction_;
};

} // namespace hilrig::hostlink
