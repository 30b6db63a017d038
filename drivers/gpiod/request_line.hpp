#pragma once
// A core LineOutput over one line of an OutputRequest, for either libgpiod backend
// (gpiod_v1.cpp, gpiod_v2.cpp): a write goes through the request, which knows the C API; the
// level last written is kept here.

#include <cstdint>

#include "core/line.hpp"
#include "drivers/gpiod/output_request.hpp"

namespace hilrig::gpiod {

class RequestLine final : public LineOutput {
public:
  RequestLine(OutputRequest& request, std::uint16_t index) : request_(request), index_(index) {}
  void set(Level level) override {
    request_.write(index_, level);
    level_ = level;
  }
  [[nodiscard]] Level driven() const override { return level_; }

private:
  OutputRequest& request_;
  std::uint16_t index_;
  Level level_ = Level::Low;
};

} // namespace hilrig::gpiod
