#pragma once
// The far-side config of `hilrig serve --far FILE`: which gpio-sim line each of the served
// board's pins sits on, and the resolver-emulator node that turns the rig's ResolverAngle
// frames into the board's stator signals. Errors are "file:line:column: key: what was
// expected", as for campaign files.
//
//   [[pin]]                 # one per board pin on the gpio-sim chip
//   board = "A"             # the board's pin name (as a campaign's [[wiring]] board = ...)
//   offset = 0              # the gpio-sim line; the rig config puts the rig's line on it
//
//   [resolver]              # optional: the node on --can
//   sin = "SIN"             # the board pins its stators feed ("SIN", "COS")
//   cos = "COS"
//   channel = 0             # ResolverAngle channel 0..15
//   frame_period = "1ms"    # the rig's stream period
//   timeout_periods = 3     # stators to zero after this many periods without a frame
//   ratio = 1.0             # transformation ratio
//   excitation_hz = 5000    # the board's reference the node locks to
//   amplitude = 1.0

#include <cstdint>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "core/time.hpp"
#include "rig/campaign/campaign_error.hpp"

namespace hilrig::far {

struct FarPin {
  std::string board;
  unsigned offset = 0;
  campaign::SourcePos where;
};

struct FarResolver {
  std::string sin_pin = "SIN";
  std::string cos_pin = "COS";
  std::uint8_t channel = 0;
  Nanos frame_period = milliseconds(1);
  unsigned timeout_periods = 3;
  double ratio = 1.0;
  double excitation_hz = 5000.0; // the ANS1 model's reference ([MODEL] in its README)
  double amplitude = 1.0;
  campaign::SourcePos where;
};

struct FarConfig {
  std::string file; // as given, for messages
  std::vector<FarPin> pins;
  std::optional<FarResolver> resolver;
};

// Throws campaign::CampaignError naming the file, line, column and key.
[[nodiscard]] FarConfig parse_far_config(std::string_view text, const std::string& file_name);
[[nodiscard]] FarConfig load_far_config(const std::string& path);

} // namespace hilrig::far
