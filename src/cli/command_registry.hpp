#pragma once
// Every group of subcommands lives in its own file and registers itself here, so adding a
// command never touches main.cpp. A command file keeps its options and helpers in a namespace
// of its own (sd::cli::<file name>): the command files compile as a unity build, one compile
// of CLI11's inline code instead of one per file (src/cli/CMakeLists.txt).
#include <functional>
#include <stdexcept>
#include <string>
#include <vector>

#include "app/errors.hpp"

namespace CLI {
class App;
}

namespace sd::cli {

/// What main() hands every command: the control software cut off the command line
/// (everything from --fsm-config / --bt-config to the end, as automode_main does).
struct Context {
  std::vector<std::string> control_software;
  /// Ranks of the MPI job this process is rank 0 of (1: not under mpirun).
  int mpi_ranks = 1;
  bool has_control_software() const { return !control_software.empty(); }
};

/// Misuse of the command line: the application's InvalidRequest, exit status 2 like every
/// malformed request (app/errors.hpp has the rule).
using UsageError = app::InvalidRequest;

using Registration = std::function<void(CLI::App& app, Context& context)>;

/// Registers a group of subcommands; `order` sorts the groups in --help.
struct CommandRegistrar {
  CommandRegistrar(int order, Registration registration);
};

void register_all_commands(CLI::App& app, Context& context);

}  // namespace sd::cli
