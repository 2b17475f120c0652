// Objectives on scripted robot positions, against values counted by hand.
#include <gtest/gtest.h>

#include "missions/catalogue.hpp"
#include "missions/objective.hpp"

namespace sd {
namespace {

TEST(Objective, AacCountsRobotsOnTheBlackSpotEveryTick) {
  const Mission m = load_mission("aac");
  ObjectiveTracker objective(m);
  objective.reset();
  SwarmState s;
  s.resize(4);
  Rng rng(1);
  // Tick 1: two robots inside the disc of radius 0.3 around (0, 0.6), one exactly on the
  // rim (inclusive), one on the white spot.
  s.position = {{0.0, 0.6}, {0.1, 0.7}, {0.3, 0.6}, {0.0, -0.6}};
  objective.post_step(s, 1, rng);
  EXPECT_EQ(objective.value(), 3.0);
  // Tick 2: one leaves.
  s.position[1] = {0.0, 0.2};
  objective.post_step(s, 2, rng);
  EXPECT_EQ(objective.value(), 5.0);
  // Tick 3: just outside the rim does not count.
  s.position = {{0.0, 0.9000001}, {0.0, 0.0}, {0.0, 0.0}, {0.0, 0.0}};
  objective.post_step(s, 3, rng);
  EXPECT_EQ(objective.value(), 5.0);
  objective.reset();
  EXPECT_EQ(objective.value(), 0.0);
}

}  // namespace
}  // namespace sd
