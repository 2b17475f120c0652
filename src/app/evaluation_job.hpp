#pragma once
// Scoring control software on a list of seeds — `evaluate`, `test-design`, a web request —
// on any Evaluator, in batches so that a watcher sees progress without any score depending on
// the batching; and one run recorded tick by tick (a trace).
#include <cstdint>
#include <filesystem>
#include <functional>
#include <vector>

#include "control/control_software.hpp"
#include "evaluation/evaluator.hpp"
#include "evaluation/simulation.hpp"
#include "missions/mission.hpp"

namespace sd::app {

struct ScoreOptions {
  int threads = 0;                 // local threads when no evaluator is given (0: all cores)
  Evaluator* evaluator = nullptr;  // another backend
  /// Called after each batch with (runs done, runs in all); batches are then a few runs per
  /// worker, else the whole list goes out at once.
  std::function<void(std::size_t, std::size_t)> progress;
};

/// Scores per seed, in seed order.
std::vector<double> score_seeds(const Mission& mission, const ControlSoftware& software,
                                const std::vector<std::uint64_t>& seeds, const ScoreOptions& options = {});

/// One run watched tick by tick (a viewer, a trace): the same run, and the same score, as
/// score_seeds gives for that seed.
double observed_run(const Mission& mission, const ControlSoftware& software, std::uint64_t seed,
                    TickObserver& observer);

/// One run whose every tick (poses, LEDs, running objective) is written to `trace` as CSV;
/// returns its score, the same as score_seeds gives for that seed.
double traced_run(const Mission& mission, const ControlSoftware& software, std::uint64_t seed,
                  const std::filesystem::path& trace);

}  // namespace sd::app
