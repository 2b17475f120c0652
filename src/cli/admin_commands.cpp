// Running a lab's home (issue #56): `admin backup`, `admin restore` and `admin check`. Whoever
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

namespace sd::cli {
namespace {

struct Options {
  std::string file, into;
  bool json = false;
};

std::string megabytes(std::uint64_t bytes) {
  char text[32];
  std::snprintf(text, sizeof text, "%.1f MB", static_cast<double>(bytes) / 1e6);
  return text;
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
  auto* admin = app.add_subcommand("admin", "Run a lab's home: back it up, restore it, check it");
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

  auto* c = admin->add_subcommand("check", "Check the home: databases, folders, links");
  c->add_flag("--json", o->json, "Print one JSON document");
  c->footer("SQLite's integrity check of every database, every folder the database names present, no project\n"
            "or design folder it does not name, no link anywhere. Exit status 1 when anything is wrong.");
  c->callback([o] { check(*o); });
}};

}  // namespace
}  // namespace sd::cli
