// OutputRequest and InputRequest on libgpiod 1.6 (Debian 12), the v1 C API.
#include <fcntl.h>
#include <gpiod.h>

#include <cerrno>
#include <cstring>

#include "drivers/gpiod/input_request.hpp"
#include "drivers/gpiod/line_names.hpp"
#include "drivers/gpiod/output_request.hpp"
#include "drivers/gpiod/request_line.hpp"

namespace hilrig::gpiod {

namespace {

int request_flags(const LineSettings& s) {
  int f = 0;
  if (s.active_low) f |= GPIOD_LINE_REQUEST_FLAG_ACTIVE_LOW;
  switch (s.bias) {
  case Bias::Disabled:
    f |= GPIOD_LINE_REQUEST_FLAG_BIAS_DISABLE;
    break;
  case Bias::PullUp:
    f |= GPIOD_LINE_REQUEST_FLAG_BIAS_PULL_UP;
    break;
  case Bias::PullDown:
    f |= GPIOD_LINE_REQUEST_FLAG_BIAS_PULL_DOWN;
    break;
  case Bias::AsIs:
    break;
  }
  switch (s.drive) {
  case Drive::OpenDrain:
    f |= GPIOD_LINE_REQUEST_FLAG_OPEN_DRAIN;
    break;
  case Drive::OpenSource:
    f |= GPIOD_LINE_REQUEST_FLAG_OPEN_SOURCE;
    break;
  case Drive::PushPull:
    break;
  }
  return f;
}

// Opens the chip and collects the lines; the caller requests them.
gpiod_chip* open_lines(const std::string& chip, std::span<const unsigned> offsets, gpiod_line_bulk& bulk) {
  if (offsets.empty() || offsets.size() > GPIOD_LINE_BULK_MAX_LINES) {
    throw GpioError(line_names(chip, offsets) + ": between 1 and 64 lines per request");
  }
  gpiod_chip* c = gpiod_chip_open_lookup(chip.c_str());
  if (c == nullptr) throw GpioError("cannot open GPIO chip " + chip + ": " + std::strerror(errno));
  gpiod_line_bulk_init(&bulk);
  for (unsigned o : offsets) {
    gpiod_line* line = gpiod_chip_get_line(c, o);
    if (line == nullptr) {
      gpiod_chip_close(c);
      throw GpioError(line_names(chip, offsets) + ": no line " + std::to_string(o) + ": " +
                      std::strerror(errno));
    }
    gpiod_line_bulk_add(&bulk, line);
  }
  return c;
}

Nanos to_nanos(const timespec& ts) {
  return Nanos{static_cast<std::int64_t>(ts.tv_sec) * 1'000'000'000 + ts.tv_nsec};
}

} // namespace

struct OutputRequest::Impl {
  gpiod_chip* chip = nullptr;
  gpiod_line_bulk bulk{};
  std::vector<std::unique_ptr<RequestLine>> views;
};

OutputRequest::OutputRequest(const std::string& chip, std::span<const unsigned> offsets,
                             const LineSettings& settings, const std::string& consumer)
    : impl_(std::make_unique<Impl>()), offsets_(offsets.begin(), offsets.end()), values_(offsets.size(), 0) {
  impl_->chip = open_lines(chip, offsets, impl_->bulk);
  if (gpiod_line_request_bulk_output_flags(&impl_->bulk, consumer.c_str(), request_flags(settings),
                                           values_.data()) != 0) {
    const int err = errno;
    gpiod_chip_close(impl_->chip);
    throw GpioError(line_names(chip, offsets) + ": output request refused: " + std::strerror(err));
  }
  for (std::size_t i = 0; i < offsets_.size(); ++i) {
    impl_->views.push_back(std::make_unique<RequestLine>(*this, static_cast<std::uint16_t>(i)));
  }
}

OutputRequest::~OutputRequest() {
  drive_inactive();
  gpiod_line_release_bulk(&impl_->bulk);
  gpiod_chip_close(impl_->chip);
}

void OutputRequest::write(std::uint16_t index, Level level) noexcept {
  if (index >= offsets_.size()) {
    ++write_errors_;
    return;
  }
  values_[index] = is_high(level) ? 1 : 0;
  // The whole request, with the cached levels of the other lines: the lines share one v1
  // handle, whose GPIOHANDLE_SET_LINE_VALUES_IOCTL sets every line of the handle from
  // values[0..n), and libgpiod 1.6's one-line gpiod_line_set_value sends values[0] only (the
  // rest zero) on that handle, so it could clear, or set, lines other than `index`.
  if (gpiod_line_set_value_bulk(&impl_->bulk, values_.data()) != 0) ++write_errors_;
}

void OutputRequest::write_all(std::span<const Level> levels) noexcept {
  if (levels.size() != values_.size()) {
    ++write_errors_;
    return;
  }
  for (std::size_t i = 0; i < levels.size(); ++i) values_[i] = is_high(levels[i]) ? 1 : 0;
  if (gpiod_line_set_value_bulk(&impl_->bulk, values_.data()) != 0) ++write_errors_;
}

void OutputRequest::drive_inactive() noexcept {
  for (int& v : values_) v = 0;
  if (gpiod_line_set_value_bulk(&impl_->bulk, values_.data()) != 0) ++write_errors_;
}

LineOutput& OutputRequest::line(std::size_t index) { return *impl_->views.at(index); }

struct InputRequest::Impl {
  gpiod_chip* chip = nullptr;
  gpiod_line_bulk bulk{};
};

InputRequest::InputRequest(const std::string& chip, std::span<const unsigned> offsets,
                           const LineSettings& settings, const std::string& consumer)
    : impl_(std::make_unique<Impl>()), offsets_(offsets.begin(), offsets.end()) {
  if (settings.debounce && !supports_debounce()) {
    throw GpioError(line_names(chip, offsets) + ": debounce asked for, but libgpiod 1.6 cannot set it");
  }
  impl_->chip = open_lines(chip, offsets, impl_->bulk);
  if (gpiod_line_request_bulk_both_edges_events_flags(&impl_->bulk, consumer.c_str(),
                                                      request_flags(settings)) != 0) {
    const int err = errno;
    gpiod_chip_close(impl_->chip);
    throw GpioError(line_names(chip, offsets) + ": edge-event request refused: " + std::strerror(err));
  }
  for (std::size_t i = 0; i < offsets_.size(); ++i) {
    const int fd = gpiod_line_event_get_fd(gpiod_line_bulk_get_line(&impl_->bulk, static_cast<unsigned>(i)));
    // Non-blocking, so poll() drains what is there and returns.
    fcntl(fd, F_SETFL, fcntl(fd, F_GETFL) | O_NONBLOCK);
    fds_.push_back(fd);
  }
}

InputRequest::~InputRequest() {
  gpiod_line_release_bulk(&impl_->bulk);
  gpiod_chip_close(impl_->chip);
}

std::size_t InputRequest::poll(std::span<InputEdge> out) noexcept {
  std::size_t n = 0;
  gpiod_line_event events[16];
  for (std::size_t i = 0; i < fds_.size() && n < out.size(); ++i) {
    for (;;) {
      const auto room = static_cast<unsigned>(std::min<std::size_t>(16, out.size() - n));
      if (room == 0) break;
      const int got = gpiod_line_event_read_fd_multiple(fds_[i], events, room);
      if (got <= 0) break; // EAGAIN: nothing pending
      for (int k = 0; k < got; ++k) {
        const gpiod_line_event& e = events[k];
        out[n++] = InputEdge{to_nanos(e.ts), static_cast<std::uint16_t>(i),
                             e.event_type == GPIOD_LINE_EVENT_RISING_EDGE ? Level::High : Level::Low};
      }
    }
  }
  return n;
}

Level InputRequest::level(std::size_t index) const {
  const int v = gpiod_line_get_value(gpiod_line_bulk_get_line(&impl_->bulk, static_cast<unsigned>(index)));
  if (v < 0)
    throw GpioError("reading line " + std::to_string(offsets_.at(index)) + ": " + std::strerror(errno));
  return level_of(v == 1);
}

bool supports_debounce() { return false; }

} // namespace hilrig::gpiod
