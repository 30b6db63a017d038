#pragma once
#include <stdexcept>
#include <string>

namespace hilrig::gpiod {

// A GPIO request that failed: names the chip, the lines and the system's reason.
class GpioError : public std::runtime_error {
public:
  using std::runtime_error::runtime_error;
};

} // namespace hilrig::gpiod
