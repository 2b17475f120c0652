#include "storage/design_store.hpp"

#include <fcntl.h>
#include <sys/file.h>
#include <unistd.h>

#include <cmath>
#include <ctime>

#include "storage/power_cut.hpp"

namespace sd::storage {

namespace {

constexpr const char* kFormat = "swarmdesign-design";

constexpr const char* kSchema = R"sql(
CREATE TABLE meta (key TEXT PRIMARY KEY, value TEXT NOT NULL);
CREATE TABLE configurations (
  id           INTEGER PRIMARY KEY,   -- the engine's id: 1, 2, ...
  parent       INTEGER NOT NULL,      -- elite it was sampled from, 0 for uniform samples
  iteration    INTEGER NOT NULL,      -- iteration that sampled it
  record       TEXT    NOT NULL,      -- exact parameter values (JSON, null = inactive)
  command_line TEXT    NOT NULL       -- the configuration string
);
CREATE TABLE experiments (
  seq              INTEGER PRIMARY KEY,  -- order of the engine's log
  iteration        INTEGER NOT NULL,
  position         INTEGER NOT NULL,     -- position in the instance list (1-based)
  seed             INTEGER NOT NULL,     -- simulation seed of that position
  configuration_id INTEGER NOT NULL REFERENCES configurations(id),
  cost             REAL,                 -- lower is better; NULL for NaN
  UNIQUE (configuration_id, position)    -- a result is never counted twice
);
CREATE TABLE races (
  iteration      INTEGER PRIMARY KEY,
  race_budget    INTEGER NOT NULL,
  configurations INTEGER NOT NULL
);
CREATE TABLE race_configurations (
  iteration        INTEGER NOT NULL REFERENCES races(iteration),
  configuration_id INTEGER NOT NULL REFERENCES configurations(id),
  elite            INTEGER NOT NULL,     -- 1: an elite of the previous iteration
  eliminated_after INTEGER,              -- instances seen when dropped; NULL: survived
  PRIMARY KEY (iteration, configuration_id)
);
CREATE TABLE elites (
  iteration        INTEGER NOT NULL,
  rank             INTEGER NOT NULL,
  configuration_id INTEGER NOT NULL REFERENCES configurations(id),
  PRIMARY KEY (iteration, rank)
);
CREATE TABLE checkpoint (
  id       INTEGER PRIMARY KEY CHECK (id = 1),
  step     INTEGER NOT NULL,
  phase    TEXT    NOT NULL,
  state    TEXT    NOT NULL,
  saved_at INTEGER NOT NULL
);
)sql";

std::string where(const std::filesystem::path& folder) { return folder.string(); }

std::unique_ptr<Database> open_database(const std::filesystem::path& folder, bool create) {
  try {
    return std::make_unique<Database>(DesignStore::file_in(folder), create);
  } catch (const DatabaseError& e) {
    throw DesignFolderError(where(folder) + "/design.db is damaged or not a database (" + e.what() + ")");
  }
}

std::string meta_value(Database& db, const std::string& key) {
  auto q = db.prepare("SELECT value FROM meta WHERE key = ?");
  q.bind(1, key);
  if (!q.step()) throw DesignFolderError("meta '" + key + "' is missing");
  return q.text(0);
}

std::int64_t to_int(const std::string& text, const std::string& key) {
  try {
    std::size_t used = 0;
    const long long v = std::stoll(text, &used);
    if (used != text.size()) throw std::invalid_argument(key);
    return v;
  } catch (const std::exception&) {
    throw DesignFolderError("meta '" + key + "' is not a number");
  }
}

void bind_cost(Statement& s, int index, double cost) {
  if (std::isnan(cost)) s.bind_null(index);
  else s.bind(index, cost);
}

/// fsync, best effort: a file system that cannot sync a folder still gets the rename.
void sync_file(const std::filesystem::path& path) {
  const int fd = ::open(path.c_str(), O_RDONLY | O_CLOEXEC);
  if (fd < 0) return;
  ::fsync(fd);
  ::close(fd);
}

void rollback(Database& db) {
  try {
    db.execute("ROLLBACK");
  } catch (const DatabaseError&) {  // no transaction open any more
  }
}

}  // namespace

DesignRunLock::DesignRunLock(const std::filesystem::path& folder) {
  const auto path = folder / "design.lock";
  fd_ = ::open(path.c_str(), O_RDWR | O_CREAT | O_CLOEXEC, 0600);
  if (fd_ < 0) throw DesignFolderError("cannot create " + path.string());
  if (::flock(fd_, LOCK_EX | LOCK_NB) != 0) {
    ::close(fd_);
    throw DesignFolderError("the design in " + where(folder) + " is being run by another process");
  }
}

DesignRunLock::~DesignRunLock() { ::close(fd_); }

DesignStore::DesignStore(std::filesystem::path folder, std::unique_ptr<Database> db)
    : folder_(std::move(folder)), db_(std::move(db)) {}

DesignStore DesignStore::create(const std::filesystem::path& folder, const DesignMeta& meta) {
  if (std::filesystem::exists(file_in(folder)))
    throw DesignFolderError(where(folder) + " already holds a design; continue it with --resume " + where(folder));
  std::filesystem::create_directories(folder);
  // Written whole under another name, then renamed: a design.db always has its schema and
  // meta, so a process killed while creating it leaves a folder that starts anew, not a
  // design.db that every resume refuses ("no meta table").
  const std::filesystem::path draft = folder / "design.db.new";
  PowerCutWindow power_cut;  // the tests' and the benchmark's kill inside this write; nothing otherwise
  for (const char* suffix : {"", "-wal", "-shm", "-journal"}) std::filesystem::remove(draft.string() + suffix);
  try {
    Database db(draft, true);  // created 0600: a design's race data is its owner's alone
    Transaction t(db);
    db.execute(kSchema);
    auto put = db.prepare("INSERT INTO meta (key, value) VALUES (?, ?)");
    const auto set = [&](const char* key, const std::string& value) {
      put.bind(1, key).bind(2, value);
      put.run();
    };
    set("format", kFormat);
    set("format_version", std::to_string(kDesignFormatVersion));
    set("mission", meta.mission);
    set("direction", meta.direction);
    set("budget", std::to_string(meta.budget));
    set("architectures", meta.architectures);
    set("flavours", meta.flavours);
    set("seed", std::to_string(meta.seed));
    set("fingerprint", meta.fingerprint);
    set("mission_digest", meta.mission_digest);
    set("results_version", std::to_string(meta.results_version));
    if (meta.method != "automode") set("method", meta.method);  // an AutoMoDe design's reads as before
    if (!meta.pseudo_reality.empty()) {
      set("pseudo_reality", meta.pseudo_reality);
      set("pseudo_reality_document", meta.pseudo_reality_document);
      set("pseudo_reality_samples", meta.pseudo_reality_samples);
    }
    set("created_at", std::to_string(std::time(nullptr)));
    t.commit();
    db.execute("PRAGMA wal_checkpoint(TRUNCATE)");  // everything in the main file before it is renamed
  } catch (const DatabaseError& e) {
    throw DesignFolderError("cannot create " + draft.string() + " (" + e.what() + ")");
  }
  // Closed, its write-ahead log is folded in and removed; what is left must be the whole design.
  std::error_code ignored;
  if (std::filesystem::file_size(draft.string() + "-wal", ignored) > 0 && !ignored)
    throw DesignFolderError("cannot create " + draft.string() + " (its write-ahead log stayed behind)");
  sync_file(draft);
  if (::rename(draft.c_str(), file_in(folder).c_str()) != 0)
    throw DesignFolderError("cannot rename " + draft.string() + " to " + file_in(folder).string());
  sync_file(folder);  // the rename itself
  power_cut.committed();
  DesignStore store(folder, open_database(folder, false));
  store.meta_ = meta;
  return store;
}

DesignStore DesignStore::open(const std::filesystem::path& folder, bool check_integrity) {
  if (!std::filesystem::is_directory(folder)) throw DesignFolderError(where(folder) + " is not a folder");
  if (!std::filesystem::exists(file_in(folder)))
    throw DesignFolderError(where(folder) + " is not a design folder (it has no design.db)");
  DesignStore store(folder, open_database(folder, false));
  try {
    if (check_integrity) {
      auto check = store.db_->prepare("PRAGMA quick_check");
      if (!check.step() || check.text(0) != "ok") throw DesignFolderError("integrity check failed");
    }
    auto has_meta = store.db_->prepare("SELECT count(*) FROM sqlite_master WHERE type = 'table' AND name = 'meta'");
    has_meta.step();
    if (has_meta.integer(0) == 0) throw DesignFolderError("no meta table");
    store.read_meta();
  } catch (const DesignFolderError& e) {
    throw DesignFolderError(where(folder) + "/design.db is not a SwarmDesign design database (" + e.what() + ")");
  } catch (const DatabaseError& e) {
    throw DesignFolderError(where(folder) + "/design.db is damaged (" + e.what() + ")");
  }
  return store;
}

void DesignStore::read_meta() {
  Database& db = *db_;
  if (meta_value(db, "format") != kFormat) throw DesignFolderError("format '" + meta_value(db, "format") + "'");
  const auto version = to_int(meta_value(db, "format_version"), "format_version");
  if (version != kDesignFormatVersion)
    throw DesignFolderError("format version " + std::to_string(version) + "; this swarmdesign reads version " +
                            std::to_string(kDesignFormatVersion));
  meta_.mission = meta_value(db, "mission");
  meta_.direction = meta_value(db, "direction");
  meta_.budget = to_int(meta_value(db, "budget"), "budget");
  meta_.architectures = meta_value(db, "architectures");
  meta_.flavours = meta_value(db, "flavours");
  meta_.seed = static_cast<std::uint64_t>(std::stoull(meta_value(db, "seed")));
  meta_.fingerprint = meta_value(db, "fingerprint");
  auto digest = db.prepare("SELECT value FROM meta WHERE key = 'mission_digest'");
  meta_.mission_digest = digest.step() ? digest.text(0) : "";  // absent in older designs
  auto results = db.prepare("SELECT value FROM meta WHERE key = 'results_version'");
  meta_.results_version = results.step() ? static_cast<int>(to_int(results.text(0), "results_version")) : 1;  // absent before 2
  const auto optional_value = [&](const char* key) {
    auto row = db.prepare("SELECT value FROM meta WHERE key = ?");
    row.bind(1, key);
    return row.step() ? row.text(0) : std::string();
  };
  meta_.pseudo_reality = optional_value("pseudo_reality");  // absent: the design model alone
  meta_.pseudo_reality_document = optional_value("pseudo_reality_document");
  meta_.pseudo_reality_samples = optional_value("pseudo_reality_samples");
  const std::string method = optional_value("method");
  meta_.method = method.empty() ? "automode" : method;
  auto step = db.prepare("SELECT step FROM checkpoint WHERE id = 1");
  step_ = step.step() ? step.integer(0) : 0;
  auto elites = db.prepare("SELECT count(DISTINCT iteration) FROM elites");
  elites.step();
  elite_iterations_ = static_cast<std::size_t>(elites.integer(0));
  auto races = db.prepare("SELECT coalesce(max(iteration), 0) FROM races");
  races.step();
  race_logged_ = static_cast<int>(races.integer(0));
}

void DesignStore::append(const CheckpointRows& rows) {
  Database& db = *db_;
  PowerCutWindow power_cut;  // the crash-loop benchmark's torn write; nothing otherwise
  Transaction t(db);
  auto config = db.prepare(
      "INSERT INTO configurations (id, parent, iteration, record, command_line) VALUES (?, ?, ?, ?, ?)");
  for (const auto& c : rows.configurations) {
    config.bind(1, c.id).bind(2, c.parent).bind(3, c.iteration).bind(4, c.record).bind(5, c.command_line);
    config.run();
  }
  auto experiment = db.prepare(
      "INSERT INTO experiments (seq, iteration, position, seed, configuration_id, cost) VALUES (?, ?, ?, ?, ?, ?)");
  for (const auto& e : rows.experiments) {
    experiment.bind(1, e.seq).bind(2, e.iteration).bind(3, e.position).bind(4, e.seed).bind(5, e.configuration_id);
    bind_cost(experiment, 6, e.cost);
    experiment.run();
  }
  if (rows.race) {
    db.prepare("INSERT INTO races (iteration, race_budget, configurations) VALUES (?, ?, ?)")
        .bind(1, rows.race->iteration).bind(2, rows.race->race_budget)
        .bind(3, static_cast<std::int64_t>(rows.race->members.size())).run();
    auto member = db.prepare(
        "INSERT INTO race_configurations (iteration, configuration_id, elite, eliminated_after) VALUES (?, ?, ?, NULL)");
    for (const auto& [id, elite] : rows.race->members) {
      member.bind(1, rows.race->iteration).bind(2, id).bind(3, elite ? 1 : 0);
      member.run();
    }
  }
  auto dropped = db.prepare(
      "UPDATE race_configurations SET eliminated_after = ? WHERE iteration = ? AND configuration_id = ?");
  for (const auto& e : rows.eliminations) {
    dropped.bind(1, e.after_instances).bind(2, e.iteration).bind(3, e.configuration_id);
    dropped.run();
  }
  auto elite = db.prepare("INSERT INTO elites (iteration, rank, configuration_id) VALUES (?, ?, ?)");
  std::size_t iteration = elite_iterations_;
  for (const auto& ids : rows.new_elites) {
    ++iteration;
    for (std::size_t rank = 0; rank < ids.size(); ++rank) {
      elite.bind(1, static_cast<std::int64_t>(iteration)).bind(2, static_cast<std::int64_t>(rank + 1)).bind(3, ids[rank]);
      elite.run();
    }
  }
  db.prepare("INSERT OR REPLACE INTO checkpoint (id, step, phase, state, saved_at) VALUES (1, ?, ?, ?, ?)")
      .bind(1, step_ + 1).bind(2, rows.phase).bind(3, rows.state)
      .bind(4, static_cast<std::int64_t>(std::time(nullptr))).run();
  t.commit();
  power_cut.committed();
  // Counted only once the rows are durable: a failed write leaves the store as it was.
  ++step_;
  elite_iterations_ = iteration;
  if (rows.race) race_logged_ = rows.race->iteration;
}

std::optional<StoredCheckpoint> DesignStore::load() {
  Database& db = *db_;
  try {
    db.execute("BEGIN");  // one snapshot for the state and its history
    auto q = db.prepare("SELECT state FROM checkpoint WHERE id = 1");
    if (!q.step()) {
      db.execute("COMMIT");
      return std::nullopt;
    }
    StoredCheckpoint stored;
    stored.state = q.text(0);
    auto configs = db.prepare("SELECT id, parent, record FROM configurations ORDER BY id");
    while (configs.step())
      stored.configurations.push_back(
          {static_cast<int>(configs.integer(0)), static_cast<int>(configs.integer(1)), 0, configs.text(2), ""});
    auto log = db.prepare("SELECT seq, iteration, position, configuration_id, cost FROM experiments ORDER BY seq");
    while (log.step())
      stored.experiments.push_back({log.integer(0), static_cast<int>(log.integer(1)), log.integer(2), 0,
                                    static_cast<int>(log.integer(3)), log.is_null(4) ? std::nan("") : log.real(4)});
    db.execute("COMMIT");
    return stored;
  } catch (const DatabaseError& e) {
    rollback(db);
    throw DesignFolderError(where(folder_) + "/design.db is damaged (" + e.what() + ")");
  }
}

}  // namespace sd::storage
