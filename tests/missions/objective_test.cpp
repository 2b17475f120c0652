// Per-tick region counts (AAC, SCA, Coconut aggregation) and end-time best-region fractions
// (Vanilla aggregation, aggregation-XOR) on scripted positions, against counts by hand.
#include <gtest/gtest.h>

#include "missions/catalogue.hpp"
#include "missions/objective.hpp"
#include "scripted_swarm.hpp"

namespace sd {
namespace {

using test::place;
using test::swarm_parked_at;

TEST(RegionCount, AacCountsRobotsOnTheBlackSpotEveryTick) {
  const Mission m = load_mission("aac");
  ObjectiveTracker objective(m);
  objective.reset();
  SwarmState s = swarm_parked_at(m.robots, {0.0, 0.0});
  Rng rng(1);
  // Tick 1: two robots inside the disc of radius 0.3 around (0, 0.6), one exactly on the
  // rim (inclusive), one on the white spot.
  place(s, {{0.0, 0.6}, {0.1, 0.7}, {0.3, 0.6}, {0.0, -0.6}});
  objective.post_step(s, 1, rng);
  EXPECT_EQ(objective.value(), 3.0);
  // Tick 2: one leaves.
  s.position[1] = {0.0, 0.2};
  objective.post_step(s, 2, rng);
  EXPECT_EQ(objective.value(), 5.0);
  // Tick 3: just outside the rim does not count.
  place(s, {{0.0, 0.9000001}, {0.0, 0.0}, {0.0, 0.0}, {0.0, 0.0}});
  objective.post_step(s, 3, rng);
  EXPECT_EQ(objective.value(), 5.0);
  objective.reset();
  EXPECT_EQ(objective.value(), 0.0);
}

TEST(RegionCount, ScaCountsTheShelterWithStrictBounds) {
  const Mission m = load_mission("sca");
  ObjectiveTracker objective(m);
  objective.reset();
  SwarmState s = swarm_parked_at(m.robots, {0.0, 0.5});  // north of the shelter: outside
  Rng rng(1);
  // In: the centre, and just inside a corner. Out: on the x = 0.3 edge, on the y = -0.075
  // edge (both strict), and on a black disc.
  place(s, {{0.0, 0.0}, {0.2999, 0.0749}, {0.3, 0.0}, {0.0, -0.075}, {0.8, -0.1}});
  objective.post_step(s, 1, rng);
  EXPECT_EQ(objective.value(), 2.0);
  objective.post_step(s, 2, rng);
  EXPECT_EQ(objective.value(), 4.0);
}

TEST(RegionCount, CoconutAggregationCountsRobotsOffTheSpot) {
  const Mission m = load_mission("coconut-aggregation");
  EXPECT_EQ(m.objective.direction, Direction::Minimize);
  ObjectiveTracker objective(m);
  objective.reset();
  SwarmState s = swarm_parked_at(m.robots, {0.0, 0.0});  // all on the spot: cost 0
  Rng rng(1);
  objective.post_step(s, 1, rng);
  EXPECT_EQ(objective.value(), 0.0);
  // On the rim still counts as on the spot (|p| <= 0.3); just beyond does not.
  place(s, {{0.3, 0.0}, {0.0, -0.30001}, {1.0, 0.0}});
  objective.post_step(s, 2, rng);
  EXPECT_EQ(objective.value(), 2.0);
}

TEST(BestRegion, AggregationXorScoresTheFullerSpotAtTheEndOnly) {
  const Mission m = load_mission("aggregation-xor");
  ASSERT_EQ(m.ticks, 1800);
  ObjectiveTracker objective(m);
  objective.reset();
  SwarmState s = swarm_parked_at(m.robots, {0.0, 0.9});  // on neither spot
  // Spot (+0.65, 0): 5 robots, one on the rim; spot (-0.65, 0): 3 robots.
  place(s, {{0.65, 0.0}, {0.7, 0.1}, {0.6, -0.1}, {0.65, 0.2}, {0.95, 0.0},  //
            {-0.65, 0.0}, {-0.7, 0.0}, {-0.6, 0.0}});
  Rng rng(1);
  objective.post_step(s, 1, rng);
  EXPECT_EQ(objective.value(), 0.0) << "scored before the last tick";
  objective.post_step(s, m.ticks, rng);
  EXPECT_DOUBLE_EQ(objective.value(), 5.0 / 20.0);
  // The other spot wins once it holds more robots.
  place(s, {{0.0, 0.9}, {0.0, 0.9}, {0.0, 0.9}, {0.0, 0.9}, {0.0, 0.9}});
  s.position[8] = {-0.65, 0.25};
  objective.post_step(s, m.ticks, rng);
  EXPECT_DOUBLE_EQ(objective.value(), 4.0 / 20.0);
}

TEST(BestRegion, ARobotOnOverlappingRegionsCountsForTheFirstOnly) {
  BestRegionObjective params;
  params.regions = {Region::circle({0, 0}, 0.5), Region::circle({0.4, 0}, 0.5)};
  BestRegionScore score(params, {4, 10});
  score.reset();
  SwarmState s = swarm_parked_at(4, {0.2, 0.0});  // in both
  s.position[3] = {0.8, 0.0};                     // only in the second
  Rng rng(1);
  score.post_step(s, 10, rng);
  EXPECT_DOUBLE_EQ(score.value(), 3.0 / 4.0);
}

TEST(BestRegion, VanillaAggregationUsesSpotsAt055AndTheRepositoryDuration) {
  const Mission m = load_mission("aggregation");
  EXPECT_EQ(m.ticks, 2500);
  ObjectiveTracker objective(m);
  objective.reset();
  SwarmState s = swarm_parked_at(m.robots, {-0.55, 0.0});  // everyone on the left spot
  Rng rng(1);
  objective.post_step(s, m.ticks, rng);
  EXPECT_DOUBLE_EQ(objective.value(), 1.0);
  s = swarm_parked_at(m.robots, {0.65 + 0.25, 0.0});  // 0.35 from (0.55, 0): off the spot
  objective.post_step(s, m.ticks, rng);
  EXPECT_DOUBLE_EQ(objective.value(), 0.0);
}

}  // namespace
}  // namespace sd
