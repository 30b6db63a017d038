#include "rig/campaign/campaign_parser.hpp"
#include "rig/campaign/file_digest.hpp"

#include <algorithm>
#include <fstream>
#include <optional>
#include <sstream>

#include <fmt/format.h>

#include "rig/campaign/limits.hpp"
#include "rig/campaign/scenario_reader.hpp"
#include "rig/campaign/toml_file.hpp"
#include "rig/campaign/toml_reader.hpp"

namespace hilrig::campaign {

namespace {

// Splits "motion.move[1].speed_rpm" into ("motion", "move[1]", "speed_rpm") steps.
struct PathStep {
  std::string key;
  std::optional<std::size_t> index;
};

std::optional<std::vector<PathStep>> split_path(std::string_view path) {
  std::vector<PathStep> steps;
  std::size_t start = 0;
  while (start <= path.size()) {
    const std::size_t dot = path.find('.', start);
    std::string_view part =
        path.substr(start, dot == std::string_view::npos ? std::string_view::npos : dot - start);
    PathStep step;
    const std::size_t bracket = part.find('[');
    if (bracket != std::string_view::npos) {
      if (!part.ends_with(']')) return std::nullopt;
      const std::string digits(part.substr(bracket + 1, part.size() - bracket - 2));
      // At most 9 digits: no array of a file of at most 1 MiB is longer, and stoull cannot overflow.
      if (digits.empty() || digits.size() > 9 ||
          !std::all_of(digits.begin(), digits.end(), [](char c) { return c >= '0' && c <= '9'; }))
        return std::nullopt;
      step.index = static_cast<std::size_t>(std::stoull(digits));
      part = part.substr(0, bracket);
    }
    if (part.empty()) return std::nullopt;
    step.key = std::string(part);
    steps.push_back(std::move(step));
    if (dot == std::string_view::npos) break;
    start = dot + 1;
  }
  return steps;
}

// Sets the value at path in root (the parent must exist). False when the path is not there.
bool assign(toml::table& root, std::string_view path, const toml::node& value) {
  const auto steps = split_path(path);
  if (!steps || steps->empty()) return false;
  toml::table* table = &root;
  for (std::size_t i = 0; i + 1 < steps->size(); ++i) {
    const PathStep& s = (*steps)[i];
    toml::node* n = table->get(s.key);
    if (n == nullptr) return false;
    if (s.index) {
      auto* arr = n->as_array();
      if (arr == nullptr || *s.index >= arr->size()) return false;
      n = arr->get(*s.index);
    }
    table = n->as_table();
    if (table == nullptr) return false;
  }
  const PathStep& last = steps->back();
  if (last.index) return false;
  value.visit([&](const auto& v) { table->insert_or_assign(last.key, v); });
  return true;
}

struct Axis {
  SweepAxis info;
  const toml::array* values = nullptr;
};

std::vector<Axis> read_sweep(const std::string& file, TableReader& root) {
  std::vector<Axis> axes;
  std::size_t i = 0;
  for (const toml::table* t : root.tables("sweep")) {
    TableReader r(file, *t, fmt::format("sweep[{}]", i++));
    Axis a;
    a.info.key = r.string("key");
    a.info.where = r.pos("key");
    const toml::node* v = r.node("values");
    if (v == nullptr || v->as_array() == nullptr || v->as_array()->empty())
      r.fail("values", "expected a non-empty array of values");
    a.values = v->as_array();
    a.info.values = a.values->size();
    if (a.info.key.starts_with("sweep") || a.info.key.starts_with("fault"))
      r.fail("key",
             "a key of the scenario (dut, wiring, encoder, motion, stimulus, host, check, campaign.end)");
    for (const Axis& other : axes)
      if (other.info.key == a.info.key)
        r.fail("key", fmt::format("each key swept once; \"{}\" is swept twice", a.info.key));
    r.finish();
    axes.push_back(a);
  }
  return axes;
}

std::string value_text(const toml::node& n) {
  std::ostringstream os;
  n.visit([&](const auto& v) { os << v; });
  return os.str();
}

} // namespace

std::uint64_t run_seed(std::uint64_t base, std::size_t index) {
  std::uint64_t z = base + 0x9E3779B97F4A7C15ULL * (static_cast<std::uint64_t>(index) + 1U);
  z = (z ^ (z >> 30U)) * 0xBF58476D1CE4E5B9ULL;
  z = (z ^ (z >> 27U)) * 0x94D049BB133111EBULL;
  return z ^ (z >> 31U);
}

std::vector<RunSpec> plan_runs(const Campaign& campaign, std::uint64_t base_seed) {
  std::vector<RunSpec> runs;
  const auto reps = static_cast<std::size_t>(campaign.repeat);
  for (std::size_t p = 0; p < campaign.points.size(); ++p) {
    for (std::size_t r = 0; r < reps; ++r) {
      RunSpec run;
      run.index = runs.size();
      run.point = p;
      run.repetition = r;
      run.label = campaign.point_labels[p] + (reps > 1 ? fmt::format(" rep {}", r) : "");
      runs.push_back(std::move(run));
    }
  }
  for (std::size_t f = 0; f < campaign.faults.size(); ++f) {
    for (std::size_t p = 0; p < campaign.points.size(); ++p) {
      RunSpec run;
      run.index = runs.size();
      run.point = p;
      run.fault = f;
      run.label = fmt::format("fault {} ({})", campaign.faults[f].name, campaign.point_labels[p]);
      runs.push_back(std::move(run));
    }
  }
  for (RunSpec& run : runs) run.seed = run_seed(base_seed, run.index);
  return runs;
}

std::vector<RunSpec> shard(const std::vector<RunSpec>& runs, std::size_t k, std::size_t n) {
  std::vector<RunSpec> out;
  for (const RunSpec& r : runs)
    if (n != 0 && r.index % n == k) out.push_back(r);
  return out;
}

Campaign parse_campaign(std::string_view text, const std::string& file_name) {
  toml::table root = parse_toml(text, file_name);

  Campaign c;
  c.file = file_name;
  c.sha256 = sha256_hex(text);

  // The sweep is read from the file as written; every point is the file with the swept
  // keys replaced, read and checked whole, so a bad sweep value is caught before any run.
  TableReader top(file_name, root, "");
  const std::vector<Axis> axes = read_sweep(file_name, top);
  for (const Axis& a : axes) c.sweep.push_back(a.info);

  // The file as written is a campaign of its own, checked whole before any point: a value that
  // every point replaces is still the file's, and a typo in it must not hide behind the sweep.
  // Its errors are the ones the file would get without the sweep, naming no point.
  if (!axes.empty()) (void)read_scenario_file(file_name, parse_toml(text, file_name));

  // The plan's size before anything is allocated for it (a product of axes can overflow).
  std::size_t points = 1;
  for (const Axis& a : axes) {
    if (a.values->size() > limits::kMaxSweepPoints / points)
      throw CampaignError(file_name, a.info.where, "sweep",
                          fmt::format("at most {} sweep points (the product of every axis' values)",
                                      limits::kMaxSweepPoints));
    points *= a.values->size();
  }
  // Each point's pick of every axis (the last axis varies fastest).
  std::vector<std::vector<std::size_t>> picks(points, std::vector<std::size_t>(axes.size()));
  for (std::size_t p = 0; p < points; ++p) {
    std::size_t rest = p;
    for (std::size_t i = axes.size(); i-- > 0;) {
      picks[p][i] = rest % axes[i].values->size();
      rest /= axes[i].values->size();
    }
  }
  // The file with point p's swept keys replaced, then `fault`'s set keys (a fresh parse:
  // copied toml++ nodes lose their source positions).
  auto point_doc = [&](std::size_t p, std::optional<std::size_t> fault, std::string* label) {
    toml::table doc =
        p == 0 && axes.empty() && !fault && root.size() != 0 ? std::move(root) : parse_toml(text, file_name);
    for (std::size_t i = 0; i < axes.size(); ++i) {
      const toml::node& v = *axes[i].values->get(picks[p][i]);
      if (!assign(doc, axes[i].info.key, v))
        throw CampaignError(
            file_name, axes[i].info.where, fmt::format("sweep[{}].key", i),
            fmt::format("a key path in this file whose table exists (\"{}\" is not)", axes[i].info.key));
      if (label != nullptr)
        *label += fmt::format("{}{}={}", label->empty() ? "" : " ", axes[i].info.key, value_text(v));
    }
    if (fault) {
      // The values as written in this parse of the file (read_faults checked their shape
      // and that no key points into [[fault]], so assigning leaves this table alone).
      const toml::table* set = doc["fault"][*fault]["set"].as_table();
      if (set == nullptr) return doc;
      for (const auto& [k, v] : *set)
        if (!assign(doc, k.str(), v))
          throw CampaignError(
              file_name, pos_of(v), fmt::format("fault[{}].set", *fault),
              fmt::format("a key path in this file whose table exists (\"{}\" is not)", k.str()));
    }
    return doc;
  };
  // Reads a point; an error in a swept or set value (no position of its own) points at
  // the value in the sweep's array or the fault's table.
  auto read_point = [&](std::size_t p, std::optional<std::size_t> fault, std::string* label) {
    std::string own_label;
    if (label == nullptr) label = &own_label;
    toml::table doc = point_doc(p, fault, label);
    try {
      return read_scenario_file(file_name, doc);
    } catch (const CampaignError& e) {
      if (axes.empty() && !fault) throw;
      if (e.where().line != 0) {
        // The file as written was read whole first (or is point 0), so this error is the point's.
        // The line is the file's, but the value there may be fine alone: say which point, or
        // which fault's set, made it wrong (a swept encoder.lines makes a speed too fast).
        std::string in;
        if (!label->empty()) in = "sweep point " + *label;
        if (fault) {
          const toml::node* name = doc["fault"][*fault]["name"].node();
          const auto* fault_name = name != nullptr ? name->as_string() : nullptr;
          in +=
              (in.empty() ? "" : ", ") +
              fmt::format("fault \"{}\"", fault_name != nullptr ? fault_name->get() : std::to_string(*fault));
        }
        throw CampaignError(file_name, e.where(), e.key(), fmt::format("{} (in {})", e.expected(), in));
      }
      if (fault) {
        const toml::table* set = doc["fault"][*fault]["set"].as_table();
        throw CampaignError(file_name, set != nullptr ? pos_of(*set) : SourcePos{},
                            fmt::format("fault[{}].set: {}", *fault, e.key()), e.expected());
      }
      std::size_t axis = 0;
      for (std::size_t i = 0; i < axes.size(); ++i)
        if (e.key().starts_with(axes[i].info.key)) axis = i;
      throw CampaignError(file_name, pos_of(*axes[axis].values->get(picks[p][axis])), e.key(), e.expected());
    }
  };
  // Where a plan too big is pointed at: the repeat count, or the campaign table.
  SourcePos plan_at{};
  if (const toml::node* n = root["campaign"]["repeat"].node())
    plan_at = pos_of(*n);
  else if (const toml::node* t = root["campaign"].node())
    plan_at = pos_of(*t);
  for (std::size_t p = 0; p < points; ++p) {
    std::string label;
    ScenarioFile parsed = read_point(p, std::nullopt, &label);
    if (p == 0) {
      c.name = parsed.name;
      c.description = parsed.description;
      c.seed = parsed.seed;
      c.repeat = parsed.repeat;
      c.faults = parsed.faults;
      // points x repeat nominal runs, then points per fault (each factor is bounded already).
      const std::size_t runs = points * (static_cast<std::size_t>(c.repeat) + c.faults.size());
      if (runs > limits::kMaxRuns) {
        throw CampaignError(file_name, plan_at, "campaign.repeat",
                            fmt::format("a plan of at most {} runs ({} sweep point(s) x ({} repeat + {} "
                                        "fault(s)) is {}); split it into campaigns or sweeps",
                                        limits::kMaxRuns, points, c.repeat, c.faults.size(), runs));
      }
    }
    c.points.push_back(std::move(parsed.scenario));
    c.point_labels.push_back(label.empty() ? std::string("nominal") : label);
  }
  c.fault_points.resize(c.faults.size());
  for (std::size_t f = 0; f < c.faults.size(); ++f) {
    if (c.faults[f].set_keys.empty()) continue;
    for (std::size_t p = 0; p < points; ++p) c.fault_points[f].push_back(read_point(p, f, nullptr).scenario);
  }
  c.runs = plan_runs(c, c.seed);
  return c;
}

Campaign load_campaign(const std::string& path) {
  return parse_campaign(read_toml_text(path, "campaign file"), path);
}

} // namespace hilrig::campaign
