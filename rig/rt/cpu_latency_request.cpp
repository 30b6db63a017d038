#include "rig/rt/cpu_latency_request.hpp"

#include <fcntl.h>
#include <unistd.h>

#include <cerrno>
#include <cstdint>
#include <cstring>

namespace hilrig::rig {

CpuLatencyRequest::CpuLatencyRequest(int max_us) {
  fd_ = ::open("/dev/cpu_dma_latency", O_WRONLY | O_CLOEXEC);
  if (fd_ < 0) {
    problem_ = std::string("/dev/cpu_dma_latency: ") + std::strerror(errno);
    return;
  }
  const std::int32_t value = max_us;
  if (::write(fd_, &value, sizeof(value)) != static_cast<ssize_t>(sizeof(value))) {
    problem_ = std::string("/dev/cpu_dma_latency: write: ") + std::strerror(errno);
    ::close(fd_);
    fd_ = -1;
  }
}

CpuLatencyRequest::~CpuLatencyRequest() {
  if (fd_ >= 0) ::close(fd_); // closing the file withdraws the request
}

} // namespace hilrig::rig
