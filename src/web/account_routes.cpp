// Sign-in, the session and sign-out: the CLI's accounts, the session kept in a cookie.
#include <chrono>

#include "app/accounts.hpp"
#include "app/errors.hpp"
#include "storage/sessions.hpp"
#include "web/http_io.hpp"
#include "web/routes.hpp"

namespace sd::web {

void add_account_routes(Routes& routes) {
  routes.post_public("/api/sign-in", [](Call& call) {
    const std::string name = text_field(call.body, "name");
    std::string token;
    try {
      token = app::open_session(call.home, name, text_field(call.body, "password"));
    } catch (const storage::AccessDenied&) {  // the same words for an unknown name: no user list for guessers
      throw HttpError(401, "wrong user name or password");
    } catch (const storage::NotFound&) {
      throw HttpError(401, "wrong user name or password");
    }
    call.response.set_header("Set-Cookie", SessionGuard::session_cookie(
                                               token, static_cast<long>(storage::kSessionLifetime.count())));
    send_json(call.response, {{"user", name}, {"csrf", call.context.guard.csrf_token(token)}});
  });

  routes.get("/api/session", [](Call& call) -> nlohmann::json {
    return {{"user", call.user.name}, {"csrf", call.context.guard.csrf_token(*SessionGuard::session_token(call.request))}};
  });

  routes.post("/api/sign-out", [](Call& call) -> nlohmann::json {
    app::close_session(call.home, *SessionGuard::session_token(call.request));
    call.response.set_header("Set-Cookie", SessionGuard::cleared_cookie());
    return nlohmann::json::object();
  });
}

}  // namespace sd::web
