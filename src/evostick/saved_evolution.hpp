#pragma once
// The file in which `swarmdesign evostick --state FILE` keeps an evolution between
// generations, so that `--resume FILE` continues it after a kill and ends exactly as the
// uninterrupted evolution would. It holds what is evolved (a mission and its digest, or a
// module), the settings, the results version of the build (a build that scores runs
// differently must not continue it) and the Checkpoint. Doubles are written so that they read
// back bit for bit. The file is replaced durably (core/durable_file.hpp), so a kill or a power
// cut leaves the previous state or the new one, never a mix.
#include <filesystem>
#include <string>

#include "evostick/evolution.hpp"

namespace sd::evostick {

/// What is evolved and how: what a resume must continue unchanged.
struct EvolutionTarget {
  std::string mission;         // catalogue name or absolute path; empty when a module is trained
  std::string mission_digest;  // Mission::digest of that mission
  std::string module;          // module name; empty for a mission
  Settings settings;
  int results_version = 0;     // kResultsVersion of the build that wrote it
};

struct SavedEvolution {
  EvolutionTarget target;
  Checkpoint checkpoint;
};

void write_saved_evolution(const std::filesystem::path& file, const EvolutionTarget& target, const Checkpoint& checkpoint);

/// std::runtime_error with a one-line reason when `file` is missing, not such a state or damaged.
SavedEvolution read_saved_evolution(const std::filesystem::path& file);

}  // namespace sd::evostick
