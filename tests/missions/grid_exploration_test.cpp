// Grid exploration (Coconut's GridExplorationLoopFunc): cell ages counted by hand on a 2 x 2
// grid, and the mission's 10 x 10 grid.
#include <gtest/gtest.h>

#include "missions/catalogue.hpp"
#include "missions/objective.hpp"
#include "scripted_swarm.hpp"

namespace sd {
namespace {

using test::swarm_parked_at;

TEST(GridExploration, AgesCountedByHandOnATwoByTwoGrid) {
  // Cells of side 1 over [-1, 1]^2: (column, row) = (0, 0) bottom left ... (1, 1) top right.
  const GridExplorationObjective params{.center = {0, 0}, .side = 2.0, .cells = 2};
  GridExplorationScore score(params, {1, 100});
  score.reset();
  SwarmState s = swarm_parked_at(1, {0.5, 0.5});
  Rng rng(1);
  // Tick 1: ages (0 0 0 0), robot in (1,1): sum 0, then all ages 1.
  score.post_step(s, 1, rng);
  EXPECT_EQ(score.value(), 0.0);
  // Tick 2: robot in (0,0): ages (0,1,1,1), sum 3; then (1,2,2,2).
  s.position[0] = {-0.5, -0.5};
  score.post_step(s, 2, rng);
  EXPECT_EQ(score.value(), 3.0 / 4);
  // Tick 3: x = -1.05 is below the grid, but trunc(2 * (-0.525 + 0.5)) = trunc(-0.05) = 0,
  // so the robot still visits column 0 (the original's truncation); row 1.
  // Ages (0,0)=1 (1,0)=2 (0,1)=0 (1,1)=2: sum 5, total 8.
  s.position[0] = {-1.05, 0.5};
  score.post_step(s, 3, rng);
  EXPECT_EQ(score.value(), 8.0 / 4);
  EXPECT_EQ(score.age(0, 1), 1);
  // Tick 4: far outside, ignored: ages 2 + 3 + 1 + 3 = 9, total 17.
  s.position[0] = {5.0, 5.0};
  score.post_step(s, 4, rng);
  EXPECT_EQ(score.value(), 17.0 / 4);
  EXPECT_EQ(score.age(1, 1), 4);
  score.reset();
  EXPECT_EQ(score.value(), 0.0);
  EXPECT_EQ(score.age(1, 1), 0);
}

TEST(GridExploration, MissionGridIsTenByTenOverTheArena) {
  const Mission m = load_mission("grid-exploration");
  EXPECT_EQ(m.objective.direction, Direction::Minimize);
  ObjectiveTracker objective(m);
  objective.reset();
  // Everyone at the centre, cell (5, 5): tick 1 sums 0, tick 2 sums the 99 other cells.
  SwarmState s = swarm_parked_at(m.robots, {0.0, 0.0});
  Rng rng(1);
  objective.post_step(s, 1, rng);
  objective.post_step(s, 2, rng);
  EXPECT_DOUBLE_EQ(objective.value(), 99.0 / 1000.0);  // the mission's scale 0.1
  // Tick 3: robots 1..9 in columns 1..9 of row 4, robots 10..19 in columns 0..9 of row 5
  // (cells of side 0.250001, points 0.1 m inside them), robot 0 in (5, 7): 20 distinct cells
  // at age 0. The 80 others are 2 (cell (5, 5), visited at tick 2, is visited again by robot 15).
  for (int i = 1; i < 20; ++i) s.position[static_cast<std::size_t>(i)] = {-1.1 + 0.25 * (i % 10), -0.1 + 0.25 * (i / 10)};
  s.position[0] = {0.1, 0.6};
  objective.post_step(s, 3, rng);
  EXPECT_DOUBLE_EQ(objective.value(), (99.0 + 80 * 2.0) / 1000.0);
}

}  // namespace
}  // namespace sd
