#pragma once
// Escaping text for XML and HTML attributes and content (both writers share it).

#include <string>
#include <string_view>

namespace hilrig::rig {

// Escapes & < > " ' and drops the control characters XML 1.0 forbids (all below 0x20 but
// tab, newline and carriage return), so any detail sentence yields a well-formed document.
[[nodiscard]] std::string xml_escape(std::string_view text);

} // namespace hilrig::rig
