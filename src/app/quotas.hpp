#pragma once
// Quotas on a shared server (issue #56): disk bytes under an account's folder and simulation
// runs per UTC day, set by an administrator per account and as the server's default. Every
// front end asks here before work that writes or runs: a mission or software saved (its bytes),
// a design or an experiment started (the disk must have room; its runs are checked first, and
// counted once it has started, never when it is refused or only resumes). A refusal is one
// line, made before anything is written.
#include <nlohmann/json_fwd.hpp>

#include <cstdint>
#include <filesystem>
#include <mutex>
#include <string>

#include "app/home.hpp"
#include "storage/accounts.hpp"
#include "storage/errors.hpp"
#include "storage/quotas.hpp"

namespace sd::app {

/// Work refused because it would pass the account's quota: a Conflict (a server answers 409,
/// the CLI exits 1) that says which quota, for scripts: the page's `"quota"`, Python's
/// QuotaExceededError.quota.
struct QuotaExceeded : storage::Conflict {
  QuotaExceeded(const char* which, const std::string& message) : storage::Conflict(message), quota(which) {}
  const char* quota;  // "disk" or "runs"
};

struct QuotaUse {
  std::uint64_t disk_bytes = 0;  // everything under the account's folder (links not followed)
  std::int64_t runs_today = 0;   // of work started this UTC day
  storage::QuotaLimits limits;   // in force
  storage::AccountQuota own;     // the account's settings (default, none or a limit)
};

/// The bytes of every regular file under the account's folder; links are not followed.
std::uint64_t account_disk_bytes(Home& home, const storage::User& user);
QuotaUse quota_use(Home& home, const storage::User& user);

/// QuotaExceeded unless the account is under its disk limit: for work whose size is known only
/// as it runs (a design, an experiment).
void require_disk_room(Home& home, const storage::User& user);
/// QuotaExceeded unless writing `bytes` to `file` (replacing what it holds) keeps the account
/// within its disk limit; a write that does not grow the account is always allowed.
void require_room_for_file(Home& home, const storage::User& user, const std::filesystem::path& file, std::uint64_t bytes);

/// The runs of work about to start, checked against the account's limit for today before it
/// starts and counted only once it has (keep()): a start that is refused for any reason, or
/// that only resumes, writes nothing. Held, it keeps other starts of this process waiting, so
/// two requests to one server cannot both slip under a limit.
class RunReservation {
 public:
  /// QuotaExceeded when the runs would pass the account's limit for today.
  RunReservation(Home& home, const storage::User& user, std::int64_t runs, const std::string& what);
  RunReservation(const RunReservation&) = delete;
  RunReservation& operator=(const RunReservation&) = delete;
  /// The work started: its runs count for today.
  void keep();

 private:
  std::unique_lock<std::mutex> lock_;
  Home& home_;
  std::int64_t user_id_, runs_, day_;
};

/// Administrators only (AccessDenied otherwise).
storage::QuotaLimits server_quota(Home& home, const storage::User& admin);
void set_server_quota(Home& home, const storage::User& admin, const storage::QuotaLimits& limits);
void set_account_quota(Home& home, const storage::User& admin, const std::string& name, const storage::AccountQuota& quota);

/// "500MB", "2GB", "1.5 GB", "1048576" (bytes; decimal units kB MB GB TB) for a disk limit;
/// InvalidRequest in one line otherwise.
std::int64_t parse_disk_bytes(const std::string& text);
/// An account's setting from a front end: "default", "none" or a limit (`parse` reads it).
storage::QuotaSetting parse_quota_setting(const std::string& text, std::int64_t (*parse)(const std::string&));
std::int64_t parse_runs(const std::string& text);
/// "disk 1.2 MB of 100.0 MB (server default); runs today 5000 of no limit (own)", for a terminal.
std::string quota_text(const QuotaUse& use);
/// "1.2 MB", for messages.
std::string bytes_text(std::uint64_t bytes);

/// {"disk_bytes", "disk_limit", "runs_today", "runs_per_day", "disk_from_default", "runs_from_default"}
nlohmann::json quota_document(const QuotaUse& use);
/// {"disk_limit", "runs_per_day"}: null for no limit.
nlohmann::json limits_document(const storage::QuotaLimits& limits);
/// The limits a page sent: each an integer or null (no limit); InvalidRequest otherwise.
storage::QuotaLimits limits_from_document(const nlohmann::json& body);
/// An account's settings a page sent: an integer, null (no limit) or "default".
storage::AccountQuota account_quota_from_document(const nlohmann::json& body);

}  // namespace sd::app
