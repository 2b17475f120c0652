#include <gtest/gtest.h>

#include "core/rng.hpp"
#include "simulator/epuck.hpp"
#include "simulator/placement.hpp"

namespace sd {
namespace {

ArenaModel dodecagon() {
  ArenaModel arena;
  for (int k = 0; k < 12; ++k) {
    Wall w;
    const double phi = k * kPi / 6;
    w.center = Vec2::polar(1.231, phi);
    w.axis = Vec2::polar(1.0, phi + kPi / 2);
    w.half_length = 0.33;
    w.half_thickness = 0.005;
    arena.walls.push_back(w);
  }
  arena.compile();
  return arena;
}

TEST(Placement, RobotsNeverOverlapWallsOrEachOther) {
  const ArenaModel arena = dodecagon();
  const Region start = Region::circle({0, 0}, 1.2);
  for (std::uint64_t seed = 1; seed <= 50; ++seed) {
    Rng rng(seed);
    SwarmState s;
    s.resize(40);
    place_robots(arena, start, s, rng);
    for (int i = 0; i < s.size; ++i) {
      EXPECT_TRUE(start.contains(s.position[i]));
      for (const Wall& w : arena.walls) EXPECT_GE(w.distance(s.position[i], nullptr), epuck::kBodyRadius);
      for (int j = 0; j < i; ++j) EXPECT_GE((s.position[i] - s.position[j]).length(), 2 * epuck::kBodyRadius);
      EXPECT_NEAR(s.heading[i].x, std::cos(s.yaw[i]), 1e-12);
    }
  }
}

TEST(Placement, DiscSamplingIsUniformOverTheArea) {
  Rng rng(5);
  const Region disc = Region::circle({0, 0}, 1.0);
  int inner = 0;
  const int n = 40000;
  for (int i = 0; i < n; ++i) inner += sample_point(disc, rng).length() < 0.5;
  EXPECT_NEAR(static_cast<double>(inner) / n, 0.25, 0.01);  // area fraction, not radius fraction
}

TEST(Placement, TooManyRobotsFailWithAClearError) {
  const ArenaModel arena = dodecagon();
  Rng rng(1);
  SwarmState s;
  s.resize(200);
  try {
    place_robots(arena, Region::circle({0, 0}, 0.2), s, rng);
    FAIL() << "expected an error";
  } catch (const std::runtime_error& e) {
    EXPECT_NE(std::string(e.what()).find("cannot place robot"), std::string::npos);
  }
}

}  // namespace
}  // namespace sd
