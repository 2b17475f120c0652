#include "storage/sqlite.hpp"

#include <sys/stat.h>

#include <algorithm>
#include <chrono>
#include <thread>

#include "core/private_files.hpp"
#include "storage/power_cut.hpp"

namespace sd::storage {

namespace {
// How long a statement waits for another connection's lock before "database is locked".
constexpr int kBusyTimeoutMilliseconds = 10000;

[[noreturn]] void fail(sqlite3* db, const std::string& what) {
  throw DatabaseError(what + ": " + (db ? sqlite3_errmsg(db) : "out of memory"));
}

// A new database file is in rollback-journal mode until someone switches it to WAL (the
// mode is then stored in the file, and later switches are no-ops that write nothing). The
// switch reads the header under a shared lock, then upgrades to a write lock to rewrite it;
// SQLite never calls the busy handler for such an upgrade (two upgraders would deadlock),
// so when several processes open a fresh home at once, all but one get SQLITE_BUSY at once,
// whatever the busy timeout. The statement has ended then, its shared lock is gone: wait a
// little and retry, within the same timeout as every other statement.
void switch_to_wal(sqlite3* db) {
  using Clock = std::chrono::steady_clock;
  const auto deadline = Clock::now() + std::chrono::milliseconds(kBusyTimeoutMilliseconds);
  auto pause = std::chrono::milliseconds(1);
  while (true) {
    const int rc = sqlite3_exec(db, "PRAGMA journal_mode = WAL", nullptr, nullptr, nullptr);
    if (rc == SQLITE_OK) return;
    if ((rc & 0xff) != SQLITE_BUSY || Clock::now() >= deadline) fail(db, "database error");
    std::this_thread::sleep_for(pause);
    pause = std::min(pause * 2, std::chrono::milliseconds(50));
  }
}
/// The folder of `file` with every link resolved (as given when it cannot be resolved: SQLite
/// then says why it cannot open the file).
std::filesystem::path real_folder(const std::filesystem::path& file) {
  std::error_code ec;
  const std::filesystem::path folder = file.has_parent_path() ? file.parent_path() : std::filesystem::path(".");
  std::filesystem::path real = std::filesystem::canonical(folder, ec);
  return ec ? folder : real;
}

void refuse_a_second_name(const std::filesystem::path& file) {
  struct stat st {};
  if (::lstat(file.c_str(), &st) != 0) return;  // missing: SQLite says so (or creates it)
  if (S_ISLNK(st.st_mode)) throw DatabaseError("cannot open database " + file.string() + ": it is a symbolic link");
  if (S_ISREG(st.st_mode) && st.st_nlink > 1)
    throw DatabaseError("cannot open database " + file.string() + ": the file has another name (a hard link)");
}

}  // namespace

Database::Database(const std::filesystem::path& path, bool create) : path_(path) {
  install_power_cut_if_asked();  // the benchmark's fault injection; a no-op otherwise
  // A database this opens anew is its owner's alone (0600, and so are its -wal and -shm files),
  // whatever the umask and whichever front end creates it: the home's, a design's design.db.
  if (create) create_private_file(path);
  // The file itself, never what a link planted at its name leads to (a design.db linked to
  // another user's): the folder's own path may go through links, the file's name may not
  // (SQLITE_OPEN_NOFOLLOW refuses a link anywhere in the name it is given), and a file with a
  // second name (a hard link, which may be another account's database) is not opened.
  const std::filesystem::path file = real_folder(path) / path.filename();
  refuse_a_second_name(file);
  const int flags = SQLITE_OPEN_READWRITE | (create ? SQLITE_OPEN_CREATE : 0) | SQLITE_OPEN_FULLMUTEX | SQLITE_OPEN_NOFOLLOW;
  if (sqlite3_open_v2(file.c_str(), &db_, flags, nullptr) != SQLITE_OK) {
    const std::string message = "cannot open database " + path.string();
    std::string detail = db_ ? sqlite3_errmsg(db_) : "out of memory";
    sqlite3_close(db_);
    db_ = nullptr;
    throw DatabaseError(message + ": " + detail);
  }
  try {
    sqlite3_busy_timeout(db_, kBusyTimeoutMilliseconds);
    execute("PRAGMA foreign_keys = ON");
    switch_to_wal(db_);
    execute("PRAGMA synchronous = NORMAL");
  } catch (...) {
    sqlite3_close_v2(db_);  // the destructor does not run for a constructor that throws
    db_ = nullptr;
    throw;
  }
}

Database::~Database() { sqlite3_close_v2(db_); }

void Database::execute(std::string_view sql) {
  char* error = nullptr;
  const std::string text(sql);
  if (sqlite3_exec(db_, text.c_str(), nullptr, nullptr, &error) != SQLITE_OK) {
    std::string message = error ? error : "unknown error";
    sqlite3_free(error);
    throw DatabaseError("database error: " + message);
  }
}

Statement Database::prepare(std::string_view sql) { return Statement(db_, sql); }
std::int64_t Database::last_insert_id() const { return sqlite3_last_insert_rowid(db_); }
int Database::changes() const { return sqlite3_changes(db_); }

Statement::Statement(sqlite3* db, std::string_view sql) : db_(db) {
  if (sqlite3_prepare_v2(db_, sql.data(), static_cast<int>(sql.size()), &stmt_, nullptr) != SQLITE_OK)
    fail(db_, "cannot prepare statement");
}

Statement::~Statement() { sqlite3_finalize(stmt_); }
Statement::Statement(Statement&& other) noexcept : db_(other.db_), stmt_(other.stmt_) { other.stmt_ = nullptr; }

Statement& Statement::bind(int index, std::int64_t value) {
  if (sqlite3_bind_int64(stmt_, index, value) != SQLITE_OK) fail(db_, "cannot bind");
  return *this;
}
Statement& Statement::bind(int index, double value) {
  if (sqlite3_bind_double(stmt_, index, value) != SQLITE_OK) fail(db_, "cannot bind");
  return *this;
}
Statement& Statement::bind(int index, std::string_view value) {
  if (sqlite3_bind_text(stmt_, index, value.data(), static_cast<int>(value.size()), SQLITE_TRANSIENT) != SQLITE_OK)
    fail(db_, "cannot bind");
  return *this;
}
Statement& Statement::bind_blob(int index, const void* data, std::size_t size) {
  if (sqlite3_bind_blob64(stmt_, index, data, size, SQLITE_TRANSIENT) != SQLITE_OK) fail(db_, "cannot bind");
  return *this;
}
Statement& Statement::bind_null(int index) {
  if (sqlite3_bind_null(stmt_, index) != SQLITE_OK) fail(db_, "cannot bind");
  return *this;
}

bool Statement::step() {
  const int rc = sqlite3_step(stmt_);
  if (rc == SQLITE_ROW) return true;
  if (rc == SQLITE_DONE) return false;
  fail(db_, "database error");
}

void Statement::run() {
  while (step()) {
  }
  reset();
}

void Statement::reset() {
  sqlite3_reset(stmt_);
  sqlite3_clear_bindings(stmt_);
}

int Statement::column_count() const { return sqlite3_column_count(stmt_); }
bool Statement::is_null(int column) const { return sqlite3_column_type(stmt_, column) == SQLITE_NULL; }
std::int64_t Statement::integer(int column) const { return sqlite3_column_int64(stmt_, column); }
double Statement::real(int column) const { return sqlite3_column_double(stmt_, column); }
std::string Statement::text(int column) const {
  const auto* p = sqlite3_column_text(stmt_, column);
  return p ? std::string(reinterpret_cast<const char*>(p), static_cast<std::size_t>(sqlite3_column_bytes(stmt_, column)))
           : std::string();
}
std::string Statement::blob(int column) const {
  const auto* p = static_cast<const char*>(sqlite3_column_blob(stmt_, column));
  return p ? std::string(p, static_cast<std::size_t>(sqlite3_column_bytes(stmt_, column))) : std::string();
}

Transaction::Transaction(Database& db) : db_(db) { db_.execute("BEGIN IMMEDIATE"); }
Transaction::~Transaction() {
  if (!done_) {
    try {
      db_.execute("ROLLBACK");
    } catch (...) {
    }
  }
}
void Transaction::commit() {
  db_.execute("COMMIT");
  done_ = true;
}

}  // namespace sd::storage
