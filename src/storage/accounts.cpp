#include "storage/accounts.hpp"

#include <optional>

#include "storage/clock.hpp"
#include "storage/errors.hpp"
#include "storage/passwords.hpp"
#include "storage/validation.hpp"

namespace sd::storage {

namespace {
struct StoredUser {
  User user;
  std::string password_hash;
  bool disabled = false;
};

std::optional<StoredUser> find_user(Database& db, std::string_view name) {
  auto query = db.prepare("SELECT id, name, created_at, password_hash, disabled FROM users WHERE name = ?");
  query.bind(1, name);
  if (!query.step()) return std::nullopt;
  return StoredUser{User{query.integer(0), query.text(1), query.integer(2)}, query.text(3), query.integer(4) != 0};
}

// Built by appending: GCC 12 at -O3 warns falsely (-Wrestrict) on "'" + std::string + "'".
std::string in_quotes(std::string_view name) {
  std::string text(1, '\'');
  text.append(name).push_back('\'');
  return text;
}
}  // namespace

bool user_exists(Database& db, std::string_view name) { return find_user(db, name).has_value(); }

User create_user(Database& db, std::string_view name, std::string_view password, const std::function<void(const User&)>& also) {
  if (auto problem = user_name_problem(name); !problem.empty()) throw InvalidInput(problem);
  if (auto problem = password_problem(password, name); !problem.empty()) throw InvalidInput(problem);
  const std::string taken = "user name " + in_quotes(name) + " is already taken; choose another";
  // Fail fast before the deliberately slow hash; the insert below settles races.
  if (find_user(db, name)) throw Conflict(taken);
  const std::string hash = hash_password(password);

  Transaction transaction(db);
  const std::int64_t now = unix_now();
  // The home's first account administers it (a lab's server: its administrator signs up first).
  auto insert = db.prepare(
      "INSERT INTO users (name, password_hash, created_at, role) "
      "VALUES (?, ?, ?, CASE WHEN EXISTS (SELECT 1 FROM users) THEN 'user' ELSE 'admin' END) ON CONFLICT (name) DO NOTHING");
  insert.bind(1, name).bind(2, hash).bind(3, now).run();
  if (db.changes() == 0) throw Conflict(taken);
  User user{db.last_insert_id(), std::string(name), now};
  if (also) also(user);
  transaction.commit();
  return user;
}

User authenticate(Database& db, std::string_view name, std::string_view password) {
  auto stored = find_user(db, name);
  const bool right = verify_password(stored ? stored->password_hash : dummy_password_hash(), password);
  if (!stored || !right) throw AccessDenied("wrong user name or password");
  // Said only to whoever knows the password: a disabled account's name is not given away.
  if (stored->disabled) throw AccountDisabled("account " + in_quotes(stored->user.name) + " is disabled; ask the server's administrator");
  db.prepare("UPDATE users SET last_sign_in = ? WHERE id = ?").bind(1, unix_now()).bind(2, stored->user.id).run();
  if (password_needs_rehash(stored->password_hash)) {
    Transaction transaction(db);
    db.prepare("UPDATE users SET password_hash = ? WHERE id = ?").bind(1, hash_password(password)).bind(2, stored->user.id).run();
    transaction.commit();
  }
  return stored->user;
}

std::vector<User> list_users(Database& db) {
  std::vector<User> users;
  auto query = db.prepare("SELECT id, name, created_at FROM users ORDER BY name");
  while (query.step()) users.push_back(User{query.integer(0), query.text(1), query.integer(2)});
  return users;
}

}  // namespace sd::storage
