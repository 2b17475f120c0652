// LCN (ChocolateLCNLoopFunc): components by hand, covered areas from circle geometry, and the
// bounding-box quirk seen through the number of random draws it consumes.
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
constexpr double kPi = std::numbers::pi;

/// Area of the intersection of two discs (radii r, R) whose centres are d apart.
double lens_area(double r, double R, double d) {
  if (d >= r + R) return 0.0;
  if (d <= std::abs(R - r)) return kPi * std::min(r, R) * std::min(r, R);
  const double a = r * r * std::acos((d * d + r * r - R * R) / (2 * d * r));
  const double b = R * R * std::acos((d * d + R * R - r * r) / (2 * d * R));
  const double c = 0.5 * std::sqrt((-d + r + R) * (d + r - R) * (d - r + R) * (d + r + R));
  return a + b - c;
}

/// 20 robots on a circle of radius 1.15, 2 * 1.15 * sin(9 deg) = 0.36 m apart: no links.
SwarmState isolated_robots() {
  SwarmState s = swarm_parked_at(20, {});
  for (int i = 0; i < 20; ++i) s.position[static_cast<std::size_t>(i)] = Vec2::polar(1.15, kPi / 10 * i);
  return s;
}

TEST(NetworkCoverage, LinksAreStrictlyShorterThanTheRangeAndTiesKeepTheFirstComponent) {
  const Mission m = load_mission("lcn");
  const auto& params = std::get<NetworkCoverageObjective>(m.objective.parameters);
  NetworkCoverageScore score(params, {m.robots, m.ticks});
  SwarmState s = isolated_robots();
  // Chain 0-1-2 with links of 0.34 (< 0.35); robot 3 exactly 0.35 from robot 2: no link.
  place(s, {{0.0, 0.0}, {0.34, 0.0}, {0.68, 0.0}, {0.68, 0.35}});
  s.position[4] = {-0.5, 0.0};
  s.position[5] = {-0.5, 0.2};  // a second component of two
  auto group = score.largest_component(s);
  ASSERT_EQ(group.size(), 3u);
  EXPECT_EQ(group[2], (Vec2{0.68, 0.0}));
  // Two components of three: the one holding the lowest robot index wins.
  s.position[6] = {-0.5, -0.2};
  group = score.largest_component(s);
  EXPECT_EQ(group.front(), (Vec2{0.0, 0.0}));
  // A chain, not a clique: 5 is linked to 4, 4 to 6, and 6 pulls in 7.
  s.position[7] = {-0.5, -0.5};
  group = score.largest_component(s);
  ASSERT_EQ(group.size(), 4u);
  EXPECT_EQ(group.front(), (Vec2{-0.5, 0.0}));
}

TEST(NetworkCoverage, OneRobotCoversADiscOfTheSensingRadius) {
  const Mission m = load_mission("lcn");
  SwarmState s = isolated_robots();  // robot 0 (first of 20 singletons) is G
  s.position[0] = {0.5, 0.5};
  // pi 0.25^2 = 0.19635; 25 000 points in a 0.5 x 0.5 box: sd 0.25 sqrt(p (1 - p) / n) = 0.0007.
  EXPECT_NEAR(end_time_value(m, s), kPi * 0.0625, 0.003);
}

TEST(NetworkCoverage, TwoLinkedRobotsCoverTheUnionOfTheirDiscs) {
  const Mission m = load_mission("lcn");
  SwarmState s = isolated_robots();
  s.position[0] = {0.0, 0.0};
  s.position[1] = {0.3, 0.0};  // linked (0.3 < 0.35)
  const double union_area = 2 * kPi * 0.0625 - lens_area(0.25, 0.25, 0.3);
  EXPECT_NEAR(end_time_value(m, s), union_area, 0.004);
}

TEST(NetworkCoverage, CoverageIsClippedToTheDiscOfDistributionRadius) {
  const Mission m = load_mission("lcn");
  SwarmState s = isolated_robots();
  s.position[0] = {1.15, 0.0};  // its disc reaches 0.2 m beyond the 1.2 m clip circle
  EXPECT_NEAR(end_time_value(m, s), lens_area(0.25, 1.2, 1.15), 0.003);
}

TEST(NetworkCoverage, TheBoxQuirkStretchesTheSamplingBoxToTheOrigin) {
  const Mission m = load_mission("lcn");
  const auto& params = std::get<NetworkCoverageObjective>(m.objective.parameters);
  ASSERT_TRUE(params.box_max_from_zero);
  SwarmState s = isolated_robots();
  s.position[0] = {-0.5, -0.5};
  NetworkCoverageScore score(params, {m.robots, m.ticks});
  score.largest_component(s);
  // With the quirk, the box is [-0.75, 0.25]^2 (max x, y start at 0): 1 m^2, 100 000 points,
  // two draws each. Without it, [-0.75, -0.25]^2: 25 000 points.
  for (const bool quirk : {true, false}) {
    NetworkCoverageObjective p = params;
    p.box_max_from_zero = quirk;
    NetworkCoverageScore q(p, {m.robots, m.ticks});
    q.largest_component(s);
    Rng rng(11), expected(11);
    const double area = q.covered_area(rng);
    for (int k = 0; k < (quirk ? 200000 : 50000); ++k) expected.uniform();
    EXPECT_EQ(rng.next(), expected.next()) << "quirk " << quirk;
    EXPECT_NEAR(area, kPi * 0.0625, 0.004) << "the estimate itself is unaffected";
  }
}

}  // namespace
}  // namespace sd
