#pragma once
// Who runs a design: a lease in the designs table — the owner (which job of which process on
// which machine) and the last heartbeat — instead of a bare local pid, so that a design can be
// owned by a CLI process, a server's job thread or a cluster job on another node, and still be
// found interrupted when its owner dies.
//
// Liveness, the one rule: an owner on this machine (same boot) is alive while its process is
// (instant, even after kill -9, and immune to pid reuse: the process's start time is part of
// the owner); an owner elsewhere is alive while its heartbeat is younger than kLeaseSeconds.
#include <cstdint>
#include <optional>
#include <string>
#include <string_view>

namespace sd::storage {

/// An owner whose heartbeat is older than this, on another machine, is taken for dead.
inline constexpr std::int64_t kLeaseSeconds = 90;
/// How often a running job renews its heartbeat.
inline constexpr std::int64_t kHeartbeatSeconds = 20;

struct Owner {
  std::string boot_id;     // this machine's boot (/proc/sys/kernel/random/boot_id)
  std::string start_time;  // the process's start, clock ticks since boot
  std::int64_t pid = 0;
  std::string job;         // the job inside the process ("cli", "web-7", "rank-0", ...)

  /// "<boot id>/<start time>/<pid>/<job>", as the designs table stores it.
  std::string text() const;
  static std::optional<Owner> parse(const std::string& text);
};

/// Owners of designs that run as Slurm jobs are "slurm:<job id>@<host>": no process here, no
/// heartbeat; their liveness is the job's state, which only Slurm knows.
inline constexpr std::string_view kSlurmOwnerPrefix = "slurm:";

/// The owner for job `job` of process `pid` on this machine (pid 0: this process). Its boot
/// id and start time are empty when /proc cannot tell (the pid alone then decides).
Owner local_owner(std::int64_t pid, const std::string& job);

/// Whether the owner can still be running the design at `now` (Unix seconds). An empty owner
/// (rows from before leases) falls back to `legacy_pid`.
bool owner_alive(const std::string& owner, std::int64_t heartbeat_at, std::int64_t now, std::int64_t legacy_pid);

}  // namespace sd::storage
