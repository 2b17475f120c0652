#pragma once
// `swarmdesign run-exp`: the web app's server. It serves the built front end (frontend/ ->
// <build>/web-root) and the API of API.md, over the application layer and nothing else.
#include <filesystem>
#include <memory>
#include <string>
#include <vector>

#include "app/accounts.hpp"
#include "app/sign_up.hpp"
#include "web/host_check.hpp"

namespace httplib {
class Server;
}

namespace sd::web {

struct WebContext;

struct WebServerOptions {
  std::string host = "127.0.0.1";  // loopback unless told otherwise
  int port = 8080;                 // 0: any free port
  std::filesystem::path web_root;  // the built front end
  std::filesystem::path home;      // the SwarmDesign home (accounts, projects)
  std::vector<std::string> allowed_hosts;  // host names it answers besides its address (host_check.hpp)
  storage::SignInPolicy sign_in;   // lock-outs after failed sign-ins
  bool behind_tls = false;         // a TLS reverse proxy serves it: session cookies are Secure
  app::SignUpPolicy sign_up = app::SignUpPolicy::closed;  // who may make an account on the page
};

/// Most bytes a request body may have (a configuration string is under 2 kB).
inline constexpr std::size_t kMaxRequestBytes = 1 << 20;
/// Connections served at once. cpp-httplib serves a connection on one thread for its whole life,
/// and a browser keeps its connections open between requests (keep-alive) besides one per
/// event stream: past this many, a new connection waits for one to close. 200 tabs, each with
/// an Exec stream, hold 400 (bench/load_bench); an idle thread costs only its stack's touched pages.
inline constexpr int kServerThreads = 512;
/// The niceness of the evaluation threads of the designs, experiments and runs it serves:
/// requests first (the scheduler gives a niceness-10 thread about a tenth of a contended core).
inline constexpr int kDesignNiceness = 10;

class WebServer {
 public:
  explicit WebServer(WebServerOptions options);
  ~WebServer();

  /// Binds the address; returns the port (the one chosen when 0 was asked). Throws on failure.
  int bind();
  /// The Host values it answers (known once bound).
  const HostCheck& hosts() const { return hosts_; }
  /// Serves until stop() (from another thread or a signal handler's thread).
  void serve();
  void stop();

 private:
  WebServerOptions options_;
  std::unique_ptr<WebContext> context_;
  std::unique_ptr<httplib::Server> server_;
  HostCheck hosts_;  // set by bind(), before the first request is read
  int binding_socket_ = -1;  // the socket bind() is making (set_socket_options sees it first)
};

}  // namespace sd::web
