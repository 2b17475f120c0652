#include "cluster/slurm.hpp"

#include <algorithm>
#include <array>
#include <cctype>
#include <charconv>
#include <utility>

namespace sd::cluster {

namespace {

bool is_digit(char c) { return c >= '0' && c <= '9'; }
bool all_digits(std::string_view text) { return !text.empty() && std::all_of(text.begin(), text.end(), is_digit); }

std::string in_quotes(std::string_view value) {  // appended: GCC 12 -Wrestrict false alarm on "'" + s + "'"
  std::string text(1, '\'');
  text.append(value).push_back('\'');
  return text;
}

std::string_view trim(std::string_view text) {
  const auto first = text.find_first_not_of(" \t\r\n");
  if (first == std::string_view::npos) return {};
  return text.substr(first, text.find_last_not_of(" \t\r\n") - first + 1);
}

std::vector<std::string_view> split(std::string_view text, char separator) {
  std::vector<std::string_view> parts;
  std::size_t start = 0;
  for (;;) {
    const std::size_t end = text.find(separator, start);
    parts.push_back(text.substr(start, end == std::string_view::npos ? std::string_view::npos : end - start));
    if (end == std::string_view::npos) return parts;
    start = end + 1;
  }
}

std::vector<std::string_view> lines_of(std::string_view text) {
  std::vector<std::string_view> lines;
  for (std::string_view line : split(text, '\n'))
    if (!trim(line).empty()) lines.push_back(trim(line));
  return lines;
}

int to_int(std::string_view digits) {
  int value = 0;
  std::from_chars(digits.data(), digits.data() + digits.size(), value);
  return value;
}

bool equals_ignoring_case(std::string_view a, std::string_view b) {
  return a.size() == b.size() && std::equal(a.begin(), a.end(), b.begin(), [](char x, char y) {
           return std::toupper(static_cast<unsigned char>(x)) == std::toupper(static_cast<unsigned char>(y));
         });
}

std::string name_problem(std::string_view what, std::string_view name) {
  if (name.empty()) return {};
  const bool valid = name.front() != '-' && std::all_of(name.begin(), name.end(), [](char c) {
                       return std::isalnum(static_cast<unsigned char>(c)) || c == '_' || c == '-' || c == '.';
                     });
  if (valid) return {};
  return std::string(what) + " " + in_quotes(name) + " is not valid: use letters, digits, '_', '-' or '.', not starting with '-'";
}

// sbatch reads #SBATCH lines with its own tokenizer: blanks split words, an unquoted '#'
// starts a comment, and inside double quotes a backslash escapes the next character.
std::string sbatch_value(std::string_view setting, std::string_view value) {
  if (value.find_first_of("\r\n") != std::string_view::npos)
    throw ClusterError("Slurm setting " + std::string(setting) + " contains a line break");
  const bool plain = !value.empty() && std::all_of(value.begin(), value.end(), [](char c) {
    return std::isalnum(static_cast<unsigned char>(c)) || std::string_view("_./%:@+,=-").find(c) != std::string_view::npos;
  });
  if (plain) return std::string(value);
  std::string quoted = "\"";
  for (char c : value) {
    if (c == '"' || c == '\\') quoted += '\\';
    quoted += c;
  }
  return quoted + '"';
}

void require_fine(const std::string& problem) {
  if (!problem.empty()) throw ClusterError(problem);
}

std::string sbatch_header(const JobSettings& settings) {
  require_fine(time_problem(settings.time));
  require_fine(partition_problem(settings.partition));
  require_fine(account_problem(settings.account));
  std::string header = "#!/bin/bash\n";
  const auto text = [&](std::string_view option, const std::string& value) {
    if (!value.empty()) header += "#SBATCH --" + std::string(option) + "=" + sbatch_value(option, value) + "\n";
  };
  const auto count = [&](std::string_view option, const std::optional<int>& value) {
    if (!value) return;
    if (*value < 1)
      throw ClusterError("Slurm setting " + std::string(option) + " must be at least 1, not " + std::to_string(*value));
    header += "#SBATCH --" + std::string(option) + "=" + std::to_string(*value) + "\n";
  };
  text("job-name", settings.job_name);
  count("nodes", settings.nodes);
  count("ntasks", settings.ntasks);
  count("cpus-per-task", settings.cpus_per_task);
  text("time", settings.time);
  text("partition", settings.partition);
  text("account", settings.account);
  text("output", settings.output);
  text("chdir", settings.workdir);
  return header;
}

// "0:15" -> {0, 15}; what Slurm prints as ExitCode (status:signal).
std::pair<int, int> parse_exit_code(std::string_view text) {
  const auto parts = split(trim(text), ':');
  const int code = all_digits(parts[0]) ? to_int(parts[0]) : 0;
  const int signal = parts.size() > 1 && all_digits(parts[1]) ? to_int(parts[1]) : 0;
  return {code, signal};
}

JobStatus status_of(std::string_view state_word, std::string_view reason) {
  JobStatus status;
  // Slurm may append flags to the word ("CANCELLED+"): keep the word itself.
  const auto end = std::find_if(state_word.begin(), state_word.end(), [](char c) {
    return !(std::isupper(static_cast<unsigned char>(c)) || c == '_');
  });
  status.slurm_state = std::string(state_word.begin(), end);
  status.state = job_state_from_slurm(status.slurm_state);
  if (reason != "None" && reason != "(null)") status.reason = std::string(reason);
  return status;
}

// The value of `key` in "Key=value Key2=value2 ..." (a key starts the text or follows a blank).
std::string_view field(std::string_view text, std::string_view key) {
  for (std::size_t at = text.find(key); at != std::string_view::npos; at = text.find(key, at + 1)) {
    const bool starts_word = at == 0 || text[at - 1] == ' ';
    if (!starts_word || at + key.size() >= text.size() || text[at + key.size()] != '=') continue;
    const std::size_t start = at + key.size() + 1;
    const std::size_t end = text.find_first_of(" \n", start);
    return text.substr(start, end == std::string_view::npos ? std::string_view::npos : end - start);
  }
  return {};
}

void require_job_id(const std::string& job_id) {
  const auto parts = split(job_id, '_');
  const bool valid = parts.size() <= 2 && std::all_of(parts.begin(), parts.end(), all_digits);
  if (!valid) throw ClusterError(in_quotes(job_id) + " is not a Slurm job id");
}

// Several tasks of an array job answer for its id: report the most active one.
JobStatus most_active(const std::vector<JobStatus>& statuses) {
  for (JobState wanted : {JobState::running, JobState::completing, JobState::pending})
    for (const JobStatus& status : statuses)
      if (status.state == wanted) return status;
  return statuses.empty() ? JobStatus{} : statuses.front();
}

// Output of a command printing "@section" lines before each part (copies: the output is
// often a temporary).
std::map<std::string, std::vector<std::string>> sections(std::string_view text) {
  std::map<std::string, std::vector<std::string>> parts;
  std::string current;
  for (std::string_view line : lines_of(text)) {
    if (line.front() == '@') {
      current = std::string(line.substr(1));
      parts[current];  // present even when empty
    } else {
      parts[current].emplace_back(line);
    }
  }
  return parts;
}

ClusterError not_on_path(const std::string& program, const Shell& shell) {
  return ClusterError(program + " is not on the path of " + shell.describe());
}

// Script lines that leave squeue's answer in $s, or stop with "@no-squeue" or, when squeue
// fails for another reason than an unknown job id (the controller is down), "@squeue-error"
// and its message: else a controller out of reach would look like a job Slurm has forgotten.
// squeue is asked once: it retries for a while before giving up on its controller.
std::string ask_squeue(const std::string& arguments) {
  return "command -v squeue >/dev/null 2>&1 || { echo @no-squeue; exit 0; }\n"
         "f=$(mktemp) || exit 1\n"
         "s=$(squeue -h " + arguments + " 2>\"$f\") || {\n"
         "  s=; e=$(cat \"$f\")\n"
         "  case $e in *'Invalid job id'*) ;; *) rm -f \"$f\"; printf '@squeue-error\\n%s\\n' \"$e\"; exit 0 ;; esac\n"
         "}\n"
         "rm -f \"$f\"\n";
}

// The sections of a status command's output, or ClusterError when it says Slurm cannot answer.
std::map<std::string, std::vector<std::string>> slurm_answer(const CommandResult& result, const Shell& shell,
                                                                  const std::string& job_id) {
  if (result.exit_code != 0)
    throw ClusterError("cannot ask Slurm about job " + job_id + " on " + shell.describe() + ": " + first_line(result.err));
  auto parts = sections(result.out);
  if (parts.count("no-squeue")) throw not_on_path("squeue", shell);
  if (const auto error = parts.find("squeue-error"); error != parts.end()) {
    const std::string why = error->second.empty() ? "no message" : std::string(error->second.front());
    throw ClusterError("squeue failed on " + shell.describe() + ": " + why);
  }
  return parts;
}

}  // namespace

std::string time_problem(std::string_view time) {
  if (time.empty() || equals_ignoring_case(time, "UNLIMITED") || equals_ignoring_case(time, "INFINITE")) return {};
  const std::size_t dash = time.find('-');
  const bool has_days = dash != std::string_view::npos;
  const auto clock = split(has_days ? time.substr(dash + 1) : time, ':');
  const bool valid = (!has_days || all_digits(time.substr(0, dash))) && clock.size() <= 3 &&
                     std::all_of(clock.begin(), clock.end(), all_digits);
  if (valid) return {};
  return "time limit " + in_quotes(time) + " is not a Slurm time: use M, M:S, H:M:S, D-H, D-H:M or D-H:M:S";
}

std::string partition_problem(std::string_view name) { return name_problem("partition", name); }
std::string account_problem(std::string_view name) { return name_problem("account", name); }

std::string sbatch_script(const JobSettings& settings, const std::string& body) {
  return sbatch_header(settings) + body;
}

std::string sbatch_array_script(const JobSettings& settings, int count, const std::string& body) {
  if (count < 1) throw ClusterError("a Slurm array needs at least 1 task, not " + std::to_string(count));
  return sbatch_header(settings) + "#SBATCH --array=0-" + std::to_string(count - 1) + "\n" + body;
}

std::string parse_job_id(const std::string& sbatch_output) {
  const auto lines = lines_of(sbatch_output);
  // The id is the last line: a site's submit filter may print notices before it.
  const std::string_view id = lines.empty() ? std::string_view{} : split(lines.back(), ';').front();
  if (!all_digits(id)) throw ClusterError("sbatch did not print a job id: " + in_quotes(first_line(sbatch_output)));
  return std::string(id);
}

std::string submit(const Shell& shell, const std::string& script_path) {
  const CommandResult result = shell.run_checked("sbatch --parsable " + shell_path(script_path));
  if (result.exit_code == 127) throw not_on_path("sbatch", shell);
  if (result.exit_code != 0) {
    const std::string why = first_line(result.err);
    throw ClusterError("sbatch refused the job: " + (why.empty() ? "exit code " + std::to_string(result.exit_code) : why));
  }
  return parse_job_id(result.out);
}

std::string to_string(JobState state) {
  switch (state) {
    case JobState::pending: return "pending";
    case JobState::running: return "running";
    case JobState::completing: return "completing";
    case JobState::completed: return "completed";
    case JobState::failed: return "failed";
    case JobState::cancelled: return "cancelled";
    case JobState::timeout: return "timeout";
    case JobState::node_fail: return "node_fail";
    case JobState::out_of_memory: return "out_of_memory";
    case JobState::preempted: return "preempted";
    case JobState::unknown: return "unknown";
  }
  return "unknown";
}

bool finished(JobState state) {
  switch (state) {
    case JobState::completed:
    case JobState::failed:
    case JobState::cancelled:
    case JobState::timeout:
    case JobState::node_fail:
    case JobState::out_of_memory:
    case JobState::preempted: return true;
    default: return false;
  }
}

JobState job_state_from_slurm(std::string_view word) {
  // Slurm's long and short names (squeue %T and %t); rare ones folded into the nearest state.
  struct Name {
    std::string_view long_name, short_name;
    JobState state;
  };
  static constexpr std::array names{
      Name{"PENDING", "PD", JobState::pending},         Name{"RUNNING", "R", JobState::running},
      Name{"COMPLETING", "CG", JobState::completing},   Name{"COMPLETED", "CD", JobState::completed},
      Name{"FAILED", "F", JobState::failed},            Name{"CANCELLED", "CA", JobState::cancelled},
      Name{"TIMEOUT", "TO", JobState::timeout},         Name{"NODE_FAIL", "NF", JobState::node_fail},
      Name{"OUT_OF_MEMORY", "OOM", JobState::out_of_memory}, Name{"PREEMPTED", "PR", JobState::preempted},
      Name{"BOOT_FAIL", "BF", JobState::failed},        Name{"SPECIAL_EXIT", "SE", JobState::failed},
      Name{"DEADLINE", "DL", JobState::timeout},        Name{"REVOKED", "RV", JobState::cancelled},
      Name{"CONFIGURING", "CF", JobState::pending},     Name{"REQUEUED", "RQ", JobState::pending},
      Name{"REQUEUE_HOLD", "RH", JobState::pending},    Name{"REQUEUE_FED", "RF", JobState::pending},
      Name{"RESV_DEL_HOLD", "RD", JobState::pending},   Name{"RESIZING", "RS", JobState::running},
      Name{"SIGNALING", "SI", JobState::running},       Name{"STOPPED", "ST", JobState::running},
      Name{"SUSPENDED", "S", JobState::running},        Name{"STAGE_OUT", "SO", JobState::completing},
  };
  for (const Name& name : names)
    if (word == name.long_name || word == name.short_name) return name.state;
  return JobState::unknown;
}

JobStatus parse_squeue_line(const std::string& line) {
  const auto parts = split(trim(line), '|');
  return status_of(trim(parts[0]), parts.size() > 1 ? trim(parts[1]) : std::string_view{});
}

JobStatus parse_scontrol_job(const std::string& text) {
  JobStatus status = status_of(field(text, "JobState"), field(text, "Reason"));
  std::tie(status.exit_code, status.signal) = parse_exit_code(field(text, "ExitCode"));
  return status;
}

JobStatus parse_sacct_line(const std::string& line) {
  const auto parts = split(trim(line), '|');
  const std::string_view state = trim(parts[0]);
  const std::size_t blank = state.find(' ');
  JobStatus status = status_of(state.substr(0, blank), {});
  if (blank != std::string_view::npos && status.state == JobState::cancelled) {
    const std::string_view by = trim(state.substr(blank + 1));  // "by 1000": the uid who cancelled
    status.reason = by.rfind("by ", 0) == 0 ? "cancelled by uid " + std::string(by.substr(3)) : std::string(by);
  }
  if (parts.size() > 1) std::tie(status.exit_code, status.signal) = parse_exit_code(parts[1]);
  return status;
}

std::vector<int> array_task_indexes(std::string_view text) {
  constexpr std::size_t most_tasks = 4'000'001;  // Slurm's own ceiling on MaxArraySize
  text = trim(text);
  if (const std::size_t underscore = text.find('_'); underscore != std::string_view::npos)
    text = text.substr(underscore + 1);
  if (!text.empty() && text.front() == '[') text.remove_prefix(1);
  if (!text.empty() && text.back() == ']') text.remove_suffix(1);
  text = text.substr(0, text.find('%'));  // "%4": how many may run at once
  std::vector<int> indexes;
  for (std::string_view item : split(text, ',')) {
    const auto step_parts = split(item, ':');
    const auto bounds = split(step_parts[0], '-');
    const bool valid = bounds.size() <= 2 && step_parts.size() <= 2 && std::all_of(bounds.begin(), bounds.end(), all_digits) &&
                       (step_parts.size() == 1 || (all_digits(step_parts[1]) && to_int(step_parts[1]) > 0));
    if (!valid) return {};
    const int first = to_int(bounds.front()), last = to_int(bounds.back());
    const int step = step_parts.size() > 1 ? to_int(step_parts[1]) : 1;
    for (int index = first; index <= last; index += step) {
      if (indexes.size() >= most_tasks) return {};
      indexes.push_back(index);
    }
  }
  return indexes;
}

JobStatus job_status(const Shell& shell, const std::string& job_id) {
  require_job_id(job_id);
  // One round trip: each source is asked only when the previous one does not know the job.
  const std::string script =
      ask_squeue("-j " + job_id + " -o '%T|%r'") +
      "[ -n \"$s\" ] && { printf '@squeue\\n%s\\n' \"$s\"; exit 0; }\n"
      "s=$(scontrol show job -o " + job_id + " 2>/dev/null) && [ -n \"$s\" ] && { printf '@scontrol\\n%s\\n' \"$s\"; exit 0; }\n"
      "s=$(sacct -n -X -P -j " + job_id + " -o State,ExitCode 2>/dev/null) && [ -n \"$s\" ] && { printf '@sacct\\n%s\\n' \"$s\"; exit 0; }\n"
      "echo @none\n";
  const auto parts = slurm_answer(shell.run_checked(script), shell, job_id);
  std::vector<JobStatus> statuses;
  for (const auto& [source, lines] : parts) {
    for (const std::string& line : lines) {
      if (source == "squeue") statuses.push_back(parse_squeue_line(line));
      if (source == "scontrol") statuses.push_back(parse_scontrol_job(line));
      if (source == "sacct") statuses.push_back(parse_sacct_line(line));
    }
  }
  if (statuses.empty()) {
    JobStatus status;
    status.reason = "Slurm no longer knows job " + job_id;
    return status;
  }
  return most_active(statuses);
}

std::map<int, JobStatus> array_status(const Shell& shell, const std::string& job_id) {
  require_job_id(job_id);
  const std::string script =
      ask_squeue("-r -j " + job_id + " -o '%i|%T|%r'") +
      "echo @sacct; sacct -n -X -P -j " + job_id + " -o JobID,State,ExitCode 2>/dev/null\n"
      "echo @scontrol; scontrol show job -o " + job_id + " 2>/dev/null\n"
      "printf '@squeue\\n%s\\n' \"$s\"\n";
  auto parts = slurm_answer(shell.run_checked(script), shell, job_id);
  std::map<int, JobStatus> tasks;
  const auto record = [&](std::string_view task_list, const JobStatus& status) {
    for (int index : array_task_indexes(task_list)) tasks[index] = status;
  };
  // Job id fields name a task only with '_' ("5_3"); a bare "5" is the whole job.
  const auto task_field = [](std::string_view line) {
    const std::string_view first = line.substr(0, line.find('|'));
    return first.find('_') == std::string_view::npos ? std::string_view{} : first;
  };
  for (std::string_view line : parts["sacct"])
    if (auto tasks_text = task_field(line); !tasks_text.empty())
      record(tasks_text, parse_sacct_line(std::string(line.substr(line.find('|') + 1))));
  for (std::string_view line : parts["scontrol"])
    if (auto tasks_text = field(line, "ArrayTaskId"); !tasks_text.empty())
      record(tasks_text, parse_scontrol_job(std::string(line)));
  for (std::string_view line : parts["squeue"])
    if (auto tasks_text = task_field(line); !tasks_text.empty())
      record(tasks_text, parse_squeue_line(std::string(line.substr(line.find('|') + 1))));
  return tasks;
}

void cancel(const Shell& shell, const std::string& job_id) {
  require_job_id(job_id);
  const CommandResult result = shell.run_checked("scancel " + job_id);
  if (result.exit_code == 127) throw not_on_path("scancel", shell);
  if (result.exit_code != 0) {
    const std::string why = first_line(result.err);
    throw ClusterError("scancel could not cancel job " + job_id + " on " + shell.describe() + ": " +
                       (why.empty() ? "exit code " + std::to_string(result.exit_code) : why));
  }
}

}  // namespace sd::cluster
