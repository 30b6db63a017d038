#pragma once
// What the rig can honour, as the campaign's own keys' ranges (devices declare their
// parameters' ranges beside them, rig/duts), and the text that names a range in an error.
// docs/campaigns.md lists every one. A value outside is bad input (exit 2) before anything runs.

#include <cstddef>
#include <cstdint>
#include <string>
#include <string_view>

#include "core/time.hpp"
#include "rig/duts/dut.hpp"

namespace hilrig::campaign::limits {

// A run is at most an hour of machine time: a DUT scanning every 10 us (ANS1, docs/spec/ans1.md
// L187) is 3.6 * 10^8 scans in virtual time, minutes of CPU. Longer soaks are `repeat`.
inline constexpr Nanos kMaxEnd = seconds(3'600);
// Host polling and the like: at least 10 us (a Modbus RTU frame at 115200 baud takes ~1 ms;
// nothing polls faster), at most 1 s.
inline constexpr Nanos kMinHostPoll = microseconds(10);
inline constexpr Nanos kMaxHostPoll = seconds(1);
// A host word: 0 .. 0xFFFF, or a PLC INT -32768 .. -1 written as its two's complement.
inline constexpr std::int64_t kMinWord = -32'768;
inline constexpr std::int64_t kMaxWord = 0xFFFF;
// A late-edge tolerance beyond 1 s judges nothing.
inline constexpr Nanos kMaxEdgeTolerance = seconds(1);

// Shaft speed: the boards report speed as a signed 16-bit rpm word, +-32767 (ANS1
// docs/spec/ans1.md L1024, manual L2019-L2020); the Series 2700 tach stops at 5000 rpm (L578).
inline constexpr double kMaxRpm = 32'767.0;
// The slowest cruise of a trapezoid or press stroke: 0.01 rpm (the ANS1's speed word's
// resolution is 1 rpm; below this a move's time overflows the run).
inline constexpr double kMinCruiseRpm = 0.01;
// Accelerations and brake decelerations: 0 .. 10^6 rpm/s (a stop from 32767 rpm in 33 ms).
inline constexpr double kMaxRpmPerS = 1'000'000.0;
// An SSI transducer's monoflop time TM (the time bit 25 stays valid, "typically 12 to 20 uS",
// 7361 manual L1091-1092): longer than half a clock period, at most 1 ms. Every clock edge
// retriggers it (signals/ssi_slave.hpp), so one that runs out within a half period returns DATA
// to idle inside the frame, and the 7361 reads all ones. `[ssi] monoflop` and `hilrig synth ssi
// --monoflop` take this range: synth with its own clock's half period; a campaign with that of
// the slower clock the 7361 can be set to at run time (125 or 500 kHz, L1123, L2150-2152):
// 125 kHz, T = 8 us, half 4 us (a 50 % duty, [MODEL] docs/spec/ssi7361.md).
inline constexpr Nanos kMaxMonoflop = milliseconds(1);
inline constexpr Nanos kSlowestSsiHalfClock = microseconds(4);
[[nodiscard]] constexpr bool monoflop_in_range(Nanos tm, Nanos half_clock) {
  return tm > half_clock && tm <= kMaxMonoflop;
}
// The range in words: `half_clock` as written ("4us"), `clock` the clock it is half a period of
// ("the 125 kHz clock"). Header-only, as `hilrig synth` links no campaign reader.
[[nodiscard]] inline std::string monoflop_range(std::string_view half_clock, std::string_view clock) {
  return "a monoflop time above " + std::string(half_clock) + " (half a period of " + std::string(clock) +
         ": at or below it DATA returns to idle inside a frame), at most 1ms (typically 12 to 20 us, L1091)";
}
// Distances and start positions in turns, and strokes.
inline constexpr double kMaxTurns = 10'000.0;
inline constexpr std::int64_t kMaxStrokes = 10'000;
// [motion] cycles: the move list played again and again; the moves of all cycles together
// are bounded like a plan (each is held, and solved, once).
inline constexpr std::int64_t kMaxCycles = 10'000;
inline constexpr std::int64_t kMaxMoves = 100'000;
// The encoder's X4 count rate: the fastest encoder input of the boards is the 4501's,
// 250 kHz per channel = 1,000,000 counts/s (docs/spec/amci4501.md L292, manual L271).
inline constexpr double kMaxCountsPerS = 1'000'000.0;
// Resolver excitation the rig synthesizes: 400 Hz .. 10 kHz covers the ANS1's accepted band
// (2.2 .. 7 kHz, docs/spec/ans1.md L60) and the common resolver references; amplitude 0 .. 100
// (the stators' unit), transformation ratio 0 .. 10.
inline constexpr double kMinExcitationHz = 400.0;
inline constexpr double kMaxExcitationHz = 10'000.0;
inline constexpr double kMaxAmplitude = 100.0;
inline constexpr double kMaxRatio = 10.0;
// Contact bounce: at most 10,000 toggles in one bounce stimulus; every n-th edge lost, n <= 10^6.
inline constexpr std::int64_t kMaxBounceEdges = 10'000;
inline constexpr std::int64_t kMaxEvery = 1'000'000;

// The plan: every run is held in memory as a RunSpec and every sweep point as a whole
// scenario, so both are bounded; a bigger study is several campaigns or --shard.
inline constexpr std::int64_t kMaxRepeat = 10'000;
inline constexpr std::size_t kMaxSweepPoints = 1'000;
inline constexpr std::size_t kMaxRuns = 10'000;

// The campaign file: at most 1 MiB (the largest shipped campaign is ~7 KB), a regular file,
// and no dotted key or table header of more than 64 parts (toml++ nests a table per part, and
// tens of thousands overflow the stack).
inline constexpr std::uintmax_t kMaxFileBytes = 1U << 20U;
inline constexpr std::size_t kMaxKeyParts = 64;

// A label the outputs carry for traceability ([dut] serial, --station): 1 .. 64 printable
// ASCII characters, so it reads the same in a report, an XML attribute and a terminal.
inline constexpr std::size_t kMaxLabel = 64;

} // namespace hilrig::campaign::limits

namespace hilrig::campaign {

// "250us", "1.5ms", "1s": the largest unit that writes the duration exactly.
[[nodiscard]] std::string duration_text(Nanos d);
// "1us .. 1ms", "-32768 .. 32767", "one of rising, falling".
[[nodiscard]] std::string range_text(duts::ParamKind kind, const duts::ParamRange& range);
// What a value of the kind is written as, after "expected " in an error: "an integer", "a
// number", "a duration with a unit, like ...", "true or false", "a string". The campaign
// reader and `hilrig serve --param` name a value of the wrong kind with it.
[[nodiscard]] std::string kind_text(duts::ParamKind kind);
// A number written as nan or inf (TOML allows both; no campaign quantity is either).
inline constexpr std::string_view kNotFiniteText = "a finite number (nan and inf are not values here)";
// A device parameter's valid values, for a value of its kind outside them: "a value in 0s ..
// 10ms (amci4501 input edge to response (L281))", "one of rising, falling (amci4501 ...)". The campaign
// reader and `hilrig serve --param` say it alike.
[[nodiscard]] std::string param_range_text(std::string_view device, const duts::ParamInfo& param);
// Whether `text` is a traceability label (limits::kMaxLabel), and the range an error names.
[[nodiscard]] bool is_label(const std::string& text);
[[nodiscard]] std::string label_range();

} // namespace hilrig::campaign
