#pragma once
// Streaming VCD: writes a trace to a file while the run goes on, so a crash leaves a readable
// file. The header (every signal declared so far and its initial value) is written on the
// first update(); each later update() appends what was recorded since, and flushes.
//
//   TraceRecorder trace;  ... declare lines ...
//   std::ofstream file("run.vcd");
//   VcdStream vcd(file);
//   vcd.update(trace);                       // header
//   every 100 ms of virtual time: vcd.update(trace);
//
// The output of update() calls is byte-identical to write_vcd() of the same trace when the
// samples were recorded in time order (as the scheduler records them).

#include <cstddef>
#include <cstdint>
#include <iosfwd>
#include <string>
#include <string_view>

#include "core/trace.hpp"

namespace hilrig {

class VcdStream {
public:
  explicit VcdStream(std::ostream& out, std::string_view date_comment = "");

  // Appends every sample recorded since the last call and flushes the stream.
  void update(const TraceRecorder& trace);

  // Samples not written: of signals declared after the header was written.
  [[nodiscard]] std::size_t skipped() const { return skipped_; }
  // Samples recorded earlier than one already written; written at the later time.
  [[nodiscard]] std::size_t late() const { return late_; }

private:
  std::ostream& out_;
  std::string date_;
  bool started_ = false;
  std::size_t declared_ = 0; // signals in the header
  std::size_t next_ = 0;     // next sample index to write
  std::int64_t time_ = 0;    // time of the last "#t" written
  std::size_t skipped_ = 0;
  std::size_t late_ = 0;
};

} // namespace hilrig
