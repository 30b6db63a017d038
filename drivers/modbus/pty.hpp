#pragma once
// A pseudo-terminal pair: the server side keeps the master; a Modbus RTU client opens
// slave_path() as if it were a serial port. The slave is held open (in raw mode) for the
// pair's lifetime, so clients may come and go without the master seeing a hang-up.

#include <string>

namespace hilrig::drivers::modbus {

class Pty {
public:
  Pty(); // throws std::runtime_error when no pty can be allocated
  Pty(const Pty&) = delete;
  Pty& operator=(const Pty&) = delete;
  ~Pty();

  [[nodiscard]] int master_fd() const { return master_; }
  [[nodiscard]] const std::string& slave_path() const { return slave_path_; }

private:
  int master_ = -1;
  int slave_ = -1;
  std::string slave_path_;
};

} // namespace hilrig::drivers::modbus
