#pragma once
// Time in hilrig: one strong type, signed 64-bit nanoseconds. It serves for instants
// (nanoseconds since a clock's epoch) and for durations alike, as CLOCK_MONOTONIC does.

#include <compare>
#include <cstdint>
#include <limits>

namespace hilrig {

class Nanos {
public:
  constexpr Nanos() = default;
  constexpr explicit Nanos(std::int64_t ns) : ns_(ns) {}

  [[nodiscard]] constexpr std::int64_t count() const { return ns_; }
  [[nodiscard]] constexpr double seconds() const { return static_cast<double>(ns_) * 1e-9; }
  [[nodiscard]] constexpr double micros() const { return static_cast<double>(ns_) * 1e-3; }

  // Rounds to the nearest nanosecond (half away from zero).
  [[nodiscard]] static constexpr Nanos from_seconds(double s) {
    const double ns = s * 1e9;
    return Nanos{static_cast<std::int64_t>(ns < 0 ? ns - 0.5 : ns + 0.5)};
  }
  [[nodiscard]] static constexpr Nanos max() { return Nanos{std::numeric_limits<std::int64_t>::max()}; }
  [[nodiscard]] static constexpr Nanos min() { return Nanos{std::numeric_limits<std::int64_t>::min()}; }
  [[nodiscard]] static constexpr Nanos zero() { return Nanos{0}; }

  constexpr auto operator<=>(const Nanos&) const = default;

  constexpr Nanos& operator+=(Nanos o) {
    ns_ += o.ns_;
    return *this;
  }
  constexpr Nanos& operator-=(Nanos o) {
    ns_ -= o.ns_;
    return *this;
  }
  friend constexpr Nanos operator+(Nanos a, Nanos b) { return Nanos{a.ns_ + b.ns_}; }
  friend constexpr Nanos operator-(Nanos a, Nanos b) { return Nanos{a.ns_ - b.ns_}; }
  friend constexpr Nanos operator-(Nanos a) { return Nanos{-a.ns_}; }
  friend constexpr Nanos operator*(Nanos a, std::int64_t k) { return Nanos{a.ns_ * k}; }
  friend constexpr Nanos operator*(std::int64_t k, Nanos a) { return Nanos{a.ns_ * k}; }
  friend constexpr Nanos operator/(Nanos a, std::int64_t k) { return Nanos{a.ns_ / k}; }
  friend constexpr std::int64_t operator/(Nanos a, Nanos b) { return a.ns_ / b.ns_; }
  friend constexpr Nanos operator%(Nanos a, Nanos b) { return Nanos{a.ns_ % b.ns_}; }

private:
  std::int64_t ns_ = 0;
};

[[nodiscard]] constexpr Nanos nanoseconds(std::int64_t n) { return Nanos{n}; }
[[nodiscard]] constexpr Nanos microseconds(std::int64_t n) { return Nanos{n * 1'000}; }
[[nodiscard]] constexpr Nanos milliseconds(std::int64_t n) { return Nanos{n * 1'000'000}; }
[[nodiscard]] constexpr Nanos seconds(std::int64_t n) { return Nanos{n * 1'000'000'000}; }

namespace literals {
constexpr Nanos operator""_ns(unsigned long long n) { return Nanos{static_cast<std::int64_t>(n)}; }
constexpr Nanos operator""_us(unsigned long long n) { return microseconds(static_cast<std::int64_t>(n)); }
constexpr Nanos operator""_ms(unsigned long long n) { return milliseconds(static_cast<std::int64_t>(n)); }
constexpr Nanos operator""_s(unsigned long long n) { return seconds(static_cast<std::int64_t>(n)); }
} // namespace literals

} // namespace hilrig
