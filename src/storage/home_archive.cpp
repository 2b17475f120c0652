#include "storage/home_archive.hpp"

#include <archive.h>
#include <archive_entry.h>
#include <fcntl.h>
#include <sodium.h>
#include <sqlite3.h>
#include <sys/stat.h>
#include <unistd.h>

#include <array>
#include <cerrno>
#include <system_error>
#include <map>
#include <memory>
#include <nlohmann/json.hpp>

#include "storage/sodium.hpp"

namespace sd::storage {

namespace fs = std::filesystem;

namespace {

constexpr const char* kManifest = "manifest.json";
constexpr const char* kFormat = "swarmdesign-home-backup";
constexpr int kFormatVersion = 1;
// Bounds on what a restore unpacks, so an archive cannot fill the disk behind the check.
constexpr std::uint64_t kMaxRestoreBytes = 256ULL << 30;
constexpr std::size_t kMaxRestoreFiles = 1'000'000;
constexpr std::size_t kChunk = 1 << 16;

class Sha256 {
 public:
  Sha256() {
    ensure_sodium();
    crypto_hash_sha256_init(&state_);
  }
  void add(const void* data, std::size_t size) {
    crypto_hash_sha256_update(&state_, static_cast<const unsigned char*>(data), size);
  }
  std::string hex() {
    std::array<unsigned char, crypto_hash_sha256_BYTES> digest{};
    crypto_hash_sha256_final(&state_, digest.data());
    std::array<char, 2 * crypto_hash_sha256_BYTES + 1> text{};
    sodium_bin2hex(text.data(), text.size(), digest.data(), digest.size());
    return text.data();
  }

 private:
  crypto_hash_sha256_state state_{};
};

/// What a backup leaves out: the CLI's signed-in session (a restored home signs in afresh),
/// design locks, SQLite's WAL side files (the database copy holds their pages) and the
/// temporaries of writes in flight.
bool left_out(const fs::path& relative) {
  const std::string name = relative.filename().string();
  if (relative == "session") return true;
  if (name.ends_with(".lock") || name.ends_with("-wal") || name.ends_with("-shm") || name.ends_with("-journal")) return true;
  return name.find(".tmp-") != std::string::npos;
}

bool is_database(const fs::path& p) { return p.extension() == ".db"; }

/// `from` as one consistent state in `to`, while other connections may be writing it.
void snapshot_database(const fs::path& from, const fs::path& to) {
  sqlite3* source = nullptr;
  sqlite3* target = nullptr;
  const auto close = [&] {
    sqlite3_close(source);
    sqlite3_close(target);
  };
  if (sqlite3_open_v2(from.c_str(), &source, SQLITE_OPEN_READWRITE, nullptr) != SQLITE_OK ||
      sqlite3_open_v2(to.c_str(), &target, SQLITE_OPEN_READWRITE | SQLITE_OPEN_CREATE, nullptr) != SQLITE_OK) {
    const std::string why = sqlite3_errmsg(source ? source : target);
    close();
    throw BackupError("cannot copy the database " + from.filename().string() + ": " + why);
  }
  sqlite3_busy_timeout(source, 10'000);
  sqlite3_backup* copy = sqlite3_backup_init(target, "main", source, "main");
  int rc = copy ? SQLITE_OK : SQLITE_ERROR;
  while (copy && (rc = sqlite3_backup_step(copy, -1)) != SQLITE_DONE) {
    if (rc != SQLITE_BUSY && rc != SQLITE_LOCKED && rc != SQLITE_OK) break;
    sqlite3_sleep(50);
  }
  if (copy) sqlite3_backup_finish(copy);
  if (rc != SQLITE_DONE) {
    const std::string why = sqlite3_errmsg(target);
    close();
    throw BackupError("cannot copy the database " + from.filename().string() + ": " + why);
  }
  close();
}

struct ArchiveWriter {
  archive* a = archive_write_new();
  ~ArchiveWriter() { archive_write_free(a); }
  void check(int rc, const std::string& what) const {
    if (rc < ARCHIVE_WARN) throw BackupError("cannot write the backup (" + what + "): " + archive_error_string(a));
  }
};

struct ArchiveReader {
  archive* a = archive_read_new();
  ~ArchiveReader() { archive_read_free(a); }
};

/// Adds the regular file at `file` as `name`, its digest taken from the bytes written.
ArchivedFile add_file(ArchiveWriter& w, const fs::path& file, const std::string& name) {
  const int fd = ::open(file.c_str(), O_RDONLY | O_NOFOLLOW | O_CLOEXEC);
  if (fd < 0) throw BackupError("cannot read " + name + ": " + std::generic_category().message(errno));
  const std::unique_ptr<int, void (*)(int*)> guard(new int(fd), [](int* f) { ::close(*f); delete f; });
  struct stat st {};
  if (::fstat(fd, &st) != 0 || !S_ISREG(st.st_mode)) throw BackupError("cannot read " + name + ": not a regular file");
  archive_entry* entry = archive_entry_new();
  archive_entry_set_pathname(entry, name.c_str());
  archive_entry_set_size(entry, st.st_size);
  archive_entry_set_filetype(entry, AE_IFREG);
  archive_entry_set_perm(entry, 0600);
  archive_entry_set_mtime(entry, st.st_mtim.tv_sec, 0);
  const int rc = archive_write_header(w.a, entry);
  archive_entry_free(entry);
  w.check(rc, name);
  // The size in the header is the file's when opened: exactly that many bytes are written.
  ArchivedFile out{name, static_cast<std::uint64_t>(st.st_size), {}};
  Sha256 hash;
  std::vector<char> buffer(kChunk);
  std::uint64_t left = out.size;
  while (left > 0) {
    const ssize_t n = ::read(fd, buffer.data(), static_cast<std::size_t>(std::min<std::uint64_t>(left, kChunk)));
    if (n <= 0) throw BackupError("cannot read " + name + ": it shrank while being copied");
    hash.add(buffer.data(), static_cast<std::size_t>(n));
    if (archive_write_data(w.a, buffer.data(), static_cast<std::size_t>(n)) != n) w.check(ARCHIVE_FATAL, name);
    left -= static_cast<std::uint64_t>(n);
  }
  out.sha256 = hash.hex();
  return out;
}

void add_text(ArchiveWriter& w, const std::string& name, const std::string& text) {
  archive_entry* entry = archive_entry_new();
  archive_entry_set_pathname(entry, name.c_str());
  archive_entry_set_size(entry, static_cast<la_int64_t>(text.size()));
  archive_entry_set_filetype(entry, AE_IFREG);
  archive_entry_set_perm(entry, 0600);
  const int rc = archive_write_header(w.a, entry);
  archive_entry_free(entry);
  w.check(rc, name);
  if (archive_write_data(w.a, text.data(), text.size()) != static_cast<la_ssize_t>(text.size())) w.check(ARCHIVE_FATAL, name);
}

/// A name from the archive as a path inside the home, or empty when it would leave it.
fs::path inside(const std::string& name) {
  fs::path p(name);
  if (name.empty() || p.is_absolute()) return {};
  for (const auto& part : p)
    if (part == ".." || part == "." || part.empty()) return {};
  return p;
}

}  // namespace

HomeArchive archive_home(const fs::path& home, const fs::path& archive_path) {
  if (!fs::is_directory(home)) throw BackupError("no SwarmDesign home at " + home.string());
  const fs::path scratch = archive_path.parent_path() / (archive_path.filename().string() + ".tmp-" + std::to_string(::getpid()));
  const fs::path snapshots = scratch.string() + "-db";
  fs::remove_all(snapshots);
  fs::create_directories(snapshots);
  HomeArchive out;
  out.home = fs::absolute(home).lexically_normal().string();
  try {
    ArchiveWriter w;
    w.check(archive_write_add_filter_gzip(w.a), "gzip");
    w.check(archive_write_set_format_pax_restricted(w.a), "tar");
    // O_EXCL through libarchive's own open: the temporary must be new.
    const int fd = ::open(scratch.c_str(), O_WRONLY | O_CREAT | O_EXCL | O_CLOEXEC | O_NOFOLLOW, 0600);
    if (fd < 0) throw BackupError("cannot write " + archive_path.string() + ": " + std::generic_category().message(errno));
    if (archive_write_open_fd(w.a, fd) != ARCHIVE_OK) {
      ::close(fd);
      w.check(ARCHIVE_FATAL, "open");
    }
    // The accounts database first: every folder it names was made before it was copied.
    std::vector<fs::path> files;
    for (auto it = fs::recursive_directory_iterator(home); it != fs::recursive_directory_iterator(); ++it)
      if (it->symlink_status().type() == fs::file_type::regular) files.push_back(it->path().lexically_relative(home));
    std::sort(files.begin(), files.end(), [](const fs::path& a, const fs::path& b) {
      return (a != "swarmdesign.db") != (b != "swarmdesign.db") ? a == "swarmdesign.db" : a < b;
    });
    std::size_t copies = 0;
    for (const fs::path& relative : files) {
      if (left_out(relative)) continue;
      const std::string name = relative.generic_string();
      if (is_database(relative)) {
        const fs::path copy = snapshots / (std::to_string(copies++) + ".db");
        snapshot_database(home / relative, copy);
        out.files.push_back(add_file(w, copy, name));
        fs::remove(copy);
      } else {
        out.files.push_back(add_file(w, home / relative, name));
      }
      out.bytes += out.files.back().size;
    }
    nlohmann::json manifest = {{"format", kFormat}, {"version", kFormatVersion}, {"home", out.home}, {"files", nlohmann::json::array()}};
    for (const ArchivedFile& f : out.files)
      manifest["files"].push_back({{"path", f.path}, {"size", f.size}, {"sha256", f.sha256}});
    add_text(w, kManifest, manifest.dump(1));
    w.check(archive_write_close(w.a), "close");
    const int sync = ::open(scratch.c_str(), O_RDONLY | O_CLOEXEC);
    if (sync >= 0) {
      ::fsync(sync);
      ::close(sync);
    }
    fs::rename(scratch, archive_path);
  } catch (...) {
    fs::remove(scratch);
    fs::remove_all(snapshots);
    throw;
  }
  fs::remove_all(snapshots);
  return out;
}

HomeArchive restore_home(const fs::path& archive_path, const fs::path& home) {
  std::error_code ec;
  if (fs::exists(home, ec) && !fs::is_empty(home, ec))
    throw BackupError("restore: " + home.string() + " is not empty; restore into a new home");
  const fs::path staging = home.string() + ".restoring-" + std::to_string(::getpid());
  fs::remove_all(staging);
  fs::create_directories(staging);
  fs::permissions(staging, fs::perms::owner_all, fs::perm_options::replace);
  HomeArchive out;
  try {
    ArchiveReader r;
    archive_read_support_filter_gzip(r.a);
    archive_read_support_format_tar(r.a);
    if (archive_read_open_filename(r.a, archive_path.c_str(), kChunk) != ARCHIVE_OK)
      throw BackupError("restore: cannot read " + archive_path.string() + ": " + archive_error_string(r.a));
    std::map<std::string, ArchivedFile> unpacked;
    nlohmann::json manifest;
    archive_entry* entry = nullptr;
    std::vector<char> buffer(kChunk);
    std::uint64_t total = 0;
    int rc;
    while ((rc = archive_read_next_header(r.a, &entry)) == ARCHIVE_OK) {
      const std::string name = archive_entry_pathname(entry) ? archive_entry_pathname(entry) : "";
      if (archive_entry_filetype(entry) != AE_IFREG)
        throw BackupError("restore: " + name + " is not a regular file: a backup holds no link, device or folder entry");
      const fs::path relative = inside(name);
      if (relative.empty()) throw BackupError("restore: the archive names a path outside the home: " + name);
      if (unpacked.count(name) || (name == kManifest && !manifest.is_null()))
        throw BackupError("restore: " + name + " is in the archive twice");
      if (unpacked.size() >= kMaxRestoreFiles) throw BackupError("restore: more than a million files: not a SwarmDesign backup");
      std::string text;  // the manifest, kept in memory (bounded below)
      const bool is_manifest = name == kManifest;
      int fd = -1;
      if (!is_manifest) {
        fs::create_directories((staging / relative).parent_path());
        fd = ::open((staging / relative).c_str(), O_WRONLY | O_CREAT | O_EXCL | O_CLOEXEC | O_NOFOLLOW, 0600);
        if (fd < 0) throw BackupError("restore: cannot write " + name + ": " + std::generic_category().message(errno));
      }
      Sha256 hash;
      std::uint64_t size = 0;
      la_ssize_t n;
      while ((n = archive_read_data(r.a, buffer.data(), buffer.size())) > 0) {
        size += static_cast<std::uint64_t>(n);
        total += static_cast<std::uint64_t>(n);
        if (total > kMaxRestoreBytes) {
          if (fd >= 0) ::close(fd);
          throw BackupError("restore: more than 256 GiB unpacked: not a SwarmDesign backup");
        }
        hash.add(buffer.data(), static_cast<std::size_t>(n));
        if (is_manifest) {
          if (text.size() + static_cast<std::size_t>(n) > (64U << 20)) throw BackupError("restore: the manifest is larger than 64 MiB");
          text.append(buffer.data(), static_cast<std::size_t>(n));
        } else if (::write(fd, buffer.data(), static_cast<std::size_t>(n)) != n) {
          ::close(fd);
          throw BackupError("restore: cannot write " + name + ": " + std::generic_category().message(errno));
        }
      }
      if (fd >= 0) {
        ::fsync(fd);
        ::close(fd);
      }
      if (n < 0) throw BackupError("restore: the archive is damaged at " + name + ": " + archive_error_string(r.a));
      if (is_manifest) {
        manifest = nlohmann::json::parse(text, nullptr, false);
        if (manifest.is_discarded()) throw BackupError("restore: the archive's manifest is not JSON");
      } else {
        unpacked[name] = {name, size, hash.hex()};
      }
    }
    if (rc != ARCHIVE_EOF) throw BackupError("restore: the archive is damaged: " + std::string(archive_error_string(r.a)));
    if (!manifest.is_object() || manifest.value("format", "") != kFormat)
      throw BackupError("restore: " + archive_path.filename().string() + " is not a SwarmDesign backup (no manifest)");
    if (manifest.value("version", 0) != kFormatVersion)
      throw BackupError("restore: backup format version " + manifest["version"].dump() + ", this swarmdesign reads 1");
    const auto& listed = manifest.at("files");
    if (!listed.is_array() || listed.size() != unpacked.size())
      throw BackupError("restore: the archive holds other files than its manifest lists: it is damaged");
    for (const auto& f : listed) {
      const std::string path = f.value("path", "");
      const auto it = unpacked.find(path);
      if (it == unpacked.end()) throw BackupError("restore: " + path + " is missing from the archive: it is damaged");
      if (it->second.size != f.value("size", std::uint64_t{0}) || it->second.sha256 != f.value("sha256", ""))
        throw BackupError("restore: " + path + " differs from the manifest's digest: the archive is damaged");
      out.files.push_back(it->second);
      out.bytes += it->second.size;
    }
    if (!unpacked.count("swarmdesign.db")) throw BackupError("restore: the archive has no swarmdesign.db: not a home's backup");
    out.home = manifest.value("home", "");
    // Every folder the server's way: only its own Unix user may enter.
    for (auto it = fs::recursive_directory_iterator(staging); it != fs::recursive_directory_iterator(); ++it)
      if (it->is_directory()) fs::permissions(it->path(), fs::perms::owner_all, fs::perm_options::replace);
    if (fs::exists(home)) fs::remove(home);  // empty, checked above
    fs::rename(staging, home);
  } catch (...) {
    fs::remove_all(staging, ec);
    throw;
  }
  return out;
}

}  // namespace sd::storage
