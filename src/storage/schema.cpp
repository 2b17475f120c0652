#include "storage/schema.hpp"

#include <algorithm>
#include <array>
#include <cstdint>
#include <string>

namespace sd::storage {

namespace {

// Append-only: a released migration never changes; a new schema is a new entry.
// Times are Unix seconds (UTC). Paths are relative to the SwarmDesign home, so a home can
// be moved or copied as a whole.
constexpr std::array kMigrations = {
    // 1: accounts, sessions, projects, cluster connections, designs.
    R"sql(
CREATE TABLE users (
  id            INTEGER PRIMARY KEY,
  name          TEXT    NOT NULL UNIQUE COLLATE NOCASE,
  -- libsodium crypto_pwhash_str output; never the password itself.
  password_hash TEXT    NOT NULL CHECK (password_hash LIKE '$argon2id$%'),
  created_at    INTEGER NOT NULL
);

-- A signed-in session: only a BLAKE2b-256 hash of the random token is stored; the token
-- itself sits in a 0600 file in the home.
CREATE TABLE sessions (
  id         INTEGER PRIMARY KEY,
  user_id    INTEGER NOT NULL REFERENCES users(id) ON DELETE CASCADE,
  token_hash BLOB    NOT NULL UNIQUE CHECK (length(token_hash) = 32),
  created_at INTEGER NOT NULL,
  expires_at INTEGER NOT NULL CHECK (expires_at > created_at)
);
CREATE INDEX sessions_by_user ON sessions(user_id);

CREATE TABLE cluster_connections (
  id        INTEGER PRIMARY KEY,
  owner_id  INTEGER NOT NULL REFERENCES users(id) ON DELETE CASCADE,
  host      TEXT    NOT NULL CHECK (host <> ''),
  user_name TEXT    NOT NULL CHECK (user_name <> ''),
  UNIQUE (owner_id, host, user_name)
);

CREATE TABLE projects (
  id         INTEGER PRIMARY KEY,
  owner_id   INTEGER NOT NULL REFERENCES users(id) ON DELETE CASCADE,
  name       TEXT    NOT NULL COLLATE NOCASE,
  path       TEXT    NOT NULL,              -- the project folder, relative to the home
  mission    TEXT,                          -- catalogue name or absolute path of a mission file
  budget     INTEGER CHECK (budget IS NULL OR budget > 0),  -- simulation runs
  location   TEXT    NOT NULL CHECK (location IN ('local', 'cluster')),
  cluster_id INTEGER REFERENCES cluster_connections(id),
  created_at INTEGER NOT NULL,
  UNIQUE (owner_id, name),
  UNIQUE (id, owner_id),                    -- target of active_projects' ownership check
  CHECK ((location = 'cluster') = (cluster_id IS NOT NULL))
);

-- The project each user works on. The composite key makes it impossible, even by a bug,
-- to make another user's project someone's active one.
CREATE TABLE active_projects (
  user_id    INTEGER PRIMARY KEY REFERENCES users(id) ON DELETE CASCADE,
  project_id INTEGER NOT NULL,
  FOREIGN KEY (project_id, user_id) REFERENCES projects(id, owner_id) ON DELETE CASCADE
);

-- One design process of a project. Its settings are copied from the project when it
-- starts, so later set-mission / set-budget do not rewrite history. The race itself
-- (iterations, experiments, elites, log) lives in the design's own folder, in its own
-- SQLite file written by the optimiser; `status` reads the state here and the progress there.
CREATE TABLE designs (
  id            INTEGER PRIMARY KEY,
  project_id    INTEGER NOT NULL REFERENCES projects(id) ON DELETE CASCADE,
  architectures TEXT    NOT NULL CHECK (architectures <> ''),  -- e.g. 'fsm,bt'
  flavours      TEXT    NOT NULL CHECK (flavours <> ''),       -- e.g. 'chocolate,maple'
  mission       TEXT    NOT NULL,
  budget        INTEGER NOT NULL CHECK (budget > 0),
  seed          INTEGER NOT NULL,
  state         TEXT    NOT NULL DEFAULT 'running'
                CHECK (state IN ('running', 'finished', 'failed', 'interrupted')),
  pid           INTEGER,                 -- process running it, to tell a killed design
  path          TEXT    NOT NULL,        -- the design's folder (race data), relative to the home
  best_config   TEXT,                    -- best control software when finished
  best_score    REAL,
  created_at    INTEGER NOT NULL,
  updated_at    INTEGER NOT NULL,
  finished_at   INTEGER
);
CREATE INDEX designs_by_project ON designs(project_id, id);
-- At most one running design per project: a second run-design fails here, atomically.
CREATE UNIQUE INDEX one_running_design_per_project ON designs(project_id) WHERE state = 'running';
)sql",
    // 2: a pid alone cannot tell a design's process from one that got the same pid later
    // (after a reboot, say), so the process's boot and start time are kept with it.
    R"sql(
ALTER TABLE designs ADD COLUMN process TEXT;  -- '<boot id>/<start time>'; NULL in older rows
)sql",
    // 3: a design is owned by a job through a lease (storage/lease.hpp), not by a local pid, so
    // that a server thread or a cluster job on another node can own one.
    R"sql(
ALTER TABLE designs ADD COLUMN owner TEXT;            -- '<boot id>/<start time>/<pid>/<job>'
ALTER TABLE designs ADD COLUMN heartbeat_at INTEGER;  -- Unix seconds of the owner's last renewal
UPDATE designs SET owner = process || '/' || coalesce(pid, 0) || '/cli', heartbeat_at = updated_at
  WHERE process IS NOT NULL;
)sql",
    // 4: experiments: a protocol run as many designs, each assessed on fresh seeds.
    // A design's race lives in its folder, as for `designs`; what the report needs is here.
    R"sql(
CREATE TABLE experiments (
  id           INTEGER PRIMARY KEY,
  project_id   INTEGER NOT NULL REFERENCES projects(id) ON DELETE CASCADE,
  name         TEXT    NOT NULL COLLATE NOCASE CHECK (name <> ''),
  protocol     TEXT    NOT NULL,          -- the protocol as run (JSON), with the command line's changes
  state        TEXT    NOT NULL DEFAULT 'running'
               CHECK (state IN ('running', 'finished', 'failed', 'interrupted')),
  owner        TEXT    NOT NULL,          -- lease, as for designs (storage/lease.hpp)
  heartbeat_at INTEGER NOT NULL,
  path         TEXT    NOT NULL,          -- its folder, relative to the home
  created_at   INTEGER NOT NULL,
  updated_at   INTEGER NOT NULL,
  finished_at  INTEGER,
  UNIQUE (project_id, name)
);

-- One design of the protocol: a mission, a condition, a replicate. Stages go pending ->
-- designing -> assessing -> done; each step is written when it is durable.
CREATE TABLE experiment_designs (
  id            INTEGER PRIMARY KEY,
  experiment_id INTEGER NOT NULL REFERENCES experiments(id) ON DELETE CASCADE,
  mission       TEXT    NOT NULL,
  condition     TEXT    NOT NULL,
  replicate     INTEGER NOT NULL CHECK (replicate >= 1),
  method        TEXT    NOT NULL CHECK (method IN ('automode', 'evostick')),
  architectures TEXT    NOT NULL,
  flavours      TEXT    NOT NULL,
  budget        INTEGER NOT NULL CHECK (budget > 0),
  seed          INTEGER NOT NULL,
  stage         TEXT    NOT NULL DEFAULT 'pending'
                CHECK (stage IN ('pending', 'designing', 'assessing', 'done')),
  configuration TEXT,                     -- the final control software
  design_score  REAL,                     -- the optimiser's estimate of it
  runs_used     INTEGER,
  wall_seconds  REAL    NOT NULL DEFAULT 0,  -- designing and assessing, summed over resumptions
  -- The same design (mission, method, space, budget, seed) already made by another experiment
  -- of the project: runs are deterministic, so its result is taken instead of made again.
  reused_from   INTEGER REFERENCES experiment_designs(id) ON DELETE SET NULL,
  UNIQUE (experiment_id, mission, condition, replicate)
);

-- Best estimated score against runs used, after every race step (convergence curves).
CREATE TABLE experiment_progress (
  design_id  INTEGER NOT NULL REFERENCES experiment_designs(id) ON DELETE CASCADE,
  runs_used  INTEGER NOT NULL,
  best_score REAL    NOT NULL,
  PRIMARY KEY (design_id, runs_used)
);

-- The final design scored on fresh seeds.
CREATE TABLE experiment_assessments (
  design_id INTEGER NOT NULL REFERENCES experiment_designs(id) ON DELETE CASCADE,
  seed      INTEGER NOT NULL,
  score     REAL    NOT NULL,
  PRIMARY KEY (design_id, seed)
);
)sql",
    // 5: designs run on a cluster (a project's cluster connection): where and with what they
    // run there, and the Slurm job that runs each one.
    R"sql(
ALTER TABLE projects ADD COLUMN cluster_workdir TEXT;  -- job folders on the cluster; NULL: ~/swarmdesign
ALTER TABLE projects ADD COLUMN cluster_binary TEXT;   -- swarmdesign there; NULL: the one on its PATH
CREATE TABLE cluster_jobs (
  design_id    INTEGER PRIMARY KEY REFERENCES designs(id) ON DELETE CASCADE,
  job_id       TEXT,              -- Slurm's, of the last submission (NULL: none accepted yet)
  folder       TEXT    NOT NULL,  -- the job's folder on the cluster
  settings     TEXT    NOT NULL,  -- sbatch settings (JSON), reused when the design is submitted again
  slurm_state  TEXT,              -- as Slurm last told it
  note         TEXT,              -- the last problem, one line (unreachable host, time limit, ...)
  submitted_at INTEGER NOT NULL,
  checked_at   INTEGER
);
-- An experiment's designs go as one Slurm job array: task i makes design tasks[i].
CREATE TABLE cluster_array_jobs (
  experiment_id INTEGER PRIMARY KEY REFERENCES experiments(id) ON DELETE CASCADE,
  job_id        TEXT,              -- Slurm's, of the last submission (NULL: none accepted yet)
  folder        TEXT    NOT NULL,  -- the experiment's folder on the cluster
  settings      TEXT    NOT NULL,  -- sbatch settings (JSON), reused when submitted again
  tasks         TEXT    NOT NULL,  -- JSON array: the experiment design id of each array task
  slurm_state   TEXT,
  note          TEXT,
  submitted_at  INTEGER NOT NULL,
  checked_at    INTEGER
);
)sql",
    // 6: failed sign-ins, counted per name as typed (lower case), known or not, so that a lock-out
    // tells no name apart; shared by the CLI and every server of the home.
    R"sql(
CREATE TABLE sign_in_failures (
  name         TEXT    PRIMARY KEY,       -- lower case
  failures     INTEGER NOT NULL CHECK (failures > 0),  -- in a row, since the last success or lock-out
  last_failure INTEGER NOT NULL,
  locked_until INTEGER NOT NULL DEFAULT 0
);
)sql",
    // 7: an experiment's final designs also scored in pseudo-reality samples (Ligot & Birattari
    // 2020), on the same seeds as in the design model; none for older experiments.
    R"sql(
CREATE TABLE experiment_reality_assessments (
  design_id INTEGER NOT NULL REFERENCES experiment_designs(id) ON DELETE CASCADE,
  sample    INTEGER NOT NULL CHECK (sample >= 1),
  seed      INTEGER NOT NULL,
  score     REAL    NOT NULL,
  PRIMARY KEY (design_id, sample, seed)
);
)sql",
    // 8: a lab's server (issue #56): an administrator role (the first account has it), accounts
    // an administrator disabled (they cannot sign in), and when each last signed in.
    R"sql(
ALTER TABLE users ADD COLUMN role TEXT NOT NULL DEFAULT 'user' CHECK (role IN ('user', 'admin'));
ALTER TABLE users ADD COLUMN disabled INTEGER NOT NULL DEFAULT 0 CHECK (disabled IN (0, 1));
ALTER TABLE users ADD COLUMN last_sign_in INTEGER;
UPDATE users SET role = 'admin' WHERE id = (SELECT min(id) FROM users);
)sql",
    // 9: the design method that races a project's design (issue #57); older rows were AutoMoDe's.
    // An experiment's design takes any method design/methods.hpp lists (the protocol reader
    // checks the name), where its CHECK named two. A CHECK is not stored in the rows, so the
    // table's text is edited in place, SQLite's documented way for such a change (rebuilding the
    // table would cascade the deletion of its assessments); migrate() then bumps
    // schema_version so that every connection reads the new text.
    R"sql(
ALTER TABLE designs ADD COLUMN method TEXT NOT NULL DEFAULT 'automode';
PRAGMA writable_schema = ON;
UPDATE sqlite_master SET sql = replace(sql, 'CHECK (method IN (''automode'', ''evostick''))', 'CHECK (method <> '''')')
  WHERE type = 'table' AND name = 'experiment_designs';
PRAGMA writable_schema = OFF;
)sql",
    // 10: quotas (issue #56). An account's own limits (NULL: the server's default applies; -1:
    // no limit for it), the server's default (one row; NULL: no limit), and the simulation runs
    // each account reserved per UTC day (a design's budget, an experiment's plan).
    R"sql(
ALTER TABLE users ADD COLUMN quota_disk_bytes INTEGER CHECK (quota_disk_bytes >= -1);
ALTER TABLE users ADD COLUMN quota_runs_per_day INTEGER CHECK (quota_runs_per_day >= -1);
CREATE TABLE server_quota (
  id           INTEGER PRIMARY KEY CHECK (id = 1),
  disk_bytes   INTEGER CHECK (disk_bytes >= 0),
  runs_per_day INTEGER CHECK (runs_per_day >= 0)
);
INSERT INTO server_quota (id) VALUES (1);
CREATE TABLE run_use (
  user_id INTEGER NOT NULL REFERENCES users(id) ON DELETE CASCADE,
  day     INTEGER NOT NULL,  -- Unix seconds / 86400: the UTC day
  runs    INTEGER NOT NULL CHECK (runs >= 0),
  PRIMARY KEY (user_id, day)
);
)sql",
    // 11: invitations (issue #56): an administrator's one-time code lets one person sign up on
    // the page of a server run with --sign-up invite. Only the code's hash is kept, as for sessions.
    R"sql(
CREATE TABLE invitations (
  id         INTEGER PRIMARY KEY,
  code_hash  BLOB    NOT NULL UNIQUE,
  created_by INTEGER REFERENCES users(id) ON DELETE SET NULL,
  created_at INTEGER NOT NULL,
  expires_at INTEGER NOT NULL,
  used_by    INTEGER REFERENCES users(id) ON DELETE SET NULL,
  used_at    INTEGER
);
)sql",
    // 12: a revoked invitation is kept, marked, rather than deleted: the administrators' list
    // says what became of every code they handed out.
    R"sql(
ALTER TABLE invitations ADD COLUMN revoked_at INTEGER;
)sql",
};

}  // namespace

int latest_schema_version() { return static_cast<int>(kMigrations.size()); }

int schema_version(Database& db) {
  auto statement = db.prepare("PRAGMA user_version");
  statement.step();
  return static_cast<int>(statement.integer(0));
}

void migrate(Database& db) { migrate_to(db, latest_schema_version()); }

void migrate_to(Database& db, int version) {
  const int latest = latest_schema_version();
  const int target = std::min(version, latest);
  while (true) {
    if (schema_version(db) >= target) break;  // cheap check outside the write lock
    Transaction transaction(db);
    // Another process may have migrated while we waited for the lock: read again.
    const int current = schema_version(db);
    if (current >= target) break;
    db.execute(kMigrations[static_cast<std::size_t>(current)]);
    // A migration that edits a table's text (9) must make connections read the schema again;
    // after any other, one more schema change changes nothing.
    std::int64_t schema_cookie = 0;
    {
      auto cookie = db.prepare("PRAGMA schema_version");
      cookie.step();
      schema_cookie = cookie.integer(0);
    }
    db.execute("PRAGMA schema_version = " + std::to_string(schema_cookie + 1));
    db.execute("PRAGMA user_version = " + std::to_string(current + 1));
    transaction.commit();
  }
  if (const int found = schema_version(db); found > latest)
    throw DatabaseError("database " + db.path().string() + " has schema version " + std::to_string(found) +
                        ", newer than this swarmdesign understands (" + std::to_string(latest) +
                        "); use a newer swarmdesign");
}

}  // namespace sd::storage
