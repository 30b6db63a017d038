#pragma once
// A small JSON Schema (2020-12) checker for the keywords docs/results.schema.json uses:
// type, enum, const, required, properties, additionalProperties (false), items, minimum,
// oneOf and local $ref ("#/$defs/..."). Any other keyword is reported as unsupported, so the
// schema cannot silently grow past what this test checks. Written independently of the
// results writer: it knows nothing of hilrig.

#include <string>
#include <vector>

#include <nlohmann/json.hpp>

namespace hilrig::rig::test {

// Every violation, as "path: message"; empty when `doc` validates against `schema`.
std::vector<std::string> validate_json_schema(const nlohmann::json& schema, const nlohmann::json& doc);

} // namespace hilrig::rig::test
