#pragma once
// The trace recorder: takes every edge, CAN frame, serial byte and named value with its
// timestamp, in the order they happen. Writers turn it into a VCD file (GTKWave,
// PulseView) and a candump-format CAN log; content_hash() fingerprints it so two runs
// can be compared byte for byte.

#include <cstdint>
#include <iosfwd>
#include <string>
#include <string_view>
#include <vector>

#include "core/can_frame.hpp"
#include "core/line.hpp"
#include "core/time.hpp"

namespace hilrig {

enum class SignalKind : std::uint8_t {
  Wire,    // a digital line (1 bit)
  Integer, // a multi-bit value (counts, register words), up to 64 bits
  Real,    // an analog value
};

struct SignalInfo {
  std::string name;  // hierarchical with '.', e.g. "rig.enc.A" or "dut.ls1"
  SignalKind kind = SignalKind::Wire;
  std::uint8_t width = 1; // bits, for Integer
};

enum class SerialDirection : std::uint8_t { AtoB, BtoA };

struct TraceSample {
  Nanos time;
  std::uint32_t signal; // index into signals()
  std::int64_t value;   // Wire: 0/1; Integer: the value
  double real;          // Real only
};

struct TraceCanFrame {
  Nanos time; // end of frame
  std::string bus;
  CanFrame frame;
};

struct TraceSerialByte {
  Nanos time; // end of stop bit
  std::string link;
  SerialDirection direction;
  std::uint8_t byte;
};

class TraceRecorder {
public:
  // Declares a signal; declaring the same name twice returns the same index.
  std::uint32_t declare(std::string_view name, SignalKind kind = SignalKind::Wire, std::uint8_t width = 1);

  void edge(std::uint32_t signal, const Edge& e);
  void value(std::uint32_t signal, Nanos t, std::int64_t v);
  void real(std::uint32_t signal, Nanos t, double v);
  void can(std::string_view bus, Nanos t, const CanFrame& frame);
  void serial(std::string_view link, SerialDirection dir, Nanos t, std::uint8_t byte);

  [[nodiscard]] const std::vector<SignalInfo>& signals() const { return signals_; }
  [[nodiscard]] const std::vector<TraceSample>& samples() const { return samples_; }
  [[nodiscard]] const std::vector<TraceCanFrame>& can_frames() const { return can_; }
  [[nodiscard]] const std::vector<TraceSerialByte>& serial_bytes() const { return serial_; }
  // Edges of one Wire signal, in time order.
  [[nodiscard]] std::vector<Edge> edges_of(std::string_view name) const;
  [[nodiscard]] std::int64_t find(std::string_view name) const; // -1 when absent

  // FNV-1a 64 over a canonical serialisation of everything recorded.
  [[nodiscard]] std::uint64_t content_hash() const;

private:
  std::vector<SignalInfo> signals_;
  std::vector<TraceSample> samples_;
  std::vector<TraceCanFrame> can_;
  std::vector<TraceSerialByte> serial_;
};

// VCD (IEEE 1364 §18): 1 ns timescale, scopes from the dotted names.
void write_vcd(const TraceRecorder& trace, std::ostream& out, std::string_view date_comment = "");
// candump -l format: "(seconds.micros) bus ID#DATA" / "ID##FDATA" for FD.
void write_candump(const TraceRecorder& trace, std::ostream& out);

} // namespace hilrig
