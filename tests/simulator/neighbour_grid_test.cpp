// The neighbour grid narrows which robots a large swarm looks at; it must never drop one
// that the full scan would have found, nor change the order pairs come in.
#include <gtest/gtest.h>

#include <algorithm>
#include <set>
#include <vector>

#include "core/rng.hpp"
#include "simulator/neighbour_grid.hpp"
#include "simulator/sensors.hpp"

namespace sd {
namespace {

struct Cloud {
  std::vector<double> x, y;
};

/// Half the robots spread over a square, half packed into a small cluster (as aggregation
/// makes them), so cells hold from none to many.
Cloud cloud(int robots, double half_width, std::uint64_t seed) {
  Rng rng(seed);
  Cloud c;
  for (int i = 0; i < robots; ++i) {
    const double spread = i % 2 ? half_width : 0.2;
    c.x.push_back(rng.uniform(-spread, spread));
    c.y.push_back(rng.uniform(-spread, spread));
  }
  return c;
}

std::vector<int> robots_in_runs(const NeighbourGrid& grid, double lo_x, double lo_y, double hi_x, double hi_y) {
  std::vector<int> found;
  grid.for_each_run(lo_x, lo_y, hi_x, hi_y, [&](int begin, int end) {
    for (int k = begin; k < end; ++k) found.push_back(grid.robot()[k]);
  });
  return found;
}

TEST(NeighbourGrid, ABoxQueryHoldsEveryRobotInTheBoxOnce) {
  const Cloud c = cloud(300, 3.0, 11);
  NeighbourGrid grid;
  grid.reserve(300);
  grid.build(c.x.data(), c.y.data(), 300, 0.5);
  // Every robot is binned once, with its own coordinates.
  const std::vector<int> all = robots_in_runs(grid, -10, -10, 10, 10);
  ASSERT_EQ(all.size(), 300u);
  EXPECT_EQ(std::set<int>(all.begin(), all.end()).size(), 300u);
  for (int k = 0; k < 300; ++k) {
    EXPECT_EQ(grid.x()[k], c.x[grid.robot()[k]]);
    EXPECT_EQ(grid.y()[k], c.y[grid.robot()[k]]);
  }
  Rng rng(3);
  for (int q = 0; q < 200; ++q) {
    const double cx = rng.uniform(-3.5, 3.5), cy = rng.uniform(-3.5, 3.5), half = rng.uniform(0.0, 1.5);
    const std::vector<int> found = robots_in_runs(grid, cx - half, cy - half, cx + half, cy + half);
    const std::set<int> unique(found.begin(), found.end());
    EXPECT_EQ(unique.size(), found.size()) << "a robot offered twice";
    for (int i = 0; i < 300; ++i)
      if (std::abs(c.x[i] - cx) <= half && std::abs(c.y[i] - cy) <= half) {
        EXPECT_TRUE(unique.count(i)) << "robot " << i << " missing from box " << q;
      }
    // Narrowing is the point: a small box must not return the whole swarm.
    if (half < 0.3) {
      EXPECT_LT(found.size(), 300u);
    }
  }
}

TEST(NeighbourGrid, KeepsToItsCellBudgetWhenRobotsStandFarApart) {
  // 200 robots along a 1 km line with 10 cm cells asked for: far more cells than the buffers
  // hold, so the cells grow instead; queries stay exact.
  Cloud c;
  for (int i = 0; i < 200; ++i) {
    c.x.push_back(5.0 * i);
    c.y.push_back(0.0);
  }
  NeighbourGrid grid;
  grid.reserve(200);
  grid.build(c.x.data(), c.y.data(), 200, 0.1);
  for (int i = 0; i < 200; ++i) {
    const std::vector<int> found = robots_in_runs(grid, c.x[i] - 0.1, -0.1, c.x[i] + 0.1, 0.1);
    EXPECT_NE(std::find(found.begin(), found.end(), i), found.end()) << i;
  }
}

/// The pairs a state lists, as (a, b, delta, distance^2), and its close pairs as (a, b).
struct Listed {
  std::vector<RobotPair> pairs;
  std::vector<std::pair<int, int>> close;
};

Listed listed(const SwarmState& s, double range) {
  Listed out;
  for (const RobotPair& p : s.broad_phase.pairs)
    if (p.distance_sq < range * range) out.pairs.push_back(p);
  for (int k = 0; k < s.broad_phase.close_pair_count; ++k) {
    const RobotPair& p = s.broad_phase.pairs[s.broad_phase.close_pairs[static_cast<std::size_t>(k)]];
    out.close.emplace_back(p.a, p.b);
  }
  return out;
}

TEST(NeighbourGrid, ListsThePairsWithinRangeAsTheFullTableDoesInItsOrder) {
  for (const int robots : {2, 30, 120}) {
    const Cloud c = cloud(robots, 2.5, static_cast<std::uint64_t>(robots));
    SwarmState full, grid;
    for (SwarmState* s : {&full, &grid}) {
      s->resize(robots);
      for (int i = 0; i < robots; ++i) s->position[i] = {c.x[i], c.y[i]};
    }
    full.use_neighbour_grid(false);
    grid.use_neighbour_grid(true);
    full.broad_phase.build(full.position, 0.8);
    grid.broad_phase.build(grid.position, 0.8);
    const Listed a = listed(full, 0.8), b = listed(grid, 0.8);
    EXPECT_EQ(b.pairs.size(), grid.broad_phase.pairs.size()) << "the grid lists only pairs within range";
    ASSERT_EQ(a.pairs.size(), b.pairs.size()) << robots << " robots";
    for (std::size_t k = 0; k < a.pairs.size(); ++k) {
      EXPECT_EQ(a.pairs[k].a, b.pairs[k].a);
      EXPECT_EQ(a.pairs[k].b, b.pairs[k].b);
      EXPECT_EQ(a.pairs[k].delta, b.pairs[k].delta);
      EXPECT_EQ(a.pairs[k].distance_sq, b.pairs[k].distance_sq);
    }
    EXPECT_EQ(a.close, b.close);
    if (robots == 120) {
      EXPECT_GT(b.close.size(), 10u);  // the cluster makes close pairs
    }
  }
}

TEST(NeighbourGrid, ClosePairsOfASwarmOfMoreThan362RobotsAreTheRightOnes) {
  // 400 robots have 79 800 pairs: pair indices no longer fit 16 bits. Robots 398 and 399
  // touch, and nothing else does; their pair is the very last one.
  SwarmState s;
  s.resize(400);
  s.use_neighbour_grid(false);
  for (int i = 0; i < 400; ++i) s.position[i] = {0.5 * (i % 20), 0.5 * (i / 20)};
  s.position[399] = s.position[398] + Vec2{0.07, 0.0};
  s.broad_phase.build(s.position);
  ASSERT_EQ(s.broad_phase.close_pair_count, 1);
  const RobotPair& p = s.broad_phase.pairs[s.broad_phase.close_pairs[0]];
  EXPECT_EQ(p.a, 398);
  EXPECT_EQ(p.b, 399);
}

}  // namespace
}  // namespace sd
