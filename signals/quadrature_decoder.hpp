#pragma once
// Quadrature decoder: X1/X2/X4 counting with illegal-transition detection and index
// handling. Forward is A leading B: (A,B) = 00 -> 10 -> 11 -> 01 -> 00 counts +1 per
// state change in X4.

#include <cstdint>

namespace hilrig::signals {

enum class CountMode : std::uint8_t { X1, X2, X4 };

class QuadratureDecoder {
public:
  explicit QuadratureDecoder(CountMode mode = CountMode::X4, bool a = false, bool b = false);

  // Feed the levels of A and B after an edge on either; returns the count change
  // (-1, 0 or +1). Both channels changing at once is an illegal transition: it is counted
  // in illegal_transitions() and leaves the count unchanged.
  int update(bool a, bool b);
  // Index (Z) level; on its rising edge the count is latched into index_count() and,
  // when reset_on_index is set, the count is reset to 0.
  void index(bool z);

  [[nodiscard]] std::int64_t count() const { return count_; }
  void set_count(std::int64_t c) { count_ = c; }
  [[nodiscard]] std::uint64_t illegal_transitions() const { return illegal_; }
  [[nodiscard]] std::uint64_t index_pulses() const { return index_pulses_; }
  [[nodiscard]] std::int64_t index_count() const { return index_count_; }
  bool reset_on_index = false;

private:
  CountMode mode_;
  std::uint8_t state_; // (A << 1) | B
  bool z_ = false;
  std::int64_t count_ = 0;
  std::int64_t index_count_ = 0;
  std::uint64_t illegal_ = 0;
  std::uint64_t index_pulses_ = 0;
};

} // namespace hilrig::signals
