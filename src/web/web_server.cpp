#include "web/web_server.hpp"

#include <httplib.h>
#include <sys/socket.h>
#include <sys/stat.h>

#include <stdexcept>

#include "core/executor.hpp"
#include "web/http_io.hpp"
#include "web/routes.hpp"

namespace sd::web {

WebServer::WebServer(WebServerOptions options)
    : options_(std::move(options)),
      context_(std::make_unique<WebContext>(options_.home, options_.web_root, options_.sign_in, options_.behind_tls, options_.sign_up)),
      server_(std::make_unique<httplib::Server>()) {
  // A shared server keeps every user's files to itself: what it creates (projects, designs,
  // saved software, exports) is 0600, its folders 0700, whatever umask it was started with.
  ::umask(077);
  // The designs it runs take the cores only when no request wants them: a sign-in beside 8
  // running designs waited 0.7 s for its 0.18 s of Argon2id at the same priority (bench/README).
  Executor::shared().set_worker_niceness(kDesignNiceness);
  httplib::Server& s = *server_;
  s.new_task_queue = [] { return new httplib::ThreadPool(kServerThreads); };
  s.set_payload_max_length(kMaxRequestBytes);
  s.set_read_timeout(10, 0);
  s.set_keep_alive_max_count(100);
  s.set_tcp_nodelay(true);
  // SO_REUSEADDR only: cpp-httplib's default adds SO_REUSEPORT, with which a second server
  // binds a port already served and the two silently share its connections.
  // Stream chunks are small: Nagle + delayed ACK would hold each for 40 ms (set_tcp_nodelay).
  s.set_socket_options([this](socket_t sock) {
    int yes = 1;
    setsockopt(sock, SOL_SOCKET, SO_REUSEADDR, &yes, sizeof yes);
    binding_socket_ = sock;  // only bind() makes sockets through this (accepted ones do not)
  });

  s.set_pre_routing_handler([this](const httplib::Request& request, httplib::Response& response) {
    // Two Host headers: a proxy and this server could each read another one; neither is taken.
    if (request.get_header_value_count("Host") > 1) {
      send_json(response, {{"error", "the request names its host more than once"}}, 400);
      return httplib::Server::HandlerResponse::Handled;
    }
    if (hosts_.allows(request.get_header_value("Host"))) return httplib::Server::HandlerResponse::Unhandled;
    send_json(response, {{"error", "this server does not answer requests for the host named in the request"}}, 403);
    return httplib::Server::HandlerResponse::Handled;
  });
  // The first unknown name's check would otherwise also pay for making the dummy hash.
  app::ready_sign_ins();

  if (!options_.web_root.empty() && !s.set_mount_point("/", options_.web_root.string()))
    throw std::runtime_error("the web root " + options_.web_root.string() +
                             " is not a folder: build the front end (cmake --build build --target frontend)");
  s.set_post_routing_handler([](const httplib::Request&, httplib::Response& response) {
    // Everything the page loads comes from this server; nothing may frame it. A route may set a
    // stricter policy of its own (the report page).
    if (!response.has_header("Content-Security-Policy"))
      response.set_header("Content-Security-Policy",
                        "default-src 'self'; img-src 'self' data: blob:; style-src 'self' 'unsafe-inline'; "
                        "frame-ancestors 'none'");
    response.set_header("X-Content-Type-Options", "nosniff");
    response.set_header("Referrer-Policy", "same-origin");
  });
  s.set_error_handler([](const httplib::Request& request, httplib::Response& response) {
    if (!response.body.empty()) return;
    if (response.status == 413) send_json(response, {{"error", "the request is larger than 1 MiB"}}, 413);
    else if (request.path.rfind("/api/", 0) == 0)
      send_json(response, {{"error", "no such route: " + request.method + " " + request.path}}, response.status);
  });

  Routes routes(s, *context_);
  add_account_routes(routes);
  add_software_routes(routes);
  add_mission_routes(routes);
  add_run_routes(routes);
  add_project_routes(routes);
  add_experiment_routes(routes);
  add_design_form_routes(routes);
  add_admin_routes(routes);
}

WebServer::~WebServer() {
  stop();
  server_.reset();  // its threads end before the context they use
  context_.reset();
}

int WebServer::bind() {
  const int port = options_.port == 0 ? server_->bind_to_any_port(options_.host)
                                      : (server_->bind_to_port(options_.host, options_.port) ? options_.port : -1);
  if (port < 0)
    throw std::runtime_error("cannot listen on " + options_.host + ":" + std::to_string(options_.port) +
                             " (in use, or not an address of this machine)");
  // Debian's cpp-httplib listens with a backlog of 5 (CPPHTTPLIB_LISTEN_BACKLOG, fixed when the
  // library was built): a few dozen tabs connecting at once overflowed it, and each dropped
  // connection waited a second or more for TCP to try again, or failed (bench/load_bench).
  // Listening again on the listening socket only sets a longer queue (the kernel caps it).
  if (binding_socket_ >= 0) ::listen(binding_socket_, SOMAXCONN);
  hosts_ = HostCheck(options_.host, port, options_.allowed_hosts);
  return port;
}

void WebServer::serve() { server_->listen_after_bind(); }

void WebServer::stop() {
  if (server_) server_->stop();
}

}  // namespace sd::web
