#include "web/session_guard.hpp"

#include <sodium.h>

#include <array>

#include "app/accounts.hpp"
#include "web/http_io.hpp"

namespace sd::web {

SessionGuard::SessionGuard() {
  app::ready_sign_ins();
  key_.resize(crypto_generichash_KEYBYTES);
  randombytes_buf(key_.data(), key_.size());
}

std::optional<std::string> SessionGuard::session_token(const httplib::Request& request) {
  const std::string cookies = request.get_header_value("Cookie");
  const std::string prefix = std::string(kSessionCookie) + "=";
  std::size_t at = 0;
  while (at < cookies.size()) {
    std::size_t end = cookies.find(';', at);
    if (end == std::string::npos) end = cookies.size();
    std::size_t start = at;
    while (start < end && cookies[start] == ' ') ++start;
    if (cookies.compare(start, prefix.size(), prefix) == 0) {
      std::string token = cookies.substr(start + prefix.size(), end - start - prefix.size());
      if (!token.empty()) return token;
    }
    at = end + 1;
  }
  return std::nullopt;
}

storage::User SessionGuard::require_user(const httplib::Request& request, app::Home& home) const {
  const auto token = session_token(request);
  if (!token) throw HttpError(401, "sign in first: this request has no session");
  try {
    return app::user_of_session(home, *token);
  } catch (const app::AccessDenied&) {
    throw HttpError(401, "the session has expired or was ended: sign in again");
  }
}

void SessionGuard::require_csrf(const httplib::Request& request) const {
  const auto token = session_token(request);
  const std::string sent = request.get_header_value(kCsrfHeader);
  const std::string expected = token ? csrf_token(*token) : std::string();
  if (!token || sent.size() != expected.size() || sodium_memcmp(sent.data(), expected.data(), sent.size()) != 0)
    throw HttpError(403, std::string("refused: the request lacks the ") + kCsrfHeader + " header of its session");
}

std::string SessionGuard::csrf_token(const std::string& session_token) const {
  std::array<unsigned char, 32> hash{};
  crypto_generichash(hash.data(), hash.size(), reinterpret_cast<const unsigned char*>(session_token.data()),
                     session_token.size(), reinterpret_cast<const unsigned char*>(key_.data()), key_.size());
  std::array<char, 65> hex{};
  sodium_bin2hex(hex.data(), hex.size(), hash.data(), hash.size());
  return hex.data();
}

std::string SessionGuard::session_cookie(const std::string& token, long max_age_seconds, bool secure) {
  return std::string(kSessionCookie) + "=" + token + "; Path=/; HttpOnly; SameSite=Strict" + (secure ? "; Secure" : "") +
         "; Max-Age=" + std::to_string(max_age_seconds);
}

std::string SessionGuard::cleared_cookie(bool secure) {
  return std::string(kSessionCookie) + "=; Path=/; HttpOnly; SameSite=Strict" + (secure ? "; Secure" : "") + "; Max-Age=0";
}

}  // namespace sd::web
