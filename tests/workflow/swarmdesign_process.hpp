#pragma once
// Runs the built swarmdesign binary as a child process, as a user's shell would.
#include <map>
#include <string>
#include <vector>

namespace sd::test {

struct Outcome {
  int exit_code = -1;  // -1 when killed by a signal
  std::string out;
  std::string err;
};

/// Environment changes for the child: a value sets the variable, nullopt-like "" with
/// `unset` removes it.
struct Environment {
  std::map<std::string, std::string> set;
  std::vector<std::string> unset;
};

/// Runs `swarmdesign args...` with `input` written to its standard input through a pipe.
Outcome run_swarmdesign(const std::vector<std::string>& args, const std::string& input, const Environment& environment);
/// The same for another program (mpirun, a script), looked up on PATH unless it is a path.
Outcome run_program(const std::string& program, const std::vector<std::string>& args, const std::string& input,
                    const Environment& environment);

/// Runs it on a pseudo-terminal: whenever the output so far ends a prompt that contains a
/// key of `answers`, types the answer and Enter. Returns everything the terminal showed.
Outcome run_swarmdesign_on_terminal(const std::vector<std::string>& args,
                                    const std::vector<std::pair<std::string, std::string>>& answers,
                                    const Environment& environment);

/// Starts `swarmdesign args...` in the background with stdin from /dev/null and stdout/stderr
/// into the given files; returns its process id.
int start_swarmdesign(const std::vector<std::string>& args, const Environment& environment,
                      const std::string& stdout_file, const std::string& stderr_file);
/// Waits for a process started by start_swarmdesign: its exit code, -1 when a signal ended it.
int wait_swarmdesign(int pid);

}  // namespace sd::test
