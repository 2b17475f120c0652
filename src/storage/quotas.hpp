#pragma once
// Quotas (issue #56): what an administrator lets each account use of a shared server — disk
// bytes under its folder and simulation runs per UTC day — as a server default and per-account
// settings. Runs are counted when work starts (a design's budget, an experiment's plan), so a
// day's count is what was started, whether or not it has run yet.
#include <cstdint>
#include <optional>

#include "storage/sqlite.hpp"

namespace sd::storage {

/// Limits in force; nullopt: no limit.
struct QuotaLimits {
  std::optional<std::int64_t> disk_bytes, runs_per_day;
};

/// One limit as an account's own setting says it.
struct QuotaSetting {
  enum class Kind { server_default, none, limit } kind = Kind::server_default;
  std::int64_t value = 0;  // Kind::limit only
};

struct AccountQuota {
  QuotaSetting disk_bytes, runs_per_day;
};

QuotaLimits server_quota(Database& db);
/// InvalidInput for a negative limit.
void set_server_quota(Database& db, const QuotaLimits& limits);

AccountQuota account_quota(Database& db, std::int64_t user_id);
/// InvalidInput for a negative limit.
void set_account_quota(Database& db, std::int64_t user_id, const AccountQuota& quota);

/// The account's settings with the server's default filled in.
QuotaLimits limits_in_force(Database& db, std::int64_t user_id);

/// The UTC day of a Unix time, as run_use counts it.
std::int64_t utc_day(std::int64_t unix_seconds);
/// Runs of the work the account started on `day`.
std::int64_t runs_on(Database& db, std::int64_t user_id, std::int64_t day);
/// Adds `runs` to the account's count for `day` (work that has started).
void add_runs(Database& db, std::int64_t user_id, std::int64_t runs, std::int64_t day);

}  // namespace sd::storage
