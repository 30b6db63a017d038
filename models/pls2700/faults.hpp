#pragma once
// Fault variants of the virtual 2700, selected by name, each breaking one documented behaviour
// so a campaign can show that its checks catch it.
#include <array>
#include <cstdint>
#include <optional>
#include <string_view>

namespace hilrig::models::pls2700 {

enum class Fault : std::uint8_t {
  Nominal,               // as specified
  LateOutputs,           // position/output update at twice the specified period
  AdvanceWrongSign,      // advances move edges later instead of earlier
  OffLeOnNotEnforced,    // a_off > a_on accepted on a standard (non -04) model
  TachWindowWrong,       // 30 ms tach response counts over 60 ms but scales as 30 ms
  ErrorLatchMissing,     // a bad instruction does not stop the rest, and no 24h afterwards
  AdvanceSpeedJitter,    // advances use one update's motion: the edge jitters, outputs chatter
  TachFirstIntervalLong, // the first tach value after a response-time change spans T + T_upd
};

struct FaultName {
  Fault fault;
  std::string_view name;
  std::string_view description;
};

inline constexpr std::array<FaultName, 8> kFaultNames{{
    {Fault::Nominal, "nominal", "as specified"},
    {Fault::LateOutputs, "late_outputs", "position/output update every 2 x 200/400 us"},
    {Fault::AdvanceWrongSign, "advance_wrong_sign", "advances move edges later instead of earlier"},
    {Fault::OffLeOnNotEnforced, "off_le_on_not_enforced",
     "OFF advance > ON advance accepted on a standard model"},
    {Fault::TachWindowWrong, "tach_window_wrong", "tach code 0 counts over 60 ms, scaled as 30 ms"},
    {Fault::ErrorLatchMissing, "error_latch_missing",
     "a bad instruction does not stop the rest of the BTW; no Message Ignored"},
    {Fault::AdvanceSpeedJitter, "advance_speed_jitter",
     "advances use the last update's motion alone, which alternates between adjacent counts: "
     "advanced edges jump by a x 1 count / T_upd and outputs chatter (several ON pulses a pass)"},
    {Fault::TachFirstIntervalLong, "tach_first_interval_long",
     "the first tach value after the response time is set also counts the update in progress: "
     "measured over T + T_upd, reads high (999.9 rpm at 0.1 rpm: 10007)"},
}};

[[nodiscard]] std::optional<Fault> fault_from_name(std::string_view name);
[[nodiscard]] std::string_view fault_name(Fault fault);

} // namespace hilrig::models::pls2700
