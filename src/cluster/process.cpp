#include "cluster/process.hpp"

#include <fcntl.h>
#include <poll.h>
#include <signal.h>
#include <spawn.h>
#include <sys/stat.h>
#include <sys/wait.h>
#include <time.h>
#include <unistd.h>

#include <algorithm>
#include <system_error>
#include <cerrno>
#include <chrono>
#include <cstdlib>
#include <cstring>
#include <optional>
#include <string_view>
#include <utility>

extern char** environ;

namespace sd::cluster {

namespace {

using Clock = std::chrono::steady_clock;

// After the program exits, its output may still be held open by a child it left running in
// the background; we wait this long without news, then stop reading.
constexpr int idle_check_ms = 100;

class Fd {
 public:
  Fd() = default;
  explicit Fd(int fd) : fd_(fd) {}
  Fd(Fd&& other) noexcept : fd_(std::exchange(other.fd_, -1)) {}
  Fd& operator=(Fd&& other) noexcept {
    if (this != &other) {
      reset();
      fd_ = std::exchange(other.fd_, -1);
    }
    return *this;
  }
  ~Fd() { reset(); }
  int get() const { return fd_; }
  bool open() const { return fd_ >= 0; }
  void reset() {
    if (fd_ >= 0) ::close(fd_);
    fd_ = -1;
  }

 private:
  int fd_ = -1;
};

struct Pipe {
  Fd read, write;
};

// Both ends close on exec; the child gets its copies through dup2.
bool make_pipe(Pipe& pipe) {
  int fds[2];
  if (::pipe2(fds, O_CLOEXEC) != 0) return false;
  pipe.read = Fd(fds[0]);
  pipe.write = Fd(fds[1]);
  return true;
}

void set_nonblocking(int fd) { ::fcntl(fd, F_SETFL, ::fcntl(fd, F_GETFL) | O_NONBLOCK); }

std::string_view name_of(std::string_view entry) { return entry.substr(0, entry.find('=')); }

// Our environment with extra_env's entries replacing those of the same name.
std::vector<std::string> merged_environment(const std::vector<std::string>& extra) {
  std::vector<std::string> merged;
  for (char** entry = environ; entry && *entry; ++entry) {
    const std::string_view name = name_of(*entry);
    const bool replaced =
        std::any_of(extra.begin(), extra.end(), [&](const std::string& e) { return name_of(e) == name; });
    if (!replaced) merged.emplace_back(*entry);
  }
  merged.insert(merged.end(), extra.begin(), extra.end());
  return merged;
}

std::string path_variable(const std::vector<std::string>& environment) {
  for (const std::string& entry : environment)
    if (name_of(entry) == "PATH") return entry.substr(5);
  return "/bin:/usr/bin";  // what execvp assumes without PATH
}

// Resolved before spawning so that "not found" is known without starting anything, and with
// the PATH the program itself will see (as `env PATH=... prog` would).
std::optional<std::string> find_program(const std::string& name, const std::string& path) {
  if (name.find('/') != std::string::npos) return name;
  std::size_t start = 0;
  while (start <= path.size()) {
    const std::size_t end = std::min(path.find(':', start), path.size());
    const std::string folder = end > start ? path.substr(start, end - start) : ".";
    const std::string candidate = folder + "/" + name;
    struct stat info {};
    if (::stat(candidate.c_str(), &info) == 0 && S_ISREG(info.st_mode) && ::access(candidate.c_str(), X_OK) == 0)
      return candidate;
    start = end + 1;
  }
  return std::nullopt;
}

std::vector<char*> pointers_to(std::vector<std::string>& strings) {
  std::vector<char*> pointers;
  pointers.reserve(strings.size() + 1);
  for (std::string& s : strings) pointers.push_back(s.data());
  pointers.push_back(nullptr);
  return pointers;
}

// A child that closes its stdin early must not kill us with SIGPIPE. Blocking the signal in
// this thread (write then fails with EPIPE) leaves the rest of the program's signals alone.
class SigpipeBlocked {
 public:
  SigpipeBlocked() {
    sigemptyset(&pipe_);
    sigaddset(&pipe_, SIGPIPE);
    pthread_sigmask(SIG_BLOCK, &pipe_, &previous_);
    sigset_t pending;
    sigpending(&pending);
    was_pending_ = sigismember(&pending, SIGPIPE) == 1;
  }
  SigpipeBlocked(const SigpipeBlocked&) = delete;
  SigpipeBlocked& operator=(const SigpipeBlocked&) = delete;
  ~SigpipeBlocked() {
    // Swallow the SIGPIPE our own writes raised, so unblocking does not deliver it.
    sigset_t pending;
    sigpending(&pending);
    if (!was_pending_ && sigismember(&pending, SIGPIPE) == 1) {
      const timespec no_wait{0, 0};
      sigtimedwait(&pipe_, nullptr, &no_wait);
    }
    pthread_sigmask(SIG_SETMASK, &previous_, nullptr);
  }

 private:
  sigset_t pipe_{}, previous_{};
  bool was_pending_ = false;
};

CommandResult not_started(int exit_code, std::string why) {
  CommandResult result;
  result.exit_code = exit_code;
  result.start_error = why;
  result.err = std::move(why);
  return result;
}

int exit_code_of(int status) {
  if (WIFEXITED(status)) return WEXITSTATUS(status);
  if (WIFSIGNALED(status)) return 128 + WTERMSIG(status);
  return -1;
}

// The started program. Leaving early (an exception) kills and reaps it, so that no zombie and
// no orphan outlive the call.
class Child {
 public:
  explicit Child(pid_t pid) : pid_(pid) {}
  Child(const Child&) = delete;
  Child& operator=(const Child&) = delete;
  ~Child() {
    kill_group();
    reap(true);
  }

  void kill_group() const {
    if (!exit_code_) ::kill(-pid_, SIGKILL);
  }

  /// Its exit code once it has exited; waits for that when `block`.
  std::optional<int> reap(bool block) {
    while (!exit_code_) {
      int status = 0;
      const pid_t r = ::waitpid(pid_, &status, block ? 0 : WNOHANG);
      if (r == pid_) exit_code_ = exit_code_of(status);
      else if (r == 0) break;
      else if (errno != EINTR) exit_code_ = -1;  // ECHILD: reaped elsewhere (SIGCHLD ignored), status lost
    }
    return exit_code_;
  }

 private:
  pid_t pid_;
  std::optional<int> exit_code_;
};

// Our ends of the child's stdin, stdout (closed when it goes to a file) and stderr.
struct Streams {
  Fd in, out, err;
};

struct Spawned {
  pid_t pid = -1;
  int error = 0;  // errno of the failure to start
  Streams streams;
};

// Starts `program` on fresh pipes, stdout to `out_file` when that is open. posix_spawn does
// the part between fork and exec (dup2, process group, signal reset) async-signal-safely.
Spawned spawn(const std::string& program, std::vector<std::string> arguments, std::vector<std::string> environment,
              const Fd& out_file) {
  Spawned spawned;
  Pipe in, out, err;
  if (!make_pipe(in) || !make_pipe(err) || (!out_file.open() && !make_pipe(out))) {
    spawned.error = errno;
    return spawned;
  }
  posix_spawn_file_actions_t actions;
  posix_spawn_file_actions_init(&actions);
  posix_spawn_file_actions_adddup2(&actions, in.read.get(), 0);
  posix_spawn_file_actions_adddup2(&actions, out_file.open() ? out_file.get() : out.write.get(), 1);
  posix_spawn_file_actions_adddup2(&actions, err.write.get(), 2);
#if defined(__GLIBC__) && (__GLIBC__ > 2 || (__GLIBC__ == 2 && __GLIBC_MINOR__ >= 34))
  posix_spawn_file_actions_addclosefrom_np(&actions, 3);  // descriptors others forgot to mark CLOEXEC
#endif
  posix_spawnattr_t attributes;
  posix_spawnattr_init(&attributes);
  posix_spawnattr_setflags(&attributes, POSIX_SPAWN_SETPGROUP | POSIX_SPAWN_SETSIGMASK | POSIX_SPAWN_SETSIGDEF);
  posix_spawnattr_setpgroup(&attributes, 0);  // its own group, so a timeout kills its children too
  sigset_t none, defaults;
  sigemptyset(&none);
  posix_spawnattr_setsigmask(&attributes, &none);
  sigemptyset(&defaults);  // a server that ignores these must not pass that on
  for (int signal_number : {SIGPIPE, SIGHUP, SIGINT, SIGQUIT, SIGTERM}) sigaddset(&defaults, signal_number);
  posix_spawnattr_setsigdefault(&attributes, &defaults);

  std::vector<char*> argv_pointers = pointers_to(arguments), env_pointers = pointers_to(environment);
  spawned.error =
      posix_spawn(&spawned.pid, program.c_str(), &actions, &attributes, argv_pointers.data(), env_pointers.data());
  posix_spawn_file_actions_destroy(&actions);
  posix_spawnattr_destroy(&attributes);
  spawned.streams = {std::move(in.write), std::move(out.read), std::move(err.read)};
  return spawned;
}

// Reads what is available from fd; false at end of file or on an error.
bool read_some(const Fd& fd, std::string& sink) {
  char buffer[65536];
  for (;;) {
    const ssize_t n = ::read(fd.get(), buffer, sizeof buffer);
    if (n > 0) {
      sink.append(buffer, static_cast<std::size_t>(n));
      continue;
    }
    if (n < 0 && errno == EINTR) continue;
    return n < 0 && (errno == EAGAIN || errno == EWOULDBLOCK);
  }
}

// Writes the next part of `input`; false when done or the child stopped reading (EPIPE).
bool write_some(const Fd& fd, const std::string& input, std::size_t& written) {
  const std::size_t chunk = std::min<std::size_t>(input.size() - written, 65536);
  const ssize_t n = ::write(fd.get(), input.data() + written, chunk);
  if (n > 0) written += static_cast<std::size_t>(n);
  const bool failed = n < 0 && errno != EAGAIN && errno != EINTR;
  return !failed && written < input.size();
}

// Feeds the input and collects stdout and stderr until both close, the program has exited and
// gone quiet, or the deadline passes (then its whole group is killed).
void exchange(Child& child, Streams& streams, const CommandOptions& options, CommandResult& result) {
  std::size_t written = 0;
  if (options.input.empty()) streams.in.reset();
  for (const Fd* fd : {&streams.in, &streams.out, &streams.err})
    if (fd->open()) set_nonblocking(fd->get());
  const auto deadline = Clock::now() + std::chrono::seconds(options.timeout_s);
  while (streams.in.open() || streams.out.open() || streams.err.open()) {
    int wait_ms = idle_check_ms;
    if (options.timeout_s > 0) {
      const auto left = std::chrono::duration_cast<std::chrono::milliseconds>(deadline - Clock::now()).count();
      if (left <= 0) {
        result.timed_out = true;
        child.kill_group();
        return;
      }
      wait_ms = static_cast<int>(std::min<long long>(left, idle_check_ms));
    }
    pollfd fds[3];
    nfds_t count = 0;
    if (streams.in.open()) fds[count++] = {streams.in.get(), POLLOUT, 0};
    if (streams.out.open()) fds[count++] = {streams.out.get(), POLLIN, 0};
    if (streams.err.open()) fds[count++] = {streams.err.get(), POLLIN, 0};
    const int ready = ::poll(fds, count, wait_ms);
    if (ready < 0) {
      if (errno == EINTR) continue;
      child.kill_group();
      return;
    }
    if (ready == 0) {
      // Quiet: has the program exited while a background child of its keeps the pipes open?
      if (!child.reap(false)) continue;
      if (streams.out.open()) read_some(streams.out, result.out);
      if (streams.err.open()) read_some(streams.err, result.err);
      return;
    }
    for (nfds_t i = 0; i < count; ++i) {
      if (fds[i].revents == 0) continue;
      if (fds[i].fd == streams.in.get() && !write_some(streams.in, options.input, written)) streams.in.reset();
      if (fds[i].fd == streams.out.get() && !read_some(streams.out, result.out)) streams.out.reset();
      if (fds[i].fd == streams.err.get() && !read_some(streams.err, result.err)) streams.err.reset();
    }
  }
}

}  // namespace

CommandResult run_command(const std::vector<std::string>& argv, const CommandOptions& options) {
  if (argv.empty() || argv.front().empty()) return not_started(127, "no program to run");
  std::vector<std::string> environment = merged_environment(options.extra_env);
  const std::optional<std::string> program = find_program(argv.front(), path_variable(environment));
  if (!program) return not_started(127, "cannot run " + argv.front() + ": not found on the PATH");
  Fd out_file;
  if (!options.stdout_file.empty()) {
    out_file = Fd(::open(options.stdout_file.c_str(), O_WRONLY | O_CREAT | O_TRUNC | O_CLOEXEC, 0600));
    if (!out_file.open()) return not_started(126, "cannot create " + options.stdout_file.string() + ": " + std::generic_category().message(errno));
  }

  const SigpipeBlocked sigpipe_blocked;
  Spawned spawned = spawn(*program, argv, std::move(environment), out_file);
  out_file.reset();
  if (spawned.error != 0)
    return not_started(spawned.error == ENOENT ? 127 : 126, "cannot run " + argv.front() + ": " + std::generic_category().message(spawned.error));
  Child child(spawned.pid);
  CommandResult result;
  exchange(child, spawned.streams, options, result);
  spawned.streams = {};  // closed before waiting: a child still writing gets EPIPE, not a hang
  result.exit_code = child.reap(true).value_or(-1);
  return result;
}

CommandResult run_command(const std::vector<std::string>& argv, const std::string& input, int timeout_s,
                          const std::vector<std::string>& extra_env) {
  CommandOptions options;
  options.input = input;
  options.timeout_s = timeout_s;
  options.extra_env = extra_env;
  return run_command(argv, options);
}

std::string first_line(const std::string& text) {
  std::size_t start = 0;
  while (start < text.size()) {
    std::size_t end = text.find('\n', start);
    if (end == std::string::npos) end = text.size();
    std::string line = text.substr(start, end - start);
    while (!line.empty() && (line.back() == '\r' || line.back() == ' ' || line.back() == '\t')) line.pop_back();
    if (line.find_first_not_of(" \t") != std::string::npos) return line;
    start = end + 1;
  }
  return {};
}

}  // namespace sd::cluster
