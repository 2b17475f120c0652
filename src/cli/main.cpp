// swarmdesign: one executable, subcommands registered by the files beside this one.
#include <CLI/CLI.hpp>

#include <algorithm>
#include <cstdio>
#include <iostream>
#include <map>
#include <string>
#include <vector>

#include "cli/command_registry.hpp"
#include "app/version.hpp"
#ifdef SWARMDESIGN_WITH_MPI
#include "mpi/session.hpp"
#endif

namespace sd::cli {

namespace {
std::multimap<int, Registration>& registry() {
  static std::multimap<int, Registration> r;
  return r;
}
}  // namespace

CommandRegistrar::CommandRegistrar(int order, Registration registration) {
  registry().emplace(order, std::move(registration));
}

void register_all_commands(CLI::App& app, Context& context) {
  for (auto& [order, registration] : registry()) registration(app, context);
}

}  // namespace sd::cli

namespace {

void print_error(const std::string& message) {
  std::string line = message;
  std::replace(line.begin(), line.end(), '\n', ' ');
  std::cerr << "swarmdesign: error: " << line << '\n';
}

}  // namespace

int run_command(int argc, char** argv, sd::cli::Context& context);

int main(int argc, char** argv) {
  // run_command reports every error of a command; this catches what escapes before or after
  // it (MPI's set-up, the context), so nothing ends in std::terminate without a line.
  try {
    sd::cli::Context context;
#ifdef SWARMDESIGN_WITH_MPI
    // Under mpirun every rank runs this program: rank 0 runs the command, the others evaluate.
    const auto mpi = sd::mpi::Session::join_if_launched(argc, argv);
    if (mpi && !mpi->is_root()) return mpi->serve();
    if (mpi) context.mpi_ranks = mpi->size();
#endif
    return run_command(argc, argv, context);
  } catch (const std::exception& e) {
    print_error(e.what());
  } catch (...) {
    print_error("unknown failure");
  }
  return 1;
}

int run_command(int argc, char** argv, sd::cli::Context& context) {
  std::vector<std::string> args;
  for (int i = 1; i < argc; ++i) {
    const std::string arg = argv[i];
    if (arg == "--fsm-config" || arg == "--bt-config" || arg == "--nn-config") {
      context.control_software.assign(argv + i, argv + argc);
      break;
    }
    args.push_back(arg);
  }

  CLI::App app{"SwarmDesign: automatic modular design of robot swarms.\n"
               "Control software (--fsm-config ... / --bt-config ...) goes last on the command line.",
               "swarmdesign"};
  app.set_version_flag("--version", sd::app::version_line());
  app.require_subcommand(1);
  app.fallthrough(false);
  sd::cli::register_all_commands(app, context);

  if (!args.empty() && args.front().rfind('-', 0) != 0) {
    bool known = false;
    for (const CLI::App* sub : app.get_subcommands({}))
      known = known || sub->check_name(args.front());
    if (!known) {
      print_error("unknown command '" + args.front() + "' (see --help)");
      return 2;
    }
  }
  // Only the commands that read control software (they all have --config-file) may be given
  // it: any other would ignore it and run, e.g. a whole design.
  if (context.has_control_software() && !args.empty() && args.front().rfind('-', 0) != 0) {
    const CLI::App* command = nullptr;
    for (const CLI::App* sub : app.get_subcommands({}))
      if (sub->check_name(args.front())) command = sub;
    if (command && !command->get_option_no_throw("--config-file")) {
      print_error(command->get_name() + " takes no control software (" + context.control_software.front() +
                  " ...); see --help");
      return 2;
    }
  }
  // CLI11 would answer "A subcommand is required" to `swarmdesign --bogus`: name the option.
  if (!args.empty() && args.front().rfind('-', 0) == 0 && !app.get_option_no_throw(args.front())) {
    print_error("unknown option '" + args.front() + "' (see --help)");
    return 2;
  }
  try {
    std::reverse(args.begin(), args.end());  // CLI11 takes the arguments reversed
    app.parse(args);
    return 0;
  } catch (const CLI::CallForHelp& e) {
    return app.exit(e);
  } catch (const CLI::CallForAllHelp& e) {
    return app.exit(e);
  } catch (const CLI::CallForVersion& e) {
    return app.exit(e);
  } catch (const CLI::RuntimeError& e) {
    return e.get_exit_code();
  } catch (const CLI::ParseError& e) {
    print_error(std::string(e.what()) + " (see --help)");
    return 2;
  } catch (const std::exception& e) {
    // One rule for every command: a malformed request exits 2, any other failure 1.
    print_error(e.what());
    return sd::app::exit_status(sd::app::classify(e));
  }
}
