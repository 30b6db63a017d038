#pragma once
// Wake-up latency histogram with 1 us bins, as cyclictest keeps it. Fixed storage:
// recording never allocates, so the RT loop may call record().

#include <array>
#include <cstdint>
#include <limits>

#include "core/time.hpp"

namespace hilrig::rig {

class LatencyHistogram {
public:
  static constexpr std::size_t kBins = 10'000; // 0..9,999 us; beyond is counted as overflow

  void record(Nanos latency) noexcept {
    const std::int64_t ns = latency.count() < 0 ? 0 : latency.count();
    const auto us = static_cast<std::uint64_t>(ns / 1'000);
    if (us < kBins) {
      ++bins_[us];
    } else {
      ++overflow_;
    }
    ++count_;
    sum_ns_ += static_cast<std::uint64_t>(ns);
    if (ns < min_ns_) min_ns_ = ns;
    if (ns > max_ns_) max_ns_ = ns;
  }

  [[nodiscard]] std::uint64_t count() const noexcept { return count_; }
  [[nodiscard]] std::uint64_t overflow() const noexcept { return overflow_; }
  [[nodiscard]] std::uint64_t bin(std::size_t us) const noexcept { return us < kBins ? bins_[us] : 0; }
  [[nodiscard]] Nanos min() const noexcept { return Nanos{count_ ? min_ns_ : 0}; }
  [[nodiscard]] Nanos max() const noexcept { return Nanos{max_ns_}; }
  [[nodiscard]] Nanos average() const noexcept {
    return Nanos{count_ ? static_cast<std::int64_t>(sum_ns_ / count_) : 0};
  }
  // Smallest bin edge (in us, upper edge) under which fraction q of the samples fall.
  [[nodiscard]] std::uint64_t percentile_us(double q) const noexcept {
    if (count_ == 0) return 0;
    const auto want = static_cast<std::uint64_t>(q * static_cast<double>(count_) + 0.999999);
    std::uint64_t seen = 0;
    for (std::size_t us = 0; us < kBins; ++us) {
      seen += bins_[us];
      if (seen >= want) return us + 1;
    }
    return kBins;
  }
  // Highest non-empty bin, for printing.
  [[nodiscard]] std::size_t last_bin() const noexcept {
    for (std::size_t us = kBins; us-- > 0;) {
      if (bins_[us] != 0) return us;
    }
    return 0;
  }

private:
  // The totals first, then the bins: a wake-up writes the totals near the low bins it lands
  // in, not 80 KB past them on another page.
  std::uint64_t overflow_ = 0;
  std::uint64_t count_ = 0;
  std::uint64_t sum_ns_ = 0;
  std::int64_t min_ns_ = std::numeric_limits<std::int64_t>::max();
  std::int64_t max_ns_ = 0;
  std::array<std::uint64_t, kBins> bins_{};
};

} // namespace hilrig::rig
