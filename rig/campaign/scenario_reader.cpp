#include "rig/campaign/scenario_reader.hpp"

#include "rig/campaign/plant_reader.hpp"
#include "rig/campaign/program_reader.hpp"

#include <algorithm>
#include <cmath>
#include <set>
#include <utility>

#include <fmt/format.h>
#include <nlohmann/json.hpp>

#include "core/did_you_mean.hpp"
#include "rig/campaign/check_times.hpp"
#include "rig/campaign/limits.hpp"
#include "rig/campaign/motion.hpp"
#include "rig/campaign/stimulus_kinds.hpp"
#include "rig/campaign/toml_reader.hpp"
#include "rig/checks/registry.hpp"
#include "rig/duts/device_programs.hpp"
#include "rig/results/measurement.hpp"

namespace hilrig::campaign {

namespace {

using duts::ParamKind;
using duts::PinDirection;

std::string join(const std::vector<std::string>& names) {
  std::string out;
  for (const auto& n : names) out += (out.empty() ? "" : ", ") + n;
  return out;
}

class Reader {
public:
  Reader(const std::string& file, const toml::table& root) : file_(file), root_(file, root, "") {}

  ScenarioFile read() {
    ScenarioFile out;
    read_campaign(out);
    read_dut(out.scenario.dut);
    read_wiring(out.scenario);
    read_encoder(out.scenario.encoder);
    read_resolver(out.scenario);
    read_motion(out.scenario);
    (void)build_motion(file_, out.scenario.motion,
                       out.scenario.encoder); // a move that cannot follow is bad input
    read_plant_table(out.scenario);
    read_ssi(out.scenario);
    read_stimuli(out.scenario);
    read_host(out.scenario);
    read_device_faults(out.scenario);
    read_power_cycles(out.scenario);
    read_panel(out.scenario);
    read_checks(out.scenario);
    read_faults(out);
    (void)root_.node("sweep"); // read by the campaign parser
    root_.finish();
    return out;
  }

private:
  [[noreturn]] void fail(SourcePos at, const std::string& key, const std::string& expected) const {
    throw CampaignError(file_, at, key, expected);
  }

  // A number in [lo, hi] (what: "a speed in rpm"), the range named in the message.
  static double number_in(TableReader& r, std::string_view key, double lo, double hi, std::string_view what) {
    const double v = r.number(key);
    if (!(v >= lo && v <= hi)) r.fail(key, fmt::format("{} in {} .. {}", what, lo, hi));
    return v;
  }
  static std::optional<double> opt_number_in(TableReader& r, std::string_view key, double lo, double hi,
                                             std::string_view what) {
    if (!r.has(key)) {
      (void)r.node(key);
      return std::nullopt;
    }
    return number_in(r, key, lo, hi, what);
  }
  static std::int64_t integer_in(TableReader& r, std::string_view key, std::int64_t lo, std::int64_t hi,
                                 std::string_view what) {
    const std::int64_t v = r.integer(key);
    if (v < lo || v > hi) r.fail(key, fmt::format("{} in {} .. {}", what, lo, hi));
    return v;
  }
  // A duration in [lo, hi].
  static Nanos duration_in(TableReader& r, std::string_view key, Nanos lo, Nanos hi) {
    const Nanos d = r.duration(key);
    if (d < lo || d > hi)
      r.fail(key, fmt::format("a duration in {} .. {}", duration_text(lo), duration_text(hi)));
    return d;
  }
  static std::optional<Nanos> opt_duration_in(TableReader& r, std::string_view key, Nanos lo, Nanos hi) {
    if (!r.has(key)) {
      (void)r.node(key);
      return std::nullopt;
    }
    return duration_in(r, key, lo, hi);
  }

  void read_campaign(ScenarioFile& out) {
    const toml::table* t = root_.opt_table("campaign");
    if (t == nullptr) fail(root_.where(), "campaign", "missing: a [campaign] table with name and end");
    TableReader r(file_, *t, "campaign");
    out.name = r.string("name");
    if (!is_label(out.name)) r.fail("name", "the campaign's name: " + label_range());
    out.description = r.opt_string("description").value_or("");
    out.scenario.end = duration_in(r, "end", Nanos{1}, limits::kMaxEnd);
    if (auto s = r.opt_integer("seed")) {
      if (*s < 0) r.fail("seed", "a seed >= 0");
      out.seed = static_cast<std::uint64_t>(*s);
    }
    out.repeat = r.has("repeat") ? integer_in(r, "repeat", 1, limits::kMaxRepeat, "a repetition count") : 1;
    if (auto p = opt_duration_in(r, "host_poll", limits::kMinHostPoll, limits::kMaxHostPoll))
      out.scenario.host_poll = *p;
    if (auto tol = opt_duration_in(r, "edge_tolerance", Nanos{1}, limits::kMaxEdgeTolerance))
      out.scenario.edge_tolerance = *tol;
    r.finish();
  }

  // The parameter as its declared kind, inside the range its device declares.
  ParamValue dut_param(TableReader& r, const duts::ParamInfo& info) {
    ParamValue v = std::int64_t{0};
    switch (info.kind) {
    case ParamKind::Integer:
      v = r.integer(info.name);
      break;
    case ParamKind::Number:
      v = r.number(info.name);
      break;
    case ParamKind::Duration:
      v = r.duration(info.name);
      break;
    case ParamKind::Boolean:
      v = r.boolean(info.name);
      break;
    case ParamKind::Text:
      v = r.string(info.name);
      break;
    }
    if (!duts::in_range(info.range, v)) r.fail(info.name, param_range_text(info_->name, info));
    return v;
  }

  void read_dut(DutSpec& dut) {
    const toml::table* t = root_.opt_table("dut");
    if (t == nullptr) fail(root_.where(), "dut", "missing: a [dut] table naming the model");
    TableReader r(file_, *t, "dut");
    dut.where = r.where();
    dut.model = r.string("model");
    dut.backend = r.opt_string("backend").value_or("virtual");
    dut.serial = r.opt_string("serial").value_or("");
    if (r.has("serial") && !is_label(dut.serial))
      r.fail("serial", "the board's serial number: " + label_range());
    if (dut.backend != "virtual" && dut.backend != "hardware" && dut.backend != "gpiod")
      r.fail("backend", "\"virtual\" or \"hardware\" (\"gpiod\" is the same)");
    if (dut.model == "external") {
      if (dut.backend == "virtual") r.fail("backend", "\"hardware\" for an external board");
      const toml::table* pins = r.opt_table("pins");
      if (pins == nullptr)
        r.fail("pins", "missing: an external board declares its pins, e.g. pins = { A = \"input\" }");
      for (const auto& [k, v] : *pins) {
        const auto* s = v.as_string();
        if (s == nullptr || (s->get() != "input" && s->get() != "output"))
          fail(pos_of(v), fmt::format("dut.pins.{}", k.str()), "\"input\" or \"output\"");
        dut.external_pins[std::string(k.str())] =
            s->get() == "input" ? PinDirection::Input : PinDirection::Output;
      }
      r.finish();
      info_ = nullptr;
      return;
    }
    info_ = duts::find_dut(dut.model);
    if (info_ == nullptr) {
      std::vector<std::string> names;
      for (const auto& d : duts::dut_registry()) names.push_back(d.name);
      names.emplace_back("external");
      r.fail("model", fmt::format("a device model: one of {}", join(names)));
    }
    dut.variant = r.opt_string("variant").value_or("nominal");
    if (!info_->has_variant(dut.variant)) r.fail("variant", variant_expected());
    std::map<std::string, ParamValue, std::less<>> given;
    if (const toml::table* p = r.opt_table("params")) {
      TableReader pr(file_, *p, "dut.params");
      for (const auto& info : info_->params) {
        if (!pr.has(info.name)) {
          (void)pr.node(info.name);
          continue;
        }
        given[info.name] = dut_param(pr, info);
        dut.params[info.name] = Param{given[info.name], pr.pos(info.name)};
      }
      pr.finish();
    }
    for (const auto& info : info_->params)
      if (!dut.params.contains(info.name)) dut.params[info.name] = Param{info.default_value, dut.where};
    // Values each in range may still not go together (a rule across keys, DutInfo::conflict).
    if (const auto conflict = info_->params_conflict(given)) {
      const std::string& key = conflict->keys.front();
      fail(dut.params.at(key).where, "dut.params." + key, conflict->expected);
    }
    r.finish();
  }

  std::string variant_expected() const {
    std::vector<std::string> names;
    for (const auto& v : info_->variants) names.push_back(v.name);
    return fmt::format("a variant of {}: one of {}", info_->name, join(names));
  }

  std::optional<PinDirection> pin_direction(const DutSpec& dut, std::string_view pin) const {
    if (info_ == nullptr) {
      const auto it = dut.external_pins.find(pin);
      if (it == dut.external_pins.end()) return std::nullopt;
      return it->second;
    }
    const duts::PinInfo* p = info_->pin(pin);
    if (p == nullptr) return std::nullopt;
    return p->direction;
  }

  std::string pin_names(const DutSpec& dut) const {
    std::vector<std::string> names;
    if (info_ == nullptr)
      for (const auto& [n, d] : dut.external_pins) names.push_back(n);
    else
      for (const auto& p : info_->pins) names.push_back(p.name);
    return join(names);
  }

  void read_wiring(Scenario& s) {
    std::size_t i = 0;
    for (const toml::table* t : root_.tables("wiring")) {
      TableReader r(file_, *t, fmt::format("wiring[{}]", i++));
      Wire w;
      w.where = r.where();
      w.rig = r.string("rig");
      // The line's name goes into trace.vcd, results and reports as every other name does.
      if (!is_label(w.rig)) r.fail("rig", "the rig line's name: " + label_range());
      w.board = r.string("board");
      const auto dir = pin_direction(s.dut, w.board);
      if (!dir) r.fail("board", fmt::format("a pin of {}: one of {}", s.dut.model, pin_names(s.dut)));
      w.direction = *dir;
      w.analog = info_ != nullptr && info_->pin(w.board)->analog;
      if (w.rig.starts_with("enc.") && !is_encoder_line(w.rig))
        r.fail("rig", "encoder lines are named enc.A and enc.B");
      if (is_encoder_line(w.rig) && w.direction != PinDirection::Input)
        r.fail("board",
               fmt::format("the encoder drives {}: a board input pin ({} is an output)", w.rig, w.board));
      for (const Wire& other : s.wiring) {
        // One analog line may feed several analog pins: a resolver jumpered into both
        // channels of a two-channel board (Series 2700, pls2700.md R-18-8, L1763).
        if (other.rig == w.rig && !(w.analog && other.analog))
          r.fail("rig", fmt::format("each rig line wired once; \"{}\" is already wired", w.rig));
        if (other.board == w.board)
          r.fail("board", fmt::format("each board pin wired once; \"{}\" is already wired", w.board));
      }
      r.finish();
      s.wiring.push_back(std::move(w));
    }
  }

  void read_encoder(EncoderSpec& e) {
    const toml::table* t = root_.opt_table("encoder");
    if (t == nullptr) return;
    TableReader r(file_, *t, "encoder");
    e.where = r.where();
    e.lines = r.opt_integer("lines").value_or(e.lines);
    if (e.lines < 1 || e.lines > 1'000'000) r.fail("lines", "lines per turn in 1..1000000");
    r.finish();
  }

  void read_resolver(Scenario& s) {
    const toml::table* t = root_.opt_table("resolver");
    if (t == nullptr) return;
    TableReader r(file_, *t, "resolver");
    ResolverSpec& res = s.resolver;
    res.where = r.where();
    for (const auto& [key, line] : {std::pair{"sin", &res.sin_line}, std::pair{"cos", &res.cos_line}}) {
      *line = r.string(key);
      const Wire* w = s.wire_for_rig(*line);
      if (w == nullptr || !w->analog)
        r.fail(key, fmt::format("a rig line wired to an analog pin (\"{}\" is not)", *line));
    }
    if (res.sin_line == res.cos_line) r.fail("cos", "a second analog line (the two stators differ)");
    res.excitation_hz = opt_number_in(r, "excitation_hz", limits::kMinExcitationHz, limits::kMaxExcitationHz,
                                      "an excitation frequency in Hz")
                            .value_or(res.excitation_hz);
    res.amplitude = r.opt_number("amplitude").value_or(res.amplitude);
    if (!(res.amplitude > 0.0 && res.amplitude <= limits::kMaxAmplitude))
      r.fail("amplitude", fmt::format("an amplitude above 0, at most {}", limits::kMaxAmplitude));
    res.ratio =
        opt_number_in(r, "ratio", 0.0, limits::kMaxRatio, "a transformation ratio").value_or(res.ratio);
    res.phase_deg = r.opt_number("phase_deg").value_or(res.phase_deg);
    if (!(res.phase_deg >= -360.0 && res.phase_deg <= 360.0))
      r.fail("phase_deg", "a phase in -360..360 degrees");
    r.finish();
  }

  // [ssi] (campaign.hpp SsiSpec): the lines, the transducer's counts a turn and its frame.
  void read_ssi(Scenario& s) {
    const toml::table* t = root_.opt_table("ssi");
    if (t == nullptr) return;
    TableReader r(file_, *t, "ssi");
    SsiSpec& ssi = s.ssi;
    ssi.where = r.where();
    ssi.clock_line = r.string("clock");
    const Wire* clock = s.wire_for_rig(ssi.clock_line);
    if (clock == nullptr || clock->analog || clock->direction != PinDirection::Output)
      r.fail("clock",
             fmt::format("a rig line wired to the board's clock output (\"{}\" is not)", ssi.clock_line));
    ssi.data_line = driven_line(s, r, "data")->rig;
    signals::SsiFrameFormat& f = ssi.format;
    f.frame_bits = static_cast<unsigned>(r.opt_integer("frame_bits").value_or(25));
    if (f.frame_bits < 1 || f.frame_bits > 32) r.fail("frame_bits", "clocks a frame in 1..32");
    f.data_msb = static_cast<unsigned>(r.opt_integer("data_msb").value_or(1));
    if (f.data_msb < 1 || f.data_msb > f.frame_bits) r.fail("data_msb", "a stream bit in 1..frame_bits");
    const std::int64_t bits = r.integer("data_bits");
    if (bits < 1 || bits > 32 || f.data_msb + static_cast<unsigned>(bits) - 1 > f.frame_bits)
      r.fail("data_bits",
             "a data field of 1..32 bits that ends inside the frame (data_msb + data_bits - 1 <= "
             "frame_bits)");
    f.data_bits = static_cast<unsigned>(bits);
    const std::string code = r.opt_string("code").value_or("binary");
    if (code != "binary" && code != "gray") r.fail("code", "binary or gray");
    f.code = code == "gray" ? signals::SsiCode::Gray : signals::SsiCode::Binary;
    const std::int64_t cpt =
        r.opt_integer("counts_per_turn").value_or(std::int64_t{1} << std::min(bits, std::int64_t{24}));
    if (cpt < 1 || static_cast<double>(cpt) > std::ldexp(1.0, static_cast<int>(bits)))
      r.fail("counts_per_turn",
             "counts a turn in 1 .. 2^data_bits (a single-turn position fits the data field)");
    ssi.counts_per_turn = static_cast<std::uint32_t>(cpt);
    ssi.monoflop = r.opt_duration("monoflop").value_or(ssi.monoflop);
    // The 7361's clock may be set to 125 or 500 kHz at run time: judged against the slower one.
    if (!limits::monoflop_in_range(ssi.monoflop, limits::kSlowestSsiHalfClock))
      r.fail("monoflop", limits::monoflop_range(duration_text(limits::kSlowestSsiHalfClock),
                                                "the 7361's slower clock, 125 kHz"));
    r.finish();
  }

  // What synthesizes a rig line, if anything does: the encoder (or the plant turning it), a
  // press plant's valve, the [ssi] transducer. A stimulus that drives levels would fight it;
  // only a signal fault goes on such a line, and overrides it.
  static std::optional<std::string> synthesized_by(const Scenario& s, std::string_view line) {
    if (is_encoder_line(line)) return s.plant ? "the plant's encoder" : "the encoder";
    if (s.plant && !s.plant->valve_monitor.empty() && line == s.plant->valve_monitor)
      return "the plant's valve (valve_monitor)";
    if (!s.ssi.data_line.empty() && line == s.ssi.data_line) return "the [ssi] transducer";
    return std::nullopt;
  }

  const Wire* driven_line(const Scenario& s, TableReader& r, std::string_view key) {
    const std::string line = r.string(key);
    const Wire* w = s.wire_for_rig(line);
    if (w == nullptr) r.fail(key, fmt::format("a wired rig line (\"{}\" is not in [[wiring]])", line));
    if (w->analog)
      r.fail(key, fmt::format("a digital line; \"{}\" is wired to analog pin {}", line, w->board));
    if (w->direction != PinDirection::Input)
      r.fail(key, fmt::format("a line the rig drives (board input); \"{}\" is wired to output {}", line,
                              w->board));
    return w;
  }

  void read_motion(Scenario& s) {
    const toml::table* t = root_.opt_table("motion");
    if (t == nullptr) return;
    TableReader r(file_, *t, "motion");
    s.motion.where = r.where();
    s.motion.start_turns =
        opt_number_in(r, "start_turns", -limits::kMaxTurns, limits::kMaxTurns, "a position in turns")
            .value_or(0.0);
    // The encoder's count rate at a speed: only an encoder that is wired makes edges.
    const bool encoder_wired = s.wire_for_rig(kEncoderA) != nullptr || s.wire_for_rig(kEncoderB) != nullptr;
    const double max_rpm =
        encoder_wired ? std::min(limits::kMaxRpm, limits::kMaxCountsPerS * 60.0 / s.encoder.counts_per_turn())
                      : limits::kMaxRpm;
    const auto speed_text = [&] {
      return encoder_wired && max_rpm < limits::kMaxRpm
                 ? fmt::format(
                       "a speed in rpm in -{0} .. {0} ({1} counts/s at most from the {2}-line encoder)",
                       max_rpm, limits::kMaxCountsPerS, s.encoder.lines)
                 : fmt::format("a speed in rpm in -{0} .. {0}", max_rpm);
    };
    std::size_t i = 0;
    for (const toml::table* mt : r.tables("move")) {
      TableReader m(file_, *mt, fmt::format("motion.move[{}]", i++));
      Move mv;
      mv.where = m.where();
      const std::string kind = m.string("kind");
      auto positive_duration = [&](std::string_view key) {
        return duration_in(m, key, Nanos{1}, limits::kMaxEnd);
      };
      auto speed = [&](std::string_view key) {
        const double v = m.number(key);
        if (!(std::fabs(v) <= max_rpm)) m.fail(key, speed_text());
        return v;
      };
      auto cruise = [&](std::string_view key) {
        const double v = speed(key);
        if (!(v >= limits::kMinCruiseRpm))
          m.fail(key, fmt::format("a cruise speed in rpm in {} .. {}", limits::kMinCruiseRpm, max_rpm));
        return v;
      };
      auto rate = [&](std::string_view key) {
        const double v = m.number(key);
        if (!(v > 0.0 && v <= limits::kMaxRpmPerS))
          m.fail(key, fmt::format("a rate in rpm/s above 0, at most {}", limits::kMaxRpmPerS));
        return v;
      };
      if (kind == "constant") {
        mv.kind = MoveKind::Constant;
        mv.speed_rpm = speed("speed_rpm");
        mv.duration = positive_duration("duration");
      } else if (kind == "accelerate") {
        mv.kind = MoveKind::Accelerate;
        mv.to_rpm = speed("to_rpm");
        mv.duration = positive_duration("duration");
      } else if (kind == "dwell") {
        mv.kind = MoveKind::Dwell;
        mv.duration = positive_duration("duration");
      } else if (kind == "trapezoid") {
        mv.kind = MoveKind::Trapezoid;
        mv.speed_rpm = cruise("speed_rpm");
        mv.accel_rpm_s = rate("accel_rpm_s");
        mv.turns = number_in(m, "turns", -limits::kMaxTurns, limits::kMaxTurns, "a distance in turns");
        if (mv.turns == 0.0) m.fail("turns", "a distance in turns, not 0 (negative runs backwards)");
        // Its time in closed form (turns/s, turns/s^2): a trapezoid when the cruise is reached,
        // else a triangle. Beyond an hour no run sees it end, and a rate near 0 overflows time.
        const double v = mv.speed_rpm / 60.0;
        const double a = mv.accel_rpm_s / 60.0;
        const double d = std::fabs(mv.turns);
        const double ramps = v / a;
        const double seconds_taken = d >= v * v / a ? d / v + ramps : 2.0 * std::sqrt(d / a);
        if (!(seconds_taken <= static_cast<double>(limits::kMaxEnd.count()) / 1e9))
          m.fail(ramps >= seconds_taken / 2 ? "accel_rpm_s" : "speed_rpm",
                 fmt::format(
                     "a move that ends within {} s (this one takes {:.10g} s: {} turns at {} rpm, ramps at "
                     "{} rpm/s)",
                     limits::kMaxEnd.count() / 1'000'000'000, seconds_taken, mv.turns, mv.speed_rpm,
                     mv.accel_rpm_s));
      } else if (kind == "press_stroke") {
        mv.kind = MoveKind::PressStroke;
        mv.speed_rpm = cruise("speed_rpm");
        mv.decel_rpm_s = rate("decel_rpm_s");
        mv.strokes =
            m.has("strokes") ? integer_in(m, "strokes", 0, limits::kMaxStrokes, "a number of strokes") : 0;
        // At speed for the strokes, then the stop: beyond an hour no run sees it end.
        const double stroke_seconds = static_cast<double>(mv.strokes + 1) / (std::fabs(mv.speed_rpm) / 60.0) +
                                      std::fabs(mv.speed_rpm) / mv.decel_rpm_s;
        if (!(stroke_seconds <= static_cast<double>(limits::kMaxEnd.count()) / 1e9))
          m.fail(std::fabs(mv.speed_rpm) / mv.decel_rpm_s >= stroke_seconds / 2 ? "decel_rpm_s" : "speed_rpm",
                 fmt::format("a stroke that ends within {} s (this one takes {:.10g} s)",
                             limits::kMaxEnd.count() / 1'000'000'000, stroke_seconds));
        mv.brake_at_deg = m.opt_number("brake_at_deg").value_or(0.0);
        if (mv.brake_at_deg < 0.0 || mv.brake_at_deg >= 360.0)
          m.fail("brake_at_deg", "a crank angle in [0, 360)");
        if (m.has("brake_line"))
          mv.brake_line = driven_line(s, m, "brake_line")->rig;
        else
          (void)m.node("brake_line");
        mv.brake_level = m.opt_level("brake_level").value_or(Level::Low);
      } else {
        m.fail("kind", "a move kind: constant, accelerate, dwell, trapezoid or press_stroke");
      }
      m.finish();
      s.motion.moves.push_back(std::move(mv));
    }
    read_motion_cycles(r, s.motion);
    r.finish();
  }

  // `cycles`: the move list played that many times in a row (a press's strokes, a
  // back-and-forth), instead of spelling the moves out again.
  static void read_motion_cycles(TableReader& r, MotionSpec& motion) {
    if (!r.has("cycles")) return;
    const std::int64_t cycles =
        integer_in(r, "cycles", 1, limits::kMaxCycles, "a number of cycles of the moves");
    if (motion.moves.empty()) r.fail("cycles", "cycles of at least one [[motion.move]]");
    const auto per_cycle = static_cast<std::int64_t>(motion.moves.size());
    if (per_cycle * cycles > limits::kMaxMoves)
      r.fail("cycles", fmt::format("at most {} moves in all ({} moves a cycle: cycles 1 .. {})",
                                   limits::kMaxMoves, per_cycle, limits::kMaxMoves / per_cycle));
    for (const Move& m : motion.moves)
      if (!m.brake_line.empty() && cycles > 1)
        r.fail("cycles", "1 with a press_stroke's brake_line (the line is applied once in a run)");
    motion.moves.reserve(static_cast<std::size_t>(per_cycle * cycles));
    for (std::int64_t c = 1; c < cycles; ++c)
      for (std::int64_t k = 0; k < per_cycle; ++k)
        motion.moves.push_back(motion.moves[static_cast<std::size_t>(k)]);
  }

  Stimulus read_stimulus(const Scenario& s, TableReader& r, bool fault_only) {
    Stimulus st;
    st.where = r.where();
    const std::string kind = r.string("kind");
    st.at = r.duration("at");
    if (st.at < Nanos{0}) r.fail("at", "a time >= 0");
    if (st.at > s.end)
      r.fail("at", fmt::format("a time within the run (campaign.end is {} ns)", s.end.count()));
    const Wire* w = driven_line(s, r, "line");
    st.line = w->rig;
    const bool encoder = is_encoder_line(st.line);
    auto positive_duration = [&](std::string_view key) {
      return duration_in(r, key, Nanos{1}, limits::kMaxEnd);
    };
    auto until = [&] {
      st.until = r.opt_duration("until").value_or(Nanos::max());
      if (st.until <= st.at) r.fail("until", "a time after `at`");
    };
    const StimulusKindInfo* info = find_stimulus_kind(kind);
    if (info == nullptr || (fault_only && !info->signal_fault)) {
      std::string names;
      for (const auto& k : stimulus_kinds())
        if (!fault_only || k.signal_fault) names += (names.empty() ? "" : ", ") + std::string(k.name);
      r.fail("kind", fmt::format("{}: one of {}", fault_only ? "a signal fault" : "a stimulus kind", names));
    }
    st.kind = info->kind;
    if (const auto by = synthesized_by(s, st.line); by && !info->signal_fault)
      r.fail("line",
             fmt::format("a discrete input line; {} is driven by {} (use a signal fault)", st.line, *by));
    switch (st.kind) {
    case StimulusKind::Level:
      st.level = r.level("level");
      break;
    case StimulusKind::Pulse:
      st.level = r.opt_level("level").value_or(Level::High);
      st.width = positive_duration("width");
      break;
    case StimulusKind::Bounce:
      st.level = r.opt_level("level").value_or(Level::High);
      st.edges = integer_in(r, "edges", 1, limits::kMaxBounceEdges, "a number of bounce edges");
      st.period = positive_duration("period");
      break;
    case StimulusKind::Glitch:
      st.width = positive_duration("width");
      break;
    case StimulusKind::Stuck:
      st.level = r.level("level");
      until();
      break;
    case StimulusKind::MissingEdges:
      if (!encoder) r.fail("line", "an encoder line (enc.A or enc.B)");
      st.every = r.has("every") ? integer_in(r, "every", 1, limits::kMaxEvery, "every n-th edge lost, n") : 1;
      until();
      break;
    }
    return st;
  }

  void read_stimuli(Scenario& s) {
    std::size_t i = 0;
    for (const toml::table* t : root_.tables("stimulus")) {
      TableReader r(file_, *t, fmt::format("stimulus[{}]", i++));
      Stimulus st = read_stimulus(s, r, false);
      if (!s.stimuli.empty() && st.at < s.stimuli.back().at)
        r.fail("at", fmt::format("times in order: this stimulus ({} ns) is before the one above ({} ns)",
                                 st.at.count(), s.stimuli.back().at.count()));
      r.finish();
      s.stimuli.push_back(std::move(st));
    }
  }

  void read_host(Scenario& s) {
    std::size_t i = 0;
    std::set<std::string, std::less<>> names;
    const duts::HostInterface* host = info_ != nullptr ? &info_->host : nullptr;
    for (const toml::table* t : root_.tables("host")) {
      TableReader r(file_, *t, fmt::format("host[{}]", i++));
      HostAction h;
      h.where = r.where();
      const bool program = r.has("program");
      const bool write = r.has("write") || program;
      const bool read = r.has("read");
      const std::string one_of =
          "exactly one of write = [words], program = \"<block>\" (the board's words) or read = word";
      if (program && r.has("write")) r.fail("program", one_of);
      if (write == read) r.fail(write ? "read" : "write", one_of);
      h.while_acknowledged = read && r.opt_boolean("while_acknowledged").value_or(false);
      if (h.while_acknowledged) {
        read_while_acknowledged(s, r, host);
        h.at = s.host.back().at;
      } else {
        h.at = r.duration("at");
        if (h.at < Nanos{0} || h.at > s.end) r.fail("at", "a time within the run (0 .. campaign.end)");
        if (!s.host.empty() && h.at < s.host.back().at)
          r.fail("at", fmt::format("times in order: this action ({} ns) is before the one above ({} ns)",
                                   h.at.count(), s.host.back().at.count()));
      }
      if (write) {
        h.kind = HostAction::Kind::Write;
        if (program) {
          std::vector<std::vector<std::uint16_t>> earlier;
          for (const HostAction& e : s.host)
            if (e.kind == HostAction::Kind::Write) earlier.push_back(e.words);
          h.words = read_program(r, info_, earlier);
        } else {
          h.words = read_words(r, "write");
        }
        if (host != nullptr && h.words.size() > host->output_words)
          r.fail("write", fmt::format("at most {} output words for {}", host->output_words, info_->name));
        if (host != nullptr && host->block_length_max != 0 && h.words[0] > host->block_length_max)
          r.fail("write", fmt::format("word 0 the block-transfer length of {}: 0 .. {} (0 = all {} words)",
                                      info_->name, host->block_length_max, host->block_length_max));
        h.raw = r.opt_boolean("raw").value_or(false);
        if (h.raw && host != nullptr && !host->handshake)
          r.fail("raw", fmt::format("no raw = true for {}: it has no Transmit handshake, every write is raw",
                                    info_->name));
        if (!h.raw && host != nullptr && host->handshake &&
            ((static_cast<unsigned>(h.words[0]) >> host->transmit_bit) & 1U) != 0U)
          r.fail("write",
                 fmt::format("word 0 with Transmit (bit {}) clear: the rig drives the handshake itself",
                             host->transmit_bit));
        h.name = r.opt_string("name").value_or("");
        if (auto to = opt_duration_in(r, "timeout", Nanos{1}, limits::kMaxEnd)) {
          if (h.raw) r.fail("timeout", "no timeout on a raw write: it waits for no Acknowledge");
          h.timeout = *to;
        }
      } else {
        h.kind = HostAction::Kind::Read;
        const std::int64_t word = r.integer("read");
        if (word < 0 || (host != nullptr && static_cast<std::size_t>(word) >= host->input_words))
          r.fail("read", host != nullptr ? fmt::format("an input word 0 .. {}", host->input_words - 1)
                                         : std::string("an input word >= 0"));
        h.word = static_cast<std::size_t>(word);
        if (host != nullptr && host->input_absent) {
          std::map<std::string, duts::ParamValue, std::less<>> params;
          for (const auto& [key, param] : s.dut.params) params[key] = param.value;
          const std::string absent = host->input_absent(duts::DutParams(std::move(params)), h.word);
          if (!absent.empty()) r.fail("read", absent);
        }
        h.name = r.string("name");
        if (!is_label(h.name)) r.fail("name", "the observation's name: " + label_range());
        if (names.contains(h.name))
          r.fail("name", fmt::format("a new observation name (\"{}\" is used above)", h.name));
        names.insert(h.name);
        h.unit = r.opt_string("unit").value_or("");
        h.is_signed = r.opt_boolean("signed").value_or(false);
      }
      r.finish();
      s.host.push_back(std::move(h));
    }
  }

  // A read within a handshake has no time of its own: it belongs to the handshake write above
  // (or follows another such read of it), on a board that has Acknowledge.
  void read_while_acknowledged(const Scenario& s, TableReader& r, const duts::HostInterface* host) const {
    if (host != nullptr && !host->handshake)
      r.fail(
          "while_acknowledged",
          fmt::format("no while_acknowledged for {}: it has no Transmit/Acknowledge handshake", info_->name));
    if (r.has("at"))
      r.fail("at",
             "no at with while_acknowledged: the read happens when Acknowledge of the write above is set");
    auto w = s.host.rbegin();
    while (w != s.host.rend() && w->kind == HostAction::Kind::Read && w->while_acknowledged) ++w;
    if (w == s.host.rend() || w->kind != HostAction::Kind::Write || w->raw)
      r.fail("while_acknowledged", "a [[host]] write with the handshake (not raw) right above this read");
  }

  // 16-bit words; a negative value is a PLC INT, stored as its two's complement.
  std::vector<std::uint16_t> read_words(TableReader& r, std::string_view key) const {
    std::vector<std::uint16_t> words;
    const auto* arr = r.node(key)->as_array();
    if (arr == nullptr || arr->empty()) r.fail(key, "an array of output words, word 0 first");
    for (const toml::node& e : *arr) {
      const auto* v = e.as_integer();
      if (v == nullptr || v->get() < limits::kMinWord || v->get() > limits::kMaxWord)
        fail(pos_of(e), r.key(key),
             "16-bit words (-32768 .. 0xFFFF; a negative one is a two's complement INT)");
      words.push_back(static_cast<std::uint16_t>(v->get()));
    }
    return words;
  }

  // [[device_fault]]: a fault the DUT's manual describes, by the names the DUT declares.
  void read_device_faults(Scenario& s) {
    std::size_t i = 0;
    for (const toml::table* t : root_.tables("device_fault")) {
      TableReader r(file_, *t, fmt::format("device_fault[{}]", i++));
      DeviceFaultEvent f;
      f.where = r.where();
      f.name = r.string("fault");
      if (info_ == nullptr || s.dut.backend != "virtual")
        r.fail("fault",
               "a fault of a virtual board (backend \"virtual\"): a real board's faults are its own");
      const auto index = info_->fault_index(f.name);
      if (!index) {
        std::vector<std::string> names;
        for (const auto& d : info_->faults) names.push_back(d.name);
        r.fail("fault", names.empty() ? fmt::format("none: {} has no device faults", info_->name)
                                      : fmt::format("a fault of {}: one of {}", info_->name, join(names)));
      }
      const duts::DeviceFaultInfo& d = info_->faults[*index];
      f.fault = *index;
      f.site = d.site;
      f.at = r.duration("at");
      if (f.at < Nanos{0} || f.at > s.end) r.fail("at", "a time within the run (0 .. campaign.end)");
      if (r.has("until")) {
        if (!d.clears)
          r.fail("until", fmt::format("no `until`: {} does not end by itself ({})", d.name, d.description));
        f.until = r.duration("until");
        if (f.until <= f.at) r.fail("until", "a time after `at`");
      }
      if (d.site != duts::FaultSite::Board && s.resolver.sin_line.empty())
        r.fail("fault", fmt::format("a [resolver] the rig drives: {} acts on its stator signals", d.name));
      if (d.site == duts::FaultSite::StatorRatio)
        f.ratio = number_in(r, "ratio", 0.0, limits::kMaxRatio, "a transformation ratio");
      r.finish();
      s.device_faults.push_back(std::move(f));
    }
  }

  // [[power_cycle]]: the board's supply off at `at` for `off`, on a virtual board whose model
  // knows what survives (DutInfo::power_cycle); in time order, one back on before the next.
  void read_power_cycles(Scenario& s) {
    std::size_t i = 0;
    for (const toml::table* t : root_.tables("power_cycle")) {
      TableReader r(file_, *t, fmt::format("power_cycle[{}]", i++));
      PowerCycleEvent p;
      p.where = r.where();
      if (info_ == nullptr || s.dut.backend != "virtual")
        r.fail("at", "a virtual board (backend \"virtual\"): the rig switches no supply of a real board");
      if (info_->power_cycle.empty())
        r.fail("at", fmt::format("none: the {} model has no power cycle", info_->name));
      p.at = r.duration("at");
      if (p.at < Nanos{0} || p.at > s.end) r.fail("at", "a time within the run (0 .. campaign.end)");
      p.off = duration_in(r, "off", Nanos{1}, limits::kMaxEnd);
      if (!s.power_cycles.empty() && p.at < s.power_cycles.back().on_at())
        r.fail("at", fmt::format("a time after the power cycle above is back on ({} ns)",
                                 s.power_cycles.back().on_at().count()));
      r.finish();
      s.power_cycles.push_back(p);
    }
  }

  // [[panel]]: a front-panel action of a virtual board, by the names the DUT declares, in time order.
  void read_panel(Scenario& s) {
    std::size_t i = 0;
    for (const toml::table* t : root_.tables("panel")) {
      TableReader r(file_, *t, fmt::format("panel[{}]", i++));
      PanelEvent p;
      p.where = r.where();
      p.name = r.string("action");
      if (info_ == nullptr || s.dut.backend != "virtual")
        r.fail("action", "a virtual board (backend \"virtual\"): the rig presses no key of a real board");
      const auto index = info_->panel_index(p.name);
      if (!index) {
        std::vector<std::string> names;
        for (const auto& a : info_->panel) names.push_back(a.name);
        r.fail("action",
               names.empty()
                   ? fmt::format("none: {} has no front panel the rig operates", info_->name)
                   : fmt::format("a front-panel action of {}: one of {}", info_->name, join(names)));
      }
      p.action = *index;
      p.at = r.duration("at");
      if (p.at < Nanos{0} || p.at > s.end) r.fail("at", "a time within the run (0 .. campaign.end)");
      if (!s.panel.empty() && p.at < s.panel.back().at)
        r.fail("at", fmt::format("times in order: this action ({} ns) is before the one above ({} ns)",
                                 p.at.count(), s.panel.back().at.count()));
      r.finish();
      s.panel.push_back(std::move(p));
    }
  }

  static nlohmann::json to_json(const toml::node& n) {
    if (const auto* i = n.as_integer()) return i->get();
    if (const auto* f = n.as_floating_point()) return f->get();
    if (const auto* b = n.as_boolean()) return b->get();
    if (const auto* s = n.as_string()) return s->get();
    if (const auto* a = n.as_array()) {
      nlohmann::json out = nlohmann::json::array();
      for (const toml::node& e : *a) out.push_back(to_json(e));
      return out;
    }
    if (const auto* t = n.as_table()) {
      nlohmann::json out = nlohmann::json::object();
      for (const auto& [k, v] : *t) out[std::string(k.str())] = to_json(v);
      return out;
    }
    return nullptr; // dates and times: refused by the check's schema
  }

  static bool is_line_param(std::string_view key) {
    return key == "line" || key == "input" || key == "output" || key == "fault_output" ||
           key.ends_with("_line");
  }

  // Which way a check's line must go for the check to judge the board: the lines it watches
  // for the board's response are board outputs the rig captures; a throughput or debounce
  // input, whose edges the response is timed from, is a board input the rig drives. A check
  // timing the rig's own line would pass whatever the board does. A brake line is either: the
  // rig's brake input to an ANS1, or a board output dropping a press's valve.
  static std::optional<duts::PinDirection> line_direction(std::string_view key) {
    if (key == "brake_line") return std::nullopt;
    return key == "input" ? duts::PinDirection::Input : duts::PinDirection::Output;
  }

  // A shaft_move check's profile_of: the [[host]] write of that name, and the move it starts
  // under the writes before it (duts::planned_move), typed here once.
  std::optional<checks::MoveProfile> profile_of(const Scenario& s, TableReader& r) const {
    const std::optional<std::string> name = r.opt_string("profile_of");
    if (!name) return std::nullopt;
    std::vector<std::vector<std::uint16_t>> earlier;
    for (const HostAction& h : s.host) {
      if (h.kind != HostAction::Kind::Write) continue;
      if (h.name != *name) {
        earlier.push_back(h.words);
        continue;
      }
      if (info_ == nullptr)
        r.fail("profile_of",
               "a [[host]] move of a virtual board's model: an external board plans no profile");
      try {
        const duts::PlannedMove m = duts::planned_move(info_->name, earlier, h.words);
        return checks::MoveProfile{h.at, m.starting_speed, m.speed, m.accel, m.decel, m.steps};
      } catch (const duts::NoPlannedMove& e) {
        r.fail("profile_of", fmt::format("the [[host]] write \"{}\" as {}", *name, e.what()));
      }
    }
    r.fail("profile_of",
           fmt::format("the name of a [[host]] write that starts a move (\"{}\" names none)", *name));
  }

  void read_checks(Scenario& s) {
    std::size_t i = 0;
    for (const toml::table* t : root_.tables("check")) {
      const std::string path = fmt::format("check[{}]", i++);
      TableReader r(file_, *t, path);
      CheckSpec c;
      c.where = r.where();
      c.kind = r.string("kind");
      c.name = r.string("name");
      if (!is_label(c.name)) r.fail("name", "the check's name: " + label_range());
      if (s.check(c.name) != nullptr)
        r.fail("name", fmt::format("a new check name (\"{}\" is used above)", c.name));
      // Every output names a measurement "<check>" or "<check>.<what>": without a dot in a
      // check's name no two checks' measurements can share a name ("on_forward.max" as a check
      // would be check on_forward's max), and the rig's own entries keep theirs.
      if (c.name.find('.') != std::string::npos)
        r.fail("name", fmt::format("a check name without '.' (\"{}\": '.' joins a check's name to the "
                                   "names of its measurements, so it could read as another check's "
                                   "measurement)",
                                   c.name));
      if (c.name == rig::kHostCheckName || c.name == rig::kRigCheckName)
        r.fail("name", fmt::format("a check name other than \"{}\" (the rig's own entry: \"host\" holds the "
                                   "host's handshakes, \"rig\" a hardware run's timing and a rig fault)",
                                   c.name));
      const checks::CheckKind* kind = checks::find_check_kind(c.kind);
      if (kind == nullptr) {
        std::vector<std::string> names;
        for (const auto& k : checks::check_kinds()) names.push_back(k.name);
        r.fail("kind", fmt::format("a check kind: one of {}", join(names)));
      }
      if (const toml::node* tags = r.node("tags")) {
        const auto* arr = tags->as_array();
        if (arr == nullptr) r.fail("tags", "an array of tag names, e.g. [\"nightly\", \"timing\"]");
        for (const toml::node& n : *arr) {
          const auto* tag = n.as_string();
          if (tag == nullptr || tag->get().empty())
            fail(pos_of(n), r.key("tags"), "a tag name (a non-empty string)");
          c.tags.push_back(tag->get());
        }
      }
      if (kind->needs_bisection) {
        c.probe_at = r.opt_duration("probe_at").value_or(Nanos{0});
        if (c.probe_at < Nanos{0} || c.probe_at >= s.end) r.fail("probe_at", "a time within the run");
      }
      nlohmann::json table = nlohmann::json::object();
      for (const auto& [k, v] : *t) {
        const std::string key(k.str());
        if (key == "kind" || key == "name" || key == "tags" || (kind->needs_bisection && key == "probe_at"))
          continue;
        (void)r.node(key);
        table[key] = to_json(v);
        if (key == "observation" || key == "reported") {
          // A mistyped name would judge a missing word at run time: a fail, and in a fault
          // run a fault "caught" by a check that never read the board.
          const auto* name = v.as_string();
          const bool read =
              name != nullptr && std::any_of(s.host.begin(), s.host.end(), [&](const HostAction& h) {
                return h.kind == HostAction::Kind::Read && h.name == name->get();
              });
          if (name != nullptr && !read) {
            std::vector<std::string> names;
            for (const HostAction& h : s.host)
              if (h.kind == HostAction::Kind::Read &&
                  std::find(names.begin(), names.end(), h.name) == names.end())
                names.push_back(h.name);
            r.fail(key, names.empty()
                            ? fmt::format("the name of a [[host]] read (\"{}\": the campaign reads no word)",
                                          name->get())
                            : fmt::format("the name of a [[host]] read (\"{}\" is not one{}): one of {}",
                                          name->get(), did_you_mean(name->get(), names), join(names)));
          }
        }
        if (is_line_param(key)) {
          const auto* line = v.as_string();
          const Wire* w = line != nullptr ? s.wire_for_rig(line->get()) : nullptr;
          if (line != nullptr && w == nullptr)
            r.fail(key, fmt::format("a wired rig line (\"{}\" is not in [[wiring]])", line->get()));
          const std::optional<duts::PinDirection> way = line_direction(key);
          if (w != nullptr && way && w->direction != *way)
            r.fail(key, *way == duts::PinDirection::Output
                            ? fmt::format("a line wired to a board output, which the rig captures; \"{}\" is "
                                          "wired to board input {}, which the rig drives",
                                          line->get(), w->board)
                            : fmt::format("a line wired to a board input, which the rig drives; \"{}\" is "
                                          "wired to board output {}",
                                          line->get(), w->board));
        }
      }
      try {
        c.params = checks::build_check_params(*kind, c.name, table);
      } catch (const checks::ParamError& e) {
        if (e.key().empty()) fail(c.where, path, e.what());
        r.fail(e.key(), e.what());
      }
      if (const auto problem = check_time_problem(s, *kind, table)) r.fail(problem->key, problem->expected);
      if (auto* move = std::get_if<checks::ShaftMoveParams>(&c.params)) move->spec.profile = profile_of(s, r);
      if (const auto* d = std::get_if<checks::DebounceParams>(&c.params)) {
        // The probe is a pulse the rig drives: on a synthesized line it would fight the source.
        if (const auto by = synthesized_by(s, d->plan.input))
          r.fail("input", fmt::format("a discrete input line; {} is driven by {}", d->plan.input, *by));
        // Every start phase's probe pulse, the widest too, ends within the run: a pulse still
        // running at the end could not be seen accepted, and a board within the limits would fail.
        const Nanos last = d->probe_starts(c.probe_at).back();
        if (last >= s.end)
          r.fail("probe_at",
                 fmt::format("probe_at + scan_us within the run (the last start phase is at {} ms)",
                             static_cast<double>(last.count()) / 1e6));
        if (last + d->plan.wide > s.end)
          r.fail("wide_us", fmt::format("a probe that ends within the run: the last start phase at {} ms + "
                                        "wide_us ends at {} ms, after campaign.end ({} ms)",
                                        static_cast<double>(last.count()) / 1e6,
                                        static_cast<double>((last + d->plan.wide).count()) / 1e6,
                                        static_cast<double>(s.end.count()) / 1e6));
      }
      r.finish();
      s.checks.push_back(std::move(c));
    }
    // A campaign that judges nothing would pass whatever the board does.
    if (s.checks.empty())
      fail(root_.where(), "check", "at least one [[check]]: a campaign with no checks judges nothing");
  }

  void read_faults(ScenarioFile& out) {
    const Scenario& s = out.scenario;
    std::size_t i = 0;
    for (const toml::table* t : root_.tables("fault")) {
      TableReader r(file_, *t, fmt::format("fault[{}]", i++));
      FaultSpec f;
      f.where = r.where();
      f.name = r.string("name");
      if (!is_label(f.name)) r.fail("name", "the fault's name: " + label_range());
      for (const FaultSpec& other : out.faults)
        if (other.name == f.name)
          r.fail("name", fmt::format("a new fault name (\"{}\" is used above)", f.name));
      if (auto v = r.opt_string("variant")) {
        if (info_ == nullptr) r.fail("variant", "device variants exist only for virtual models");
        // A device fault is a condition in time, not a model: its fault run puts it in with `set`.
        if (!info_->has_variant(*v) && info_->fault_index(*v))
          r.fail("variant",
                 fmt::format("a device variant: {} is a device fault of {}; a fault run puts it in "
                             "with set = {{ device_fault = [{{ fault = \"{}\", at = \"...\" }}] }}",
                             *v, info_->name, *v));
        if (!info_->has_variant(*v)) r.fail("variant", variant_expected());
        f.variant = *v;
      }
      if (const toml::table* sig = r.opt_table("signal")) {
        TableReader sr(file_, *sig, r.key("signal"));
        f.signal = read_stimulus(s, sr, true);
        sr.finish();
      }
      if (const toml::table* set = r.opt_table("set")) {
        if (set->empty())
          r.fail("set", "a table of scenario keys and their values, e.g. { \"campaign.end\" = \"2s\" }");
        for (const auto& [k, v] : *set) {
          const std::string key(k.str());
          if (key.starts_with("sweep") || key.starts_with("fault") ||
              (key.starts_with("campaign") && key != "campaign.end"))
            fail(pos_of(v), r.key("set"),
                 "a key of the scenario (dut, wiring, encoder, motion, stimulus, host, device_fault, "
                 "power_cycle, panel, check, campaign.end)");
          f.set_keys.push_back(key);
        }
      }
      if (!f.variant && !f.signal && f.set_keys.empty())
        r.fail("variant", "a device variant, a signal = { kind = ... } fault or set = { key = value }");
      const toml::node* by = r.node("caught_by");
      if (by == nullptr) r.fail("caught_by", "missing: the check (or checks) that must catch this fault");
      auto add = [&](const toml::node& n) {
        const auto* name = n.as_string();
        if (name == nullptr) fail(pos_of(n), r.key("caught_by"), "a check name or an array of check names");
        if (s.check(name->get()) == nullptr)
          fail(pos_of(n), r.key("caught_by"),
               fmt::format("a check of this campaign (\"{}\" is not)", name->get()));
        f.caught_by.push_back(name->get());
      };
      if (const auto* arr = by->as_array()) {
        if (arr->empty()) r.fail("caught_by", "at least one check name");
        for (const toml::node& n : *arr) add(n);
      } else {
        add(*by);
      }
      r.finish();
      out.faults.push_back(std::move(f));
    }
  }

  // [plant] (plant_reader.cpp): a plant turns the encoder shaft instead of [motion].
  void read_plant_table(Scenario& s) {
    (void)root_.node("plant");
    s.plant = read_plant(file_, root_.table(), s.wiring);
    if (!s.plant) return;
    if (!s.motion.moves.empty())
      fail(s.plant->where, "plant", "no [motion] moves beside it (the plant turns the shaft)");
  }

  const std::string& file_;
  TableReader root_;
  const duts::DutInfo* info_ = nullptr;
};

} // namespace

ScenarioFile read_scenario_file(const std::string& file, const toml::table& root) {
  return Reader(file, root).read();
}

} // namespace hilrig::campaign
