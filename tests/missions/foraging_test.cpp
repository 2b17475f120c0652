// Foraging with carry state, on scripted trajectories: Vanilla (value 1 per item), Coconut
// (-1 per item) and TuttiFrutti-style sources of opposite values.
#include <gtest/gtest.h>

#include "missions/catalogue.hpp"
#include "missions/objective.hpp"
#include "scripted_swarm.hpp"

namespace sd {
namespace {

using test::swarm_parked_at;

/// Robot 0 follows `path`, one point per tick; returns the objective after each tick.
std::vector<double> run_path(const Mission& m, const std::vector<Vec2>& path) {
  ObjectiveTracker objective(m);
  objective.reset();
  SwarmState s = swarm_parked_at(m.robots, {0.0, 0.5});  // neither source nor nest
  Rng rng(1);
  std::vector<double> values;
  for (std::size_t t = 0; t < path.size(); ++t) {
    s.position[0] = path[t];
    objective.post_step(s, static_cast<int>(t + 1), rng);
    values.push_back(objective.value());
  }
  return values;
}

TEST(Foraging, VanillaDeliversOneItemPerSourceThenNestVisit) {
  const Mission m = load_mission("foraging");
  const std::vector<Vec2> path = {
      {0.0, -0.8},    // nest, empty-handed: nothing
      {0.75, 0.0},    // source: picks an item
      {0.80, 0.1},    // still in the source (0.112 <= 0.15)
      {0.0, 0.0},     // travelling
      {0.0, -0.7},    // nest: delivers (1)
      {0.0, -0.9},    // nest again: nothing left to deliver
      {-0.75, 0.15},  // the other source, on its rim
      {0.3, -0.6},    // y = -0.6 exactly is in the nest: delivers (2)
      {-0.75, 0.0},   // source
      {0.0, -0.59},   // just above the nest line: nothing
  };
  const std::vector<double> expected = {0, 0, 0, 0, 1, 1, 1, 2, 2, 2};
  EXPECT_EQ(run_path(m, path), expected);
}

TEST(Foraging, CoconutCountsDeliveriesNegatively) {
  const Mission m = load_mission("coconut-foraging");
  EXPECT_EQ(m.objective.direction, Direction::Minimize);
  const std::vector<Vec2> path = {{0.75, 0.0}, {0.0, -0.7}, {-0.75, 0.0}, {1.0, -0.65}};
  const std::vector<double> expected = {0, -1, -1, -2};
  EXPECT_EQ(run_path(m, path), expected);
}

TEST(Foraging, EveryRobotCarriesItsOwnItem) {
  ForagingObjective params;
  params.sources = {{Region::circle({1, 0}, 0.1), 1.0}};
  params.nest = Limits{.x_max = -0.5};
  ForagingScore score(params, {3, 100});
  score.reset();
  SwarmState s = swarm_parked_at(3, {0, 0});
  Rng rng(1);
  s.position[1] = {1.0, 0.0};  // robot 1 picks an item
  score.post_step(s, 1, rng);
  EXPECT_EQ(score.carried(1), 0);
  EXPECT_EQ(score.carried(0), ForagingScore::kNothing);
  s.position = {{-1, 0}, {-1, 0}, {-1, 0}};  // all three reach the nest: one item only
  score.post_step(s, 2, rng);
  EXPECT_EQ(score.value(), 1.0);
  score.reset();
  EXPECT_EQ(score.value(), 0.0);
  EXPECT_EQ(score.carried(1), ForagingScore::kNothing);
}

TEST(Foraging, ALaterSourceOverwritesTheItemAndTheFirstMatchingSourceWins) {
  // TuttiFrutti foraging (TuttiFrLoopFunc): source 1 (bottom) +1, source 2 (top) -1.
  ForagingObjective params;
  params.sources = {{Limits{.x_min = 0.565, .y_max = -0.006}, 1.0}, {Limits{.x_min = 0.565, .y_min = 0.006}, -1.0}};
  params.nest = Limits{.x_max = -0.565};
  ForagingScore score(params, {1, 100});
  score.reset();
  SwarmState s = swarm_parked_at(1, {0, 0});
  Rng rng(1);
  const std::vector<Vec2> path = {{0.6, -0.3}, {0.6, 0.3}, {-0.6, 0.0},   // 1 then 2: delivers a 2 (-1)
                                  {0.6, 0.3}, {0.6, -0.3}, {-0.7, 0.2},   // 2 then 1: delivers a 1 (+1)
                                  {0.6, 0.0}, {-0.7, 0.0}};               // between the sources: nothing
  std::vector<double> values;
  for (std::size_t t = 0; t < path.size(); ++t) {
    s.position[0] = path[t];
    score.post_step(s, static_cast<int>(t + 1), rng);
    values.push_back(score.value());
  }
  EXPECT_EQ(values, (std::vector<double>{0, 0, -1, -1, -1, 0, 0, 0}));
}

}  // namespace
}  // namespace sd
