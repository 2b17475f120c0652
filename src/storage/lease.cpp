#include "storage/lease.hpp"

#include <signal.h>
#include <unistd.h>

#include <cerrno>
#include <fstream>
#include <sstream>
#include <vector>

namespace sd::storage {

namespace {

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

/// A process that no longer exists cannot be running a design (EPERM: it exists, not ours);
/// nor can a zombie (killed, not yet reaped), which answers kill(pid, 0) but runs nothing; nor
/// can one whose start time differs from the recorded one: its pid has been reused.
bool process_alive(std::int64_t pid, const std::string& recorded_start) {
  if (pid <= 0 || !(::kill(static_cast<pid_t>(pid), 0) == 0 || errno == EPERM)) return false;
  const auto stat = stat_fields(pid);
  if (!stat.empty() && stat[0] == "Z") return false;
  if (recorded_start.empty() || stat.size() < 20) return true;
  return stat[19] == recorded_start;
}

}  // namespace

std::string Owner::text() const { return boot_id + "/" + start_time + "/" + std::to_string(pid) + "/" + job; }

std::optional<Owner> Owner::parse(const std::string& text) {
  Owner owner;
  std::size_t from = 0;
  std::string parts[3];
  for (auto& part : parts) {
    const auto slash = text.find('/', from);
    if (slash == std::string::npos) return std::nullopt;
    part = text.substr(from, slash - from);
    from = slash + 1;
  }
  owner.boot_id = parts[0];
  owner.start_time = parts[1];
  try {
    owner.pid = std::stoll(parts[2]);
  } catch (const std::exception&) {
    return std::nullopt;
  }
  owner.job = text.substr(from);
  return owner;
}

Owner local_owner(std::int64_t pid, const std::string& job) {
  if (pid == 0) pid = ::getpid();
  Owner owner;
  owner.pid = pid;
  owner.job = job;
  const auto stat = stat_fields(pid);
  if (stat.size() >= 20) {
    owner.boot_id = this_boot_id();
    owner.start_time = stat[19];
  }
  return owner;
}

bool owner_alive(const std::string& owner_text, std::int64_t heartbeat_at, std::int64_t now, std::int64_t legacy_pid) {
  if (owner_text.empty()) return process_alive(legacy_pid, "");
  // A Slurm job: Slurm tells whether it still runs (app/cluster_designs asks it).
  if (owner_text.rfind(kSlurmOwnerPrefix, 0) == 0) return true;
  const auto owner = Owner::parse(owner_text);
  if (!owner) return false;
  if (owner->boot_id.empty() || owner->boot_id == this_boot_id()) return process_alive(owner->pid, owner->start_time);
  return now - heartbeat_at < kLeaseSeconds;
}

}  // namespace sd::storage
