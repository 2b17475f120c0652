#pragma once
// Who runs a leased row (a design, an experiment): a lease in its table — the owner and the
// last heartbeat — instead of a bare local pid, so that a row can be owned by a CLI process, a
// job thread of a server or a Slurm job on another node, and still be found interrupted when
// its owner dies.
//
// The owner is a typed value (`Owner`); its text in the `owner` column is written and read
// only here (`owner_text`, `parse_owner`), in the format existing databases hold:
//   LocalProcess  "<boot id>/<start time>/<pid>/cli"
//   ServerThread  "<boot id>/<start time>/<pid>/<job>"   (job "web-3", "rank-0", ..., never "cli")
//   SlurmJob      "slurm:<job id>@<host>"  ("slurm:submitting" before Slurm accepted it)
//
// Liveness, the one rule: an owner on this machine (same boot) is alive while its process is
// (instant, even after kill -9, and immune to pid reuse: the process's start time is part of
// the owner); an owner elsewhere is alive while its heartbeat is younger than kLeaseSeconds; a
// Slurm job while Slurm says so (app/ asks it; here it is always alive).
#include <cstdint>
#include <optional>
#include <string>
#include <string_view>
#include <variant>

namespace sd::storage {

class Database;

/// An owner whose heartbeat is older than this, on another machine, is taken for dead.
inline constexpr std::int64_t kLeaseSeconds = 90;
/// How often a running job renews its heartbeat.
inline constexpr std::int64_t kHeartbeatSeconds = 20;

/// One process on one machine. Boot id and start time are empty when /proc could not tell
/// (the pid alone then decides).
struct Process {
  std::string boot_id;     // the machine's boot (/proc/sys/kernel/random/boot_id)
  std::string start_time;  // the process's start, clock ticks since boot
  std::int64_t pid = 0;
};

/// A command-line process that runs one job and stops on SIGTERM (run-design, experiment).
struct LocalProcess : Process {};

/// One job among several of a long-lived process (a web server's "web-3"): only that process
/// can stop it, through the job's cancel token.
struct ServerThread : Process {
  std::string job;
};

/// A Slurm job on a cluster: no process here and no heartbeat.
struct SlurmJob {
  std::string id;    // Slurm's job id; "submitting" until Slurm accepted it; "array" for a job array
  std::string host;  // the cluster's login host ("" while submitting)
};

using Owner = std::variant<LocalProcess, ServerThread, SlurmJob>;

/// The owner's text in the `owner` column, and back (nullopt for text no owner writes).
std::string owner_text(const Owner& owner);
std::optional<Owner> parse_owner(const std::string& text);

/// This process (pid 0) or process `pid` of this machine, as a CLI owner or as a job thread.
LocalProcess local_process(std::int64_t pid = 0);
ServerThread server_thread(const std::string& job, std::int64_t pid = 0);
inline SlurmJob slurm_submitting() { return {"submitting", ""}; }

/// Whether `process` is a process of this machine that still runs (same boot, same start:
/// its pid not reused); false for one elsewhere.
bool runs_here(const Process& process);

/// Whether the owner (column text) can still be running the row at `now` (Unix seconds). An
/// empty owner (designs from before leases) falls back to `legacy_pid`.
bool owner_alive(const std::string& owner, std::int64_t heartbeat_at, std::int64_t now, std::int64_t legacy_pid);

/// A table whose rows are leased: it has id, project_id, state ('running' while leased),
/// owner, heartbeat_at and updated_at columns.
struct LeasedTable {
  std::string_view table;  // "designs"
  std::string_view noun;   // "design", for messages
  bool keeps_pid;          // a pid column beside the owner, for people and for rows from before leases
};
inline constexpr LeasedTable kDesignLeases{"designs", "design", true};
inline constexpr LeasedTable kExperimentLeases{"experiments", "experiment", false};

/// The one implementation of a lease, for every leased table, scoped to one project. Writes go
/// to the caller's connection (inside its transaction when it has one).
///
/// Release of a lease the caller does not hold is an error (Conflict) on every table: the row
/// is then another job's (taken over after this one was found dead) or no longer running, and
/// saying "interrupted, resume it later" would be false; the row itself is never touched.
class Lease {
 public:
  Lease(Database& db, const LeasedTable& table, std::int64_t project_id);

  /// Running rows whose owner is gone become interrupted.
  void sweep_dead();
  /// Gives the running row to `owner` with a fresh heartbeat; false when it is not running.
  bool hand_over(std::int64_t id, const std::string& owner);
  /// Renews the owner's heartbeat; false when the row is no longer this owner's.
  bool renew(std::int64_t id, const std::string& owner);
  /// The owner stops a running row it can resume later: it becomes interrupted. Conflict when
  /// the owner does not hold it.
  void release(std::int64_t id, const std::string& owner);

 private:
  Database& db_;
  LeasedTable table_;
  std::int64_t project_id_;
};

/// The pid kept beside a lease (0 for a Slurm job or an unreadable owner).
std::int64_t owner_pid(const std::string& owner);

}  // namespace sd::storage
