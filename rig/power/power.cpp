#include "rig/power/power.hpp"

#include <algorithm>
#include <cmath>
#include <functional>
#include <limits>
#include <map>
#include <optional>
#include <variant>

#include <fmt/format.h>

#include "rig/campaign/check_selection.hpp"
#include "rig/campaign/executive.hpp"
#include "rig/duts/dut.hpp"
#include "rig/power/bisect.hpp"
#include "rig/power/knobs.hpp"

namespace hilrig::power {
namespace {

// How far a measurement lies beyond the limit it broke, as a fraction of that limit (of 1 when
// the limit is 0); nullopt when it broke none (a failure without a value).
struct Excess {
  double fraction = 0.0;
  double limit = 0.0;
};
std::optional<Excess> excess(const rig::Measurement& m) {
  const auto over = [](double by, double limit) {
    return Excess{by / std::max(std::abs(limit), 1e-300), limit};
  };
  if (m.upper && m.value > *m.upper)
    return *m.upper == 0.0 ? Excess{m.value, 0.0} : over(m.value - *m.upper, *m.upper);
  if (m.lower && m.value < *m.lower)
    return *m.lower == 0.0 ? Excess{-m.value, 0.0} : over(*m.lower - m.value, *m.lower);
  return std::nullopt;
}

// The knob of a press plant's brake: every brake torque the scenario gives, from the start and
// in each [[plant.change]] (which states the whole parameter set in force from its time).
void scale_brake_torque(campaign::Scenario& s, double factor) {
  if (!s.plant) return;
  s.plant->press.brake_torque *= factor;
  for (plants::ParamChange<plants::PressParams>& change : s.plant->press_changes)
    change.params.brake_torque *= factor;
}

// One probe's finding: the check's outcome over every nominal run, and its most failing measurement.
struct Finding {
  Probe probe = Probe::Pass;
  std::optional<rig::Measurement> worst;
  std::optional<Excess> worst_excess;
  std::optional<rig::Measurement> coverage; // the least covered run's `<check>.phase_coverage`
  std::string error;
};

Finding judge_check(const rig::CampaignResult& result, const std::string& check) {
  Finding f;
  bool judged = false;
  for (const rig::RunResult& run : result.runs) {
    if (!run.error.empty()) {
      f.probe = Probe::Error;
      f.error = run.error;
      return f;
    }
    for (const rig::CheckResult& c : run.checks) {
      if (c.check != check) continue;
      judged = true;
      for (const rig::Measurement& m : c.measurements)
        if (m.name == check + ".phase_coverage" && (!f.coverage || m.value < f.coverage->value))
          f.coverage = m;
      const rig::Outcome o = c.outcome();
      if (o == rig::Outcome::Error) {
        f.probe = Probe::Error;
        f.error = c.measurements.empty() ? "nothing judged" : c.measurements.front().detail;
        return f;
      }
      if (o != rig::Outcome::Fail) continue;
      f.probe = Probe::Fail;
      for (const rig::Measurement& m : c.measurements) {
        if (m.outcome != rig::Outcome::Fail) continue;
        const auto e = excess(m);
        // A value against a spec figure says more than a count over 0 (a debounce's
        // misjudged probes beside its boundary): it wins, then the larger fraction.
        const auto rank = [](const std::optional<Excess>& x) { return !x ? 0 : x->limit == 0.0 ? 1 : 2; };
        const bool better = !f.worst || rank(e) > rank(f.worst_excess) ||
                            (e && rank(e) == rank(f.worst_excess) && e->fraction > f.worst_excess->fraction);
        if (better) {
          f.worst = m;
          f.worst_excess = e;
        }
      }
    }
  }
  if (!judged) {
    f.probe = Probe::Error;
    f.error = "the check judged nothing";
  }
  return f;
}

// The campaign's nominal runs with only this check, every fault left out.
campaign::Campaign probe_base(const campaign::Campaign& c, const std::string& check) {
  campaign::Campaign base = c;
  campaign::select_checks(base, campaign::CheckSelection{{check}, {}});
  base.faults.clear();
  base.fault_points.clear();
  return base;
}

// One probe: the knob set in every scenario point, then run through the executive as `hilrig
// run` runs them.
rig::CampaignResult run_probe(const campaign::Campaign& base,
                              const std::function<void(campaign::Scenario&)>& set, std::uint64_t seed) {
  campaign::Campaign probe_campaign = base;
  for (campaign::Scenario& s : probe_campaign.points) set(s);
  probe_campaign.runs = campaign::plan_runs(probe_campaign, seed);
  const campaign::Executive exec(probe_campaign);
  return exec.run_all(probe_campaign.runs, seed, rig::Shard{});
}

// The knob as the bisection sees it: a deviation from the nominal value in the knob's own
// unit (ns for a duration, exact integers), and how the campaign's dut.params take a value.
struct KnobScale {
  duts::ParamKind kind = duts::ParamKind::Duration;
  double nominal = 0.0; // ns or the number
  double min = 0.0;
  double max = 0.0;
  int sign = 1;
  [[nodiscard]] double value_at(double deviation) const { return nominal + sign * deviation; }
  [[nodiscard]] duts::ParamValue param_at(double deviation) const {
    const double v = value_at(deviation);
    if (kind == duts::ParamKind::Duration) return Nanos{static_cast<std::int64_t>(std::llround(v))};
    if (kind == duts::ParamKind::Integer) return static_cast<std::int64_t>(std::llround(v));
    return v;
  }
  // Written in us for a duration, as is for a number.
  [[nodiscard]] double shown(double deviation) const {
    return kind == duts::ParamKind::Duration ? value_at(deviation) / 1e3 : value_at(deviation);
  }
};

std::optional<double> numeric(const duts::ParamValue& v) {
  if (const auto* n = std::get_if<Nanos>(&v)) return static_cast<double>(n->count());
  if (const auto* d = std::get_if<double>(&v)) return *d;
  if (const auto* i = std::get_if<std::int64_t>(&v)) return static_cast<double>(*i);
  return std::nullopt;
}

std::string kind_of_check(const campaign::Campaign& c, const std::string& name) {
  for (const campaign::Scenario& s : c.points)
    if (const campaign::CheckSpec* k = s.check(name)) return k->kind;
  return {};
}

// A latency check meets the board's worst case only for a stimulus just after a scan: the row
// says how much of the scan its stimulus met (docs/campaigns.md, "Phase coverage"), or that it
// does not know. A response the model puts at a fixed delay (WorstCase::Knob) has no phase.
void describe_phase_coverage(PowerRow& row, const Finding& f, const Knob& knob,
                             const std::optional<checks::PhaseScan>& phase) {
  if (f.coverage) {
    row.phase_coverage = "phase coverage " + f.coverage->detail;
    row.phase_coverage_complete = phase && f.coverage->value >= static_cast<double>(phase->bins);
  } else if (row.kind == "throughput" && knob.worst_case != WorstCase::Knob) {
    row.phase_coverage = "phase coverage not measured (the check has no scan_us): its stimulus may "
                         "meet one phase of the board's scan only, and the board's worst case lie beyond "
                         "what it read";
  }
}

// The scan a check's phase coverage is binned against (its scan_us, phase_bins), if it has one.
std::optional<checks::PhaseScan> phase_scan_of(const campaign::Campaign& c, const std::string& name) {
  for (const campaign::Scenario& s : c.points)
    if (const campaign::CheckSpec* k = s.check(name))
      return std::visit(
          [](const auto& p) -> std::optional<checks::PhaseScan> {
            if constexpr (requires { p.phase; })
              return p.phase;
            else
              return std::nullopt;
          },
          k->params);
  return std::nullopt;
}

const checks::PulseWidthSpec* pulse_spec(const campaign::Campaign& c, const std::string& name) {
  for (const campaign::Scenario& s : c.points)
    if (const campaign::CheckSpec* k = s.check(name))
      if (const auto* p = std::get_if<checks::PulseWidthParams>(&k->params)) return &p->spec;
  return nullptr;
}

// A throughput check with a lower limit (min_limit_us: the fastest answer the manual states;
// early_us: a start that may come as early as late) is two-sided: a board that answers too
// fast is as far out of spec as one too slow, so its knob is bisected down as well as up.
bool throughput_has_min(const campaign::Campaign& c, const std::string& name) {
  for (const campaign::Scenario& s : c.points)
    if (const campaign::CheckSpec* k = s.check(name))
      if (const auto* t = std::get_if<checks::ThroughputParams>(&k->params);
          t && (t->spec.min_limit || t->spec.early))
        return true;
  return false;
}

// A pulse-width knob's side that lengthens the judged pulse (an ON pulse when the knob moves
// up; a pulse at the low level is the gap between ON pulses, shortened) against a check with no
// max_us, or shortens it against one with no min_us, breaks no width limit: named, not bisected.
std::optional<std::string> no_width_limit(const checks::PulseWidthSpec& spec, KnobDirection side) {
  const bool longer = (side == KnobDirection::Up) == (spec.level == Level::High);
  if (longer && !spec.max) return "no knob this way: the pulse gets longer, and the check has no max_us";
  if (!longer && !spec.min) return "no knob this way: the pulse gets shorter, and the check has no min_us";
  return std::nullopt;
}

// One side of the check's knob: `side` replaces a two-sided knob's direction.
PowerRow measure_check(const campaign::Campaign& c, const std::string& name, std::uint64_t seed,
                       const PowerOptions& options, Knob knob, std::optional<KnobDirection> side) {
  PowerRow row;
  row.check = name;
  row.kind = kind_of_check(c, name);
  const std::string& model = c.points.front().dut.model;
  if (side) knob.direction = *side;
  row.two_sided = side.has_value();
  if (knob.param.empty()) {
    row.reason = knob.no_knob;
    return row;
  }
  if (const checks::PulseWidthSpec* pulse = pulse_spec(c, name)) {
    if (auto why = no_width_limit(*pulse, knob.direction)) {
      row.knob = knob.param;
      row.direction = knob.direction == KnobDirection::Up ? "up" : "down";
      row.reason = *why;
      return row;
    }
  }
  KnobScale scale;
  scale.sign = knob.direction == KnobDirection::Up ? 1 : -1;
  // How a probe sets the knob at a deviation, in every scenario point.
  std::function<void(campaign::Scenario&, double)> set;
  std::string knob_name = knob.param;
  const campaign::PlantSpec* plant = c.points.front().plant ? &*c.points.front().plant : nullptr;
  if (knob.target == KnobTarget::MotionBrakeDecel && plant != nullptr &&
      plant->kind == campaign::PlantKind::Press) {
    // A press plant brakes the shaft: its knob is a factor on every brake torque the
    // campaign gives (the nominal and each [[plant.change]]'s, which would otherwise put a
    // worn brake's torque back), down: a weaker brake stops later at every instant.
    scale.kind = duts::ParamKind::Number;
    scale.nominal = 1.0;
    scale.min = 0.01; // a brake that still stops the shaft
    scale.max = 1.0;
    knob_name = "plant brake_torque factor";
    set = [scale](campaign::Scenario& s, double deviation) {
      scale_brake_torque(s, scale.value_at(deviation));
    };
  } else if (knob.target == KnobTarget::MotionBrakeDecel) {
    const campaign::Move* brake = nullptr;
    for (const campaign::Move& m : c.points.front().motion.moves)
      if (m.kind == campaign::MoveKind::PressStroke && brake == nullptr) brake = &m;
    if (brake == nullptr || plant != nullptr) {
      row.reason = "no knob: the stop time is the machine's, and this campaign's brake is neither a motion "
                   "press_stroke nor a press [plant]";
      return row;
    }
    scale.kind = duts::ParamKind::Number;
    scale.nominal = brake->decel_rpm_s;
    scale.min = 0.01 * brake->decel_rpm_s; // a brake that still stops the shaft
    scale.max = brake->decel_rpm_s;
    row.knob_unit = "rpm/s";
    set = [scale](campaign::Scenario& s, double deviation) {
      for (campaign::Move& m : s.motion.moves)
        if (m.kind == campaign::MoveKind::PressStroke) m.decel_rpm_s = scale.value_at(deviation);
    };
  } else {
    const duts::DutInfo* dut = duts::find_dut(model);
    const duts::ParamInfo* info = dut != nullptr ? dut->param(knob.param) : nullptr;
    const auto given = c.points.front().dut.params.find(knob.param);
    if (info == nullptr || given == c.points.front().dut.params.end() || !numeric(given->second.value)) {
      row.reason = fmt::format("no knob: the {} model has no numeric parameter {}", model, knob.param);
      return row;
    }
    scale.kind = info->kind;
    scale.nominal = *numeric(given->second.value);
    scale.min = info->range.min;
    scale.max = info->range.max;
    row.knob_unit = info->kind == duts::ParamKind::Duration ? "us" : "";
    set = [scale, param = knob.param](campaign::Scenario& s, double deviation) {
      s.dut.params[param].value = scale.param_at(deviation);
    };
  }
  const bool duration = scale.kind == duts::ParamKind::Duration;
  row.knob = knob_name;
  row.direction = knob.direction == KnobDirection::Up ? "up" : "down";
  row.nominal = scale.shown(0.0);

  BisectSpec spec;
  spec.integer = duration || scale.kind == duts::ParamKind::Integer;
  spec.resolution = spec.integer ? 1.0 : std::max(std::abs(scale.nominal), 1.0) * 1e-6;
  spec.first_step = std::max(spec.resolution, std::abs(scale.nominal) / 100.0);
  if (spec.integer) spec.first_step = std::ceil(spec.first_step);
  const double room =
      knob.direction == KnobDirection::Up ? scale.max - scale.nominal : scale.nominal - scale.min;
  spec.max_deviation =
      std::isfinite(room) ? room : 1000.0 * std::max(std::abs(scale.nominal), spec.first_step);
  spec.max_probes = 48;
  if (spec.max_deviation <= 0.0) {
    row.reason = fmt::format("never fails within knob range: {} is already at its range's end", knob_name);
    return row;
  }

  const campaign::Campaign base = probe_base(c, name);
  std::map<double, Finding> findings;
  const auto probe = [&](double deviation) {
    Finding f = judge_check(run_probe(
                                base, [&](campaign::Scenario& s) { set(s, deviation); }, seed),
                            name);
    const Probe p = f.probe;
    if (options.progress)
      options.progress(fmt::format("power: {}: {}: {} = {:.6g}{}: {}", c.name, name, knob_name,
                                   scale.shown(deviation), row.knob_unit.empty() ? "" : " " + row.knob_unit,
                                   p == Probe::Pass   ? "pass"
                                   : p == Probe::Fail ? "fail"
                                                      : "error"));
    findings[deviation] = std::move(f);
    return p;
  };
  const BisectResult b = bisect_threshold(spec, probe);
  row.probes = b.probes;
  row.last_pass = scale.shown(b.last_pass);
  if (!b.threshold) {
    row.reason = b.reason;
    if (b.reason.rfind("never fails", 0) == 0)
      row.reason =
          fmt::format("never fails within knob range {} {:.6g} .. {:.6g}{}", knob_name, scale.shown(0.0),
                      scale.shown(spec.max_deviation), row.knob_unit.empty() ? "" : " " + row.knob_unit);
    for (const auto& [deviation, f] : findings)
      if (f.probe == Probe::Error) row.reason += fmt::format(" ({})", f.error);
    return row;
  }
  row.threshold = scale.shown(*b.threshold);
  const Finding& at = findings.at(*b.threshold);
  describe_phase_coverage(row, at, knob, phase_scan_of(c, name));
  if (at.worst) {
    row.measurement = at.worst->name;
    row.unit = at.worst->unit;
    row.detail = at.worst->detail;
    if (at.worst_excess) {
      row.measured = at.worst->value;
      row.limit = at.worst_excess->limit;
      row.margin_pct = at.worst_excess->fraction * 100.0;
    }
  }
  // The board's own extreme at the threshold: its latest answer (the knob, plus a scan where
  // an event waits for one) against an upper limit; against a lower limit its earliest, the
  // knob alone (an event just before a scan waits for nothing).
  const bool lower = row.measured && row.limit && *row.measured < *row.limit;
  if (duration && row.unit == "us" && row.limit && *row.limit > 0.0 &&
      knob.worst_case != WorstCase::Unknown) {
    double worst_ns = scale.value_at(*b.threshold);
    if (knob.worst_case == WorstCase::KnobPlusParam && !lower) {
      const auto plus = c.points.front().dut.params.find(knob.plus_param);
      const Nanos* ns =
          plus == c.points.front().dut.params.end() ? nullptr : std::get_if<Nanos>(&plus->second.value);
      worst_ns = ns == nullptr ? std::nan("") : worst_ns + static_cast<double>(ns->count());
    }
    if (std::isfinite(worst_ns)) {
      row.board_worst = worst_ns / 1e3;
      row.board_margin_pct =
          (lower ? *row.limit - *row.board_worst : *row.board_worst - *row.limit) / *row.limit * 100.0;
    }
  }
  return row;
}

} // namespace

PowerResult measure_power(const campaign::Campaign& c, const PowerOptions& options) {
  PowerResult out;
  out.campaign = c.name;
  out.device = c.points.empty() ? std::string() : c.points.front().dut.model;
  out.seed = options.seed.value_or(c.seed);
  for (const std::string& name : campaign::check_names(c)) {
    if (!options.checks.empty() &&
        std::find(options.checks.begin(), options.checks.end(), name) == options.checks.end())
      continue;
    if (const checks::PulseWidthSpec* pulse = pulse_spec(c, name); pulse && !pulse->min && !pulse->max) {
      PowerRow row;
      row.check = name;
      row.kind = "pulse_width";
      row.reason = "no knob: no width limit (neither min_us nor max_us): the check judges that the pulse "
                   "comes (min_pulses), not its width";
      out.rows.push_back(row);
      continue;
    }
    for (const Knob& knob : knobs_for(out.device, kind_of_check(c, name))) {
      const bool both = knob.direction == KnobDirection::Both ||
                        (knob.direction == KnobDirection::Up && throughput_has_min(c, name));
      if (both && !knob.param.empty()) {
        out.rows.push_back(measure_check(c, name, out.seed, options, knob, KnobDirection::Up));
        out.rows.push_back(measure_check(c, name, out.seed, options, knob, KnobDirection::Down));
      } else {
        out.rows.push_back(measure_check(c, name, out.seed, options, knob, std::nullopt));
      }
    }
  }
  return out;
}

Probe probe_param(const campaign::Campaign& c, const std::string& check, const std::string& param,
                  const duts::ParamValue& value, std::uint64_t seed) {
  const campaign::Campaign base = probe_base(c, check);
  return judge_check(run_probe(
                         base, [&](campaign::Scenario& s) { s.dut.params[param].value = value; }, seed),
                     check)
      .probe;
}

Probe probe_plant_brake_factor(const campaign::Campaign& c, const std::string& check, double factor,
                               std::uint64_t seed) {
  const campaign::Campaign base = probe_base(c, check);
  return judge_check(run_probe(
                         base, [&](campaign::Scenario& s) { scale_brake_torque(s, factor); }, seed),
                     check)
      .probe;
}

bool over_margin(const PowerRow& row, double max_pct) {
  if (!row.margin_pct) return true;
  return *row.margin_pct > max_pct || (row.board_margin_pct && *row.board_margin_pct > max_pct);
}

} // namespace hilrig::power
