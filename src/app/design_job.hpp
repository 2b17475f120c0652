#pragma once
// One design process, as `design` and `run-design` run it: mission + design space + budget
// + seed, evaluated by SimulationRunner, checkpointed into DIR/design.db after every race
// step, resumable after kill -9 with exactly the result of an uninterrupted run.
//
//   PreparedDesign d = prepare_new_design(settings, folder);   // or prepare_resume(folder)
//   DesignReport r = run_prepared_design(d, {threads, progress});
//
// prepare_* check everything (mission, flags, minimum budget, the folder) without side
// effects, so a caller can refuse bad input before it records or forks anything.
#include <cstdint>
#include <filesystem>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "control/control_software.hpp"
#include "design/design_space.hpp"
#include "design/iterated_race.hpp"
#include "missions/mission.hpp"
#include "storage/design_store.hpp"

namespace sd::cli {

struct NewDesignSettings {
  std::string mission;  // name or mission file
  long long budget = 0;
  design::DesignSpaceRequest space;
  std::uint64_t seed = 0;
};

struct PreparedDesign {
  std::filesystem::path folder;
  Mission mission;
  std::string mission_reference;  // as stored: catalogue name or absolute path
  design::DesignSpaceChoice choice;
  std::unique_ptr<design::ParameterSpace> space;  // IteratedRace keeps a reference to it
  design::IraceOptions options;
  std::optional<design::DesignState> restored;    // set when resuming from a checkpoint
  bool resuming = false;
};

/// Checks the settings of a new design (no folder yet): UsageError for an unknown mission, an
/// unavailable flavour or a budget below the engine's minimum.
PreparedDesign check_new_design(const NewDesignSettings& settings);
/// check_new_design in a folder; storage::DesignFolderError when it already holds a design.
/// An empty folder means ./design-<mission>-seed<S> (with -2, -3 ... when taken).
PreparedDesign prepare_new_design(const NewDesignSettings& settings, const std::filesystem::path& folder);
/// Throws storage::DesignFolderError for a folder that is not a design, of another format or
/// space, damaged, or (unless allow_finished) finished.
PreparedDesign prepare_resume(const std::filesystem::path& folder, bool allow_finished = false);

struct RunOptions {
  unsigned threads = 0;          // 0: all cores
  bool progress = false;         // a live line on stderr (a terminal)
  bool log_iterations = false;   // one line per finished iteration on stderr (a log file)
};

struct EliteReport {
  int id = 0;
  std::string configuration;
  double mean_score = 0.0;       // the mission's natural units
  std::size_t evaluations = 0;
};

struct DesignReport {
  std::filesystem::path folder;
  std::string mission, direction;
  long long budget = 0;
  std::uint64_t seed = 0;
  std::string architectures, flavours;
  std::vector<std::string> notes;
  bool resumed = false;
  long long experiments_used = 0;
  int iterations = 0;
  std::string finish_reason;
  ControlSoftware best;
  std::vector<EliteReport> elites;  // best first
  double wall_seconds = 0.0, evaluation_seconds = 0.0;
  int threads = 0;
};

DesignReport run_prepared_design(PreparedDesign& design, const RunOptions& options);

/// A mission as a design stores it: a catalogue name as given, a mission file by absolute path
/// (so that the design resumes, and target-runner runs, from any directory).
std::string mission_reference(const std::string& mission);

/// The smallest budget the engine accepts for this space (irace's minimum). nb_iterations 0
/// means the default floor(2 + log2 N_param), as both the engine and irace pick it.
long long minimum_design_budget(const design::ParameterSpace& space, int nb_iterations = 0);
/// UsageError naming the minimum when `budget` is below it: `design`, `run-design` and
/// `irace-export` refuse a too small budget with the same words.
void require_minimum_budget(long long budget, const design::ParameterSpace& space, int nb_iterations = 0);

/// Text for people, or one JSON document.
void print_design_report(const DesignReport& report, bool json);

}  // namespace sd::cli
