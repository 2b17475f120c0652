#pragma once
// Which Host a request may name. A web page on the internet can make a browser send requests to
// 127.0.0.1 under a host name its owner controls (DNS rebinding); the Host header still names
// that foreign host, so a server that answers only its own names cannot be reached that way.
// Bound to a loopback address, the server answers 127.0.0.1, localhost and [::1] with its port;
// bound elsewhere, also any IP address (which no page can rebind) and the names given with
// --allowed-host.
#include <string>
#include <string_view>
#include <vector>

namespace sd::web {

class HostCheck {
 public:
  HostCheck() = default;  // answers nothing until made for an address and port
  HostCheck(const std::string& bound_address, int port, const std::vector<std::string>& allowed_hosts);

  bool allows(std::string_view host_header) const;
  /// What it answers, in words, for the server's start message.
  std::string describe() const;

  static bool is_loopback(std::string_view address);

 private:
  int port_ = -1;
  bool any_ip_ = false;              // bound beyond loopback
  std::vector<std::string> names_;   // lower case, without port
};

}  // namespace sd::web
