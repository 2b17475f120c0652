// The page's Admin section (issue #56): for administrators only (403 for anyone else), the
// CLI's `admin users/disable/enable/reset-password/role/delete-user/quota` over the same services.
#include <algorithm>

#include "app/account_admin.hpp"
#include "app/errors.hpp"
#include "app/quotas.hpp"
#include "app/sign_up.hpp"
#include "web/http_io.hpp"
#include "web/routes.hpp"

namespace sd::web {

void add_admin_routes(Routes& routes) {
  const std::string account = std::string("/api/admin/users/") + kNamePattern;

  routes.get("/api/admin/users", [](Call& call) { return app::accounts_document(app::account_uses(call.home, call.user)); });

  routes.post(account + "/disable", [](Call& call) -> nlohmann::json {
    app::set_account_disabled(call.home, call.user, call.match(1), true);
    return {{"disabled", call.match(1)}};
  });
  routes.post(account + "/enable", [](Call& call) -> nlohmann::json {
    app::set_account_disabled(call.home, call.user, call.match(1), false);
    return {{"enabled", call.match(1)}};
  });
  // The new password is in this answer only: the page shows it once for the administrator to hand over.
  routes.post(account + "/reset-password", [](Call& call) -> nlohmann::json {
    return {{"name", call.match(1)}, {"password", app::reset_account_password(call.home, call.user, call.match(1))}};
  });
  routes.post(account + "/role", [](Call& call) -> nlohmann::json {
    const std::string role = text_field(call.body, "role");
    if (role != "admin" && role != "user") throw app::InvalidRequest("role must be admin or user");
    app::set_account_role(call.home, call.user, call.match(1), role == "admin" ? storage::Role::Admin : storage::Role::User);
    return {{"name", call.match(1)}, {"role", role}};
  });
  // Quotas: the server's default, and an account's own (a number, null for none, "default").
  routes.get("/api/admin/quota", [](Call& call) { return app::limits_document(app::server_quota(call.home, call.user)); });
  routes.post("/api/admin/quota", [](Call& call) {
    app::set_server_quota(call.home, call.user, app::limits_from_document(call.body));
    return app::limits_document(app::server_quota(call.home, call.user));
  });
  routes.post(account + "/quota", [](Call& call) -> nlohmann::json {
    app::set_account_quota(call.home, call.user, call.match(1), app::account_quota_from_document(call.body));
    const storage::User user = storage::account_row(call.home.workspace().database(), call.match(1)).user;
    return {{"name", call.match(1)}, {"quota", app::quota_document(app::quota_use(call.home, user))}};
  });
  // Invitations (a server run with --sign-up invite): the code is in the answer that made it only.
  routes.get("/api/admin/invitations", [](Call& call) { return app::invitations_document(app::invitations(call.home, call.user)); });
  routes.post("/api/admin/invitations", [](Call& call) {
    std::int64_t days = 7;
    if (call.body.contains("days")) {
      if (!call.body["days"].is_number_integer()) throw app::InvalidRequest("days must be a whole number of 1 to 90");
      days = std::clamp<std::int64_t>(call.body["days"].get<std::int64_t>(), -1, 91);  // out of range either way
    }
    return app::new_invitation_document(app::invite(call.home, call.user, static_cast<int>(days)));
  });
  routes.post("/api/admin/invitations/([0-9]{1,18})/revoke", [](Call& call) -> nlohmann::json {
    app::revoke_invitation(call.home, call.user, std::stoll(call.match(1)));
    return {{"revoked", std::stoll(call.match(1))}};
  });
  routes.post(account + "/delete", [](Call& call) -> nlohmann::json {
    app::delete_account(call.home, call.user, call.match(1), text_field(call.body, "confirm"));
    return {{"deleted", call.match(1)}};
  });
}

}  // namespace sd::web
