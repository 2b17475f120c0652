#include "app/account_admin.hpp"

#include <nlohmann/json.hpp>

#include "app/errors.hpp"
#include "app/quotas.hpp"
#include "storage/errors.hpp"
#include "storage/folder_removal.hpp"
#include "storage/session_file.hpp"
#include "storage/sodium.hpp"
#include "storage/workspace.hpp"

namespace sd::app {


namespace {

int count(storage::Database& db, const char* sql, std::int64_t user_id) {
  storage::Statement q = db.prepare(sql);
  q.bind(1, user_id);
  return q.step() ? static_cast<int>(q.integer(0)) : 0;
}

int running_designs(storage::Database& db, std::int64_t user_id) {
  return count(db, "SELECT count(*) FROM designs d JOIN projects p ON p.id = d.project_id WHERE p.owner_id = ? AND d.state = 'running'",
               user_id);
}
int running_experiments(storage::Database& db, std::int64_t user_id) {
  return count(db, "SELECT count(*) FROM experiments e JOIN projects p ON p.id = e.project_id WHERE p.owner_id = ? AND e.state = 'running'",
               user_id);
}

/// Someone else's account: an administrator acts on others, never on themselves here.
storage::AccountRow other_account(Home& home, const storage::User& admin, const std::string& name, const char* what) {
  require_admin(home, admin);
  storage::AccountRow row = storage::account_row(home.workspace().database(), name);
  if (row.user.id == admin.id) throw InvalidRequest(std::string("you cannot ") + what + " your own account");
  return row;
}

/// A one-time password: 20 symbols (about 116 bits), typed once.
std::string one_time_password() { return storage::readable_secret(20); }

}  // namespace

bool is_admin(Home& home, const storage::User& who) {
  return storage::account_row(home.workspace().database(), who.name).role == storage::Role::Admin;
}

void require_admin(Home& home, const storage::User& who) {
  if (!is_admin(home, who)) throw AccessDenied("only an administrator of this SwarmDesign may do that");
}

std::vector<AccountUse> account_uses(Home& home, const storage::User& admin) {
  require_admin(home, admin);
  storage::Database& db = home.workspace().database();
  std::vector<AccountUse> out;
  for (storage::AccountRow& row : storage::account_rows(db)) {
    AccountUse use;
    use.quota = quota_use(home, row.user);
    use.disk_bytes = use.quota.disk_bytes;
    use.running_designs = running_designs(db, row.user.id);
    use.running_experiments = running_experiments(db, row.user.id);
    use.account = std::move(row);
    out.push_back(std::move(use));
  }
  return out;
}

void set_account_disabled(Home& home, const storage::User& admin, const std::string& name, bool disabled) {
  const storage::AccountRow row = other_account(home, admin, name, disabled ? "disable" : "enable");
  storage::set_disabled(home.workspace().database(), row.user.id, disabled);
}

std::string reset_account_password(Home& home, const storage::User& admin, const std::string& name) {
  const storage::AccountRow row = other_account(home, admin, name, "reset the password of");
  std::string password = one_time_password();
  storage::set_password(home.workspace().database(), row.user, password, std::nullopt);
  return password;
}

void set_account_role(Home& home, const storage::User& admin, const std::string& name, storage::Role role) {
  const storage::AccountRow row = other_account(home, admin, name, "change the role of");
  storage::set_role(home.workspace().database(), row.user.id, role);
}

void delete_account(Home& home, const storage::User& admin, const std::string& name, const std::string& confirm) {
  const storage::AccountRow row = other_account(home, admin, name, "delete");
  if (confirm != row.user.name) throw InvalidRequest("confirm by repeating the account's name, " + row.user.name);
  storage::Database& db = home.workspace().database();
  if (running_designs(db, row.user.id) + running_experiments(db, row.user.id) > 0)
    throw Conflict("account " + row.user.name + " has a design or an experiment running; stop it first");
  // Its folder set aside inside the transaction, deleted once the rows are gone.
  storage::Transaction transaction(db);
  storage::FolderRemoval folder(home.workspace().resolve(storage::Workspace::projects_folder(row.user)).parent_path());
  storage::delete_account_rows(db, row.user.id);
  transaction.commit();
  folder.commit();
}

void change_password(Home& home, const storage::User& user, const std::string& old_password,
                     const std::string& new_password, std::optional<std::string> keep_token) {
  storage::Database& db = home.workspace().database();
  try {
    storage::authenticate(db, user.name, old_password);
  } catch (const storage::AccessDenied&) {
    throw AccessDenied("the current password is wrong; nothing changed");
  }
  if (new_password == old_password) throw InvalidRequest("the new password is the current one");
  storage::set_password(db, user, new_password, keep_token ? std::optional<std::string_view>(*keep_token) : std::nullopt);
}

void change_password_here(Home& home, const std::string& old_password, const std::string& new_password) {
  const storage::User user = home.workspace().require_signed_in_user();
  change_password(home, user, old_password, new_password, storage::read_session_file(home.workspace().session_file()));
}

nlohmann::json accounts_document(const std::vector<AccountUse>& accounts) {
  nlohmann::json list = nlohmann::json::array();
  for (const AccountUse& a : accounts)
    list.push_back({{"name", a.account.user.name},
                    {"role", storage::role_name(a.account.role)},
                    {"disabled", a.account.disabled},
                    {"created_at", a.account.user.created_at},
                    {"last_sign_in", a.account.last_sign_in ? nlohmann::json(*a.account.last_sign_in) : nlohmann::json()},
                    {"disk_bytes", a.disk_bytes},
                    {"running_designs", a.running_designs},
                    {"running_experiments", a.running_experiments},
                    {"quota", quota_document(a.quota)}});
  return list;
}

}  // namespace sd::app
