// Sign-in, sign-up (by the server's policy), the session and sign-out: the CLI's accounts, the
// session kept in a cookie.
#include <chrono>

#include "app/account_admin.hpp"
#include "app/quotas.hpp"
#include "app/sign_up.hpp"
#include "app/accounts.hpp"
#include "app/errors.hpp"
#include "web/host_check.hpp"
#include "web/http_io.hpp"
#include "web/routes.hpp"

namespace sd::web {

namespace {

/// The client whose failed sign-ins count. Behind a TLS proxy on this machine every request
/// comes from the proxy's loopback address, which would lock every user out together: there the
/// client is the last address of X-Forwarded-For, the one the proxy itself appended. A request
/// from elsewhere cannot pick its own address that way.
std::string client_address(const Call& call) {
  const std::string& direct = call.request.remote_addr;
  if (!call.context.behind_tls || !HostCheck::is_loopback(direct)) return direct;
  const std::string forwarded = call.request.get_header_value("X-Forwarded-For");
  const std::size_t comma = forwarded.rfind(',');
  std::string last = comma == std::string::npos ? forwarded : forwarded.substr(comma + 1);
  last.erase(0, last.find_first_not_of(' '));
  last.erase(last.find_last_not_of(' ') + 1);
  return last.empty() || last.size() > 64 ? direct : last;
}

}  // namespace

void add_account_routes(Routes& routes) {
  routes.post_public("/api/sign-in", [](Call& call) {
    const std::string name = text_field(call.body, "name");
    const std::string address = client_address(call);
    // The slot first: a request that waited for it finds a lock-out its predecessors set, and
    // is refused without a check.
    const PasswordSlots::Held slot = call.context.passwords.take();
    if (const std::int64_t wait = call.context.addresses.locked_for(address); wait > 0)
      throw app::TooManyAttempts("too many failed sign-ins from your address: try again in " +
                                         std::to_string(wait) + " s",
                                     wait);
    std::string token;
    try {
      token = app::open_session(call.home, name, text_field(call.body, "password"), call.context.sign_in);
    } catch (const storage::AccountDisabled& e) {  // only said to whoever gave its password
      call.context.addresses.succeeded(address);
      throw HttpError(403, e.what());
    } catch (const app::AccessDenied&) {  // the same words and work for an unknown name
      call.context.addresses.failed(address);
      throw HttpError(401, "wrong user name or password");
    }
    call.context.addresses.succeeded(address);
    call.response.set_header("Set-Cookie",
                             SessionGuard::session_cookie(token, static_cast<long>(app::kSessionLifetime.count()),
                                                          call.context.behind_tls));
    send_json(call.response, {{"user", name}, {"csrf", call.context.guard.csrf_token(token)}});
  });

  // Sign-up on the page (issue #56): closed unless the server was started with --sign-up
  // invite or open. Like a sign-in it takes a password slot (Argon2id), and a refused one
  // counts against the address, so codes cannot be guessed in bulk.
  routes.get_public("/api/sign-up", [](Call& call) -> nlohmann::json {
    return {{"policy", app::sign_up_policy_name(call.context.sign_up)}};
  });
  routes.post_public("/api/sign-up", [](Call& call) {
    const std::string address = client_address(call);
    const PasswordSlots::Held slot = call.context.passwords.take();
    if (const std::int64_t wait = call.context.addresses.locked_for(address); wait > 0)
      throw app::TooManyAttempts("too many failed attempts from your address: try again in " + std::to_string(wait) + " s",
                                 wait);
    const std::string invitation = call.body.contains("invitation") ? text_field(call.body, "invitation") : std::string();
    app::SignedUp made;
    try {
      made = app::sign_up_on_server(call.home, call.context.sign_up, text_field(call.body, "name"),
                                    text_field(call.body, "password"), invitation);
    } catch (const app::AccessDenied&) {
      call.context.addresses.failed(address);
      throw;
    }
    call.response.set_header("Set-Cookie", SessionGuard::session_cookie(made.token, static_cast<long>(app::kSessionLifetime.count()),
                                                                        call.context.behind_tls));
    send_json(call.response, {{"user", made.user.name}, {"csrf", call.context.guard.csrf_token(made.token)}});
  });

  routes.get("/api/session", [](Call& call) -> nlohmann::json {
    return {{"user", call.user.name},
            {"admin", app::is_admin(call.home, call.user)},
            {"csrf", call.context.guard.csrf_token(*SessionGuard::session_token(call.request))}};
  });

  // What the account uses of its quotas (issue #56), shown on the page.
  routes.get("/api/quota", [](Call& call) { return app::quota_document(app::quota_use(call.home, call.user)); });

  // A user's own new password (`change-password`): the current one first; every other session
  // of the account ends, this page's stays.
  routes.post("/api/password", [](Call& call) -> nlohmann::json {
    const PasswordSlots::Held slot = call.context.passwords.take();  // two Argon2id checks
    app::change_password(call.home, call.user, text_field(call.body, "current"), text_field(call.body, "new"),
                         SessionGuard::session_token(call.request));
    return {{"changed", true}};
  });

  routes.post("/api/sign-out", [](Call& call) -> nlohmann::json {
    app::close_session(call.home, *SessionGuard::session_token(call.request));
    call.response.set_header("Set-Cookie", SessionGuard::cleared_cookie(call.context.behind_tls));
    return nlohmann::json::object();
  });
}

}  // namespace sd::web
