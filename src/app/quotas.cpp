#include "app/quotas.hpp"

#include <nlohmann/json.hpp>

#include <charconv>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <system_error>

#include "app/account_admin.hpp"
#include "app/errors.hpp"
#include "storage/account_admin.hpp"
#include "storage/clock.hpp"

namespace sd::app {

namespace fs = std::filesystem;

namespace {

std::int64_t today() { return storage::utc_day(storage::unix_now()); }

nlohmann::json limit_json(const std::optional<std::int64_t>& limit) { return limit ? nlohmann::json(*limit) : nlohmann::json(); }

std::optional<std::int64_t> limit_field(const nlohmann::json& body, const char* key) {
  if (!body.is_object() || !body.contains(key)) throw InvalidRequest(std::string(key) + " is missing (a number, or null for no limit)");
  const nlohmann::json& v = body.at(key);
  if (v.is_null()) return std::nullopt;
  if (!v.is_number_integer() || v.get<std::int64_t>() < 0)
    throw InvalidRequest(std::string(key) + " must be a whole number of 0 or more, or null for no limit");
  return v.get<std::int64_t>();
}

storage::QuotaSetting setting_field(const nlohmann::json& body, const char* key) {
  if (body.is_object() && body.contains(key) && body.at(key) == "default") return {};
  const auto limit = limit_field(body, key);
  if (!limit) return {storage::QuotaSetting::Kind::none, 0};
  return {storage::QuotaSetting::Kind::limit, *limit};
}

std::int64_t account_id(Home& home, const std::string& name) { return storage::account_row(home.workspace().database(), name).user.id; }

}  // namespace

std::uint64_t account_disk_bytes(Home& home, const storage::User& user) {
  const fs::path folder = home.workspace().resolve(storage::Workspace::projects_folder(user)).parent_path();
  std::uint64_t bytes = 0;
  std::error_code walk;
  for (auto it = fs::recursive_directory_iterator(folder, walk); !walk && it != fs::recursive_directory_iterator();
       it.increment(walk)) {
    // A file a running design replaces as it is read is skipped, not the end of the walk: one
    // error code for both would stop the count there and let the account pass its limit.
    std::error_code entry;
    if (it->symlink_status(entry).type() != fs::file_type::regular) continue;
    const std::uintmax_t size = it->file_size(entry);
    if (!entry) bytes += size;
  }
  return bytes;
}

QuotaUse quota_use(Home& home, const storage::User& user) {
  storage::Database& db = home.workspace().database();
  QuotaUse use;
  use.disk_bytes = account_disk_bytes(home, user);
  use.runs_today = storage::runs_on(db, user.id, today());
  use.limits = storage::limits_in_force(db, user.id);
  use.own = storage::account_quota(db, user.id);
  return use;
}

void require_disk_room(Home& home, const storage::User& user) { require_room_for_file(home, user, {}, 0); }

void require_room_for_file(Home& home, const storage::User& user, const fs::path& file, std::uint64_t bytes) {
  const auto limit = storage::limits_in_force(home.workspace().database(), user.id).disk_bytes;
  if (!limit) return;
  std::error_code ec;
  std::uint64_t replaced = 0;
  if (!file.empty() && fs::symlink_status(file, ec).type() == fs::file_type::regular) {
    const std::uintmax_t size = fs::file_size(file, ec);
    replaced = ec ? 0 : size;  // unreadable: counted as nothing replaced, never as room
  }
  if (bytes > 0 && bytes <= replaced) return;  // no growth: allowed even over the limit
  const std::uint64_t used = account_disk_bytes(home, user), cap = static_cast<std::uint64_t>(*limit);
  const std::uint64_t more = bytes - replaced;
  if (bytes == 0 ? used < cap : used + more <= cap) return;
  const std::string needs = bytes == 0 ? "" : "this needs " + bytes_text(more) + " more, and ";
  throw QuotaExceeded("disk", "disk quota: " + needs + user.name + " uses " + bytes_text(used) + " of " + bytes_text(cap) +
                      "; delete designs or files, or ask an administrator");
}

namespace {
std::mutex starts;  // one start at a time in this process: its check and its count go together
}  // namespace

RunReservation::RunReservation(Home& home, const storage::User& user, std::int64_t runs, const std::string& what)
    : lock_(starts), home_(home), user_id_(user.id), runs_(runs), day_(today()) {
  storage::Database& db = home.workspace().database();
  const auto limit = storage::limits_in_force(db, user.id).runs_per_day;
  const std::int64_t used = storage::runs_on(db, user.id, day_);
  if (limit && runs > 0 && used + runs > *limit)
    throw QuotaExceeded("runs", "runs quota: " + what + " needs " + std::to_string(runs) + " runs, and " + user.name + " has " +
                        std::to_string(std::max<std::int64_t>(0, *limit - used)) + " of " + std::to_string(*limit) +
                        " runs left today (UTC); ask an administrator, or wait until tomorrow");
}

void RunReservation::keep() {
  if (runs_ > 0) storage::add_runs(home_.workspace().database(), user_id_, runs_, day_);
}

storage::QuotaLimits server_quota(Home& home, const storage::User& admin) {
  require_admin(home, admin);
  return storage::server_quota(home.workspace().database());
}

void set_server_quota(Home& home, const storage::User& admin, const storage::QuotaLimits& limits) {
  require_admin(home, admin);
  storage::set_server_quota(home.workspace().database(), limits);
}

void set_account_quota(Home& home, const storage::User& admin, const std::string& name, const storage::AccountQuota& quota) {
  require_admin(home, admin);
  storage::set_account_quota(home.workspace().database(), account_id(home, name), quota);
}

std::int64_t parse_disk_bytes(const std::string& text) {
  double number = -1;
  const auto [rest, ec] = std::from_chars(text.data(), text.data() + text.size(), number);
  std::string unit(rest, text.data() + text.size());
  if (!unit.empty() && unit.front() == ' ') unit.erase(0, 1);
  double scale = 0;
  if (unit.empty() || unit == "B") scale = 1;
  else if (unit == "kB" || unit == "KB") scale = 1e3;
  else if (unit == "MB") scale = 1e6;
  else if (unit == "GB") scale = 1e9;
  else if (unit == "TB") scale = 1e12;
  if (ec != std::errc() || scale == 0 || !std::isfinite(number) || number < 0 || number * scale > 9e18)
    throw InvalidRequest("disk quota '" + text + "': a size such as 500MB or 2GB (kB, MB, GB, TB), or a number of bytes");
  return static_cast<std::int64_t>(std::llround(number * scale));
}

std::int64_t parse_runs(const std::string& text) {
  std::size_t end = 0;
  long long runs = -1;
  try {
    runs = std::stoll(text, &end);
  } catch (const std::exception&) {
  }
  if (runs < 0 || end != text.size()) throw InvalidRequest("runs per day '" + text + "': a whole number of 0 or more");
  return runs;
}

storage::QuotaSetting parse_quota_setting(const std::string& text, std::int64_t (*parse)(const std::string&)) {
  if (text == "default") return {};
  if (text == "none") return {storage::QuotaSetting::Kind::none, 0};
  return {storage::QuotaSetting::Kind::limit, parse(text)};
}

std::string bytes_text(std::uint64_t bytes) {
  static constexpr const char* kUnits[] = {"B", "kB", "MB", "GB", "TB"};
  double v = static_cast<double>(bytes);
  int unit = 0;
  while (v >= 1000 && unit < 4) v /= 1000, ++unit;
  char text[32];
  std::snprintf(text, sizeof text, unit == 0 ? "%.0f %s" : "%.1f %s", v, kUnits[unit]);
  return text;
}

std::string quota_text(const QuotaUse& use) {
  using Kind = storage::QuotaSetting::Kind;
  const auto source = [](const storage::QuotaSetting& s) { return s.kind == Kind::server_default ? " (server default)" : " (own)"; };
  const std::string disk = use.limits.disk_bytes ? bytes_text(static_cast<std::uint64_t>(*use.limits.disk_bytes)) : "no limit";
  const std::string runs = use.limits.runs_per_day ? std::to_string(*use.limits.runs_per_day) : "no limit";
  return "disk " + bytes_text(use.disk_bytes) + " of " + disk + source(use.own.disk_bytes) + "; runs today (UTC) " +
         std::to_string(use.runs_today) + " of " + runs + source(use.own.runs_per_day);
}

nlohmann::json quota_document(const QuotaUse& use) {
  using Kind = storage::QuotaSetting::Kind;
  return {{"disk_bytes", use.disk_bytes},
          {"disk_limit", limit_json(use.limits.disk_bytes)},
          {"runs_today", use.runs_today},
          {"runs_per_day", limit_json(use.limits.runs_per_day)},
          {"disk_from_default", use.own.disk_bytes.kind == Kind::server_default},
          {"runs_from_default", use.own.runs_per_day.kind == Kind::server_default}};
}

nlohmann::json limits_document(const storage::QuotaLimits& limits) {
  return {{"disk_limit", limit_json(limits.disk_bytes)}, {"runs_per_day", limit_json(limits.runs_per_day)}};
}

storage::QuotaLimits limits_from_document(const nlohmann::json& body) {
  return {limit_field(body, "disk_limit"), limit_field(body, "runs_per_day")};
}

storage::AccountQuota account_quota_from_document(const nlohmann::json& body) {
  return {setting_field(body, "disk_limit"), setting_field(body, "runs_per_day")};
}

}  // namespace sd::app
