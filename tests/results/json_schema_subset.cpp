#include "json_schema_subset.hpp"

#include <algorithm>
#include <set>

namespace hilrig::rig::test {
namespace {

using nlohmann::json;

bool has_type(const json& v, const std::string& t) {
  if (t == "object") return v.is_object();
  if (t == "array") return v.is_array();
  if (t == "string") return v.is_string();
  if (t == "boolean") return v.is_boolean();
  if (t == "null") return v.is_null();
  if (t == "number") return v.is_number();
  if (t == "integer")
    return v.is_number_integer() ||
           (v.is_number_float() &&
            v.get<double>() == static_cast<double>(static_cast<long long>(v.get<double>())));
  return false;
}

struct Checker {
  const json& root;
  std::vector<std::string> errors;

  const json& resolve(const std::string& ref) {
    const std::string prefix = "#/$defs/";
    if (ref.rfind(prefix, 0) != 0) {
      errors.push_back("unsupported $ref " + ref);
      static const json empty = json::object();
      return empty;
    }
    return root.at("$defs").at(ref.substr(prefix.size()));
  }

  void check(const json& s, const json& v, const std::string& path) {
    static const std::set<std::string> known{
        "$schema", "$id",     "title",    "description", "type",
        "enum",    "const",   "required", "properties",  "additionalProperties",
        "items",   "minimum", "oneOf",    "$ref",        "$defs"};
    for (const auto& [k, unused] : s.items()) {
      if (!known.contains(k)) errors.push_back(path + ": unsupported keyword " + k);
    }
    if (s.contains("$ref")) check(resolve(s.at("$ref").get<std::string>()), v, path);
    if (s.contains("type")) {
      const json& t = s.at("type");
      const bool ok = t.is_string() ? has_type(v, t.get<std::string>())
                                    : std::any_of(t.begin(), t.end(), [&](const json& x) {
                                        return has_type(v, x.get<std::string>());
                                      });
      if (!ok) {
        errors.push_back(path + ": expected type " + t.dump() + ", got " + v.dump());
        return;
      }
    }
    if (s.contains("const") && v != s.at("const"))
      errors.push_back(path + ": expected " + s.at("const").dump());
    if (s.contains("enum")) {
      const json& e = s.at("enum");
      if (std::find(e.begin(), e.end(), v) == e.end())
        errors.push_back(path + ": " + v.dump() + " not in enum");
    }
    if (s.contains("minimum") && v.is_number() && v.get<double>() < s.at("minimum").get<double>()) {
      errors.push_back(path + ": below minimum");
    }
    if (s.contains("oneOf")) {
      int matches = 0;
      for (const auto& alt : s.at("oneOf")) {
        Checker sub{root, {}};
        sub.check(alt, v, path);
        if (sub.errors.empty()) ++matches;
      }
      if (matches != 1) errors.push_back(path + ": matches " + std::to_string(matches) + " of oneOf");
    }
    if (v.is_object()) {
      if (s.contains("required")) {
        for (const auto& r : s.at("required")) {
          if (!v.contains(r.get<std::string>()))
            errors.push_back(path + ": missing required " + r.get<std::string>());
        }
      }
      const json props = s.value("properties", json::object());
      for (const auto& [k, child] : v.items()) {
        if (props.contains(k)) {
          check(props.at(k), child, path + "/" + k);
        } else if (s.contains("additionalProperties") && s.at("additionalProperties") == false) {
          errors.push_back(path + ": unexpected property " + k);
        }
      }
    }
    if (v.is_array() && s.contains("items")) {
      for (std::size_t i = 0; i < v.size(); ++i) check(s.at("items"), v[i], path + "/" + std::to_string(i));
    }
  }
};

} // namespace

std::vector<std::string> validate_json_schema(const json& schema, const json& doc) {
  Checker c{schema, {}};
  c.check(schema, doc, "");
  return c.errors;
}

} // namespace hilrig::rig::test
