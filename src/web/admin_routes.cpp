// The page's Admin section (issue #56): for administrators only (403 for anyone else), the
// CLI's `admin users/disable/enable/reset-password/role/delete-user/quota` over the same services.
#include "app/account_admin.hpp"
#include "app/errors.hpp"
#include "app/quotas.hpp"
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
  routes.post(account + "/delete", [](Call& call) -> nlohmann::json {
    app::delete_account(call.home, call.user, call.match(1), text_field(call.body, "confirm"));
    return {{"deleted", call.match(1)}};
  });
}

}  // namespace sd::web
