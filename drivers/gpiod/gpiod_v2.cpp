// OutputRequest and InputRequest on libgpiod 2.x (Debian 12 bookworm-backports: 2.1), the v2
// C API over the kernel's v2 character-device ABI. One line request holds all the lines, so a
// bulk write is one ioctl and every line's edges come through one file descriptor.
#include <dirent.h>
#include <fcntl.h>
#include <gpiod.h>

#include <algorithm>
#include <cctype>
#include <cerrno>
#include <cstring>

#include "drivers/gpiod/input_request.hpp"
#include "drivers/gpiod/line_names.hpp"
#include "drivers/gpiod/output_request.hpp"
#include "drivers/gpiod/request_line.hpp"

namespace hilrig::gpiod {

namespace {

// The kernel's limit on lines in one request (GPIO_V2_LINES_MAX), as in 1.6.
constexpr std::size_t max_lines = 64;

bool all_digits(const std::string& s) {
  return !s.empty() &&
         std::all_of(s.begin(), s.end(), [](char c) { return std::isdigit(static_cast<unsigned char>(c)); });
}

// 2.x opens chips by path only; the rig's wiring names them as 1.6's gpiod_chip_open_lookup
// did: a path, a name ("gpiochip0"), a number, or a label (searched over /dev/gpiochip*).
gpiod_chip* open_chip(const std::string& chip) {
  if (chip.empty()) throw GpioError("cannot open GPIO chip: empty name");
  std::string path = chip;
  if (all_digits(chip)) {
    path = "/dev/gpiochip" + chip;
  } else if (chip.find('/') == std::string::npos) {
    path = "/dev/" + chip;
  }
  if (gpiod_chip* c = gpiod_chip_open(path.c_str()); c != nullptr) return c;
  const int err = errno;
  if (chip.find('/') == std::string::npos && !all_digits(chip)) {
    if (DIR* dev = opendir("/dev"); dev != nullptr) {
      gpiod_chip* found = nullptr;
      while (dirent* entry = readdir(dev)) {
        if (std::strncmp(entry->d_name, "gpiochip", 8) != 0) continue;
        gpiod_chip* c = gpiod_chip_open((std::string("/dev/") + entry->d_name).c_str());
        if (c == nullptr) continue;
        gpiod_chip_info* info = gpiod_chip_get_info(c);
        const bool match = info != nullptr && chip == gpiod_chip_info_get_label(info);
        gpiod_chip_info_free(info);
        if (match) {
          found = c;
          break;
        }
        gpiod_chip_close(c);
      }
      closedir(dev);
      if (found != nullptr) return found;
    }
  }
  throw GpioError("cannot open GPIO chip " + chip + ": " + std::strerror(err));
}

// The libgpiod objects that only live while a request is being made.
struct RequestParts {
  gpiod_line_settings* settings = gpiod_line_settings_new();
  gpiod_line_config* line_config = gpiod_line_config_new();
  gpiod_request_config* request_config = gpiod_request_config_new();
  RequestParts() = default;
  RequestParts(const RequestParts&) = delete;
  RequestParts& operator=(const RequestParts&) = delete;
  ~RequestParts() {
    gpiod_request_config_free(request_config);
    gpiod_line_config_free(line_config);
    gpiod_line_settings_free(settings);
  }
};

void apply(gpiod_line_settings* s, const LineSettings& wanted) {
  gpiod_line_settings_set_active_low(s, wanted.active_low);
  gpiod_line_bias bias = GPIOD_LINE_BIAS_AS_IS;
  switch (wanted.bias) {
  case Bias::Disabled:
    bias = GPIOD_LINE_BIAS_DISABLED;
    break;
  case Bias::PullUp:
    bias = GPIOD_LINE_BIAS_PULL_UP;
    break;
  case Bias::PullDown:
    bias = GPIOD_LINE_BIAS_PULL_DOWN;
    break;
  case Bias::AsIs:
    break;
  }
  gpiod_line_settings_set_bias(s, bias);
  gpiod_line_drive drive = GPIOD_LINE_DRIVE_PUSH_PULL;
  switch (wanted.drive) {
  case Drive::OpenDrain:
    drive = GPIOD_LINE_DRIVE_OPEN_DRAIN;
    break;
  case Drive::OpenSource:
    drive = GPIOD_LINE_DRIVE_OPEN_SOURCE;
    break;
  case Drive::PushPull:
    break;
  }
  gpiod_line_settings_set_drive(s, drive);
}

// Requests `offsets` from `chip` with `settings` for every line; closes the chip on failure.
gpiod_line_request* request_lines(const std::string& chip, std::span<const unsigned> offsets,
                                  gpiod_chip*& handle, RequestParts& parts, const std::string& consumer,
                                  const char* what) {
  if (offsets.empty() || offsets.size() > max_lines) {
    throw GpioError(line_names(chip, offsets) + ": between 1 and 64 lines per request");
  }
  if (parts.settings == nullptr || parts.line_config == nullptr || parts.request_config == nullptr) {
    throw GpioError(line_names(chip, offsets) + ": out of memory");
  }
  if (gpiod_line_config_add_line_settings(parts.line_config, offsets.data(), offsets.size(),
                                          parts.settings) != 0) {
    throw GpioError(line_names(chip, offsets) + ": line settings refused: " + std::strerror(errno));
  }
  gpiod_request_config_set_consumer(parts.request_config, consumer.c_str());
  handle = open_chip(chip);
  gpiod_line_request* r = gpiod_chip_request_lines(handle, parts.request_config, parts.line_config);
  if (r == nullptr) {
    const int err = errno;
    gpiod_chip_close(handle);
    handle = nullptr;
    throw GpioError(line_names(chip, offsets) + ": " + what + " request refused: " + std::strerror(err));
  }
  return r;
}

gpiod_line_value value_of(Level level) {
  return is_high(level) ? GPIOD_LINE_VALUE_ACTIVE : GPIOD_LINE_VALUE_INACTIVE;
}

} // namespace

struct OutputRequest::Impl {
  gpiod_chip* chip = nullptr;
  gpiod_line_request* request = nullptr;
  std::vector<gpiod_line_value> values; // the bulk-write array, in `offsets` order
  std::vector<std::unique_ptr<RequestLine>> views;
};

OutputRequest::OutputRequest(const std::string& chip, std::span<const unsigned> offsets,
                             const LineSettings& settings, const std::string& consumer)
    : impl_(std::make_unique<Impl>()), offsets_(offsets.begin(), offsets.end()), values_(offsets.size(), 0) {
  RequestParts parts;
  if (parts.settings != nullptr) {
    gpiod_line_settings_set_direction(parts.settings, GPIOD_LINE_DIRECTION_OUTPUT);
    gpiod_line_settings_set_output_value(parts.settings, GPIOD_LINE_VALUE_INACTIVE);
    apply(parts.settings, settings);
  }
  impl_->request = request_lines(chip, offsets, impl_->chip, parts, consumer, "output");
  impl_->values.assign(offsets_.size(), GPIOD_LINE_VALUE_INACTIVE);
  for (std::size_t i = 0; i < offsets_.size(); ++i) {
    impl_->views.push_back(std::make_unique<RequestLine>(*this, static_cast<std::uint16_t>(i)));
  }
}

OutputRequest::~OutputRequest() {
  drive_inactive();
  gpiod_line_request_release(impl_->request);
  gpiod_chip_close(impl_->chip);
}

void OutputRequest::write(std::uint16_t index, Level level) noexcept {
  if (index >= offsets_.size()) {
    ++write_errors_;
    return;
  }
  values_[index] = is_high(level) ? 1 : 0;
  impl_->values[index] = value_of(level);
  if (gpiod_line_request_set_value(impl_->request, offsets_[index], impl_->values[index]) != 0)
    ++write_errors_;
}

void OutputRequest::write_all(std::span<const Level> levels) noexcept {
  if (levels.size() != values_.size()) {
    ++write_errors_;
    return;
  }
  for (std::size_t i = 0; i < levels.size(); ++i) {
    values_[i] = is_high(levels[i]) ? 1 : 0;
    impl_->values[i] = value_of(levels[i]);
  }
  if (gpiod_line_request_set_values(impl_->request, impl_->values.data()) != 0) ++write_errors_;
}

void OutputRequest::drive_inactive() noexcept {
  for (int& v : values_) v = 0;
  for (gpiod_line_value& v : impl_->values) v = GPIOD_LINE_VALUE_INACTIVE;
  if (gpiod_line_request_set_values(impl_->request, impl_->values.data()) != 0) ++write_errors_;
}

LineOutput& OutputRequest::line(std::size_t index) { return *impl_->views.at(index); }

namespace {
// Events read per read(2); poll() loops until the kernel's queue is empty or `out` is full.
constexpr std::size_t event_batch = 16;
} // namespace

struct InputRequest::Impl {
  gpiod_chip* chip = nullptr;
  gpiod_line_request* request = nullptr;
  gpiod_edge_event_buffer* events = nullptr; // allocated once: poll() must not allocate
  ~Impl() {
    if (events != nullptr) gpiod_edge_event_buffer_free(events);
    if (request != nullptr) gpiod_line_request_release(request);
    if (chip != nullptr) gpiod_chip_close(chip);
  }
};

InputRequest::InputRequest(const std::string& chip, std::span<const unsigned> offsets,
                           const LineSettings& settings, const std::string& consumer)
    : impl_(std::make_unique<Impl>()), offsets_(offsets.begin(), offsets.end()) {
  unsigned long debounce_us = 0;
  if (settings.debounce) {
    if (settings.debounce->count() < 0)
      throw GpioError(line_names(chip, offsets) + ": negative debounce period");
    // Whole microseconds (the ABI's unit), rounded up so a line is never debounced for less.
    debounce_us = static_cast<unsigned long>((settings.debounce->count() + 999) / 1000);
  }
  RequestParts parts;
  if (parts.settings != nullptr) {
    gpiod_line_settings_set_direction(parts.settings, GPIOD_LINE_DIRECTION_INPUT);
    gpiod_line_settings_set_edge_detection(parts.settings, GPIOD_LINE_EDGE_BOTH);
    gpiod_line_settings_set_event_clock(parts.settings, GPIOD_LINE_CLOCK_MONOTONIC);
    // The kernel debounces in the chip where it can, otherwise in gpiolib (software).
    gpiod_line_settings_set_debounce_period_us(parts.settings, debounce_us);
    apply(parts.settings, settings);
  }
  gpiod_request_config_set_event_buffer_size(parts.request_config, 16 * offsets.size());
  impl_->events = gpiod_edge_event_buffer_new(event_batch);
  if (impl_->events == nullptr) throw GpioError(line_names(chip, offsets) + ": out of memory");
  impl_->request = request_lines(chip, offsets, impl_->chip, parts, consumer, "edge-event");
  // Non-blocking, so poll() drains what is there and returns.
  const int fd = gpiod_line_request_get_fd(impl_->request);
  fcntl(fd, F_SETFL, fcntl(fd, F_GETFL) | O_NONBLOCK);
  // One request carries every line's events: the same descriptor stands for each line, so
  // callers that wait per line (as with 1.6) keep working.
  fds_.assign(offsets_.size(), fd);
}

InputRequest::~InputRequest() = default;

std::size_t InputRequest::poll(std::span<InputEdge> out) noexcept {
  std::size_t n = 0;
  while (n < out.size()) {
    const std::size_t room = std::min(event_batch, out.size() - n);
    const int got = gpiod_line_request_read_edge_events(impl_->request, impl_->events, room);
    if (got <= 0) break; // EAGAIN: nothing pending
    for (int k = 0; k < got; ++k) {
      gpiod_edge_event* e = gpiod_edge_event_buffer_get_event(impl_->events, static_cast<unsigned long>(k));
      const unsigned offset = gpiod_edge_event_get_line_offset(e);
      std::size_t index = 0;
      while (index < offsets_.size() && offsets_[index] != offset) ++index;
      out[n++] = InputEdge{Nanos{static_cast<std::int64_t>(gpiod_edge_event_get_timestamp_ns(e))},
                           static_cast<std::uint16_t>(index),
                           gpiod_edge_event_get_event_type(e) == GPIOD_EDGE_EVENT_RISING_EDGE ? Level::High
                                                                                              : Level::Low};
    }
  }
  return n;
}

Level InputRequest::level(std::size_t index) const {
  const gpiod_line_value v = gpiod_line_request_get_value(impl_->request, offsets_.at(index));
  if (v == GPIOD_LINE_VALUE_ERROR)
    throw GpioError("reading line " + std::to_string(offsets_.at(index)) + ": " + std::strerror(errno));
  return level_of(v == GPIOD_LINE_VALUE_ACTIVE);
}

bool supports_debounce() { return true; }

} // namespace hilrig::gpiod
