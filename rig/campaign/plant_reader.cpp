#include "rig/campaign/plant_reader.hpp"

#include <algorithm>
#include <cmath>

#include <fmt/format.h>

#include "rig/campaign/toml_reader.hpp"

namespace hilrig::campaign {

namespace {

using plants::PlantInput;

// One numeric parameter of a plant kind: its key, unit and valid range (inclusive).
template <class P> struct Field {
  const char* name;
  const char* unit;
  double lo;
  double hi;
  bool positive; // lo excluded (an inertia, a length)
  double& (*ref)(P&);
};

template <class P> std::string range_text(const Field<P>& f) {
  return fmt::format("a finite number {} {} and <= {} ({})", f.positive ? ">" : ">=", f.lo, f.hi, f.unit);
}

template <class P> bool in_range(const Field<P>& f, double v) {
  return std::isfinite(v) && (f.positive ? v > f.lo : v >= f.lo) && v <= f.hi;
}

// clang-format off
const std::vector<Field<plants::PressParams>> kPress = {
  {"flywheel_inertia", "kg·m²", 0.0, 1e6, true, [](plants::PressParams& p) -> double& { return p.flywheel_inertia; }},
  {"crank_inertia", "kg·m²", 0.0, 1e6, true, [](plants::PressParams& p) -> double& { return p.crank_inertia; }},
  {"motor_stall_torque", "N·m", 0.0, 1e7, false, [](plants::PressParams& p) -> double& { return p.motor_stall_torque; }},
  {"motor_sync_speed", "rad/s", 0.0, 1e4, false, [](plants::PressParams& p) -> double& { return p.motor_sync_speed; }},
  {"flywheel_viscous", "N·m·s/rad", 0.0, 1e6, false, [](plants::PressParams& p) -> double& { return p.flywheel_viscous; }},
  {"crank_viscous", "N·m·s/rad", 0.0, 1e6, false, [](plants::PressParams& p) -> double& { return p.crank_viscous; }},
  {"coulomb_torque", "N·m", 0.0, 1e7, false, [](plants::PressParams& p) -> double& { return p.coulomb_torque; }},
  {"clutch_torque", "N·m", 0.0, 1e8, false, [](plants::PressParams& p) -> double& { return p.clutch_torque; }},
  {"brake_torque", "N·m", 0.0, 1e8, false, [](plants::PressParams& p) -> double& { return p.brake_torque; }},
  {"valve_delay", "s", 0.0, 10.0, false, [](plants::PressParams& p) -> double& { return p.valve_delay; }},
  {"brake_rise", "s", 0.0, 10.0, false, [](plants::PressParams& p) -> double& { return p.brake_rise; }},
  {"ram_mass", "kg", 0.0, 1e6, false, [](plants::PressParams& p) -> double& { return p.ram_mass; }},
  {"crank_radius", "m", 0.0, 10.0, true, [](plants::PressParams& p) -> double& { return p.crank.radius; }},
  {"rod_length", "m", 0.0, 100.0, true, [](plants::PressParams& p) -> double& { return p.crank.rod; }},
};
const std::vector<Field<plants::RotaryParams>> kRotary = {
  {"motor_inertia", "kg·m²", 0.0, 1e6, true, [](plants::RotaryParams& p) -> double& { return p.motor_inertia; }},
  {"load_inertia", "kg·m²", 0.0, 1e6, true, [](plants::RotaryParams& p) -> double& { return p.load_inertia; }},
  {"stiffness", "N·m/rad", 0.0, 1e9, false, [](plants::RotaryParams& p) -> double& { return p.stiffness; }},
  {"coupling_damping", "N·m·s/rad", 0.0, 1e6, false, [](plants::RotaryParams& p) -> double& { return p.coupling_damping; }},
  {"motor_viscous", "N·m·s/rad", 0.0, 1e6, false, [](plants::RotaryParams& p) -> double& { return p.motor_viscous; }},
  {"load_viscous", "N·m·s/rad", 0.0, 1e6, false, [](plants::RotaryParams& p) -> double& { return p.load_viscous; }},
  {"coulomb_torque", "N·m", 0.0, 1e7, false, [](plants::RotaryParams& p) -> double& { return p.coulomb_torque; }},
  {"motor_torque", "N·m", -1e7, 1e7, false, [](plants::RotaryParams& p) -> double& { return p.motor_torque; }},
};
const std::vector<Field<plants::StepperParams>> kStepper = {
  {"rotor_inertia", "kg·m²", 0.0, 10.0, true, [](plants::StepperParams& p) -> double& { return p.rotor_inertia; }},
  {"load_inertia", "kg·m²", 0.0, 1e3, false, [](plants::StepperParams& p) -> double& { return p.load_inertia; }},
  {"holding_torque", "N·m", 0.0, 1e3, true, [](plants::StepperParams& p) -> double& { return p.holding_torque; }},
  {"detent_torque", "N·m", 0.0, 1e3, false, [](plants::StepperParams& p) -> double& { return p.detent_torque; }},
  {"viscous", "N·m·s/rad", 0.0, 1e3, false, [](plants::StepperParams& p) -> double& { return p.viscous; }},
  {"load_torque", "N·m", -1e3, 1e3, false, [](plants::StepperParams& p) -> double& { return p.load_torque; }},
};
// clang-format on

template <class P> std::string names(const std::vector<Field<P>>& fields) {
  std::string out;
  for (const auto& f : fields) out += fmt::format("{}{}", out.empty() ? "" : ", ", f.name);
  return out;
}

template <class P> const Field<P>* find(const std::vector<Field<P>>& fields, std::string_view name) {
  for (const auto& f : fields)
    if (name == f.name) return &f;
  return nullptr;
}

// Every field the table gives, checked against its range.
template <class P> void read_fields(TableReader& r, const std::vector<Field<P>>& fields, P& p) {
  for (const auto& f : fields) {
    const std::optional<double> v = r.opt_number(f.name);
    if (!v) continue;
    if (!in_range(f, *v)) r.fail(f.name, range_text(f));
    f.ref(p) = *v;
  }
}

// [[plant.change]]: at, param, and value or scale (of the value in force before it).
template <class P>
std::vector<plants::ParamChange<P>> read_changes(const std::string& file, TableReader& plant,
                                                 const std::vector<Field<P>>& fields, const P& nominal) {
  struct Raw {
    Nanos at;
    const Field<P>* field;
    std::optional<double> value;
    std::optional<double> scale;
    SourcePos where;
    std::string path;
  };
  std::vector<Raw> raws;
  std::size_t i = 0;
  for (const toml::table* t : plant.tables("change")) {
    TableReader r(file, *t, fmt::format("plant.change[{}]", i++));
    Raw raw;
    raw.at = r.duration("at");
    if (raw.at < Nanos{0}) r.fail("at", "a time >= 0");
    const std::string name = r.string("param");
    raw.field = find(fields, name);
    if (raw.field == nullptr)
      r.fail("param", fmt::format("a parameter of this plant kind: {}", names(fields)));
    raw.value = r.opt_number("value");
    raw.scale = r.opt_number("scale");
    if (raw.value.has_value() == raw.scale.has_value())
      r.fail("value", "exactly one of value (the new value) and scale (a factor on the value in force)");
    if (raw.value && !in_range(*raw.field, *raw.value)) r.fail("value", range_text(*raw.field));
    if (raw.scale && !(std::isfinite(*raw.scale) && *raw.scale >= 0.0 && *raw.scale <= 1e3))
      r.fail("scale", "a finite factor >= 0 and <= 1000");
    raw.where = r.pos(raw.value ? "value" : "scale");
    raw.path = r.key(raw.value ? "value" : "scale");
    r.finish();
    raws.push_back(raw);
  }
  std::stable_sort(raws.begin(), raws.end(), [](const Raw& a, const Raw& b) { return a.at < b.at; });
  std::vector<plants::ParamChange<P>> out;
  P now = nominal;
  for (const Raw& raw : raws) {
    double& v = raw.field->ref(now);
    v = raw.value ? *raw.value : v * *raw.scale;
    if (!in_range(*raw.field, v))
      throw CampaignError(file, raw.where, raw.path,
                          fmt::format("a change leaving {} as {}", raw.field->name, range_text(*raw.field)));
    out.push_back(plants::ParamChange<P>{raw.at, now});
  }
  return out;
}

PlantInput input_named(TableReader& r, std::string_view key, std::string_view name) {
  if (name == "valve") return PlantInput::Valve;
  if (name == "motor_enable") return PlantInput::MotorEnable;
  if (name == "step") return PlantInput::Step;
  if (name == "direction") return PlantInput::Direction;
  r.fail(key, "a plant input: valve, motor_enable, step, direction");
}

const Wire* wire_of(const std::vector<Wire>& wiring, std::string_view rig) {
  for (const Wire& w : wiring)
    if (w.rig == rig) return &w;
  return nullptr;
}

} // namespace

std::optional<PlantSpec> read_plant(const std::string& file, const toml::table& root,
                                    const std::vector<Wire>& wiring) {
  const toml::node* n = root.get("plant");
  if (n == nullptr) return std::nullopt;
  const toml::table* t = n->as_table();
  if (t == nullptr) throw CampaignError(file, pos_of(*n), "plant", "a table");
  TableReader r(file, *t, "plant");
  PlantSpec s;
  s.where = r.where();
  const std::string kind = r.string("kind");
  if (kind == "press")
    s.kind = PlantKind::Press;
  else if (kind == "rotary_axis")
    s.kind = PlantKind::RotaryAxis;
  else if (kind == "stepper_load")
    s.kind = PlantKind::StepperLoad;
  else
    r.fail("kind", "press, rotary_axis or stepper_load");
  if (const auto step = r.opt_duration("step")) {
    if (*step < Nanos{1'000} || *step > Nanos{10'000'000}) r.fail("step", "a duration from 1us to 10ms");
    s.step = *step;
  }
  const auto start_angle = r.opt_number("start_angle");
  const auto start_speed = r.opt_number("start_speed");
  if (start_angle && !(std::isfinite(*start_angle) && std::abs(*start_angle) <= 1e6))
    r.fail("start_angle", "a finite angle within ±1e6 (rad)");
  if (start_speed && !(std::isfinite(*start_speed) && std::abs(*start_speed) <= 1e4))
    r.fail("start_speed", "a finite speed within ±1e4 (rad/s)");
  const bool motor = r.opt_boolean("start_motor").value_or(true);
  switch (s.kind) {
  case PlantKind::Press:
    read_fields(r, kPress, s.press);
    if (s.press.crank.rod <= s.press.crank.radius) r.fail("rod_length", "longer than crank_radius");
    s.press_start.angle = start_angle.value_or(0.0);
    s.press_start.speed = start_speed.value_or(0.0);
    s.press_start.valve = r.opt_boolean("start_valve").value_or(true);
    s.press_start.motor = motor;
    if (const auto fly = r.opt_number("start_flywheel_speed")) {
      if (!(std::isfinite(*fly) && std::abs(*fly) <= 1e4))
        r.fail("start_flywheel_speed", "a finite speed within ±1e4 (rad/s)");
      s.press_start.flywheel_speed = *fly;
    }
    s.press_changes = read_changes(file, r, kPress, s.press);
    for (const auto& c : s.press_changes)
      if (c.params.crank.rod <= c.params.crank.radius)
        r.fail("change", "changes that keep rod_length longer than crank_radius");
    break;
  case PlantKind::RotaryAxis: {
    read_fields(r, kRotary, s.rotary);
    s.rotary.two_mass = r.opt_boolean("two_mass").value_or(false);
    s.rotary.encoder_on_load = r.opt_boolean("encoder_on_load").value_or(true);
    if (s.rotary.two_mass && s.rotary.coulomb_torque != 0.0)
      r.fail("coulomb_torque", "0 on a two-mass axis (Coulomb friction is modelled on the rigid axis only)");
    std::size_t i = 0;
    for (const toml::table* lt : r.tables("load")) {
      TableReader l(file, *lt, fmt::format("plant.load[{}]", i++));
      plants::LoadStep step;
      step.from = l.duration("from");
      step.torque = l.number("torque");
      if (!std::isfinite(step.torque) || std::abs(step.torque) > 1e7)
        l.fail("torque", "a finite torque within ±1e7 (N·m)");
      l.finish();
      s.rotary.load.push_back(step);
    }
    s.rotary_start = plants::RotaryStart{start_angle.value_or(0.0), start_speed.value_or(0.0), motor};
    s.rotary_changes = read_changes(file, r, kRotary, s.rotary);
    for (const auto& c : s.rotary_changes)
      if (c.params.two_mass && c.params.coulomb_torque != 0.0)
        r.fail("change", "no Coulomb friction on a two-mass axis");
    break;
  }
  case PlantKind::StepperLoad:
    read_fields(r, kStepper, s.stepper);
    if (const auto teeth = r.opt_integer("rotor_teeth")) {
      if (*teeth < 1 || *teeth > 1000) r.fail("rotor_teeth", "an integer from 1 to 1000");
      s.stepper.rotor_teeth = static_cast<int>(*teeth);
    }
    if (const auto micro = r.opt_integer("microsteps")) {
      if (*micro < 1 || *micro > 1024) r.fail("microsteps", "an integer from 1 to 1024 (per full step)");
      s.stepper.microsteps = static_cast<int>(*micro);
    }
    s.stepper.step_every_edge = r.opt_boolean("step_every_edge").value_or(false);
    if (start_angle || start_speed) r.fail("start_angle", "a stepper load starts at rest at angle 0");
    s.stepper_changes = read_changes(file, r, kStepper, s.stepper);
    break;
  }

  if (const toml::table* in = r.opt_table("inputs")) {
    TableReader ir(file, *in, "plant.inputs");
    for (const auto& [k, v] : *in) {
      const PlantInput input = input_named(ir, k.str(), k.str());
      const std::string line = ir.string(k.str());
      const Wire* w = wire_of(wiring, line);
      if (w == nullptr || w->direction != duts::PinDirection::Output)
        ir.fail(k.str(), fmt::format("a rig line wired to a board output (\"{}\" is not)", line));
      for (const auto& [other, taken] : s.inputs)
        if (taken == input) ir.fail(k.str(), "each input driven by one line");
      s.inputs[line] = input;
    }
    ir.finish();
  }
  std::size_t i = 0;
  for (const toml::table* ct : r.tables("command")) {
    TableReader c(file, *ct, fmt::format("plant.command[{}]", i++));
    PlantCommand cmd;
    cmd.where = c.where();
    cmd.at = c.duration("at");
    if (cmd.at < Nanos{0}) c.fail("at", "a time >= 0");
    cmd.input = input_named(c, "input", c.string("input"));
    cmd.level = c.level("level");
    for (const auto& [line, taken] : s.inputs)
      if (taken == cmd.input) c.fail("input", fmt::format("an input no board output drives ({} does)", line));
    c.finish();
    s.commands.push_back(cmd);
  }
  std::stable_sort(s.commands.begin(), s.commands.end(),
                   [](const PlantCommand& a, const PlantCommand& b) { return a.at < b.at; });
  if (const auto mon = r.opt_string("valve_monitor")) {
    const Wire* w = wire_of(wiring, *mon);
    if (w == nullptr || w->direction != duts::PinDirection::Input)
      r.fail("valve_monitor", fmt::format("a rig line wired to a board input (\"{}\" is not)", *mon));
    if (s.kind != PlantKind::Press) r.fail("valve_monitor", "a press plant's (only a press has a valve)");
    s.valve_monitor = *mon;
  }
  r.finish();
  return s;
}

} // namespace hilrig::campaign
