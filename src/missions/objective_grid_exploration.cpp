#include "missions/objective_grid_exploration.hpp"

#include <algorithm>

#include "missions/json_field.hpp"

namespace sd {

GridExplorationObjective read_grid_exploration(const Field& f) {
  f.only({"type", "direction", "center", "side", "cells", "scale"});
  GridExplorationObjective o;
  o.center = f.at("center").vec2();
  o.side = f.at("side").positive();
  o.cells = f.at("cells").integer_in(1, 1000);
  o.scale = f.positive_or("scale", 1.0);
  return o;
}

GridExplorationScore::GridExplorationScore(const GridExplorationObjective& params, RunContext)
    : params_(&params), ages_(static_cast<std::size_t>(params.cells * params.cells), 0) {}

void GridExplorationScore::reset() {
  std::fill(ages_.begin(), ages_.end(), 0);
  total_ = 0.0;
}

void GridExplorationScore::post_step(const SwarmState& swarm, int /*tick*/, Rng& /*rng*/) {
  const int n = params_->cells;
  for (int i = 0; i < swarm.size; ++i) {
    const Vec2 p = swarm.position[static_cast<std::size_t>(i)] - params_->center;
    const double u = n * (p.x / params_->side + 0.5), v = n * (p.y / params_->side + 0.5);
    if (!(u > -1.0 && u < n && v > -1.0 && v < n)) continue;  // outside the grid (or NaN)
    // Truncation towards zero, not floor: the original's int conversion, so (-1, 0) -> 0.
    const int column = static_cast<int>(u), row = static_cast<int>(v);
    const int cell = row * n + column;
    ages_[static_cast<std::size_t>(cell)] = 0;
  }
  long long sum = 0;
  for (long long& a : ages_) {
    sum += a;
    ++a;
  }
  total_ += static_cast<double>(sum);
}

}  // namespace sd
