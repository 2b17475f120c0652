#pragma once
// Coconut grid exploration (AmmarHsn/loop_functions' GridExplorationLoopFunc): a square of
// `cells` x `cells` cells, each with an age, initially 0. Every tick: (1) the cell of every
// robot gets age 0; (2) the sum of all ages is added to a total; (3) every age grows by 1. F =
// total / number of cells, i.e. the sum over ticks of the mean time since a cell was last
// visited, times `scale` (default 1; the loop function's current version divides by 10 more:
// scale 0.1). Minimise. A robot's cell is trunc(cells * (x / side + 1/2)) per axis, as the
// original, so a robot just below the square's lower edge still falls in cell 0; outside
// 0..cells-1 it is ignored. Cells the robots cannot reach (the square's corners outside the
// dodecagon) just age.
#include <vector>

#include "missions/objective_base.hpp"

namespace sd {

class GridExplorationScore;

struct GridExplorationObjective {
  using Score = GridExplorationScore;
  Vec2 center;
  double side = 2.50001;
  int cells = 10;  // per side
  double scale = 1.0;
};

/// {"center": [x, y], "side": 2.50001, "cells": 10, "scale": 0.1}
GridExplorationObjective read_grid_exploration(const Field& f);

class GridExplorationScore {
 public:
  GridExplorationScore(const GridExplorationObjective& params, RunContext run);
  void reset();
  void post_step(const SwarmState& swarm, int tick, Rng& rng);
  double value() const { return total_ / static_cast<double>(ages_.size()) * params_->scale; }
  /// The age of cell (column, row) after the last tick.
  long long age(int column, int row) const {
    const int cell = row * params_->cells + column;
    return ages_[static_cast<std::size_t>(cell)];
  }

 private:
  const GridExplorationObjective* params_;
  std::vector<long long> ages_;
  double total_ = 0.0;
};

}  // namespace sd
