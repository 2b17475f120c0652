#include "storage/sign_in_attempts.hpp"

#include <algorithm>
#include <cctype>
#include <string>

namespace sd::storage {

namespace {
// Names are case-insensitive (users.name is COLLATE NOCASE): "Alice" and "alice" share a count.
std::string key(std::string_view name) {
  std::string lower(name.substr(0, 256));
  std::transform(lower.begin(), lower.end(), lower.begin(), [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
  return lower;
}
}  // namespace

std::int64_t SignInAttempts::locked_for(std::string_view name, std::int64_t now) {
  auto query = db_.prepare("SELECT locked_until FROM sign_in_failures WHERE name = ?");
  query.bind(1, key(name));
  if (!query.step()) return 0;
  return std::max<std::int64_t>(0, query.integer(0) - now);
}

void SignInAttempts::failed(std::string_view name, std::int64_t now) {
  Transaction transaction(db_);
  // A failure after a lock-out ran out starts a new count (the row keeps the old lock time).
  db_.prepare(
         "INSERT INTO sign_in_failures (name, failures, last_failure) VALUES (?1, 1, ?2) "
         "ON CONFLICT (name) DO UPDATE SET failures = CASE WHEN locked_until > 0 AND locked_until <= ?2 THEN 1 "
         "ELSE failures + 1 END, locked_until = CASE WHEN locked_until <= ?2 THEN 0 ELSE locked_until END, "
         "last_failure = ?2")
      .bind(1, key(name))
      .bind(2, now)
      .run();
  db_.prepare("UPDATE sign_in_failures SET locked_until = ?2 + ?3 WHERE name = ?1 AND failures >= ?4 AND locked_until = 0")
      .bind(1, key(name))
      .bind(2, now)
      .bind(3, static_cast<std::int64_t>(policy_.lockout.count()))
      .bind(4, policy_.failures_before_lockout)
      .run();
  // Counts of names nobody tried for a day are forgotten, so guessed names do not pile up.
  db_.prepare("DELETE FROM sign_in_failures WHERE last_failure < ?1 AND locked_until < ?1")
      .bind(1, now - 86400)
      .run();
  transaction.commit();
}

void SignInAttempts::succeeded(std::string_view name) {
  db_.prepare("DELETE FROM sign_in_failures WHERE name = ?").bind(1, key(name)).run();
}

}  // namespace sd::storage
