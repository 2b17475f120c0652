#pragma once
// Where the commands for a cluster run: on this machine when it is the cluster's login node,
// otherwise over ssh. Either way a command is one POSIX sh command line, so the rest of the
// folder writes each command once.
#include <string>
#include <string_view>
#include <vector>

#include "cluster/error.hpp"
#include "cluster/process.hpp"

namespace sd::cluster {

/// `text` as one word for a POSIX shell: single quotes, with ' written as '\''.
std::string shell_quote(std::string_view text);

/// A path as one word for the shell that runs the command: quoted like shell_quote, except
/// that a leading "~/" (or a lone "~") becomes "$HOME"/ so that the home folder expanded is
/// the one of the machine where the command runs.
std::string shell_path(std::string_view path);

class Shell {
 public:
  /// Local when host is "localhost" or this machine's host name (or its short form before the
  /// first '.'), and user is the current user (or empty); anything else — 127.0.0.1 too — goes
  /// over ssh. The ssh command is $SWARMDESIGN_SSH split on spaces (default "ssh"), read now.
  /// Throws ClusterError for a host or user that ssh could read as an option.
  static Shell for_cluster(const std::string& host, const std::string& user);
  static Shell here();  ///< always local

  bool local() const { return local_; }
  std::string describe() const;  ///< "this machine" or "user@host (ssh)"
  std::string target() const;    ///< "user@host" ("host" without a user); "this machine" when local

  /// A copy whose programs (sh when local, the ssh program when remote) also get these
  /// "NAME=value" entries in their environment. ssh does not forward them to the cluster.
  Shell with_environment(std::vector<std::string> extra_env) const;

  /// The argv that runs `script`: {"/bin/sh", "-c", script}, or the ssh command followed by
  /// -o BatchMode=yes -o ConnectTimeout=10 user@host -- script (ssh hands the script, one
  /// argument, to the remote login shell, which must be sh-like: bash, dash, zsh).
  std::vector<std::string> command_for(const std::string& script) const;

  CommandResult run(const std::string& script, const std::string& input = "", int timeout_s = 60) const;
  CommandResult run_with(const std::string& script, CommandOptions options) const;

  /// Like run, but throws ClusterError when the command never ran: ssh failed (exit 255:
  /// "cannot reach user@host over ssh: <ssh's error line>"), the program could not start, or
  /// no answer within the timeout. The script's own non-zero exits are returned.
  CommandResult run_checked(const std::string& script, const std::string& input = "", int timeout_s = 60) const;
  CommandResult run_checked_with(const std::string& script, CommandOptions options) const;

 private:
  Shell() = default;

  bool local_ = true;
  std::string host_, user_;
  std::vector<std::string> ssh_command_;
  std::vector<std::string> environment_;
};

}  // namespace sd::cluster
