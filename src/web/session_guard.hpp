#pragma once
// Who is asking: the session cookie (HttpOnly, SameSite=Strict) names an account session of
// the accounts database (app::open_session), and every state-changing request must also carry
// that session's CSRF token. The token is a keyed hash of the session token under a key this
// server draws at start, so it needs no storage and a page of another site cannot compute it.
#include <httplib.h>

#include <optional>
#include <string>

#include "app/home.hpp"
#include "app/accounts.hpp"

namespace sd::web {

inline constexpr const char* kSessionCookie = "sd_session";
inline constexpr const char* kCsrfHeader = "X-CSRF-Token";

class SessionGuard {
 public:
  SessionGuard();

  /// The cookie's session token, if the request has one.
  static std::optional<std::string> session_token(const httplib::Request& request);
  /// The user of the request's session; HttpError 401 without a valid one.
  storage::User require_user(const httplib::Request& request, app::Home& home) const;
  /// HttpError 403 unless the request carries the CSRF token of its session.
  void require_csrf(const httplib::Request& request) const;

  std::string csrf_token(const std::string& session_token) const;
  /// The cookie, `secure` (only ever sent over HTTPS) when a TLS proxy serves the page.
  static std::string session_cookie(const std::string& token, long max_age_seconds, bool secure);
  static std::string cleared_cookie(bool secure);

 private:
  std::string key_;  // crypto_generichash key, drawn per server start
};

}  // namespace sd::web
