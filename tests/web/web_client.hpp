#pragma once
// A signed-in browser as the tests see it: cpp-httplib's client with the session cookie and
// the CSRF token, against a WebServer running in this process on a loopback port.
#include <httplib.h>
#include <nlohmann/json.hpp>

#include <filesystem>
#include <memory>
#include <string>
#include <thread>

#include "web/web_server.hpp"

namespace sd::test {

/// A two-state FSM (exploration and stop, switching on black floor) the web tests run and save.
inline const std::string kFsm =
    "--fsm-config --nstates 2 --s0 0 --rwm0 50 --n0 1 --n0x0 0 --c0x0 0 --p0x0 0.5 --s1 1 --n1 1 --n1x0 0 --c1x0 1 "
    "--p1x0 0.5";

/// The server on a free loopback port, serving on its own thread until destroyed.
class RunningServer {
 public:
  explicit RunningServer(const std::filesystem::path& home, const std::filesystem::path& web_root = {});
  /// With these options, but always on a free loopback port.
  explicit RunningServer(web::WebServerOptions options);
  ~RunningServer();
  int port() const { return port_; }

 private:
  std::unique_ptr<web::WebServer> server_;
  int port_ = 0;
  std::thread thread_;
};

struct Answer {
  int status = 0;
  nlohmann::json body;  // null when the body is not JSON
  std::string text;
  httplib::Headers headers;
};

class WebClient {
 public:
  explicit WebClient(int port);
  /// Another tab of the same browser: a new connection with `other`'s session.
  WebClient(int port, const WebClient& other) : WebClient(port) {
    cookie_ = other.cookie_;
    csrf_ = other.csrf_;
  }
  /// Signs in; false on refusal.
  bool sign_in(const std::string& name, const std::string& password);
  /// Signs up on the page (POST /api/sign-up with `body`), keeping the new session on success.
  Answer sign_up(const nlohmann::json& body);

  Answer get(const std::string& path);
  /// A JSON POST with the session's CSRF token (unless `csrf` is false).
  Answer post(const std::string& path, const nlohmann::json& body, bool csrf = true);
  /// The whole event stream of a run, as text.
  Answer stream(const std::string& path);

  httplib::Client& raw() { return client_; }
  const std::string& cookie() const { return cookie_; }
  const std::string& last_refusal() const { return last_refusal_; }

 private:
  httplib::Headers headers(bool csrf) const;
  httplib::Client client_;
  std::string cookie_, csrf_, last_refusal_;
};

}  // namespace sd::test
