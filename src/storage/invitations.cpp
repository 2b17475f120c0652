#include "storage/invitations.hpp"

#include "storage/clock.hpp"
#include "storage/errors.hpp"
#include "storage/sodium.hpp"

namespace sd::storage {

namespace {

/// 24 symbols (about 139 bits): typed or pasted from a link.
constexpr std::size_t kCodeLength = 24;

std::optional<std::string> optional_text(Statement& q, int column) {
  if (q.is_null(column)) return std::nullopt;
  return q.text(column);
}

}  // namespace

NewInvitation create_invitation(Database& db, std::int64_t admin_id, std::int64_t lifetime_seconds) {
  NewInvitation out{0, readable_secret(kCodeLength), unix_now() + lifetime_seconds};
  const SecretHash hash = hash_secret(out.code);
  db.prepare("INSERT INTO invitations (code_hash, created_by, created_at, expires_at) VALUES (?, ?, ?, ?)")
      .bind_blob(1, hash.data(), hash.size())
      .bind(2, admin_id)
      .bind(3, unix_now())
      .bind(4, out.expires_at)
      .run();
  out.id = db.last_insert_id();
  return out;
}

std::vector<InvitationRow> invitation_rows(Database& db) {
  Statement q = db.prepare(
      "SELECT i.id, c.name, u.name, i.created_at, i.expires_at, i.used_at, i.revoked_at FROM invitations i "
      "LEFT JOIN users c ON c.id = i.created_by LEFT JOIN users u ON u.id = i.used_by ORDER BY i.id");
  std::vector<InvitationRow> rows;
  while (q.step()) {
    InvitationRow r;
    r.id = q.integer(0);
    r.created_by = optional_text(q, 1);
    r.used_by = optional_text(q, 2);
    r.created_at = q.integer(3);
    r.expires_at = q.integer(4);
    if (!q.is_null(5)) r.used_at = q.integer(5);
    if (!q.is_null(6)) r.revoked_at = q.integer(6);
    rows.push_back(std::move(r));
  }
  return rows;
}

void revoke_invitation(Database& db, std::int64_t id) {
  db.prepare("UPDATE invitations SET revoked_at = ? WHERE id = ? AND used_at IS NULL AND revoked_at IS NULL")
      .bind(1, unix_now())
      .bind(2, id)
      .run();
  if (db.changes() == 0) throw NotFound("no open invitation " + std::to_string(id) + " (unknown, used or revoked)");
}

bool invitation_open(Database& db, std::string_view code, std::int64_t now) {
  const SecretHash hash = hash_secret(code);
  Statement q = db.prepare("SELECT 1 FROM invitations WHERE code_hash = ? AND used_at IS NULL AND revoked_at IS NULL AND expires_at > ?");
  q.bind_blob(1, hash.data(), hash.size()).bind(2, now);
  return q.step();
}

void use_invitation(Database& db, std::string_view code, const User& user, std::int64_t now) {
  const SecretHash hash = hash_secret(code);
  db.prepare("UPDATE invitations SET used_by = ?, used_at = ? WHERE code_hash = ? AND used_at IS NULL AND revoked_at IS NULL "
             "AND expires_at > ?")
      .bind(1, user.id)
      .bind(2, now)
      .bind_blob(3, hash.data(), hash.size())
      .bind(4, now)
      .run();
  if (db.changes() == 0) throw AccessDenied(kInvalidInvitation);
}

}  // namespace sd::storage
