// Running a lab's home (issue #56): accounts, quotas, invitations, `admin backup`, `admin restore`
// and `admin check`. Whoever
// runs them owns the home's files (0700): on a shared server, its administrator's Unix account.
// The work is the application layer's (app/home_backup); this file parses and prints.
#include <CLI/CLI.hpp>
#include <nlohmann/json.hpp>

#include <filesystem>
#include <iostream>
#include <memory>
#include <string>

#include "app/documents.hpp"
#include "app/home.hpp"
#include "app/home_backup.hpp"
#include "cli/command_registry.hpp"
#include "core/home.hpp"
#include "app/account_admin.hpp"
#include "app/accounts.hpp"
#include "app/quotas.hpp"
#include "app/sign_up.hpp"
#include "storage/account_admin.hpp"
#include "storage/clock.hpp"

#include <unistd.h>

namespace sd::cli::admin_commands {
namespace {

struct Options {
  std::string file, into, name, role, disk, runs;
  bool json = false, yes = false, server_default = false;
  int days = 7;
  std::int64_t id = 0;
};

std::string megabytes(std::uint64_t bytes) {
  char text[32];
  std::snprintf(text, sizeof text, "%.1f MB", static_cast<double>(bytes) / 1e6);
  return text;
}

std::string when(const nlohmann::json& t) { return t.is_null() ? "never" : storage::format_time(t.get<std::int64_t>()); }

void users(const Options& o) {
  app::Home home;
  const nlohmann::json list = app::accounts_document(app::account_uses(home, app::signed_in_user(home)));
  if (o.json) {
    std::cout << list.dump(2) << "\n";
    return;
  }
  // Quota columns: use of limit ("-": no limit).
  const auto of = [](const std::string& used, const nlohmann::json& limit, auto text) {
    return used + " / " + (limit.is_null() ? std::string("-") : text(limit.get<std::int64_t>()));
  };
  const auto mb = [](std::int64_t b) { return megabytes(static_cast<std::uint64_t>(b)); };
  const auto number = [](std::int64_t n) { return std::to_string(n); };
  std::printf("%-20s %-6s %-9s %21s %19s %8s  %s\n", "ACCOUNT", "ROLE", "STATE", "DISK / QUOTA", "RUNS TODAY / QUOTA",
              "RUNNING", "LAST SIGN-IN");
  for (const auto& a : list) {
    const nlohmann::json& q = a["quota"];
    std::printf("%-20s %-6s %-9s %21s %19s %8d  %s\n", a["name"].get<std::string>().c_str(), a["role"].get<std::string>().c_str(),
                a["disabled"].get<bool>() ? "disabled" : "active",
                of(megabytes(a["disk_bytes"].get<std::uint64_t>()), q["disk_limit"], mb).c_str(),
                of(std::to_string(q["runs_today"].get<std::int64_t>()), q["runs_per_day"], number).c_str(),
                a["running_designs"].get<int>() + a["running_experiments"].get<int>(), when(a["last_sign_in"]).c_str());
  }
}

void set_disabled(const Options& o, bool disabled) {
  app::Home home;
  app::set_account_disabled(home, app::signed_in_user(home), o.name, disabled);
  std::cout << (disabled ? "Disabled " : "Enabled ") << o.name << (disabled ? ": its sessions ended; it cannot sign in.\n" : ".\n");
}

void reset_password(const Options& o) {
  app::Home home;
  const std::string password = app::reset_account_password(home, app::signed_in_user(home), o.name);
  if (o.json) {
    std::cout << nlohmann::json{{"name", o.name}, {"password", password}}.dump(2) << "\n";
    return;
  }
  std::cout << "New password for " << o.name << " (shown once; its sessions ended): " << password << "\n"
            << "Hand it over; they change it with: swarmdesign change-password\n";
}

void set_role(const Options& o) {
  if (o.role != "admin" && o.role != "user") throw UsageError("ROLE: admin or user, not '" + o.role + "'");
  app::Home home;
  app::set_account_role(home, app::signed_in_user(home), o.name, o.role == "admin" ? storage::Role::Admin : storage::Role::User);
  std::cout << o.name << " is now " << (o.role == "admin" ? "an administrator" : "a user") << ".\n";
}

void delete_user(const Options& o) {
  app::Home home;
  const storage::User admin = app::signed_in_user(home);
  std::string confirmation = o.name;
  if (!o.yes) {
    if (!isatty(STDIN_FILENO)) throw UsageError("nothing deleted: confirm with --yes (no terminal to ask on)");
    std::cerr << "This deletes account " << o.name << " with all its projects, designs, experiments and files.\n"
              << "Type its name to delete it: " << std::flush;
    std::getline(std::cin, confirmation);
  }
  app::delete_account(home, admin, o.name, confirmation);
  std::cout << "Deleted account " << o.name << " and everything it owned.\n";
}

// `admin quota`: the server's default (--default) or an account's; shown, then changed by
// whichever of --disk and --runs-per-day is given.
void quota(const Options& o) {
  app::Home home;
  const storage::User admin = app::signed_in_user(home);
  if (o.server_default == !o.name.empty()) throw UsageError("name an account or give --default, not both or neither");
  if (o.server_default) {
    storage::QuotaLimits limits = app::server_quota(home, admin);
    const auto limit = [](const std::string& text, auto parse) -> std::optional<std::int64_t> {
      if (text == "none") return std::nullopt;
      return parse(text);
    };
    if (!o.disk.empty()) limits.disk_bytes = limit(o.disk, app::parse_disk_bytes);
    if (!o.runs.empty()) limits.runs_per_day = limit(o.runs, app::parse_runs);
    if (!o.disk.empty() || !o.runs.empty()) app::set_server_quota(home, admin, limits);
    if (o.json) {
      std::cout << app::limits_document(limits).dump(2) << "\n";
      return;
    }
    std::cout << "Server default: disk " << (limits.disk_bytes ? app::bytes_text(static_cast<std::uint64_t>(*limits.disk_bytes)) : "no limit")
              << "; runs per day " << (limits.runs_per_day ? std::to_string(*limits.runs_per_day) : "no limit") << "\n";
    return;
  }
  const storage::User user = storage::account_row(home.workspace().database(), o.name).user;
  app::require_admin(home, admin);
  storage::AccountQuota own = app::quota_use(home, user).own;
  if (!o.disk.empty()) own.disk_bytes = app::parse_quota_setting(o.disk, app::parse_disk_bytes);
  if (!o.runs.empty()) own.runs_per_day = app::parse_quota_setting(o.runs, app::parse_runs);
  if (!o.disk.empty() || !o.runs.empty()) app::set_account_quota(home, admin, o.name, own);
  const app::QuotaUse use = app::quota_use(home, user);
  if (o.json) std::cout << nlohmann::json{{"name", o.name}, {"quota", app::quota_document(use)}}.dump(2) << "\n";
  else std::cout << o.name << ": " << app::quota_text(use) << "\n";
}

// Invitations for a server run with --sign-up invite: the code is printed once.
void invite(const Options& o) {
  app::Home home;
  const storage::NewInvitation made = app::invite(home, app::signed_in_user(home), o.days);
  if (o.json) {
    std::cout << app::new_invitation_document(made).dump(2) << "\n";
    return;
  }
  std::cout << "Invitation " << made.id << " (shown once; valid until " << storage::format_time(made.expires_at)
            << ", for one sign-up): " << made.code << "\n"
            << "Hand it over with the page's address; on the page: Sign up, with this code. Or send the link\n"
            << "  http://SERVER/#invite=" << made.code << "\n"
            << "It works on a server run with: swarmdesign run-exp --sign-up invite\n";
}

void list_invitations(const Options& o) {
  app::Home home;
  const nlohmann::json list = app::invitations_document(app::invitations(home, app::signed_in_user(home)));
  if (o.json) {
    std::cout << list.dump(2) << "\n";
    return;
  }
  if (list.empty()) std::cout << "No invitations. Make one with: swarmdesign admin invite\n";
  for (const auto& i : list)
    std::cout << i["id"].get<std::int64_t>() << "  " << i["state"].get<std::string>() << "  made by "
              << (i["created_by"].is_null() ? "(deleted)" : i["created_by"].get<std::string>()) << ", valid until "
              << storage::format_time(i["expires_at"].get<std::int64_t>())
              << (i["used_by"].is_null() ? "" : ", used by " + i["used_by"].get<std::string>()) << "\n";
}

void revoke(const Options& o) {
  app::Home home;
  app::revoke_invitation(home, app::signed_in_user(home), o.id);
  std::cout << "Revoked invitation " << o.id << ": its code no longer signs anyone up.\n";
}

void backup(const Options& o) {
  app::Home home;
  const storage::HomeArchive archive = app::back_up_home(home, o.file);
  if (o.json) {
    std::cout << app::home_archive_document(archive, o.file).dump(2) << "\n";
    return;
  }
  std::cout << "Backed up " << home.folder().string() << " into " << o.file << ": " << archive.files.size() << " files, "
            << megabytes(archive.bytes) << " (databases copied as one consistent state each).\n"
            << "Restore it with: SWARMDESIGN_HOME=NEW-HOME swarmdesign admin restore " << o.file << "\n";
}

void restore(const Options& o) {
  // Not app::Home: opening it would create the database the restore must not find.
  const std::filesystem::path folder = o.into.empty() ? swarmdesign_home() : std::filesystem::absolute(o.into);
  const storage::HomeArchive archive = app::restore_home(o.file, folder);
  app::Home home(folder);
  const app::HomeCheck check = app::check_home(home);
  if (o.json) {
    nlohmann::json doc = app::home_archive_document(archive, o.file);
    doc["home"] = folder.string();
    doc["check"] = app::home_check_document(check);
    std::cout << doc.dump(2) << "\n";
  } else {
    std::cout << "Restored " << archive.files.size() << " files (" << megabytes(archive.bytes) << ", every digest checked) into "
              << folder.string() << ": " << check.users << " accounts, " << check.projects << " projects, " << check.designs
              << " designs. Sign in again there; interrupted designs resume with run-design.\n";
    for (const app::HomeProblem& p : check.problems) std::cout << "  check: " << p.kind << ": " << p.what << "\n";
  }
  if (!check.ok()) throw CLI::RuntimeError(1);
}

void check(const Options& o) {
  app::Home home;
  const app::HomeCheck c = app::check_home(home);
  if (o.json) {
    std::cout << app::home_check_document(c).dump(2) << "\n";
  } else {
    std::cout << home.folder().string() << ": " << c.users << " accounts, " << c.projects << " projects, " << c.designs
              << " designs, " << c.databases << " databases checked: " << (c.ok() ? "no problem" : "problems:") << "\n";
    for (const app::HomeProblem& p : c.problems) std::cout << "  " << p.kind << ": " << p.what << "\n";
  }
  if (!c.ok()) throw CLI::RuntimeError(1);
}

CommandRegistrar registrar{70, [](CLI::App& app, Context&) {
  auto* admin = app.add_subcommand("admin", "Run a lab's home: accounts, backups, checks");
  admin->require_subcommand(1);
  auto o = std::make_shared<Options>();

  auto* b = admin->add_subcommand("backup", "Back up the home into one archive while it is in use");
  b->add_option("FILE", o->file, "the archive to write (a .tar.gz with a manifest of digests)")->required();
  b->add_flag("--json", o->json, "Print one JSON document");
  b->footer("Every database (accounts, each design's race) is copied with SQLite's online backup, so running\n"
            "designs and a running server need not stop. The CLI's own sign-in is left out.\n\n"
            "Example:\n  swarmdesign admin backup lab-2026-12-06.tar.gz");
  b->callback([o] { backup(*o); });

  auto* r = admin->add_subcommand("restore", "Restore a backup into a new, empty home");
  r->add_option("FILE", o->file, "the archive admin backup wrote")->required()->check(CLI::ExistingFile);
  r->add_option("--into", o->into, "The home to restore into (default: this one, $SWARMDESIGN_HOME); it must be empty");
  r->add_flag("--json", o->json, "Print one JSON document");
  r->footer("Every file is checked against the archive's manifest before the home appears; a damaged or\n"
            "foreign archive is refused and nothing is restored. Mission files named by the old home's path\n"
            "are renamed into the new one, so its designs resume there.\n\n"
            "Example:\n  swarmdesign admin restore lab-2026-12-06.tar.gz --into /srv/swarmdesign");
  r->callback([o] { restore(*o); });

  auto* u = admin->add_subcommand("users", "The accounts: role, state, disk use, running jobs, last sign-in");
  u->add_flag("--json", o->json, "Print one JSON document");
  u->footer("For administrators (the home's first account, or one made so with `admin role NAME admin`).\n"
            "Quotas read use / limit (\"-\": no limit); `admin quota` sets them.");
  u->callback([o] { users(*o); });
  auto* d = admin->add_subcommand("disable", "Disable an account: its sessions end and it cannot sign in");
  d->add_option("NAME", o->name, "the account")->required();
  d->callback([o] { set_disabled(*o, true); });
  auto* e = admin->add_subcommand("enable", "Enable a disabled account");
  e->add_option("NAME", o->name, "the account")->required();
  e->callback([o] { set_disabled(*o, false); });
  auto* p = admin->add_subcommand("reset-password", "Give an account a new one-time password (printed once)");
  p->add_option("NAME", o->name, "the account")->required();
  p->add_flag("--json", o->json, "Print one JSON document");
  p->callback([o] { reset_password(*o); });
  auto* role = admin->add_subcommand("role", "Make an account an administrator, or a user again");
  role->add_option("NAME", o->name, "the account")->required();
  role->add_option("ROLE", o->role, "admin or user")->required();
  role->callback([o] { set_role(*o); });
  auto* del = admin->add_subcommand("delete-user", "Delete an account with its projects, designs, experiments and files");
  del->add_option("NAME", o->name, "the account")->required();
  del->add_flag("--yes", o->yes, "Do not ask for its name again");
  del->footer("Refused while one of its designs or experiments runs. Nothing of another account is touched.");
  del->callback([o] { delete_user(*o); });

  auto* q = admin->add_subcommand("quota", "Show or set an account's quotas, or the server's default");
  q->add_option("NAME", o->name, "the account (or --default)");
  q->add_flag("--default", o->server_default, "The server's default, for every account without its own");
  q->add_option("--disk", o->disk, "Disk limit: a size (500MB, 2GB), none, or default (an account follows the server's)");
  q->add_option("--runs-per-day", o->runs, "Simulation runs per UTC day: a number, none, or default");
  q->add_flag("--json", o->json, "Print one JSON document");
  q->footer("Disk counts every file under the account's folder (designs, experiments, uploads). A design counts\n"
            "its budget when it starts, an experiment its whole plan; work or a file that would pass a limit is\n"
            "refused in one line before anything is written. Users see theirs with `swarmdesign quota`.\n\n"
            "Examples:\n  swarmdesign admin quota --default --disk 20GB --runs-per-day 2000000\n"
            "  swarmdesign admin quota alice --disk none\n  swarmdesign admin quota bob --runs-per-day default");
  q->callback([o] { quota(*o); });

  auto* inv = admin->add_subcommand("invite", "Make a one-time invitation to sign up on the page (printed once)");
  inv->add_option("--days", o->days, "How long it is valid, 1 to 90 days")->capture_default_str();
  inv->add_flag("--json", o->json, "Print one JSON document");
  inv->footer("For a server run with `swarmdesign run-exp --sign-up invite`: whoever brings the code signs up\n"
              "once, before it expires. Only its hash is stored.\n\nExample:\n  swarmdesign admin invite --days 14");
  inv->callback([o] { invite(*o); });
  auto* invs = admin->add_subcommand("invitations", "List the invitations: open, used (by whom), revoked or expired");
  invs->add_flag("--json", o->json, "Print one JSON document");
  invs->callback([o] { list_invitations(*o); });
  auto* rev = admin->add_subcommand("revoke-invitation", "Revoke an unused invitation");
  rev->add_option("ID", o->id, "the invitation's number (admin invitations)")->required();
  rev->callback([o] { revoke(*o); });

  auto* c = admin->add_subcommand("check", "Check the home: databases, folders, links");
  c->add_flag("--json", o->json, "Print one JSON document");
  c->footer("SQLite's integrity check of every database, every folder the database names present, no project\n"
            "or design folder it does not name, no link anywhere. Exit status 1 when anything is wrong.");
  c->callback([o] { check(*o); });
}};

}  // namespace
}  // namespace sd::cli::admin_commands
