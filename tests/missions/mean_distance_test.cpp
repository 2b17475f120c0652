// Coverage by Monte-Carlo sample points (CFA, SPC): exact values where every sample gives
// the same distance, and expectations computed by hand (with >= 4-sigma tolerances) otherwise.
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

#include "missions/catalogue.hpp"
#include "missions/objective.hpp"
#include "scripted_swarm.hpp"

namespace sd {
namespace {

using test::place;
using test::end_time_value;
using test::swarm_parked_at;

TEST(MeanDistance, ExactWhenEverySampleIsAtTheSameDistance) {
  // Points on a circle of radius 0.5 around robot 0: d = 0.5 for every sample.
  MeanDistanceTerm term;
  term.points.kind = PointSampler::Kind::OnCircle;
  term.points.region = Region::circle({1, 1}, 0.5);
  term.count = 100;
  term.missing_distance = 9.0;
  term.weight = 3.0;
  term.normalizer = 0.25;
  MeanDistanceObjective params;
  params.terms = {term};
  params.offset = 1.0;
  MeanDistanceScore score(params, {2, 10});
  SwarmState s = swarm_parked_at(2, {1, 1});
  s.position[1] = {5, 5};  // farther from every sample than robot 0
  Rng rng(3);
  score.post_step(s, 10, rng);
  EXPECT_NEAR(score.value(), 1.0 + 3.0 * 0.5 / 0.25, 1e-12);
  // No robot passes the filter: every sample takes the missing distance.
  params.terms[0].robots = {RobotFilter::Kind::InZone, {Region::circle({-5, -5}, 0.1)}};
  score.post_step(s, 10, rng);
  EXPECT_NEAR(score.value(), 1.0 + 3.0 * 9.0 / 0.25, 1e-12);
  // at_least is a floor.
  params.at_least = 200.0;
  score.post_step(s, 10, rng);
  EXPECT_EQ(score.value(), 200.0);
}

TEST(MeanDistance, CfaIsZeroWhenEveryRobotIsOnAForbiddenArea) {
  const Mission m = load_mission("cfa");
  SwarmState s = swarm_parked_at(m.robots, {0.5, 0.5});
  place(s, {{0.5, -0.5}, {-0.5, 0.0}, {-0.2, 0.0}});  // (-0.2, 0) is on the rim of (-0.5, 0)
  // E[d] = 2.5 (no allowed robot): F = max(0, (2.5 - 2.5) * 100) = 0.
  EXPECT_NEAR(end_time_value(m, s), 0.0, 1e-9);
}

TEST(MeanDistance, CfaSamplesArePolarUniformNotAreaUniform) {
  const Mission m = load_mission("cfa");
  SwarmState s = swarm_parked_at(m.robots, {0.5, 0.5});  // on a forbidden area
  s.position[0] = {0.0, 0.0};                             // the only allowed robot
  s.position[1] = {-0.2, 0.0};                            // on the rim of (-0.5, 0): forbidden
  // d = rho ~ U(0, 1.2): E[d] = 0.6, F = (2.5 - 0.6) * 100 = 190 (area-uniform points would
  // give E[d] = 0.8, F = 170). sd(rho) = 1.2 / sqrt(12) = 0.346, so F has sd 0.35.
  EXPECT_NEAR(end_time_value(m, s, 1), 190.0, 1.5);
  EXPECT_NEAR(end_time_value(m, s, 2), 190.0, 1.5);
  EXPECT_EQ(end_time_value(m, s, 7), end_time_value(m, s, 7)) << "same seed, same score";
  EXPECT_NE(end_time_value(m, s, 7), end_time_value(m, s, 8)) << "the samples come from the run's generator";
}

TEST(MeanDistance, SpcWithNobodyOnEitherPatchIsTheWorstValue) {
  const Mission m = load_mission("spc");
  EXPECT_EQ(m.objective.direction, Direction::Minimize);
  SwarmState s = swarm_parked_at(m.robots, {0.0, 0.8});
  // A robot 0.05 m off the circle is not "on the perimeter" (tolerance 0.04).
  s.position[0] = {0.95, 0.0};
  EXPECT_NEAR(end_time_value(m, s), 0.85 / 0.08 + 0.6 / 0.06, 1e-9);  // 20.625
}

TEST(MeanDistance, SpcAreaTermWithOneRobotAtTheSquaresCentre) {
  const Mission m = load_mission("spc");
  SwarmState s = swarm_parked_at(m.robots, {0.0, 0.8});
  s.position[0] = {-0.6, 0.0};
  // Mean distance from the centre of a square of side a to a uniform point:
  // a (sqrt 2 + ln(1 + sqrt 2)) / 6 = 0.2296 for a = 0.6 (sd 0.085, so 0.034 after / 0.08).
  const double d_a = 0.6 * (std::sqrt(2.0) + std::log(1.0 + std::sqrt(2.0))) / 6.0;
  EXPECT_NEAR(end_time_value(m, s), d_a / 0.08 + 0.6 / 0.06, 0.15);
  // The square's bounds are inclusive: a robot on its corner counts. From a corner the mean
  // distance is a (sqrt 2 + ln(1 + sqrt 2)) / 3 (sd 0.068 after / 0.08).
  s.position[0] = {-0.3, 0.3};
  EXPECT_NEAR(end_time_value(m, s), 2.0 * d_a / 0.08 + 0.6 / 0.06, 0.3);
}

TEST(MeanDistance, SpcPerimeterTermWithOneRobotOnTheCircle) {
  const Mission m = load_mission("spc");
  SwarmState s = swarm_parked_at(m.robots, {0.0, 0.8});
  s.position[0] = {0.9, 0.0};  // on the circle of radius 0.3 around (0.6, 0)
  // A sample at angle theta from the robot is a chord 0.6 |sin(theta / 2)| away: mean
  // 0.6 * 2 / pi = 0.382 (sd 0.185, so 0.1 after / 0.06).
  const double d_p = 0.6 * 2.0 / std::numbers::pi;
  EXPECT_NEAR(end_time_value(m, s), 0.85 / 0.08 + d_p / 0.06, 0.4);
  // 0.035 m off the circle still counts as on the perimeter.
  s.position[0] = {0.935, 0.0};
  EXPECT_LT(end_time_value(m, s), 18.0);
}

}  // namespace
}  // namespace sd
