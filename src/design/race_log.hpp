#pragma once
// Who was dropped from a race, and when: the engine's checkpoint keeps only the race in
// progress, so the race log of `status --complete` is collected step by step from the state
// the engine exposes between a race step and the end of its race (IteratedRace::on_progress).
#include <cstddef>
#include <vector>

#include "design/state.hpp"

namespace sd::design {

struct Elimination {
  int iteration = 0;
  int configuration_id = 0;
  std::size_t after_instances = 0;  // instances the race had processed when it was dropped
};

class EliminationTracker {
 public:
  /// Starts from a (restored) state: configurations already dead in its race are not reported.
  void reset(const DesignState& state);
  /// Records the configurations that died since the last call; drained by take().
  void observe(const DesignState& state);
  std::vector<Elimination> take();

 private:
  int iteration_ = 0;
  std::vector<char> alive_;
  std::vector<Elimination> pending_;
};

}  // namespace sd::design
