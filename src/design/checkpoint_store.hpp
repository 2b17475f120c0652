#pragma once
// Where a design's race is kept between steps so that a killed design resumes exactly
// (irace's recovery file; Optuna's storage behind an interface). The optimiser only talks to
// this seam: the design database (app/design_db_checkpoints, over storage/design_store) and
// the in-memory store of the tests implement it.
#include <nlohmann/json.hpp>

#include <cstdint>
#include <optional>
#include <span>

#include "design/iterated_race.hpp"
#include "design/race_log.hpp"

namespace sd::design {

class CheckpointStore {
 public:
  virtual ~CheckpointStore() = default;
  /// Appends what is new since the last save (Checkpoint says from where) and the race log's
  /// eliminations, and replaces the engine's compact state: all of it or nothing.
  virtual void save(const Checkpoint& checkpoint, std::span<const Elimination> eliminations) = 0;
  /// The last state saved with its whole history; nullopt before the first save.
  virtual std::optional<DesignState> load() = 0;
  /// The number of the last checkpoint saved (0 before the first).
  virtual std::int64_t step() const = 0;
};

/// A design kept in memory: the tests' store, and the reference the others must agree with.
class MemoryCheckpointStore final : public CheckpointStore {
 public:
  void save(const Checkpoint& checkpoint, std::span<const Elimination> eliminations) override;
  std::optional<DesignState> load() override;
  std::int64_t step() const override { return step_; }
  /// Every elimination saved, in order (what `status --complete` would show).
  const std::vector<Elimination>& eliminations() const { return eliminations_; }

 private:
  std::int64_t step_ = 0;
  std::optional<nlohmann::json> state_;  // state_to_json(state, false): no history
  History history_;
  std::vector<Elimination> eliminations_;
};

}  // namespace sd::design
