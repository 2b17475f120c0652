#pragma once
// A design's whole state in its own folder: DIR/design.db, written by the process that runs
// the design after every race step and read by `design --resume` and `status` (from another
// process while it runs: WAL, busy timeout).
//
// Tables (format version kDesignFormatVersion):
//   meta(key, value)                      format, version, mission, direction, budget, flags, seed,
//                                         fingerprint of the parameter space and options, and a
//                                         robust design's pseudo-realities
//   configurations(id, parent, iteration, record, command_line)
//                                         every configuration sampled; record = exact values (JSON)
//   experiments(seq, iteration, position, seed, configuration_id, cost)
//                                         every result, once: UNIQUE(configuration_id, position)
//   races(iteration, race_budget, configurations)          one row per race started
//   race_configurations(iteration, configuration_id, elite, eliminated_after)
//                                         who raced, and after how many instances it was dropped
//   elites(iteration, rank, configuration_id)              elites at the end of every iteration
//   checkpoint(id = 1, step, phase, state, saved_at)       the engine's compact state (JSON)
//
// The rows are plain values: storage does not know the optimiser. Turning the optimiser's
// checkpoints into rows and back is app/design_db_checkpoints (a design::CheckpointStore).
#include <cstdint>
#include <filesystem>
#include <memory>
#include <optional>
#include <stdexcept>
#include <string>
#include <vector>

#include "storage/sqlite.hpp"

namespace sd::storage {

inline constexpr int kDesignFormatVersion = 1;

/// A folder that cannot be used as asked (not a design, another format, corrupted, finished,
/// already holds a design). The message is the user's one-line explanation.
struct DesignFolderError : std::runtime_error {
  using std::runtime_error::runtime_error;
};

struct DesignMeta {
  std::string mission;        // catalogue name or absolute path of a mission file
  std::string direction;      // "maximize" or "minimize"
  std::int64_t budget = 0;
  std::string architectures;  // "fsm"
  std::string flavours;       // "chocolate"
  std::uint64_t seed = 0;
  std::string fingerprint;    // IteratedRace::fingerprint(): parameter space and options
  std::string mission_digest; // Mission::digest; empty for designs made before it was kept
  int results_version = 1;    // kResultsVersion of the build that started it; 1 when not kept
  /// A robust design's pseudo-realities (Ligot & Birattari 2020): the specification as the user
  /// named it, its whole text (so it resumes alike if the file changes) and the samples its
  /// instances are, "A-B". Empty for a design in the design model alone.
  std::string pseudo_reality{}, pseudo_reality_document{}, pseudo_reality_samples{};
  /// The design method (design/methods.hpp) whose optimiser raced it; absent (automode) in
  /// designs made before there was a choice.
  std::string method = "automode";
};

/// One checkpoint's new rows, written in one transaction.
struct CheckpointRows {
  struct Configuration {
    int id = 0, parent = 0, iteration = 0;
    std::string record;        // exact parameter values (JSON)
    std::string command_line;
  };
  struct Experiment {
    std::int64_t seq = 0;      // 1-based place in the engine's log
    int iteration = 0;
    std::int64_t position = 0;
    std::int64_t seed = 0;
    int configuration_id = 0;
    double cost = 0.0;         // NaN is kept as NULL
  };
  struct Race {                // a race that started since the last checkpoint
    int iteration = 0;
    std::int64_t race_budget = 0;
    std::vector<std::pair<int, bool>> members;  // configuration id, elite of the previous iteration
  };
  struct Elimination {
    int iteration = 0, configuration_id = 0;
    std::int64_t after_instances = 0;
  };
  std::vector<Configuration> configurations;
  std::vector<Experiment> experiments;
  std::optional<Race> race;
  std::vector<Elimination> eliminations;
  std::vector<std::vector<int>> new_elites;  // per iteration from elite_iterations() + 1, best first
  std::string phase;
  std::string state;                         // the engine's compact state (JSON text)
};

/// The last checkpoint as stored: the compact state and the whole append-only history.
struct StoredCheckpoint {
  std::string state;
  std::vector<CheckpointRows::Configuration> configurations;  // id, parent, record; by id
  std::vector<CheckpointRows::Experiment> experiments;        // iteration, position, id, cost; by seq
};

class DesignStore {
 public:
  static std::filesystem::path file_in(const std::filesystem::path& folder) { return folder / "design.db"; }

  /// Creates DIR/design.db for a new design; DesignFolderError when it already exists.
  static DesignStore create(const std::filesystem::path& folder, const DesignMeta& meta);
  /// Opens an existing design; DesignFolderError for a folder without one, another format
  /// version, or a damaged file. `check_integrity` runs SQLite's quick_check (for resume).
  static DesignStore open(const std::filesystem::path& folder, bool check_integrity = false);

  const DesignMeta& meta() const { return meta_; }
  const std::filesystem::path& folder() const { return folder_; }
  Database& database() { return *db_; }

  /// Appends a checkpoint's new rows and replaces the engine state, in one transaction.
  void append(const CheckpointRows& rows);
  /// The last checkpoint with its whole history, or nullopt when the design saved none yet;
  /// DesignFolderError when the file cannot be read.
  std::optional<StoredCheckpoint> load();
  /// The number of the last checkpoint saved (0 before the first).
  std::int64_t step() const { return step_; }
  /// Iterations whose elites are stored, and the last iteration whose race is logged: what a
  /// writer needs to tell the new rows from the stored ones.
  std::size_t elite_iterations() const { return elite_iterations_; }
  int race_logged() const { return race_logged_; }

 private:
  DesignStore(std::filesystem::path folder, std::unique_ptr<Database> db);
  void read_meta();

  std::filesystem::path folder_;
  std::unique_ptr<Database> db_;
  DesignMeta meta_;
  std::int64_t step_ = 0;
  std::size_t elite_iterations_ = 0;  // rows of `elites` already written, by iteration
  int race_logged_ = 0;               // last iteration with a `races` row
};

/// Held by the one process that runs a design: a second process (say `design --resume` on a
/// folder that run-design is running) is refused instead of writing the same results twice.
/// An flock on DIR/design.lock, so the kernel releases it when the holder dies, even by kill -9.
class DesignRunLock {
 public:
  explicit DesignRunLock(const std::filesystem::path& folder);  // DesignFolderError when held
  ~DesignRunLock();
  DesignRunLock(const DesignRunLock&) = delete;
  DesignRunLock& operator=(const DesignRunLock&) = delete;

 private:
  int fd_ = -1;
};

}  // namespace sd::storage
