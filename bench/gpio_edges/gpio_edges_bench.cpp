// Figure 6b: output edges per second through the gpiod backend (drivers/gpiod OutputRequest),
// against a bare libgpiod set-value loop on the same gpio-sim line, in one binary. Rounds
// alternate hilrig and peer so both see the same machine; medians are reported.
// After each timed loop the far side (gpio-sim's sim_gpioN/value) must show the last level
// written, so neither loop is measured writing nowhere.
//
// Usage: bench_gpio_edges CHIP LINE EDGES ROUNDS [SIM_DIR]   (prints key=value lines)
#include <gpiod.h>

#include <algorithm>
#include <array>
#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <stdexcept>
#include <string>
#include <vector>

#include "core/clock.hpp"
#include "drivers/gpiod/output_request.hpp"

using namespace hilrig;

namespace {

struct Loop {
  double edges_per_s = 0;
  std::uint64_t errors = 0;
  int far_side = -1; // sim_gpioN/value after the loop, the line still held; -1: not read
};

// What gpio-sim's far side reads on the line (-1 when no simulator directory was given).
int far_side(const std::string& sim, unsigned line) {
  if (sim.empty()) return -1;
  std::ifstream f(sim + "/sim_gpio" + std::to_string(line) + "/value");
  int v = -1;
  f >> v;
  return v;
}

double seconds_between(Nanos a, Nanos b) { return static_cast<double>((b - a).count()) * 1e-9; }

Loop hilrig_loop(const std::string& chip, unsigned line, std::uint64_t edges, const std::string& sim) {
  const std::array<unsigned, 1> lines{line};
  gpiod::OutputRequest out(chip, lines, gpiod::LineSettings{}, "bench-hilrig");
  const MonotonicClock clock;
  const Nanos start = clock.now();
  for (std::uint64_t i = 0; i < edges; ++i) out.write(0, (i % 2 == 0) ? Level::High : Level::Low);
  const Nanos end = clock.now();
  return Loop{static_cast<double>(edges) / seconds_between(start, end), out.write_errors(),
              far_side(sim, line)};
}

#if HILRIG_GPIOD_API == 2
Loop bare_loop(const std::string& chip, unsigned line, std::uint64_t edges, const std::string& sim) {
  const std::string path = chip.find('/') == std::string::npos ? "/dev/" + chip : chip;
  gpiod_chip* c = gpiod_chip_open(path.c_str());
  if (c == nullptr) throw std::runtime_error("cannot open " + path);
  gpiod_line_settings* s = gpiod_line_settings_new();
  gpiod_line_settings_set_direction(s, GPIOD_LINE_DIRECTION_OUTPUT);
  gpiod_line_config* lc = gpiod_line_config_new();
  gpiod_line_config_add_line_settings(lc, &line, 1, s);
  gpiod_request_config* rc = gpiod_request_config_new();
  gpiod_request_config_set_consumer(rc, "bench-bare");
  gpiod_line_request* r = gpiod_chip_request_lines(c, rc, lc);
  gpiod_request_config_free(rc);
  gpiod_line_config_free(lc);
  gpiod_line_settings_free(s);
  if (r == nullptr) throw std::runtime_error("cannot request the line");
  std::uint64_t errors = 0;
  const MonotonicClock clock;
  const Nanos start = clock.now();
  for (std::uint64_t i = 0; i < edges; ++i) {
    if (gpiod_line_request_set_value(r, line,
                                     (i % 2 == 0) ? GPIOD_LINE_VALUE_ACTIVE : GPIOD_LINE_VALUE_INACTIVE) != 0)
      ++errors;
  }
  const Nanos end = clock.now();
  const int far = far_side(sim, line);
  gpiod_line_request_release(r);
  gpiod_chip_close(c);
  return Loop{static_cast<double>(edges) / seconds_between(start, end), errors, far};
}
#else
Loop bare_loop(const std::string& chip, unsigned line, std::uint64_t edges, const std::string& sim) {
  gpiod_chip* c = gpiod_chip_open_lookup(chip.c_str());
  if (c == nullptr) throw std::runtime_error("cannot open " + chip);
  gpiod_line* l = gpiod_chip_get_line(c, line);
  if (l == nullptr || gpiod_line_request_output(l, "bench-bare", 0) != 0) {
    gpiod_chip_close(c);
    throw std::runtime_error("cannot request the line");
  }
  std::uint64_t errors = 0;
  const MonotonicClock clock;
  const Nanos start = clock.now();
  for (std::uint64_t i = 0; i < edges; ++i) {
    if (gpiod_line_set_value(l, (i % 2 == 0) ? 1 : 0) != 0) ++errors;
  }
  const Nanos end = clock.now();
  const int far = far_side(sim, line);
  gpiod_line_release(l);
  gpiod_chip_close(c);
  return Loop{static_cast<double>(edges) / seconds_between(start, end), errors, far};
}
#endif

double median(std::vector<double> v) {
  std::sort(v.begin(), v.end());
  const std::size_t n = v.size();
  return n % 2 == 1 ? v[n / 2] : (v[n / 2 - 1] + v[n / 2]) / 2;
}

} // namespace

int main(int argc, char** argv) {
  if (argc < 5) {
    std::fprintf(stderr, "usage: %s CHIP LINE EDGES ROUNDS [SIM_DIR]\n", argv[0]);
    return 2;
  }
  const std::string chip = argv[1];
  const auto line = static_cast<unsigned>(std::strtoul(argv[2], nullptr, 10));
  // Odd, so the last level written is High and differs from the released line's.
  const std::uint64_t edges = std::strtoull(argv[3], nullptr, 10) | 1U;
  const int rounds = std::max(1, std::atoi(argv[4]));
  const std::string sim = argc > 5 ? argv[5] : "";
  try {
    std::vector<double> hil, bare, paired;
    std::uint64_t hil_errors = 0, bare_errors = 0, far_side_wrong = 0;
    for (int r = 0; r < rounds; ++r) {
      // Who goes first alternates, so neither always runs on the warmer (or busier) machine.
      Loop h, b;
      if (r % 2 == 0) {
        h = hilrig_loop(chip, line, edges, sim);
        b = bare_loop(chip, line, edges, sim);
      } else {
        b = bare_loop(chip, line, edges, sim);
        h = hilrig_loop(chip, line, edges, sim);
      }
      // The last level written is High: the far side must see it (when it can be read).
      if (h.far_side == 0) ++far_side_wrong;
      if (b.far_side == 0) ++far_side_wrong;
      hil.push_back(h.edges_per_s);
      bare.push_back(b.edges_per_s);
      paired.push_back(h.edges_per_s / b.edges_per_s); // same moment, same machine load
      hil_errors += h.errors;
      bare_errors += b.errors;
      std::printf("round%d_hilrig=%.1f\nround%d_bare=%.1f\n", r, h.edges_per_s, r, b.edges_per_s);
    }
    std::printf("libgpiod_api=%d\nlibgpiod_version=%s\nchip=%s\nline=%u\nedges=%llu\nrounds=%d\n",
                HILRIG_GPIOD_API,
#if HILRIG_GPIOD_API == 2
                gpiod_api_version(),
#else
                gpiod_version_string(),
#endif
                chip.c_str(), line, static_cast<unsigned long long>(edges), rounds);
    std::printf("paired_ratio=%.3f\n", median(paired));
    std::printf("hilrig_eps=%.1f\nbare_eps=%.1f\nhilrig_errors=%llu\nbare_errors=%llu\nfar_side_checked=%s\n"
                "far_side_wrong=%llu\n",
                median(hil), median(bare), static_cast<unsigned long long>(hil_errors),
                static_cast<unsigned long long>(bare_errors), sim.empty() ? "no" : "yes",
                static_cast<unsigned long long>(far_side_wrong));
    return hil_errors == 0 && bare_errors == 0 && far_side_wrong == 0 ? 0 : 1;
  } catch (const std::exception& e) {
    std::fprintf(stderr, "bench_gpio_edges: %s\n", e.what());
    return 2;
  }
}
