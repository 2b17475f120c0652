// run-exp (alias web): the web app on this machine. It binds the loopback address unless told
// otherwise, says so when told otherwise, and stops cleanly on Ctrl-C (running designs are
// interrupted and resume later, as in the CLI).
#include <CLI/CLI.hpp>

#include <csignal>
#include <iostream>
#include <memory>
#include <string>
#include <thread>
#include <vector>

#include "cli/command_registry.hpp"
#include "cli/web_root.hpp"
#include "app/sign_up.hpp"
#include "core/home.hpp"
#include "web/web_server.hpp"

namespace sd::cli::web_commands {
namespace {

struct WebOptions {
  std::string host = "127.0.0.1";
  int port = 8080;
  std::string web_root = default_web_root();
  std::vector<std::string> allowed_hosts;
  bool behind_tls = false;
  std::string sign_up = "closed";
};

void run_exp(const WebOptions& o) {
  if (o.port < 0 || o.port > 65535) throw UsageError("--port " + std::to_string(o.port) + " is not a port (0-65535)");
  // Signals go to one waiting thread, which stops the server: no work in a signal handler.
  sigset_t signals;
  sigemptyset(&signals);
  sigaddset(&signals, SIGINT);
  sigaddset(&signals, SIGTERM);
  pthread_sigmask(SIG_BLOCK, &signals, nullptr);

  for (const std::string& name : o.allowed_hosts)
    if (name.empty() || name.size() > 253 || name.find_first_of(" /\\@?#") != std::string::npos)
      throw UsageError("--allowed-host '" + name + "' is not a host name (give a name such as lab.example.org)");
  const auto sign_up = app::parse_sign_up_policy(o.sign_up);
  if (!sign_up) throw UsageError("--sign-up '" + o.sign_up + "': closed, invite or open");
  web::WebServer server({o.host, o.port, o.web_root, swarmdesign_home(), o.allowed_hosts, {}, o.behind_tls, *sign_up});
  const int port = server.bind();
  if (!web::HostCheck::is_loopback(o.host)) {
    std::cout << "Warning: listening on " << o.host << ", not only on this machine: anyone who can reach it "
              << "may try to sign in.\n";
    // Plain HTTP carries passwords and session cookies in clear over the network.
    if (!o.behind_tls)
      std::cout << "Warning: plain HTTP: serve it through a TLS reverse proxy and pass --behind-tls "
                << "(README, \"A lab server over HTTPS\").\n";
  }
  std::cout << "Answers requests for " << server.hosts().describe()
            << " (others: --allowed-host NAME)" << std::endl;
  const std::string shown = o.host.find(':') != std::string::npos ? "[" + o.host + "]" : o.host;
  std::cout << "SwarmDesign web app: http://" << shown << ":" << port << "/  (Ctrl-C stops it)" << std::endl;
  std::thread waiter([&server, signals] {
    int signal = 0;
    sigwait(&signals, &signal);
    server.stop();
  });
  server.serve();
  // Wake the waiter if the server ended for another reason.
  // SIGTERM is blocked here and only ends the waiter's sigwait: it terminates nothing.
  // NOLINTNEXTLINE(bugprone-bad-signal-to-kill-thread,cert-pos44-c)
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
  cmd->add_option("--allowed-host", o->allowed_hosts,
                  "a host name the server answers besides its address (repeatable), e.g. the lab's name for it");
  cmd->add_flag("--behind-tls", o->behind_tls,
                "a TLS reverse proxy (e.g. Caddy or nginx) serves the page over HTTPS: session cookies are marked "
                "Secure, so a browser never sends them over plain HTTP");
  cmd->add_option("--sign-up", o->sign_up,
                  "who may make an account on the page: closed (accounts are made here with swarmdesign sign-up), "
                  "invite (whoever brings an invitation: swarmdesign admin invite) or open (anyone who reaches it)")
      ->capture_default_str();
  cmd->footer("Sign in with your SwarmDesign account (swarmdesign sign-up). Every page and API route needs a "
              "session. A request naming another Host is refused (no web page can reach the server by DNS "
              "rebinding); 5 wrong passwords in a row lock a name for a minute, 20 lock the client's address."
              "\n\nExample:\n  swarmdesign run-exp\n  swarmdesign run-exp --port 9000\n"
              "  swarmdesign run-exp --host 0.0.0.0 --allowed-host lab.example.org\n"
              "  swarmdesign run-exp --allowed-host lab.example.org --behind-tls   (Caddy on the same machine)\n"
              "  swarmdesign run-exp --sign-up invite   (a lab's members sign up with an administrator's invitation)");
  cmd->callback([o] { run_exp(*o); });
}};

}  // namespace
}  // namespace sd::cli::web_commands
