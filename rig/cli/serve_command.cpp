#include "rig/cli/serve_command.hpp"

#include <csignal>
#include <cstdio>
#include <fstream>
#include <memory>
#include <stdexcept>

#include "core/clock.hpp"
#include "core/scheduler.hpp"
#include "drivers/modbus/tcp_server.hpp"
#include "models/smd23e/smd23e.hpp"
#include "rig/cli/exit_status.hpp"

namespace hilrig::cli {

namespace {

std::atomic<bool> g_stop{false};

extern "C" void on_stop_signal(int /*signo*/) { g_stop.store(true); }

bool is_loopback(const std::string& addr) { return addr.rfind("127.", 0) == 0 || addr == "localhost"; }

struct ServeArgs {
  ServeOptions options;
  std::string endpoint;
  std::string bind;
  std::string port_file;
};

void serve_main(const ServeArgs& args) {
  ServeOptions o = args.options;
  // --modbus-tcp [ADDR:]PORT; an address beyond loopback needs an explicit --bind.
  std::string host;
  std::string port = args.endpoint;
  if (const auto colon = args.endpoint.rfind(':'); colon != std::string::npos) {
    host = args.endpoint.substr(0, colon);
    port = args.endpoint.substr(colon + 1);
  }
  try {
    const unsigned long p = std::stoul(port);
    if (p > 65535) {
      throw std::out_of_range("port");
    }
    o.port = static_cast<std::uint16_t>(p);
  } catch (const std::exception&) {
    std::fprintf(stderr, "hilrig serve: bad port in --modbus-tcp %s\n", args.endpoint.c_str());
    exit_with(kBadInput);
  }
  if (!args.bind.empty()) {
    o.bind = args.bind;
  } else if (!host.empty()) {
    if (!is_loopback(host)) {
      std::fprintf(stderr, "hilrig serve: %s is not loopback; pass --bind %s to serve beyond this host\n",
                   host.c_str(), host.c_str());
      exit_with(kBadInput);
    }
    o.bind = host == "localhost" ? "127.0.0.1" : host;
  }
  g_stop.store(false);
  struct sigaction sa {};
  sa.sa_handler = on_stop_signal;
  sigemptyset(&sa.sa_mask);
  struct sigaction old_int {};
  struct sigaction old_term {};
  sigaction(SIGINT, &sa, &old_int);
  sigaction(SIGTERM, &sa, &old_term);
  try {
    run_serve(o, g_stop, [&](std::uint16_t bound) {
      std::printf("hilrig serve: %s listening on %s:%u (Modbus TCP)\n", o.device.c_str(), o.bind.c_str(),
                  static_cast<unsigned>(bound));
      std::fflush(stdout);
      if (!args.port_file.empty()) {
        std::ofstream(args.port_file) << bound << '\n';
      }
    });
  } catch (const std::invalid_argument& e) {
    sigaction(SIGINT, &old_int, nullptr);
    sigaction(SIGTERM, &old_term, nullptr);
    std::fprintf(stderr, "hilrig serve: %s\n", e.what());
    exit_with(kBadInput);
  } catch (...) {
    sigaction(SIGINT, &old_int, nullptr);
    sigaction(SIGTERM, &old_term, nullptr);
    throw;
  }
  sigaction(SIGINT, &old_int, nullptr);
  sigaction(SIGTERM, &old_term, nullptr);
}

} // namespace

void run_serve(const ServeOptions& options, const std::atomic<bool>& stop,
               const std::function<void(std::uint16_t port)>& on_listening) {
  if (options.device != "smd23e") {
    throw std::invalid_argument("unknown device '" + options.device + "' (served: smd23e)");
  }
  const auto fault = models::smd23e::fault_from_name(options.fault);
  if (!fault) {
    throw std::invalid_argument("unknown fault variant '" + options.fault + "'");
  }
  models::smd23e::Params params;
  params.fault = *fault;
  params.m12 = options.m12;
  params.has_encoder = !options.no_encoder;
  Scheduler scheduler;
  models::smd23e::Smd23e device(scheduler, params);
  drivers::modbus::TcpServerOptions server_options;
  server_options.bind = options.bind;
  server_options.port = options.port;
  drivers::modbus::TcpServer server(device, server_options);
  // Real time: virtual time is the monotonic time since the server started.
  const MonotonicClock clock;
  const Nanos t0 = clock.now();
  server.on_tick([&] { scheduler.run_until(clock.now() - t0); });
  if (on_listening) {
    on_listening(server.port());
  }
  server.run(stop);
}

void add_serve_command(CLI::App& app) {
  auto args = std::make_shared<ServeArgs>();
  CLI::App* cmd = app.add_subcommand("serve", "Run a virtual device as a Modbus TCP server in real time");
  cmd->add_option("device", args->options.device, "Device model to serve (smd23e)")->required();
  cmd->add_option("--modbus-tcp", args->endpoint, "[ADDR:]PORT to listen on (PORT 0 picks a free port)")
      ->required();
  cmd->add_option("--bind", args->bind, "Address to bind (default 127.0.0.1; needed for non-loopback)");
  cmd->add_option("--fault", args->options.fault,
                  "Fault variant: none, wrong-acceleration, lost-steps, "
                  "ignored-limit, late-stop");
  cmd->add_flag("--m12", args->options.m12, "Model an M12 unit (two inputs)");
  cmd->add_flag("--no-encoder", args->options.no_encoder, "Model a unit without the internal encoder");
  cmd->add_option("--port-file", args->port_file, "Write the bound port to this file once listening");
  cmd->callback([args] { serve_main(*args); });
}

} // namespace hilrig::cli
