#pragma once
// Running an external program without a shell in between: the arguments reach it as they
// are, its output comes back whole, and a program that hangs is killed instead of hanging
// us. Everything this folder does on a cluster goes through here (sh -c or ssh).
#include <filesystem>
#include <string>
#include <vector>

namespace sd::cluster {

struct CommandResult {
  int exit_code = 0;  ///< 127: program not found, 126: found but not runnable, 128+N: killed by signal N
  std::string out;    ///< stdout, byte for byte (binary-safe)
  std::string err;    ///< stderr; the reason when the program could not start
  bool timed_out = false;
  std::string start_error;  ///< why the program could not start; empty when it ran

  bool started() const { return start_error.empty(); }
};

struct CommandOptions {
  std::string input;                   ///< written to its stdin, which is then closed
  int timeout_s = 60;                  ///< then SIGKILL to its process group; <= 0: no limit
  std::vector<std::string> extra_env;  ///< "NAME=value" entries added to, or replacing, our environment
  std::filesystem::path stdout_file;   ///< when set, stdout goes to this file (created or truncated), not to out
};

/// Runs argv[0] (looked up on the PATH the program will see: extra_env's PATH when given)
/// in its own process group, feeding stdin and reading stdout and stderr concurrently.
/// Never throws for the program's failures: they are in the result. Keep SIGCHLD not ignored.
CommandResult run_command(const std::vector<std::string>& argv, const CommandOptions& options);

CommandResult run_command(const std::vector<std::string>& argv, const std::string& input = "", int timeout_s = 60,
                          const std::vector<std::string>& extra_env = {});

/// The first line of `text` that is not blank, without its line ending ("" when none):
/// the line an error message quotes from a program's stderr.
std::string first_line(const std::string& text);

}  // namespace sd::cluster
