#include "rig/duts/ssi7361_dut.hpp"
#include "rig/duts/seed_phase.hpp"

#include <memory>
#include <stdexcept>

#include "drivers/virtual/virtual_bus.hpp"
#include "models/ssi7361/ssi7361.hpp"

namespace hilrig::duts {

using namespace hilrig::literals;

namespace {

namespace s = hilrig::models::ssi7361;

constexpr const char* kPinClock = "CLK";
constexpr const char* kPinData = "DATA";

class Ssi7361Dut final : public Dut {
public:
  Ssi7361Dut(Scheduler& scheduler, const s::Params& params) : scheduler_(scheduler), params_(params) {}

  // The module starts clocking when attached: its lines exist only then.
  void attach(virt::VirtualBus& bus,
              const std::map<std::string, std::string, std::less<>>& pin_to_line) override {
    std::string clock = "ssi7361.CLK";
    std::string data = "ssi7361.DATA";
    for (const auto& [pin, line] : pin_to_line) {
      if (pin == kPinClock)
        clock = line;
      else if (pin == kPinData)
        data = line;
      else
        throw std::invalid_argument("ssi7361 has no pin " + pin);
    }
    virt::DigitalLine& clk = bus.line(clock, Level::High);
    virt::DigitalLine& dat = bus.line(data, Level::High);
    module_ = std::make_unique<s::Ssi7361>(scheduler_, clk.driver(), dat.reader(), params_);
  }

  void host_write(std::size_t word, std::uint16_t value) override { module().write_command(word, value); }
  [[nodiscard]] std::uint16_t host_read(std::size_t word) const override {
    if (!module_) throw std::logic_error("ssi7361: host read before attach");
    return module_->status_words().at(word);
  }
  // The one board fault: an EEPROM parameter corrupted (E2Err). It has no end of its own:
  // the host's E2CLR clears it (the parser refuses an `until`).
  void device_fault(std::size_t fault, bool active) override {
    if (fault != 0 || !active) throw std::logic_error("ssi7361: no such device fault");
    module().corrupt_eeprom();
  }
  void power(bool on) override {
    if (on)
      module().power_on();
    else
      module().power_off();
  }

private:
  s::Ssi7361& module() {
    if (!module_) throw std::logic_error("ssi7361: host write before attach");
    return *module_;
  }

  Scheduler& scheduler_;
  s::Params params_;
  std::unique_ptr<s::Ssi7361> module_;
};

} // namespace

s::Params ssi7361_params(const DutParams& params) {
  s::Params p;
  p.first_frame = params.duration("first_frame");
  p.sample_instant = params.boolean("sample_at_rising_edge") ? s::SampleInstant::AtRisingEdge
                                                             : s::SampleInstant::HalfPeriodAfterRising;
  p.read_all_ones_without_supply = params.boolean("read_all_ones_without_supply");
  p.invert_before_gray = params.boolean("invert_before_gray");
  p.count_direction_wrap = params.boolean("count_direction_wrap");
  const std::string& rounding = params.text("rate_rounding");
  if (rounding != "truncate" && rounding != "nearest")
    throw std::invalid_argument("ssi7361 rate_rounding is truncate or nearest, not " + rounding);
  p.rate_rounding = rounding == "nearest" ? s::RateRounding::Nearest : s::RateRounding::Truncate;
  p.rate_overflow_limit = params.integer("rate_overflow_limit");
  p.preset_restarts_rate_window = params.boolean("preset_restarts_rate_window");
  const std::string& clears = params.text("format_clears_offset");
  if (clears != "when_changed" && clears != "always")
    throw std::invalid_argument("ssi7361 format_clears_offset is when_changed or always, not " + clears);
  p.format_clears_offset =
      clears == "always" ? s::FormatClearsOffset::Always : s::FormatClearsOffset::WhenSetupChanges;
  p.preset_limit = static_cast<std::int32_t>(params.integer("preset_limit"));
  p.multiplier_may_equal_divisor = params.boolean("multiplier_may_equal_divisor");
  p.acknowledge_delay = params.duration("acknowledge_delay");
  p.clock_period_error = params.duration("clock_period_error");
  p.frame_period_error = params.duration("frame_period_error");
  return p;
}

DutInfo ssi7361_info() {
  DutInfo info;
  info.name = "ssi7361";
  info.description = "AMCI 7361 SSI interface module, the SSI master (virtual model, docs/spec/ssi7361.md)";
  info.pins = {
      {kPinClock, PinDirection::Output, "SSI clock CLK+/- (idles high; 25 clocks per frame)", false},
      {kPinData, PinDirection::Input, "SSI data DATA+/- from the transducer (idle high)", false},
  };
  const s::Params d{};
  // Ranges (docs/spec/ssi7361.md): data values are 25-bit, |Preset| <= 33,554,431 (L91, L148; A2);
  // ROVErr above 64,108,863 counts/s (L182, A3), a limit of 0 .. 2^31 - 1; the first frame
  // within 0 .. 1 s (a frame every 250/500 us, L53); ACK within 0 .. 1 s.
  info.params = {
      {"first_frame", ParamKind::Duration, d.first_frame, "F1 of the first frame", between(0_us, 1_s)},
      {"frame_phase_from_seed",
       ParamKind::Boolean,
       true,
       "[MODEL] F1 of the first frame also moves by the seed's phase within a 125 kHz frame period",
       {}},
      {"sample_at_rising_edge",
       ParamKind::Boolean,
       false,
       "sample bit k at R_k instead of half a period later",
       {}},
      {"read_all_ones_without_supply",
       ParamKind::Boolean,
       d.read_all_ones_without_supply,
       "no +24 V on pins 1/2: every bit reads 1 (L2182-2184)",
       {}},
      {"invert_before_gray",
       ParamKind::Boolean,
       d.invert_before_gray,
       "Data Logic inversion before Gray (A14)",
       {}},
      {"count_direction_wrap",
       ParamKind::Boolean,
       d.count_direction_wrap,
       "negative direction maps 0 to 0 (A12)",
       {}},
      {"rate_rounding", ParamKind::Text, std::string("truncate"), "rate of change: truncate or nearest (A9)",
       one_of({"truncate", "nearest"})},
      {"rate_overflow_limit", ParamKind::Integer, d.rate_overflow_limit, "ROVErr above this |RoC| (A3)",
       between(0.0, 2'147'483'647.0)},
      {"preset_restarts_rate_window",
       ParamKind::Boolean,
       d.preset_restarts_rate_window,
       "an applied preset starts a new rate window",
       {}},
      {"format_clears_offset", ParamKind::Text, std::string("when_changed"),
       "Format clears LO: when_changed or always (A27)", one_of({"when_changed", "always"})},
      {"preset_limit", ParamKind::Integer, std::int64_t{d.preset_limit}, "largest |Preset| accepted (A2)",
       between(0.0, 33'554'431.0)},
      {"multiplier_may_equal_divisor",
       ParamKind::Boolean,
       d.multiplier_may_equal_divisor,
       "MUL <= DIV (A4)",
       {}},
      {"acknowledge_delay", ParamKind::Duration, d.acknowledge_delay, "TRMT edge to ACK", between(0_us, 1_s)},
      // Detection-power knobs (docs/power.md). Ranges keep every frame's 25 clocks inside its
      // TINT at both rates: at 125 kHz R25 = 24.5 T = 196 us of TINT 500 us, at 500 kHz 49 of
      // 250 us (L1090, L1096-1098); T + 1 us and TINT - 100 us still leave room.
      {"clock_period_error", ParamKind::Duration, d.clock_period_error,
       "[KNOB] added to the SSI clock period T (8 / 2 us, L1123): a clock off its rate (0)",
       between(-1_us, 1_us)},
      {"frame_period_error", ParamKind::Duration, d.frame_period_error,
       "[KNOB] added to the frame period TINT (500 / 250 us, L1090, L1096): a frame timer off its rate (0)",
       between(-100_us, 100_us)},
  };
  for (const auto& v : s::kVariantNames)
    info.variants.push_back({std::string(v.name), std::string(v.description)});
  info.faults.push_back(
      {"eeprom_error",
       "a parameter in EEPROM is corrupted: E2Err (%I bit 13) set at once (L2043-2044); the module "
       "keeps converting with its setup; every programming cycle without E2CLR (%Q bit 15) is refused "
       "with CMDErr (%I bit 7, L2029); E2CLR clears E2Err and loads the factory defaults, LO 0 "
       "(L253-255, L2119-2121). No `until`: only E2CLR clears it",
       FaultSite::Board, false});
  info.power_cycle =
      "the setup (format, scalars, RUT, direction) and the preset's offset LO are in EEPROM and survive "
      "(L1304-1306); every error bit is cleared (L254-256, L921-923) except E2Err [MODEL: the corrupted "
      "parameter is still in EEPROM]; while off: no frames, CLK idle high, status words 0 [MODEL]; back on: "
      "ACK 0, raw/Data Value/rate 0 until the first frame is read [MODEL A28], the first frame first_frame "
      "after power-up (the "
      "manual: "
      "'a few seconds' to the RUN LED, L718)";
  info.host = HostInterface{s::kCommandWords, s::kStatusWords, true, 15, 15};
  info.make = [](Scheduler& scheduler, const DutParams& params, std::string_view variant,
                 std::uint64_t seed) -> std::unique_ptr<Dut> {
    s::Params p = ssi7361_params(params);
    if (params.boolean("frame_phase_from_seed"))
      p.frame_phase =
          phase_from_seed(seed, signals::SsiMaster(signals::ssi7361_master(false)).frame_period());
    const auto v = s::variant_from_string(variant);
    if (!v) throw std::invalid_argument("ssi7361 has no variant " + std::string(variant));
    p.variant = *v;
    return std::make_unique<Ssi7361Dut>(scheduler, p);
  };
  return info;
}

} // namespace hilrig::duts
