// `hilrig serve DEVICE --param KEY=VALUE` and `hilrig serve pls2700 --motion`: a served board
// takes every [MODEL] choice its campaign adapter lists (the same names, kinds and ranges as
// a campaign's [dut.params], `hilrig list`), and the Series 2700 serves the chosen module's
// register map with a built-in transducer, so a PLC programs it without a far side.
#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <stdexcept>
#include <string>
#include <utility>
#include <vector>

#include <fmt/format.h>

#include "drivers/hostlink/modbus_client.hpp"
#include "rig/campaign/campaign_error.hpp"
#include "rig/campaign/campaign_parser.hpp"
#include "rig/cli/serve_params.hpp"
#include "rig/duts/dut.hpp"
#include "tests/modbus/serve_thread.hpp"

namespace hilrig::test {
namespace {

cli::ServeOptions on_tcp(std::string device, std::vector<std::string> params, std::string motion = "") {
  cli::ServeOptions o;
  o.device = std::move(device);
  o.link = cli::ServeLink::Tcp;
  o.port = 0;
  o.params = std::move(params);
  o.motion = std::move(motion);
  return o;
}

std::unique_ptr<hostlink::ModbusClient> client_of(const ServeThread& server) {
  hostlink::TcpSettings s;
  s.port = server.port();
  return hostlink::ModbusClient::tcp(s);
}

TEST(ServedParams, Pls2700ServesTheChosenModulesBtr) {
  // BTR length (pls2700 spec §1 table, L1257-L1260): 3 words on 1-channel modules, 5 on
  // 2-channel ones; reading past it is Illegal Data Address (README "Host register map").
  for (const auto& [model, words] : {std::pair{"2731", 3}, std::pair{"2731-04", 3}, std::pair{"2741", 3},
                                     std::pair{"2732", 5}, std::pair{"2742", 5}, std::pair{"2742-18", 5}}) {
    ServeThread server(on_tcp("pls2700", {std::string("model=") + model}));
    auto client = client_of(server);
    std::vector<std::uint16_t> btr(static_cast<std::size_t>(words));
    EXPECT_EQ(client->read_input_registers(0, btr), RegisterStatus::Ok) << model;
    std::array<std::uint16_t, 1> past{};
    EXPECT_EQ(client->read_input_registers(static_cast<std::uint16_t>(words), past),
              RegisterStatus::IllegalDataAddress)
        << model;
  }
}

TEST(ServedParams, Pls2700WithABuiltInTransducerTakesAProgram) {
  // With --motion the stators carry a turning resolver from the first update on: no
  // transducer fault, so a BTW (8400h Clear Errors; 9801h SF of channel 1 = 4096, BCD) is
  // accepted: error byte (holding 64) 00h, and the position word is a position, not 8000h
  // (R-T-6 / §7.20), below the Scale Factor on every module and speed.
  for (const char* model : {"2731", "2742", "2742-18"}) {
    for (const char* motion : {"constant:300rpm", "constant:0rpm", "constant:-1000.5rpm"}) {
      ServeThread server(on_tcp("pls2700", {std::string("model=") + model}, motion));
      auto client = client_of(server);
      const bool twelve_bit = std::string(model).starts_with("274");
      const std::uint16_t sf = twelve_bit ? 0x4096 : 0x1024;
      const std::array<std::uint16_t, 3> btw{0x8400, 0x8801, sf};
      ASSERT_EQ(client->write_holding_registers(0, btw), RegisterStatus::Ok);
      std::array<std::uint16_t, 1> error{0xFFFF};
      ASSERT_EQ(client->read_holding_registers(64, error), RegisterStatus::Ok);
      EXPECT_EQ(error[0], 0x00) << model << " " << motion;
      std::array<std::uint16_t, 1> position{};
      ASSERT_EQ(client->read_input_registers(0, position), RegisterStatus::Ok);
      EXPECT_LT(position[0], twelve_bit ? 4096 : 1024) << model << " " << motion;
    }
  }
}

TEST(ServedParams, EveryAdapterParameterOfTheThreeModelsIsAccepted) {
  // Each parameter `hilrig list` shows, set to its own default as text, starts the server.
  for (const char* device : {"pls2700", "amci4501", "ssi7361"}) {
    const duts::DutInfo* info = duts::find_dut(device);
    ASSERT_NE(info, nullptr);
    std::vector<std::string> all;
    for (const duts::ParamInfo& p : info->params) {
      std::string text;
      std::visit(
          [&text](const auto& v) {
            using T = std::decay_t<decltype(v)>;
            if constexpr (std::is_same_v<T, bool>)
              text = v ? "true" : "false";
            else if constexpr (std::is_same_v<T, std::string>)
              text = v;
            else if constexpr (std::is_same_v<T, Nanos>)
              text = std::to_string(v.count()) + "ns";
            else
              text = std::to_string(v);
          },
          p.default_value);
      all.push_back(p.name + "=" + text);
    }
    ServeThread server(on_tcp(device, all));
    EXPECT_GT(server.port(), 0) << device;
  }
}

TEST(ServedParams, ParamsReachTheModel) {
  // The parsed --param values are the model's: the typed DutParams the builders read.
  const duts::DutInfo* info = duts::find_dut("amci4501");
  ASSERT_NE(info, nullptr);
  const duts::DutParams p = cli::serve_params(
      *info, {"program_clears_results=true", "default_timeout=250ms", "no_response_missed=5"});
  EXPECT_TRUE(p.boolean("program_clears_results"));
  EXPECT_EQ(p.duration("default_timeout"), milliseconds(250));
  EXPECT_EQ(p.integer("no_response_missed"), 5);
  EXPECT_FALSE(p.boolean("mode4_timeout_sets_new")); // not written: the default
}

TEST(ServedParams, BadParamsAreRefusedBeforeServing) {
  // Unknown key, wrong kind, outside the adapter's range (the 2742-18 input delay is at most
  // 3 ms, L1724; the module list of §1), no '=', a bad motion, a motion for another device.
  const std::vector<cli::ServeOptions> bad{
      on_tcp("pls2700", {"no_such_key=1"}),
      on_tcp("pls2700", {"model=2799"}),
      on_tcp("pls2700", {"input_delay=3001us"}),
      on_tcp("pls2700", {"wrap_pairs=yes"}),
      on_tcp("pls2700", {"power_up_mask=256"}),
      on_tcp("pls2700", {"model"}),
      on_tcp("pls2700", {}, "constant:300"),
      on_tcp("pls2700", {}, "ramp:300rpm"),
      on_tcp("amci4501", {}, "constant:300rpm"),
      on_tcp("ssi7361", {"rate_rounding=up"}),
      on_tcp("ans1", {"model=2742"}),
      // Each in range, not together: a reference off the 2741's 200 us grid (L377), an empty
      // transducer-fault band (models/pls2700/README.md "Decoder").
      on_tcp("pls2700", {"model=2741", "excitation_hz=3000"}),
      on_tcp("pls2700", {"min_stator_ratio=0.6", "max_stator_ratio=0.5"}),
  };
  for (const cli::ServeOptions& o : bad) {
    EXPECT_THROW(ServeThread server(o), std::invalid_argument)
        << o.device << " " << (o.params.empty() ? o.motion : o.params[0]);
  }
  // At the limit it is accepted (limits are inclusive).
  ServeThread at_limit(on_tcp("pls2700", {"input_delay=3ms", "power_up_mask=255"}));
  EXPECT_GT(at_limit.port(), 0);
  ServeThread on_grid(on_tcp("pls2700", {"model=2741", "excitation_hz=7500"}));
  EXPECT_GT(on_grid.port(), 0);
  ServeThread one_point_band(on_tcp("pls2700", {"min_stator_ratio=1", "max_stator_ratio=1"}));
  EXPECT_GT(one_point_band.port(), 0);
}

TEST(ServedParams, Pls2700RulesAcrossKeysNameTheKeyAndTheValidValues) {
  // The update period is 200 us on a 2741 (L377), so a reference is a multiple of
  // 1/(2 * 200 us) = 2,500 Hz (models/pls2700/README.md "Decoder"); --model is model=.
  const duts::DutInfo& pls = *duts::find_dut("pls2700");
  const auto refusal = [&](const std::vector<std::string>& given) {
    try {
      (void)cli::serve_params(pls, given);
      return std::string("accepted");
    } catch (const std::invalid_argument& e) {
      return std::string(e.what());
    }
  };
  for (const char* hz : {"2500", "5000", "7500", "10000"})
    EXPECT_EQ(refusal({"model=2741", std::string("excitation_hz=") + hz}), "accepted") << hz;
  for (const char* hz : {"2499", "2501", "4999", "5001", "7499", "7501", "9999"})
    EXPECT_EQ(refusal({"excitation_hz=" + std::string(hz), "model=2741"}),
              "--param excitation_hz=" + std::string(hz) +
                  ": a reference whose half period 1/(2f) divides the 2741's 200 us update, so every update "
                  "samples at a peak (models/pls2700/README.md \"Decoder\", L377): a multiple of 2500 Hz up "
                  "to 10000: "
                  "2500, 5000, 7500, 10000 (got " +
                  hz + " Hz)");
  // The band: equal ends accepted, the minimum a hair above refused naming both keys.
  EXPECT_EQ(refusal({"min_stator_ratio=1", "max_stator_ratio=1"}), "accepted");
  EXPECT_EQ(refusal({"max_stator_ratio=1", "min_stator_ratio=1.000000000001"}),
            "--param min_stator_ratio=1.000000000001: min_stator_ratio at most max_stator_ratio: the "
            "transducer-fault band [min_stator_ratio, max_stator_ratio] is empty with 1.000000000001 > 1, a "
            "fault whatever the signal");
  EXPECT_EQ(
      refusal({"max_stator_ratio=0.4"}).rfind("--param max_stator_ratio=0.4: min_stator_ratio at most", 0),
      0U);
}

// What a campaign's [dut.params] says of `key = toml` (the value as TOML) on `device`: the
// reader's words after "dut.params.KEY: ", or why it was not about that key.
std::string campaign_param_says(const std::string& device, const std::string& key, const std::string& toml) {
  const std::string text = "[campaign]\nname = \"t\"\nend = \"1ms\"\n[dut]\nmodel = \"" + device +
                           "\"\n[dut.params]\n" + key + " = " + toml + "\n";
  try {
    (void)campaign::parse_campaign(text, "t.toml");
    return "accepted";
  } catch (const campaign::CampaignError& e) {
    return e.key() == "dut.params." + key ? e.expected() : std::string("another error: ") + e.what();
  }
}

// What `hilrig serve DEVICE --param KEY=TEXT` says: its words after "--param KEY=TEXT: ".
std::string serve_param_says(const duts::DutInfo& device, const std::string& key, const std::string& text) {
  try {
    (void)cli::serve_params(device, {key + "=" + text});
    return "accepted";
  } catch (const std::invalid_argument& e) {
    const std::string said = e.what();
    const std::string prefix = "--param " + key + "=" + text + ": ";
    return said.starts_with(prefix) ? said.substr(prefix.size()) : "no \"" + prefix + "\": " + said;
  }
}

TEST(ServedParams, AValueOfTheWrongKindSaysWhatTheKindIsWrittenAs) {
  // The audit's case (s23 finding 3): a duration without its unit, or with a wrong one, is
  // named as such (docs/campaigns.md "Durations and times are strings with a unit"), not as a
  // range it seems to lie in.
  const duts::DutInfo& amci = *duts::find_dut("amci4501");
  for (const char* text : {"125", "1.5", "125xs", "abc", "", " 125us"})
    EXPECT_EQ(serve_param_says(amci, "throughput", text),
              R"(expected a duration with a unit, like "250us", "10ms" or "1.5s")")
        << text;
  // A duration too long to hold is out of the range, named as such (re-verification R5).
  for (const char* text : {"99999999999999999999s", "1e400s"})
    EXPECT_EQ(serve_param_says(amci, "throughput", text).rfind("a value in 0s .. 10ms", 0), 0U)
        << serve_param_says(amci, "throughput", text);
  EXPECT_EQ(serve_param_says(amci, "no_response_missed", "4.5"), "expected an integer");
  EXPECT_EQ(serve_param_says(amci, "no_response_missed", "0x"), "expected an integer");
  EXPECT_EQ(serve_param_says(amci, "no_response_missed", "0x-5"), "expected an integer");
  EXPECT_EQ(serve_param_says(amci, "program_clears_results", "yes"), "expected true or false");
  EXPECT_EQ(serve_param_says(amci, "start_jumper", "up"),
            "one of rising, falling (amci4501 " + amci.param("start_jumper")->description + ")");
  // An integer is decimal (a leading 0 is not octal) or hex after 0x, as in a campaign (TOML).
  const duts::DutInfo& pls = *duts::find_dut("pls2700");
  EXPECT_EQ(cli::serve_params(pls, {"power_up_mask=010"}).integer("power_up_mask"), 10);
  EXPECT_EQ(cli::serve_params(pls, {"power_up_mask=0xFF"}).integer("power_up_mask"), 255);
  EXPECT_EQ(cli::serve_params(pls, {"power_up_mask=+7"}).integer("power_up_mask"), 7);
}

TEST(ServedParams, EveryRefusalReadsAsTheCampaignReadersForTheSameValue) {
  // Every parameter of every device: values of the wrong kind, and a hair beyond each end of
  // the declared range (the ends themselves are accepted: limits are inclusive), are refused by
  // `serve --param` in the words a campaign's [dut.params] gets for the same value. An end a
  // rule across keys refuses beside the other keys' defaults (the 2700's min_stator_ratio 10
  // above max_stator_ratio 1.5) is refused by both in the rule's words.
  for (const duts::DutInfo& device : duts::dut_registry()) {
    for (const duts::ParamInfo& p : device.params) {
      std::vector<std::pair<std::string, std::string>> refused; // (serve text, TOML)
      struct InRange {
        std::string text, toml;
        duts::ParamValue value;
      };
      std::vector<InRange> accepted;
      const auto quoted = [](const std::string& t) { return "\"" + t + "\""; };
      switch (p.kind) {
      case duts::ParamKind::Integer: {
        const auto lo = static_cast<std::int64_t>(p.range.min);
        const auto hi = static_cast<std::int64_t>(p.range.max);
        refused = {{"1.5", "1.5"},
                   {"abc", quoted("abc")},
                   {"", quoted("")},
                   {std::to_string(lo - 1), std::to_string(lo - 1)},
                   {std::to_string(hi + 1), std::to_string(hi + 1)}};
        accepted = {{std::to_string(lo), std::to_string(lo), lo},
                    {std::to_string(hi), std::to_string(hi), hi}};
        break;
      }
      case duts::ParamKind::Number: {
        const auto hair = [](double v) { return std::max(1e-9, std::abs(v) * 1e-9); };
        const std::string below = fmt::format("{:.12e}", p.range.min - hair(p.range.min));
        const std::string above = fmt::format("{:.12e}", p.range.max + hair(p.range.max));
        refused = {{"abc", quoted("abc")}, {"inf", "inf"}, {"nan", "nan"}, {below, below}, {above, above}};
        for (const double end : {p.range.min, p.range.max})
          accepted.push_back({fmt::format("{}", end), fmt::format("{}", end), end});
        break;
      }
      case duts::ParamKind::Duration: {
        const auto ns = [](double v, std::int64_t step) {
          return std::to_string(static_cast<std::int64_t>(v) + step) + "ns";
        };
        const std::string below = ns(p.range.min, -1);
        const std::string above = ns(p.range.max, 1);
        refused = {{"125", "125"},         {"1.5", "1.5"},         {"125xs", quoted("125xs")},
                   {"abc", quoted("abc")}, {below, quoted(below)}, {above, quoted(above)}};
        for (const double end : {p.range.min, p.range.max})
          accepted.push_back({ns(end, 0), quoted(ns(end, 0)), Nanos{static_cast<std::int64_t>(end)}});
        break;
      }
      case duts::ParamKind::Boolean:
        refused = {{"yes", quoted("yes")}, {"1", "1"}};
        accepted = {{"true", "true", true}, {"false", "false", false}};
        break;
      case duts::ParamKind::Text:
        if (!p.range.choices.empty()) refused = {{"no_such_word", quoted("no_such_word")}};
        for (const std::string& word : p.range.choices) accepted.push_back({word, quoted(word), word});
        break;
      }
      for (const auto& [text, toml] : refused) {
        const std::string campaign = campaign_param_says(device.name, p.name, toml);
        EXPECT_NE(campaign, "accepted") << device.name << " " << p.name << " = " << toml;
        EXPECT_EQ(serve_param_says(device, p.name, text), campaign)
            << device.name << " --param " << p.name << "=" << text;
      }
      for (const InRange& in : accepted) {
        const auto conflict = device.params_conflict({{p.name, in.value}});
        const std::string want = conflict ? conflict->expected : "accepted";
        EXPECT_EQ(serve_param_says(device, p.name, in.text), want)
            << device.name << " " << p.name << "=" << in.text;
        if (conflict) { // a campaign of this key alone has no checks: only its refusal says anything
          EXPECT_EQ(campaign_param_says(device.name, p.name, in.toml), want)
              << device.name << " " << p.name << " = " << in.toml;
        }
      }
    }
  }
}

} // namespace
} // namespace hilrig::test
