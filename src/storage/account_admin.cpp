#include "storage/account_admin.hpp"

#include "storage/errors.hpp"
#include "storage/passwords.hpp"
#include "storage/sessions.hpp"

namespace sd::storage {

namespace {

AccountRow row_of(Statement& q) {
  AccountRow r;
  r.user = User{q.integer(0), q.text(1), q.integer(2)};
  r.role = q.text(3) == "admin" ? Role::Admin : Role::User;
  r.disabled = q.integer(4) != 0;
  if (!q.is_null(5)) r.last_sign_in = q.integer(5);
  return r;
}

constexpr const char* kColumns = "SELECT id, name, created_at, role, disabled, last_sign_in FROM users ";

}  // namespace

std::string_view role_name(Role role) { return role == Role::Admin ? "admin" : "user"; }

std::vector<AccountRow> account_rows(Database& db) {
  std::vector<AccountRow> rows;
  Statement q = db.prepare(std::string(kColumns) + "ORDER BY name");
  while (q.step()) rows.push_back(row_of(q));
  return rows;
}

AccountRow account_row(Database& db, std::string_view name) {
  Statement q = db.prepare(std::string(kColumns) + "WHERE name = ?");
  q.bind(1, name);
  if (!q.step()) throw NotFound("no account named '" + std::string(name) + "'");
  return row_of(q);
}

void set_disabled(Database& db, std::int64_t user_id, bool disabled) {
  Transaction transaction(db);
  db.prepare("UPDATE users SET disabled = ? WHERE id = ?").bind(1, disabled ? 1 : 0).bind(2, user_id).run();
  if (disabled) end_sessions_of(db, user_id);
  transaction.commit();
}

void set_role(Database& db, std::int64_t user_id, Role role) {
  db.prepare("UPDATE users SET role = ? WHERE id = ?").bind(1, role_name(role)).bind(2, user_id).run();
}

void set_password(Database& db, const User& user, std::string_view password, std::optional<std::string_view> keep_token) {
  if (auto problem = password_problem(password, user.name); !problem.empty()) throw InvalidInput(problem);
  const std::string hash = hash_password(password);  // slow: outside the transaction
  Transaction transaction(db);
  db.prepare("UPDATE users SET password_hash = ? WHERE id = ?").bind(1, hash).bind(2, user.id).run();
  end_sessions_of(db, user.id, keep_token);
  transaction.commit();
}

void delete_account_rows(Database& db, std::int64_t user_id) {
  db.prepare("DELETE FROM users WHERE id = ?").bind(1, user_id).run();
}

}  // namespace sd::storage
