#pragma once
// Files with which the real irace 3.5 can drive SwarmDesign's evaluator: parameters.txt (irace
// syntax, dependent domains for transition targets), scenario.txt, instances.txt and an
// executable target-runner that calls `swarmdesign evaluate` and prints the cost.
#include <cstdint>
#include <filesystem>
#include <string>
#include <vector>

#include "design/parameter_space.hpp"

namespace sd::design {

/// The parameter file: `NAME "switch" type (domain) | condition`, one line per parameter in
/// definition order (which is also the order of the tokens irace passes to target-runner).
std::string irace_parameters_text(const ParameterSpace& space);

/// The condition of one parameter as an R expression ("" when unconditional).
std::string irace_condition_text(const ParameterSpace& space, std::size_t param);

struct IraceScenarioSpec {
  long long max_experiments = 0;
  std::uint64_t seed = 0;      // 0: let irace pick
  int digits = 2;
  bool deterministic = false;
  int nb_iterations = 0;     // 0: irace's default floor(2 + log2 N_param)
  int min_nb_survival = 0;   // 0: irace's default
  std::string parameter_file = "./parameters.txt";
  std::string instances_file = "./instances.txt";
  std::string target_runner = "./target-runner";
  std::string exec_dir = "./";
};
std::string irace_scenario_text(const IraceScenarioSpec& spec);

/// One instance per line (SwarmDesign: the mission name; the seed is irace's).
std::string irace_instances_text(const std::vector<std::string>& instances);

struct TargetRunnerSpec {
  std::string executable;  // absolute path of swarmdesign; overridable with $SWARMDESIGN at run time
  std::string mission;
  bool maximise = true;    // the mission's objective is maximised: print -score
};
/// Bash script following irace's target-runner contract: arguments
/// `<configID> <instanceID> <seed> <instance> <config tokens...>`, prints one number.
std::string target_runner_text(const TargetRunnerSpec& spec);

/// Writes the four files into `dir` (created if needed); target-runner is made executable.
void write_irace_files(const std::filesystem::path& dir, const ParameterSpace& space, const IraceScenarioSpec& scenario,
                       const std::vector<std::string>& instances, const TargetRunnerSpec& runner);

}  // namespace sd::design
