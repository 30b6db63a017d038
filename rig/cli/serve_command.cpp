#include "rig/cli/serve_command.hpp"

#include <arpa/inet.h>
#include <netinet/in.h>
#include <unistd.h>

#include <CLI/CLI.hpp>
#include <cerrno>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <memory>
#include <optional>
#include <stdexcept>

#include "core/clock.hpp"
#include "core/scheduler.hpp"
#include "drivers/modbus/pty.hpp"
#include "drivers/modbus/rtu_server.hpp"
#include "drivers/modbus/tcp_server.hpp"
#include "rig/campaign/campaign_error.hpp"
#include "rig/campaign/duration.hpp"
#include "rig/campaign/limits.hpp"
#include "rig/campaign/stop_request.hpp"
#include "rig/cli/exit_status.hpp"
#include "rig/cli/serve_devices.hpp"
#include "rig/cli/serve_params.hpp"
#include "rig/cli/stop_signals.hpp"
#include "rig/duts/dut.hpp"

namespace hilrig::cli {

namespace {

bool is_loopback(const std::string& addr) { return addr.rfind("127.", 0) == 0 || addr == "localhost"; }

struct ServeArgs {
  ServeOptions options;
  std::string tcp_endpoint;
  std::string rtu_device;
  bool pty = false;
  char parity = 'E';
  unsigned baud = 19200;
  unsigned data_bits = 8;
  unsigned stop_bits = 1;
  unsigned unit = 1;
  std::string bind;
  std::string port_file;
  std::string tick;
  std::string scan;
  std::string idle_timeout;
  std::string byte_timeout;
};

[[noreturn]] void bad_input(const std::string& why) {
  std::fprintf(stderr, "hilrig serve: %s\n", why.c_str());
  exit_with(kBadInput);
}

// A duration option's value in lo .. hi. Refused with the option, the whole range in WHAT, and
// first what is wrong with a text that is no duration ("100h": "h" is not a unit).
Nanos duration_option(const std::string& option, const std::string& text, Nanos lo, Nanos hi,
                      const std::string& what) {
  const auto d = campaign::parse_duration(text);
  if (d && *d >= lo && *d <= hi) return *d;
  const std::string problem = campaign::duration_text_problem(text);
  bad_input(option + " " + text + ": " + (problem.empty() ? "" : problem + ": ") + what);
}

// At least 1 ms, and at most the longest a duration's text holds (duration.hpp).
std::string range_from_1ms(const std::string& example) {
  return "a duration of 1ms .. " + campaign::duration_text(campaign::kMaxDurationText) + ", like \"" +
         example + "\"";
}

// --modbus-tcp [ADDR:]PORT; an address beyond loopback needs an explicit --bind.
void parse_tcp(const ServeArgs& args, ServeOptions& o) {
  std::string host;
  std::string port = args.tcp_endpoint;
  if (const auto colon = args.tcp_endpoint.rfind(':'); colon != std::string::npos) {
    host = args.tcp_endpoint.substr(0, colon);
    port = args.tcp_endpoint.substr(colon + 1);
  }
  try {
    const unsigned long p = std::stoul(port);
    if (p > 65535) {
      throw std::out_of_range("port");
    }
    o.port = static_cast<std::uint16_t>(p);
  } catch (const std::exception&) {
    bad_input("bad port in --modbus-tcp " + args.tcp_endpoint);
  }
  if (!args.bind.empty()) {
    o.bind = args.bind;
  } else if (!host.empty()) {
    if (!is_loopback(host)) {
      bad_input(host + " is not loopback; pass --bind " + host + " to serve beyond this host");
    }
    o.bind = host == "localhost" ? "127.0.0.1" : host;
  }
  // The server takes a dotted-quad IPv4 address (inet_pton's, as Asio's): anything else is the
  // command line's mistake, named before a port is bound.
  in_addr parsed{};
  if (::inet_pton(AF_INET, o.bind.c_str(), &parsed) != 1)
    bad_input(o.bind + " is not an IPv4 address (four numbers 0..255, like 127.0.0.1 or 0.0.0.0): " +
              (args.bind.empty() ? "--modbus-tcp " + args.tcp_endpoint : "--bind " + args.bind));
}

void parse_rtu(const ServeArgs& args, ServeOptions& o) {
  o.serial_device = args.rtu_device;
  o.format.baud = args.baud;
  o.format.data_bits = static_cast<std::uint8_t>(args.data_bits);
  o.format.stop_bits = static_cast<std::uint8_t>(args.stop_bits);
  o.format.parity = args.parity == 'N' ? Parity::None : args.parity == 'O' ? Parity::Odd : Parity::Even;
  o.unit = static_cast<std::uint8_t>(args.unit);
}

const char* parity_name(Parity p) { return p == Parity::None ? "N" : p == Parity::Odd ? "O" : "E"; }

// The bound port (or the serial path) in --port-file, before the announcement: a script waits
// for the file, so one that cannot be written stops the server (exit 2) rather than leaving
// the script waiting for a file that never comes.
void write_port_file(const std::string& port_file, const ServeEndpoint& e) {
  errno = 0;
  FILE* f = std::fopen(port_file.c_str(), "w");
  bool written = f != nullptr;
  if (written) {
    if (e.link == ServeLink::Tcp)
      written = std::fprintf(f, "%u\n", static_cast<unsigned>(e.port)) > 0;
    else
      written = std::fprintf(f, "%s\n", e.serial_path.c_str()) > 0;
    written = std::fclose(f) == 0 && written;
  }
  if (!written)
    throw std::invalid_argument("--port-file " + port_file +
                                ": cannot write it: " + std::strerror(errno != 0 ? errno : EIO));
}

void announce(const ServeOptions& o, const ServeEndpoint& e, const std::string& port_file) {
  if (!port_file.empty()) write_port_file(port_file, e);
  if (e.link == ServeLink::Tcp) {
    std::printf("hilrig serve: %s listening on %s:%u (Modbus TCP)\n", o.device.c_str(), o.bind.c_str(),
                static_cast<unsigned>(e.port));
  } else {
    std::printf("hilrig serve: %s on %s (Modbus RTU unit %u, %u %u%s%u)\n", o.device.c_str(),
                e.serial_path.c_str(), static_cast<unsigned>(o.unit), static_cast<unsigned>(o.format.baud),
                static_cast<unsigned>(o.format.data_bits), parity_name(o.format.parity),
                static_cast<unsigned>(o.format.stop_bits));
  }
  if (!e.note.empty()) {
    std::printf("hilrig serve: note: %s\n", e.note.c_str());
  }
  if (!e.far_side.empty()) {
    std::printf("hilrig serve: far side: %s\n", e.far_side.c_str());
  }
  std::fflush(stdout);
}

void serve_main(const ServeArgs& args) {
  ServeOptions o = args.options;
  const int links =
      (args.tcp_endpoint.empty() ? 0 : 1) + (args.rtu_device.empty() ? 0 : 1) + (args.pty ? 1 : 0);
  if (links != 1) {
    bad_input("give exactly one link: --modbus-tcp [ADDR:]PORT, --modbus-rtu DEVICE or --pty");
  }
  if (!args.tcp_endpoint.empty()) {
    o.link = ServeLink::Tcp;
    parse_tcp(args, o);
  } else {
    o.link = args.pty ? ServeLink::Pty : ServeLink::Rtu;
    parse_rtu(args, o);
  }
  if (!args.tick.empty())
    o.tick = duration_option("--tick", args.tick, milliseconds(1), campaign::kMaxDurationText,
                             range_from_1ms("1ms"));
  if (!args.idle_timeout.empty()) {
    o.tcp_limits.idle_timeout = duration_option("--idle-timeout", args.idle_timeout, milliseconds(1),
                                                campaign::kMaxDurationText, range_from_1ms("60s"));
  }
  if (!args.byte_timeout.empty()) {
    // On TCP the MBAP header says where a frame ends: there is no next-byte wait to set.
    if (o.link == ServeLink::Tcp)
      bad_input("--byte-timeout " + args.byte_timeout +
                ": applies to an RTU link only (--modbus-rtu or --pty); a Modbus TCP frame ends where its "
                "MBAP length says");
    o.byte_timeout = duration_option("--byte-timeout", args.byte_timeout, Nanos{0}, seconds(10),
                                     "an RTU link's wait for a frame's next byte, 0s..10s, like \"100ms\"");
  }
  if (!args.scan.empty()) {
    if (o.device != "ans1")
      bad_input("--scan " + args.scan + ": applies to the ans1 only (its scan period), not to " + o.device);
    o.scan_period = duration_option("--scan", args.scan, microseconds(1), milliseconds(1),
                                    "the ans1's scan period, 1us..1ms, like \"100us\"");
  }
  if (o.far.config.empty() && (!o.far.gpio_sim.empty() || !o.far.can.empty())) {
    bad_input("--gpio-sim and --can need --far FAR.toml (which pin is on which line)");
  }
  if (!args.port_file.empty()) {
    // Its directory is checked before the device is built or a port bound: the common mistake
    // (a directory that is not there) is named before anything serves.
    const std::filesystem::path dir = std::filesystem::path(args.port_file).parent_path();
    const std::string where = dir.empty() ? "." : dir.string();
    std::error_code ec;
    if (std::filesystem::is_directory(args.port_file, ec))
      bad_input("--port-file " + args.port_file + ": a directory, not a file to write the port to");
    if (::access(where.c_str(), W_OK | X_OK) != 0)
      bad_input("--port-file " + args.port_file + ": cannot write in " + where + ": " + std::strerror(errno));
  }
  campaign::StopRequest stop;
  const StopSignals signals(stop);
  try {
    serve_device(o, stop.flag(), [&](const ServeEndpoint& e) { announce(o, e, args.port_file); });
  } catch (const std::invalid_argument& e) {
    bad_input(e.what());
  } catch (const campaign::CampaignError& e) {
    bad_input(e.what());
  }
}

// Runs a server with the model in real time: virtual time is the monotonic time since start.
// A far side first hands the model what arrived on its pins, stamped with that time.
template <typename Server>
void serve_in_real_time(Server& server, Scheduler& scheduler, ServedFarSide* far,
                        const std::atomic<bool>& stop) {
  const MonotonicClock clock;
  const Nanos t0 = clock.now();
  server.on_tick([&] {
    const Nanos t = clock.now() - t0;
    if (far != nullptr) {
      far->tick(t);
    }
    scheduler.run_until(t);
    if (far != nullptr) {
      far->note_lag(clock.now() - t0 - t); // how far behind real time the model finished
    }
  });
  server.run(stop);
  if (far != nullptr) {
    std::printf("hilrig serve: far side: %s\n", far->summary().c_str());
    std::fflush(stdout);
  }
}

} // namespace

void serve_device(const ServeOptions& options, const std::atomic<bool>& stop,
                  const std::function<void(const ServeEndpoint&)>& on_ready) {
  const ServedDevice* device = find_served_device(options.device);
  if (device == nullptr) {
    throw std::invalid_argument("unknown device '" + options.device + "' (served: " + served_device_names() +
                                ")");
  }
  ServeModelOptions model_options;
  model_options.fault = options.fault;
  model_options.m12 = options.m12;
  model_options.no_encoder = options.no_encoder;
  model_options.scan_period = options.scan_period;
  if (const duts::DutInfo* info = duts::find_dut(options.device); info != nullptr) {
    model_options.params = serve_params(*info, options.params); // throws on a bad --param
  } else if (!options.params.empty()) {
    throw std::invalid_argument("--param: " + options.device + " has no parameters");
  }
  model_options.params_given = !options.params.empty();
  if (!options.motion.empty() && options.device != "pls2700") {
    throw std::invalid_argument("--motion is for pls2700 (a built-in resolver), not " + options.device);
  }
  model_options.motion = options.motion;
  Scheduler scheduler;
  const ServedModel model = device->build(scheduler, model_options);
  // The board's map behind the rig's controls (docs/serve.md "Rig controls").
  ControlledRegisters registers(*model.registers, model.controls, scheduler);
  std::unique_ptr<ServedFarSide> far;
  if (!options.far.config.empty()) {
    far = std::make_unique<ServedFarSide>(scheduler, options.far, model, options.device);
  }
  ServeEndpoint endpoint;
  endpoint.link = options.link;
  endpoint.far_side = far ? far->describe() : std::string();
  if (options.link == ServeLink::Tcp) {
    drivers::modbus::TcpServerOptions server_options;
    server_options.bind = options.bind;
    server_options.port = options.port;
    server_options.limits = options.tcp_limits;
    server_options.poll_period = options.tick;
    server_options.fc23_read = device->fc23_read;
    server_options.on_close = [](const std::string& peer, const std::string& reason) {
      std::fprintf(stderr, "hilrig serve: closed %s: %s\n", peer.c_str(), reason.c_str());
    };
    drivers::modbus::TcpServer server(registers, server_options);
    endpoint.port = server.port();
    endpoint.tcp_stats = &server.stats();
    if (on_ready) {
      on_ready(endpoint);
    }
    serve_in_real_time(server, scheduler, far.get(), stop);
    return;
  }
  drivers::modbus::RtuServerOptions server_options;
  server_options.device = options.serial_device;
  server_options.format = options.format;
  server_options.unit = options.unit;
  server_options.rs485 = options.rs485;
  server_options.byte_timeout = options.byte_timeout;
  server_options.poll_period = options.tick;
  server_options.fc23_read = device->fc23_read;
  std::optional<drivers::modbus::Pty> pty;
  std::optional<drivers::modbus::RtuServer> server;
  if (options.link == ServeLink::Pty) {
    pty.emplace();
    server.emplace(registers, pty->master_fd(), server_options);
    endpoint.serial_path = pty->slave_path();
  } else {
    server.emplace(registers, server_options);
    endpoint.serial_path = options.serial_device;
  }
  endpoint.note = server->rs485_note();
  endpoint.rtu_stats = &server->stats();
  if (on_ready) {
    on_ready(endpoint);
  }
  serve_in_real_time(*server, scheduler, far.get(), stop);
}

// --fault's help: every served device's variants, from the registry the error message names
// them from (a help text listing only some devices sent the others' users to trial and error).
std::string fault_help() {
  std::string text = "Fault variant (none: as the manual specifies), by device:";
  for (const ServedDevice& d : served_devices()) {
    text += ' ';
    text += d.name;
    text += ": ";
    text += d.faults;
    text += ';';
  }
  text.back() = '.';
  return text;
}

void add_serve_command(CLI::App& app) {
  auto args = std::make_shared<ServeArgs>();
  CLI::App* cmd =
      app.add_subcommand("serve", "Run a virtual device in real time behind a Modbus TCP or RTU link");
  cmd->add_option("device", args->options.device, "Device model to serve (" + served_device_names() + ")")
      ->required();
  cmd->add_option("--modbus-tcp", args->tcp_endpoint, "[ADDR:]PORT to listen on (PORT 0 picks a free port)");
  cmd->add_option("--modbus-rtu", args->rtu_device, "Serial device to serve Modbus RTU on");
  cmd->add_flag("--pty", args->pty,
                "Serve Modbus RTU on a new pty pair; prints the slave path for the client");
  cmd->add_option("--bind", args->bind, "Address to bind (default 127.0.0.1; needed for non-loopback)");
  cmd->add_option("--max-connections", args->options.tcp_limits.max_connections,
                  "TCP clients served at once (default 64); a newcomer at the limit replaces the "
                  "connection idle the longest")
      ->check(CLI::Range(std::size_t{1}, std::size_t{4096}));
  cmd->add_option(
      "--idle-timeout", args->idle_timeout,
      "Close a TCP connection with no byte either way for this long (default 60s; ns, us, ms or s; "
      "limits: docs/serve.md)");
  cmd->add_option("--max-output", args->options.tcp_limits.max_output_bytes,
                  "Unsent reply bytes held for one TCP client before it is closed as one that sends "
                  "and never reads (default 65536)")
      ->check(CLI::Range(std::size_t{260}, std::size_t{1} << 24U));
  cmd->add_option("--baud", args->baud, "RTU baud rate (default 19200)");
  cmd->add_option("--parity", args->parity, "RTU parity N, E or O (default E)")
      ->check(CLI::IsMember({'N', 'E', 'O'}));
  cmd->add_option("--data-bits", args->data_bits, "RTU data bits 7 or 8 (default 8)")
      ->check(CLI::Range(7U, 8U));
  cmd->add_option("--stop-bits", args->stop_bits, "RTU stop bits 1 or 2 (default 1)")
      ->check(CLI::Range(1U, 2U));
  cmd->add_option("--unit", args->unit, "RTU unit id 1..247 (default 1)")->check(CLI::Range(1U, 247U));
  cmd->add_option("--byte-timeout", args->byte_timeout,
                  "RTU: how long a frame whose function fixes its length waits for its next byte (default: "
                  "the 3.5-character silence ends it; e.g. 100ms for a USB adapter that delivers bursts)");
  cmd->add_flag("--rs485", args->options.rs485,
                "Put the serial port in RS-485 mode (reported when unsupported)");
  cmd->add_option("--fault", args->options.fault, fault_help());
  cmd->add_option(
         "--param", args->options.params,
         "KEY=VALUE: a [MODEL] choice of the device by its campaign name (`hilrig list`); repeatable")
      ->allow_extra_args(false);
  cmd->add_option_function<std::string>(
      "--model", [args](const std::string& m) { args->options.params.push_back("model=" + m); },
      "pls2700: the module, 2731, 2731-04, 2732, 2732-04, 2741, 2742 (default) or 2742-18 (= --param "
      "model=)");
  cmd->add_option("--motion", args->options.motion,
                  "pls2700: a built-in transducer on the stators, constant:<rpm>rpm (e.g. constant:300rpm)");
  cmd->add_flag("--m12", args->options.m12, "smd23e: model an M12 unit (two inputs)");
  cmd->add_flag("--no-encoder", args->options.no_encoder,
                "smd23e: model a unit without the internal encoder");
  cmd->add_option("--far", args->options.far.config,
                  "Far-side config (TOML): the board pins on gpio-sim lines, the resolver node");
  cmd->add_option("--gpio-sim", args->options.far.gpio_sim,
                  "gpio-sim chip directory (/sys/devices/platform/DEV/CHIP) the far side reads and pulls");
  cmd->add_option("--can", args->options.far.can,
                  "CAN interface of the far side's resolver-emulator node (e.g. can1)");
  cmd->add_option("--tick", args->tick,
                  "How often the model runs and the far side reads its pins while idle (default 5ms)");
  cmd->add_option(
      "--scan", args->scan,
      "ans1: the master scan period (default 10us); longer keeps real time on a slow host (QEMU)");
  cmd->add_option("--port-file", args->port_file,
                  "Write the bound TCP port (or the RTU device / pty slave path) to this file once serving");
  cmd->callback([args] { serve_main(*args); });
}

} // namespace hilrig::cli
