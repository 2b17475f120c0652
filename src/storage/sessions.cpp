#include "storage/sessions.hpp"

#include <sodium.h>

#include <array>

#include "storage/clock.hpp"
#include "storage/sodium.hpp"

namespace sd::storage {

namespace {
std::string random_token() {
  ensure_sodium();
  std::array<unsigned char, 32> bytes{};
  randombytes_buf(bytes.data(), bytes.size());
  std::string hex(bytes.size() * 2 + 1, '\0');
  sodium_bin2hex(hex.data(), hex.size(), bytes.data(), bytes.size());
  hex.pop_back();  // the terminating NUL
  sodium_memzero(bytes.data(), bytes.size());
  return hex;
}
}  // namespace

NewSession start_session(Database& db, const User& user) {
  NewSession session{random_token(), 0};
  const SecretHash hash = hash_secret(session.token);
  const std::int64_t now = unix_now();
  session.expires_at = now + kSessionLifetime.count();
  Transaction transaction(db);
  db.prepare("DELETE FROM sessions WHERE expires_at <= ?").bind(1, now).run();
  db.prepare("INSERT INTO sessions (user_id, token_hash, created_at, expires_at) VALUES (?, ?, ?, ?)")
      .bind(1, user.id)
      .bind_blob(2, hash.data(), hash.size())
      .bind(3, now)
      .bind(4, session.expires_at)
      .run();
  transaction.commit();
  return session;
}

std::optional<SessionRecord> find_session(Database& db, std::string_view token) {
  const SecretHash hash = hash_secret(token);
  auto query = db.prepare(
      "SELECT u.id, u.name, u.created_at, s.expires_at FROM sessions s JOIN users u ON u.id = s.user_id "
      "WHERE s.token_hash = ?");
  query.bind_blob(1, hash.data(), hash.size());
  if (!query.step()) return std::nullopt;
  return SessionRecord{User{query.integer(0), query.text(1), query.integer(2)}, query.integer(3)};
}

void end_session(Database& db, std::string_view token) {
  const SecretHash hash = hash_secret(token);
  Transaction transaction(db);
  db.prepare("DELETE FROM sessions WHERE token_hash = ?").bind_blob(1, hash.data(), hash.size()).run();
  transaction.commit();
}

void end_sessions_of(Database& db, std::int64_t user_id, std::optional<std::string_view> except_token) {
  if (!except_token) {
    db.prepare("DELETE FROM sessions WHERE user_id = ?").bind(1, user_id).run();
    return;
  }
  const SecretHash keep = hash_secret(*except_token);
  db.prepare("DELETE FROM sessions WHERE user_id = ? AND token_hash <> ?").bind(1, user_id).bind_blob(2, keep.data(), keep.size()).run();
}

}  // namespace sd::storage
