#include "cluster/shell.hpp"

#include <pwd.h>
#include <unistd.h>

#include <algorithm>
#include <cctype>
#include <climits>
#include <cstdlib>

namespace sd::cluster {

namespace {

std::string lower(std::string text) {
  std::transform(text.begin(), text.end(), text.begin(), [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
  return text;
}

std::string this_host_name() {
  char name[HOST_NAME_MAX + 1] = {};
  if (::gethostname(name, sizeof name - 1) != 0) return {};
  return name;
}

std::string current_user_name() {
  // getpwuid_r: the server's threads may ask at once (getpwuid shares one buffer).
  passwd entry{};
  passwd* found = nullptr;
  char buffer[4096];
  if (::getpwuid_r(::geteuid(), &entry, buffer, sizeof buffer, &found) != 0 || !found || !found->pw_name) return "";
  return found->pw_name;
}

bool names_this_machine(const std::string& host) {
  const std::string wanted = lower(host);
  if (wanted == "localhost") return true;
  const std::string full = lower(this_host_name());
  return !full.empty() && (wanted == full || wanted == full.substr(0, full.find('.')));
}

std::vector<std::string> split_on_spaces(const std::string& text) {
  std::vector<std::string> words;
  std::size_t start = 0;
  while ((start = text.find_first_not_of(" \t", start)) != std::string::npos) {
    const std::size_t end = text.find_first_of(" \t", start);
    words.push_back(text.substr(start, end - start));
    start = end;
  }
  return words;
}

// Checked here too, not only where users type them: a host starting with '-' would reach ssh
// as an option (-oProxyCommand=...).
void require_plain(const std::string& what, const std::string& value, bool may_be_empty) {
  const bool bad_char = std::any_of(value.begin(), value.end(), [](unsigned char c) {
    return std::isspace(c) || std::iscntrl(c) || c == '@' || c == '\'' || c == '"' || c == '\\';
  });
  if ((value.empty() && !may_be_empty) || (!value.empty() && value.front() == '-') || bad_char)
    throw ClusterError("cluster " + what + " '" + value + "' is not valid for ssh");
}

// ssh's own error, skipping the host-key notice it prints before it on first contact.
std::string ssh_error_line(const std::string& err) {
  std::size_t start = 0;
  while (start < err.size()) {
    const std::size_t end = std::min(err.find('\n', start), err.size());
    std::string line = first_line(err.substr(start, end - start));
    if (!line.empty() && line.rfind("Warning: Permanently added", 0) != 0) return line;
    start = end + 1;
  }
  return first_line(err);
}

}  // namespace

std::string shell_quote(std::string_view text) {
  std::string quoted = "'";
  for (char c : text) {
    if (c == '\'')
      quoted += "'\\''";
    else
      quoted += c;
  }
  quoted += '\'';
  return quoted;
}

std::string shell_path(std::string_view path) {
  if (path == "~") return "\"$HOME\"";
  if (path.rfind("~/", 0) == 0) {
    const std::string_view rest = path.substr(2);
    return rest.empty() ? "\"$HOME\"/" : "\"$HOME\"/" + shell_quote(rest);
  }
  return shell_quote(path);
}

Shell Shell::for_cluster(const std::string& host, const std::string& user) {
  require_plain("host", host, false);
  require_plain("user", user, true);
  Shell shell;
  shell.host_ = host;
  shell.user_ = user;
  shell.local_ = names_this_machine(host) && (user.empty() || user == current_user_name());
  if (!shell.local_) {
    const char* configured = std::getenv("SWARMDESIGN_SSH");
    shell.ssh_command_ = split_on_spaces(configured ? configured : "");
    if (shell.ssh_command_.empty()) shell.ssh_command_ = {"ssh"};
  }
  return shell;
}

Shell Shell::here() {
  Shell shell;
  shell.host_ = "localhost";
  return shell;
}

std::string Shell::target() const {
  if (local_) return "this machine";
  return user_.empty() ? host_ : user_ + "@" + host_;
}

std::string Shell::describe() const { return local_ ? "this machine" : target() + " (ssh)"; }

Shell Shell::with_environment(std::vector<std::string> extra_env) const {
  Shell copy = *this;
  copy.environment_.insert(copy.environment_.end(), extra_env.begin(), extra_env.end());
  return copy;
}

std::vector<std::string> Shell::command_for(const std::string& script) const {
  if (local_) return {"/bin/sh", "-c", script};
  std::vector<std::string> argv = ssh_command_;
  // BatchMode: a password prompt would wait forever for a user who is not at a terminal.
  for (const char* option : {"-o", "BatchMode=yes", "-o", "ConnectTimeout=10"}) argv.emplace_back(option);
  argv.push_back(target());
  argv.emplace_back("--");
  argv.push_back(script);
  return argv;
}

CommandResult Shell::run(const std::string& script, const std::string& input, int timeout_s) const {
  CommandOptions options;
  options.input = input;
  options.timeout_s = timeout_s;
  return run_with(script, std::move(options));
}

CommandResult Shell::run_with(const std::string& script, CommandOptions options) const {
  options.extra_env.insert(options.extra_env.begin(), environment_.begin(), environment_.end());
  return run_command(command_for(script), options);
}

CommandResult Shell::run_checked(const std::string& script, const std::string& input, int timeout_s) const {
  CommandOptions options;
  options.input = input;
  options.timeout_s = timeout_s;
  return run_checked_with(script, std::move(options));
}

CommandResult Shell::run_checked_with(const std::string& script, CommandOptions options) const {
  const int timeout_s = options.timeout_s;
  CommandResult result = run_with(script, std::move(options));
  if (!result.started()) {
    if (local_) throw ClusterError("cannot run commands on this machine: " + result.start_error);
    throw ClusterError("cannot reach " + target() + " over ssh: " + result.start_error);
  }
  if (result.timed_out)
    throw ClusterError(describe() + " did not answer within " + std::to_string(timeout_s) + " s");
  if (!local_ && result.exit_code == 255) {
    const std::string why = ssh_error_line(result.err);
    throw ClusterError("cannot reach " + target() + " over ssh: " + (why.empty() ? "ssh exited with code 255" : why));
  }
  return result;
}

}  // namespace sd::cluster
