#include "storage/lease.hpp"

#include <signal.h>
#include <unistd.h>

#include <cerrno>
#include <fstream>
#include <sstream>
#include <vector>

#include "storage/clock.hpp"
#include "storage/errors.hpp"
#include "storage/sqlite.hpp"

namespace sd::storage {

namespace {

constexpr std::string_view kSlurmPrefix = "slurm:";
constexpr std::string_view kCliJob = "cli";

/// The fields of /proc/PID/stat after the command name (which may hold spaces and
/// parentheses): [0] is the state, [19] the start time in clock ticks since boot.
std::vector<std::string> stat_fields(std::int64_t pid) {
  std::ifstream stat("/proc/" + std::to_string(pid) + "/stat");
  std::string line;
  if (!std::getline(stat, line)) return {};
  const auto end_of_name = line.rfind(')');
  if (end_of_name == std::string::npos) return {};
  std::istringstream rest(line.substr(end_of_name + 1));
  std::vector<std::string> fields;
  for (std::string field; rest >> field;) fields.push_back(field);
  return fields;
}

std::string this_boot_id() {
  std::ifstream boot("/proc/sys/kernel/random/boot_id");
  std::string id;
  std::getline(boot, id);
  return id;
}

/// A process that no longer exists cannot be running a job (EPERM: it exists, not ours); nor
/// can a zombie (killed, not yet reaped), which answers kill(pid, 0) but runs nothing; nor can
/// one whose start time differs from the recorded one: its pid has been reused.
bool process_alive(std::int64_t pid, const std::string& recorded_start) {
  if (pid <= 0 || !(::kill(static_cast<pid_t>(pid), 0) == 0 || errno == EPERM)) return false;
  const auto stat = stat_fields(pid);
  if (!stat.empty() && stat[0] == "Z") return false;
  if (recorded_start.empty() || stat.size() < 20) return true;
  return stat[19] == recorded_start;
}

Process process(std::int64_t pid) {
  if (pid == 0) pid = ::getpid();
  Process p;
  p.pid = pid;
  const auto stat = stat_fields(pid);
  if (stat.size() >= 20) {
    p.boot_id = this_boot_id();
    p.start_time = stat[19];
  }
  return p;
}

std::string process_text(const Process& p, std::string_view job) {
  return p.boot_id + "/" + p.start_time + "/" + std::to_string(p.pid) + "/" + std::string(job);
}

/// "<boot id>/<start time>/<pid>/<job>": the job is everything after the third slash.
std::optional<Owner> parse_process(const std::string& text) {
  Process p;
  std::size_t from = 0;
  std::string parts[3];
  for (auto& part : parts) {
    const auto slash = text.find('/', from);
    if (slash == std::string::npos) return std::nullopt;
    part = text.substr(from, slash - from);
    from = slash + 1;
  }
  p.boot_id = parts[0];
  p.start_time = parts[1];
  try {
    p.pid = std::stoll(parts[2]);
  } catch (const std::exception&) {
    return std::nullopt;
  }
  std::string job = text.substr(from);
  if (job == kCliJob) return LocalProcess{p};
  return ServerThread{p, std::move(job)};
}

template <class... F> struct Overloaded : F... { using F::operator()...; };
template <class... F> Overloaded(F...) -> Overloaded<F...>;

}  // namespace

std::string owner_text(const Owner& owner) {
  return std::visit(Overloaded{
                        [](const LocalProcess& o) { return process_text(o, kCliJob); },
                        [](const ServerThread& o) { return process_text(o, o.job); },
                        [](const SlurmJob& o) {
                          return std::string(kSlurmPrefix).append(o.id).append(o.host.empty() ? "" : "@").append(o.host);
                        },
                    },
                    owner);
}

std::optional<Owner> parse_owner(const std::string& text) {
  if (text.rfind(kSlurmPrefix, 0) != 0) return parse_process(text);
  const std::string rest = text.substr(kSlurmPrefix.size());
  const auto at = rest.find('@');
  if (at == std::string::npos) return SlurmJob{rest, ""};
  return SlurmJob{rest.substr(0, at), rest.substr(at + 1)};
}

LocalProcess local_process(std::int64_t pid) { return {process(pid)}; }

ServerThread server_thread(const std::string& job, std::int64_t pid) { return {process(pid), job}; }

bool runs_here(const Process& p) {
  const Process now = process(p.pid);
  return !p.boot_id.empty() && now.boot_id == p.boot_id && now.start_time == p.start_time &&
         process_alive(p.pid, p.start_time);
}

bool owner_alive(const std::string& owner_text, std::int64_t heartbeat_at, std::int64_t now, std::int64_t legacy_pid) {
  if (owner_text.empty()) return process_alive(legacy_pid, "");
  const auto owner = parse_owner(owner_text);
  if (!owner) return false;
  // A Slurm job: Slurm tells whether it still runs (app/ asks it).
  if (std::holds_alternative<SlurmJob>(*owner)) return true;
  const Process& p = std::holds_alternative<LocalProcess>(*owner) ? static_cast<const Process&>(std::get<LocalProcess>(*owner))
                                                                  : std::get<ServerThread>(*owner);
  if (p.boot_id.empty() || p.boot_id == this_boot_id()) return process_alive(p.pid, p.start_time);
  return now - heartbeat_at < kLeaseSeconds;
}

std::int64_t owner_pid(const std::string& owner_text) {
  const auto owner = parse_owner(owner_text);
  if (!owner) return 0;
  if (const auto* o = std::get_if<LocalProcess>(&*owner)) return o->pid;
  if (const auto* o = std::get_if<ServerThread>(&*owner)) return o->pid;
  return 0;
}

Lease::Lease(Database& db, const LeasedTable& table, std::int64_t project_id)
    : db_(db), table_(table), project_id_(project_id) {}

void Lease::sweep_dead() {
  const std::string table(table_.table);
  const std::string pid = table_.keeps_pid ? "coalesce(pid, 0)" : "0";
  std::vector<std::int64_t> dead;  // collected first: no updates while the query is open
  auto running = db_.prepare("SELECT id, " + pid + ", coalesce(owner, ''), coalesce(heartbeat_at, 0) FROM " + table +
                             " WHERE project_id = ? AND state = 'running'");
  running.bind(1, project_id_);
  const std::int64_t now = unix_now();
  while (running.step())
    if (!owner_alive(running.text(2), running.integer(3), now, running.integer(1))) dead.push_back(running.integer(0));
  for (const std::int64_t id : dead)
    db_.prepare("UPDATE " + table + " SET state = 'interrupted', updated_at = ? WHERE id = ? AND state = 'running'")
        .bind(1, now).bind(2, id).run();
}

bool Lease::hand_over(std::int64_t id, const std::string& owner) {
  const std::int64_t now = unix_now();
  const std::string pid = table_.keeps_pid ? "pid = " + std::to_string(owner_pid(owner)) + ", " : "";
  db_.prepare("UPDATE " + std::string(table_.table) + " SET " + pid +
              "owner = ?, heartbeat_at = ?, updated_at = ? WHERE id = ? AND project_id = ? AND state = 'running'")
      .bind(1, owner).bind(2, now).bind(3, now).bind(4, id).bind(5, project_id_).run();
  return db_.changes() > 0;
}

bool Lease::renew(std::int64_t id, const std::string& owner) {
  db_.prepare("UPDATE " + std::string(table_.table) +
              " SET heartbeat_at = ? WHERE id = ? AND project_id = ? AND state = 'running' AND owner = ?")
      .bind(1, unix_now()).bind(2, id).bind(3, project_id_).bind(4, owner).run();
  return db_.changes() > 0;
}

void Lease::release(std::int64_t id, const std::string& owner) {
  db_.prepare("UPDATE " + std::string(table_.table) +
              " SET state = 'interrupted', updated_at = ? WHERE id = ? AND project_id = ? AND state = 'running' AND owner = ?")
      .bind(1, unix_now()).bind(2, id).bind(3, project_id_).bind(4, owner).run();
  if (db_.changes() == 0)
    throw Conflict(std::string(table_.noun) + " " + std::to_string(id) + " is not running under this job");
}

}  // namespace sd::storage
