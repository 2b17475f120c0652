#pragma once
// A SwarmDesign home as one archive (a gzip'd POSIX tar, Debian's libarchive), taken while it
// is in use: every SQLite database (the accounts database, each design's design.db) copied
// with SQLite's online backup API, so a database being written is copied as one consistent
// state; every other file as it is (the home replaces files atomically, so a reader sees the
// old file or the new one). The archive ends with manifest.json: the format, every file's
// size and SHA-256, so a restore refuses an archive that was cut short or altered.
#include <cstdint>
#include <filesystem>
#include <stdexcept>
#include <string>
#include <vector>

namespace sd::storage {

/// A backup or restore refused: one line naming what is wrong (never half a home restored).
struct BackupError : std::runtime_error {
  using std::runtime_error::runtime_error;
};

struct ArchivedFile {
  std::string path;  // relative to the home, '/'-separated
  std::uint64_t size = 0;
  std::string sha256;  // hex
};

struct HomeArchive {
  std::vector<ArchivedFile> files;
  std::uint64_t bytes = 0;
  std::string home;  // the absolute folder it was taken from (files name their missions by it)
};

/// Writes `home` (its databases as consistent copies; sockets, locks, WAL side files and the
/// CLI's own session left out) into `archive`, replaced atomically. Symbolic links are not
/// followed and not archived: a home holds none (app::check_home says so).
HomeArchive archive_home(const std::filesystem::path& home, const std::filesystem::path& archive);

/// Unpacks `archive` into `home`, which must not exist or be empty: every file checked
/// against the manifest first (in a folder beside it, moved into place only when all match),
/// folders 0700 and files 0600. BackupError for anything else: not an archive, no manifest,
/// a digest or size that differs, a path that leaves the home or a link.
HomeArchive restore_home(const std::filesystem::path& archive, const std::filesystem::path& home);

}  // namespace sd::storage
