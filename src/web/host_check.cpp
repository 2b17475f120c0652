#include "web/host_check.hpp"

#include <arpa/inet.h>

#include <algorithm>
#include <cctype>

namespace sd::web {

namespace {

std::string lower(std::string_view text) {
  std::string out(text);
  std::transform(out.begin(), out.end(), out.begin(), [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
  return out;
}

bool is_ip_literal(const std::string& host) {
  unsigned char buffer[16];
  if (host.size() > 2 && host.front() == '[' && host.back() == ']')
    return ::inet_pton(AF_INET6, host.substr(1, host.size() - 2).c_str(), buffer) == 1;
  return ::inet_pton(AF_INET, host.c_str(), buffer) == 1;
}

}  // namespace

bool HostCheck::is_loopback(std::string_view address) {
  return address == "localhost" || address == "::1" || address.rfind("127.", 0) == 0;
}

HostCheck::HostCheck(const std::string& bound_address, int port, const std::vector<std::string>& allowed_hosts)
    : port_(port), any_ip_(!is_loopback(bound_address)) {
  names_ = {"127.0.0.1", "localhost", "[::1]"};
  std::string own = lower(bound_address);
  if (own.find(':') != std::string::npos) {  // an IPv6 address is written in brackets in a Host
    own.insert(own.begin(), '[');
    own.push_back(']');
  }
  names_.push_back(std::move(own));
  for (const std::string& name : allowed_hosts) names_.push_back(lower(name));
  std::sort(names_.begin(), names_.end());
  names_.erase(std::unique(names_.begin(), names_.end()), names_.end());
}

bool HostCheck::allows(std::string_view header) const {
  if (port_ < 0 || header.empty() || header.size() > 255) return false;
  std::string host = lower(header), port;
  // "name:port", "[v6]:port", or a name alone (the default port 80).
  const std::size_t colon = host.rfind(':');
  if (colon != std::string::npos && host.find(']', colon) == std::string::npos) {
    port = host.substr(colon + 1);
    host.resize(colon);
  }
  if (port.empty() ? port_ != 80 : port != std::to_string(port_)) return false;
  if (std::binary_search(names_.begin(), names_.end(), host)) return true;
  return any_ip_ && is_ip_literal(host);
}

std::string HostCheck::describe() const {
  std::string out;
  for (const std::string& name : names_) out += (out.empty() ? "" : ", ") + name;
  out += " (port " + std::to_string(port_) + ")";
  if (any_ip_) out += " and any IP address of this machine";
  return out;
}

}  // namespace sd::web
