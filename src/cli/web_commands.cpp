// run-exp (alias web): the web app on this machine. It binds the loopback address unless told
// otherwise, says so when told otherwise, and stops cleanly on Ctrl-C (running designs are
// interrupted and resume later, as in the CLI).
#include <CLI/CLI.hpp>

#include <csignal>
#include <iostream>
#include <memory>
#include <thread>

#include "cli/command_registry.hpp"
#include "core/home.hpp"
#include "web/web_server.hpp"

namespace sd::cli {
namespace {

struct WebOptions {
  std::string host = "127.0.0.1";
  int port = 8080;
  std::string web_root = SWARMDESIGN_WEB_ROOT;
};

bool is_loopback(const std::string& host) {
  return host == "localhost" || host == "::1" || host.rfind("127.", 0) == 0;
}

void run_exp(const WebOptions& o) {
  if (o.port < 0 || o.port > 65535) throw UsageError("--port " + std::to_string(o.port) + " is not a port (0-65535)");
  // Signals go to one waiting thread, which stops the server: no work in a signal handler.
  sigset_t signals;
  sigemptyset(&signals);
  sigaddset(&signals, SIGINT);
  sigaddset(&signals, SIGTERM);
  pthread_sigmask(SIG_BLOCK, &signals, nullptr);

  web::WebServer server({o.host, o.port, o.web_root, swarmdesign_home()});
  const int port = server.bind();
  if (!is_loopback(o.host))
    std::cout << "Warning: listening on " << o.host << ", not only on this machine: anyone who can reach it "
              << "may try to sign in.\n";
  const std::string shown = o.host.find(':') != std::string::npos ? "[" + o.host + "]" : o.host;
  std::cout << "SwarmDesign web app: http://" << shown << ":" << port << "/  (Ctrl-C stops it)" << std::endl;
  std::thread waiter([&server, signals] {
    int signal = 0;
    sigwait(&signals, &signal);
    server.stop();
  });
  server.serve();
  // Wake the waiter if the server ended for another reason.
  pthread_kill(waiter.native_handle(), SIGTERM);
  waiter.join();
  std::cout << "SwarmDesign web app stopped." << std::endl;
}

const CommandRegistrar registrar{60, [](CLI::App& app, Context&) {
  auto o = std::make_shared<WebOptions>();
  auto* cmd = app.add_subcommand("run-exp", "Serve the web app: draw control software, run it, follow designs");
  cmd->alias("web");
  cmd->add_option("--port", o->port, "TCP port (0: any free port)")->capture_default_str();
  cmd->add_option("--host", o->host, "address to listen on (127.0.0.1: this machine only)")->capture_default_str();
  cmd->add_option("--web-root", o->web_root, "folder of the built front end")->capture_default_str();
  cmd->footer("Sign in with your SwarmDesign account (swarmdesign sign-up). Every page and API route needs a "
              "session.\n\nExample:\n  swarmdesign run-exp\n  swarmdesign run-exp --port 9000");
  cmd->callback([o] { run_exp(*o); });
}};

}  // namespace
}  // namespace sd::cli
