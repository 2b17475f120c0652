#include "workflow/swarmdesign_process.hpp"
#include "test_paths.hpp"

#include <fcntl.h>
#include <poll.h>
#include <spawn.h>
#include <sys/wait.h>
#include <unistd.h>

#include <cerrno>
#include <csignal>
#include <cstdio>
#include <cstdlib>
#include <stdexcept>
#include <system_error>

extern char** environ;

namespace sd::test {

namespace {
[[noreturn]] void fail(const char* what) { throw std::system_error(errno, std::generic_category(), what); }

std::vector<std::string> child_environment(const Environment& environment) {
  std::vector<std::string> variables;
  for (char** entry = environ; *entry; ++entry) {
    const std::string variable = *entry;
    const std::string name = variable.substr(0, variable.find('='));
    bool dropped = environment.set.count(name) > 0;
    for (const auto& unset : environment.unset) dropped = dropped || unset == name;
    if (!dropped) variables.push_back(variable);
  }
  for (const auto& [name, value] : environment.set) variables.push_back(name + "=" + value);
  return variables;
}

std::vector<char*> pointers(std::vector<std::string>& strings) {
  std::vector<char*> result;
  for (auto& text : strings) result.push_back(text.data());
  result.push_back(nullptr);
  return result;
}

std::string read_all(std::FILE* file) {
  std::rewind(file);
  std::string text;
  char buffer[4096];
  while (const std::size_t size = std::fread(buffer, 1, sizeof buffer, file)) text.append(buffer, size);
  return text;
}

int wait_for(pid_t pid) {
  int status = 0;
  while (::waitpid(pid, &status, 0) < 0)
    if (errno != EINTR) fail("waitpid");
  return WIFEXITED(status) ? WEXITSTATUS(status) : -1;
}

/// Spawns a program (looked up on PATH unless it is a path) with the given file actions.
pid_t spawn(const std::string& program, const std::vector<std::string>& args, const Environment& environment,
            const posix_spawn_file_actions_t* actions, const posix_spawnattr_t* attributes = nullptr) {
  std::vector<std::string> argv_strings{program};
  argv_strings.insert(argv_strings.end(), args.begin(), args.end());
  auto env_strings = child_environment(environment);
  auto argv = pointers(argv_strings);
  auto envp = pointers(env_strings);
  pid_t pid = 0;
  if (const int error = ::posix_spawnp(&pid, program.c_str(), actions, attributes, argv.data(), envp.data()))
    throw std::system_error(error, std::generic_category(), "posix_spawn " + program);
  return pid;
}

pid_t spawn(const std::vector<std::string>& args, const Environment& environment,
            const posix_spawn_file_actions_t* actions, const posix_spawnattr_t* attributes = nullptr) {
  return spawn(::sd::test::swarmdesign_binary(), args, environment, actions, attributes);
}
}  // namespace

Outcome run_swarmdesign(const std::vector<std::string>& args, const std::string& input, const Environment& environment) {
  return run_program(::sd::test::swarmdesign_binary(), args, input, environment);
}

Outcome run_program(const std::string& program, const std::vector<std::string>& args, const std::string& input,
                    const Environment& environment) {
  std::signal(SIGPIPE, SIG_IGN);  // the child may exit without reading its input
  int stdin_pipe[2];
  if (::pipe2(stdin_pipe, O_CLOEXEC) != 0) fail("pipe2");
  std::FILE* out = std::tmpfile();
  std::FILE* err = std::tmpfile();
  if (!out || !err) fail("tmpfile");

  posix_spawn_file_actions_t actions;
  posix_spawn_file_actions_init(&actions);
  posix_spawn_file_actions_adddup2(&actions, stdin_pipe[0], STDIN_FILENO);
  posix_spawn_file_actions_adddup2(&actions, fileno(out), STDOUT_FILENO);
  posix_spawn_file_actions_adddup2(&actions, fileno(err), STDERR_FILENO);
  const pid_t pid = spawn(program, args, environment, &actions);
  posix_spawn_file_actions_destroy(&actions);

  ::close(stdin_pipe[0]);
  for (std::size_t written = 0; written < input.size();) {
    const ssize_t n = ::write(stdin_pipe[1], input.data() + written, input.size() - written);
    if (n <= 0) break;  // the child closed its end: it has all it wanted
    written += static_cast<std::size_t>(n);
  }
  ::close(stdin_pipe[1]);

  Outcome outcome;
  outcome.exit_code = wait_for(pid);
  outcome.out = read_all(out);
  outcome.err = read_all(err);
  std::fclose(out);
  std::fclose(err);
  return outcome;
}

Outcome run_swarmdesign_on_terminal(const std::vector<std::string>& args,
                                    const std::vector<std::pair<std::string, std::string>>& answers,
                                    const Environment& environment) {
  const int master = ::posix_openpt(O_RDWR | O_NOCTTY | O_CLOEXEC);
  if (master < 0 || ::grantpt(master) != 0 || ::unlockpt(master) != 0) fail("posix_openpt");
  const char* terminal = ::ptsname(master);
  if (!terminal) fail("ptsname");

  posix_spawn_file_actions_t actions;
  posix_spawn_file_actions_init(&actions);
  posix_spawn_file_actions_addopen(&actions, STDIN_FILENO, terminal, O_RDWR | O_NOCTTY, 0);
  posix_spawn_file_actions_adddup2(&actions, STDIN_FILENO, STDOUT_FILENO);
  posix_spawn_file_actions_adddup2(&actions, STDIN_FILENO, STDERR_FILENO);
  const pid_t pid = spawn(args, environment, &actions);
  posix_spawn_file_actions_destroy(&actions);

  Outcome outcome;
  std::size_t next_answer = 0;
  std::size_t unanswered_from = 0;  // prompts already answered lie before this
  while (true) {
    pollfd ready{master, POLLIN, 0};
    if (::poll(&ready, 1, 10000) <= 0) break;  // nothing for 10 s: the child hangs
    char buffer[1024];
    const ssize_t n = ::read(master, buffer, sizeof buffer);
    if (n <= 0) break;  // EIO once the child has closed the terminal
    outcome.out.append(buffer, static_cast<std::size_t>(n));
    if (next_answer < answers.size() && outcome.out.find(answers[next_answer].first, unanswered_from) != std::string::npos &&
        outcome.out.back() == ' ') {
      const std::string typed = answers[next_answer].second + "\n";
      if (::write(master, typed.data(), typed.size()) != static_cast<ssize_t>(typed.size())) fail("write");
      outcome.out += "<typed>";  // mark where the answer went, to tell prompts apart
      ++next_answer;
      unanswered_from = outcome.out.size();
    }
  }
  ::close(master);
  outcome.exit_code = wait_for(pid);
  return outcome;
}

int start_swarmdesign(const std::vector<std::string>& args, const Environment& environment,
                      const std::string& stdout_file, const std::string& stderr_file) {
  posix_spawn_file_actions_t actions;
  posix_spawn_file_actions_init(&actions);
  posix_spawn_file_actions_addopen(&actions, STDIN_FILENO, "/dev/null", O_RDONLY, 0);
  posix_spawn_file_actions_addopen(&actions, STDOUT_FILENO, stdout_file.c_str(), O_WRONLY | O_CREAT | O_TRUNC, 0600);
  posix_spawn_file_actions_addopen(&actions, STDERR_FILENO, stderr_file.c_str(), O_WRONLY | O_CREAT | O_TRUNC, 0600);
  const pid_t pid = spawn(args, environment, &actions);
  posix_spawn_file_actions_destroy(&actions);
  return pid;
}

int wait_swarmdesign(int pid) { return wait_for(pid); }

}  // namespace sd::test
