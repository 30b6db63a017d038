#pragma once
// Reading a TOML file the rig is given (a campaign, a rig config, a far-side config) so that
// no file can hang, exhaust or crash it: the path must name a regular file of at most
// limits::kMaxFileBytes (not /dev/zero, a FIFO or a directory), and no dotted key or table
// header may have more than limits::kMaxKeyParts parts (toml++ nests one table per part and
// recurses through them). Every refusal is a CampaignError (bad input, exit 2).

#include <string>
#include <string_view>

#include <toml++/toml.h>

namespace hilrig::campaign {

// The text of the file at path; `what` names it in messages ("campaign file").
[[nodiscard]] std::string read_toml_text(const std::string& path, std::string_view what);
// The parsed text; file_name is used in messages.
[[nodiscard]] toml::table parse_toml(std::string_view text, const std::string& file_name);

} // namespace hilrig::campaign
