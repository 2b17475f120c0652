#pragma once
// The swarmdesign binary run as a user runs it, for the tests of its commands end to end:
// exit status, standard output and standard error of one command line.
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>
#include <sys/wait.h>
#include <unistd.h>
#include "test_paths.hpp"

namespace sd::test {

struct CliResult {
  int status;
  std::string out, err;
};

/// Runs `swarmdesign ARGS` (ARGS as a shell would split them).
inline CliResult run_cli(const std::string& args) {
  const auto err_file = std::filesystem::temp_directory_path() / ("sd_cli_err_" + std::to_string(::getpid()));
  const std::string command = std::string(::sd::test::swarmdesign_binary()) + " " + args + " 2>" + err_file.string();
  FILE* pipe = ::popen(command.c_str(), "r");
  CliResult r;
  char buffer[4096];
  for (std::size_t n; (n = std::fread(buffer, 1, sizeof buffer, pipe)) > 0;) r.out.append(buffer, n);
  const int status = ::pclose(pipe);
  r.status = WIFEXITED(status) ? WEXITSTATUS(status) : -1;
  std::ifstream err(err_file);
  std::stringstream text;
  text << err.rdbuf();
  r.err = text.str();
  std::filesystem::remove(err_file);
  return r;
}

}  // namespace sd::test
