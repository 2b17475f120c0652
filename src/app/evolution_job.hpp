#pragma once
// EvoStick as a job: evolve the Arlequin perceptron for one module (against its training
// measure) or for a mission (the EvoStick baseline), keeping its state in a file after every
// generation so that a killed evolution resumes to exactly the result it would have had.
#include <cstdint>
#include <functional>
#include <optional>
#include <string>

#include "app/cancel_token.hpp"
#include "evostick/evolution.hpp"

namespace sd::app {

struct EvolutionRequest {
  std::string module;            // train this Arlequin module, or
  std::string mission;           // design a network for this mission (name or file)
  evostick::Settings settings;   // validated here (InvalidRequest)
  std::int64_t budget = 0;       // > 0: generations = budget / (population x evaluations)
  std::string state;             // keep the state in this file (empty: not kept)
  std::string output;            // also write the document to this file
};

struct EvolutionRun {
  int threads = 0;  // 0: all cores
  /// After every generation, with the number of generations in all.
  std::function<void(const evostick::GenerationRecord&, int generations)> progress;
  /// After the state file holds checkpoint `generation` (only when the state is kept).
  std::function<void(int generation)> saved;
  /// Stops the evolution after the generation it is in, once its state is saved (resumable
  /// when the state is kept).
  const CancelToken* cancel = nullptr;
};

struct EvolutionOutcome {
  evostick::Result result;
  evostick::Settings settings;
  std::string module;            // set for a module evolution
  std::string measure;           // its training measure
  std::string control_software;  // the best network as --nn-config ...
  std::string document;          // the JSON document (module: data/arlequin's format)
  bool cancelled = false;        // stopped by the token: only `settings` is set
};

EvolutionOutcome start_evolution(const EvolutionRequest& request, const EvolutionRun& run);
/// Continues the evolution kept in `file` with its own target and settings; DesignFolderError
/// when its mission changed or this build would score its runs differently.
EvolutionOutcome resume_evolution(const std::string& file, const EvolutionRun& run, const std::string& output = "");

}  // namespace sd::app
