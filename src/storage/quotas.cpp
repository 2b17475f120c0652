#include "storage/quotas.hpp"

#include <string>

#include "storage/errors.hpp"

namespace sd::storage {

namespace {

// An account's own column: NULL follows the server, -1 lifts the limit, else the limit.
constexpr std::int64_t kNoLimit = -1;

QuotaSetting setting_of(Statement& q, int column) {
  if (q.is_null(column)) return {};
  const std::int64_t v = q.integer(column);
  if (v == kNoLimit) return {QuotaSetting::Kind::none, 0};
  return {QuotaSetting::Kind::limit, v};
}

void bind_setting(Statement& q, int index, const QuotaSetting& s) {
  switch (s.kind) {
    case QuotaSetting::Kind::server_default: q.bind_null(index); break;
    case QuotaSetting::Kind::none: q.bind(index, kNoLimit); break;
    case QuotaSetting::Kind::limit: q.bind(index, s.value); break;
  }
}

void bind_limit(Statement& q, int index, const std::optional<std::int64_t>& limit) {
  if (limit) q.bind(index, *limit);
  else q.bind_null(index);
}

void require_not_negative(const std::optional<std::int64_t>& limit, const char* what) {
  if (limit && *limit < 0) throw InvalidInput(std::string(what) + " must be 0 or more, not " + std::to_string(*limit));
}

std::optional<std::int64_t> in_force(const QuotaSetting& own, const std::optional<std::int64_t>& server) {
  switch (own.kind) {
    case QuotaSetting::Kind::server_default: return server;
    case QuotaSetting::Kind::none: return std::nullopt;
    case QuotaSetting::Kind::limit: return own.value;
  }
  return server;
}

}  // namespace

QuotaLimits server_quota(Database& db) {
  Statement q = db.prepare("SELECT disk_bytes, runs_per_day FROM server_quota WHERE id = 1");
  QuotaLimits out;
  if (!q.step()) return out;
  if (!q.is_null(0)) out.disk_bytes = q.integer(0);
  if (!q.is_null(1)) out.runs_per_day = q.integer(1);
  return out;
}

void set_server_quota(Database& db, const QuotaLimits& limits) {
  require_not_negative(limits.disk_bytes, "the disk quota");
  require_not_negative(limits.runs_per_day, "the runs-per-day quota");
  Statement q = db.prepare("UPDATE server_quota SET disk_bytes = ?, runs_per_day = ? WHERE id = 1");
  bind_limit(q, 1, limits.disk_bytes);
  bind_limit(q, 2, limits.runs_per_day);
  q.run();
}

AccountQuota account_quota(Database& db, std::int64_t user_id) {
  Statement q = db.prepare("SELECT quota_disk_bytes, quota_runs_per_day FROM users WHERE id = ?");
  q.bind(1, user_id);
  if (!q.step()) throw NotFound("no such account");
  return {setting_of(q, 0), setting_of(q, 1)};
}

void set_account_quota(Database& db, std::int64_t user_id, const AccountQuota& quota) {
  for (const QuotaSetting* s : {&quota.disk_bytes, &quota.runs_per_day})
    if (s->kind == QuotaSetting::Kind::limit) require_not_negative(s->value, "a quota");
  Statement q = db.prepare("UPDATE users SET quota_disk_bytes = ?, quota_runs_per_day = ? WHERE id = ?");
  bind_setting(q, 1, quota.disk_bytes);
  bind_setting(q, 2, quota.runs_per_day);
  q.bind(3, user_id).run();
}

QuotaLimits limits_in_force(Database& db, std::int64_t user_id) {
  const QuotaLimits server = server_quota(db);
  const AccountQuota own = account_quota(db, user_id);
  return {in_force(own.disk_bytes, server.disk_bytes), in_force(own.runs_per_day, server.runs_per_day)};
}

std::int64_t utc_day(std::int64_t unix_seconds) { return unix_seconds / 86400; }

std::int64_t runs_on(Database& db, std::int64_t user_id, std::int64_t day) {
  Statement q = db.prepare("SELECT runs FROM run_use WHERE user_id = ? AND day = ?");
  q.bind(1, user_id).bind(2, day);
  return q.step() ? q.integer(0) : 0;
}

void add_runs(Database& db, std::int64_t user_id, std::int64_t runs, std::int64_t day) {
  db.prepare("INSERT INTO run_use (user_id, day, runs) VALUES (?1, ?2, ?3) "
             "ON CONFLICT (user_id, day) DO UPDATE SET runs = runs + ?3")
      .bind(1, user_id)
      .bind(2, day)
      .bind(3, runs)
      .run();
}

}  // namespace sd::storage
