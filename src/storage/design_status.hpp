#pragma once
// What `status` shows of a design, read from its DIR/design.db while another process may be
// writing it: one read transaction, so every number belongs to the same checkpoint.
#include <cstdint>
#include <filesystem>
#include <optional>
#include <string>
#include <vector>

namespace sd::storage {

struct ConfigurationScore {
  int id = 0;
  std::string command_line;
  double mean_score = 0.0;  // the mission's natural units, over every run it had
  std::int64_t runs = 0;
};

struct DesignProgress {
  bool started = false;              // false until the first checkpoint
  std::string phase;                 // "start-iteration", "racing", "finished"
  int iteration = 0;                 // current (or, when finished, last) iteration
  int nb_iterations = 0;             // total iterations planned (grows if budget remains)
  std::int64_t budget = 0;
  std::int64_t experiments_used = 0;  // results stored, including the current race
  std::int64_t race_budget = 0;      // budget of the current race
  int race_configurations = 0;       // configurations in the current race
  int race_alive = 0;                // of them, the ones not eliminated (yet)
  std::int64_t configurations_sampled = 0;
  std::optional<ConfigurationScore> best;  // best elite, or the current race's leader before any
  std::string finish_reason;
  std::vector<ConfigurationScore> elites;  // the current elites, best first, each over all its runs
};

struct RaceMember {
  ConfigurationScore configuration;  // mean over the runs it had in this race
  bool elite = false;                // an elite of the previous iteration
  std::optional<std::int64_t> eliminated_after;  // instances seen when dropped
};

struct RaceRecord {
  int iteration = 0;
  std::int64_t race_budget = 0;
  std::vector<std::pair<std::int64_t, std::int64_t>> instances;  // (position, seed), in order raced
  std::vector<RaceMember> members;
  std::vector<int> elites;           // at the end of the iteration, best first (empty: racing)
};

/// Where a design stood at the end of an iteration: runs used so far, and its best elite's mean
/// score over every run that elite had so far (the mission's natural units).
struct ConvergencePoint {
  int iteration = 0;
  std::int64_t runs_used = 0;
  double best_score = 0.0;
  int best_id = 0;
};

/// DesignFolderError when the folder holds no readable design.
DesignProgress read_design_progress(const std::filesystem::path& folder);
std::vector<RaceRecord> read_race_log(const std::filesystem::path& folder);
/// One point per finished iteration, in order (convergence curves).
std::vector<ConvergencePoint> read_convergence(const std::filesystem::path& folder);

}  // namespace sd::storage
