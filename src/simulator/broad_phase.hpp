#pragma once
// The broad phase: the pairs of robots close enough to matter this tick, listed once per tick
// (after physics, before sensing) and read by the sensors (proximity, range and bearing) and
// by the next physics step (its contact candidates). It owns the neighbour grid the sensors'
// occlusion tests also query. Exact distances only: which pairs it lists never depends on
// whether the grid is used.
#include <cstddef>
#include <cstdint>
#include <span>
#include <vector>

#include "core/geometry.hpp"
#include "simulator/epuck.hpp"
#include "simulator/neighbour_grid.hpp"

namespace sd {

/// One unordered pair of robots, refreshed every tick after physics.
struct RobotPair {
  std::uint16_t a, b;
  Vec2 delta;          // position[b] - position[a]
  double distance_sq;
};

/// Unordered pairs of `robots` robots: the length of BroadPhase::pairs in a small swarm.
constexpr std::size_t pair_count(std::size_t robots) { return robots * (robots - 1) / 2; }

/// Centre distance below which a proximity ray of one robot can meet the other's body.
inline constexpr double kProximityPairRange = epuck::kProximityRingRadius + epuck::kProximityRange + epuck::kBodyRadius;

/// From this many robots on, pairs are found with the neighbour grid. In AAC's density
/// (bench/, BM_Scaling*) the grid is 1.2-1.4x faster than all pairs at 75-100 robots for
/// exploration and as fast for attraction; at 20-50 robots all pairs are faster.
inline constexpr int kNeighbourGridFromRobots = 75;

struct BroadPhase {
  /// Whether the pairs come from the neighbour grid (only those within pair_range, listed
  /// anew each tick) or are all pairs of the swarm. The same pairs within range, in the same
  /// order, either way: the grid only saves looking at far ones, which in a small swarm
  /// costs more than it saves.
  bool use_grid = false;
  NeighbourGrid grid;
  /// The centre distance within which `pairs` holds every pair (grid only).
  double pair_range = 0.0;
  /// Pairs i < j in lexicographic order: all of them in a small swarm, those within
  /// pair_range in a large one.
  std::vector<RobotPair> pairs;
  /// Indices into `pairs` of the pairs close enough for a proximity ray to meet the other
  /// body (the first close_pair_count entries): physics' contact candidates come from these.
  std::vector<std::uint32_t> close_pairs;
  int close_pair_count = 0;
  /// The positions the pairs were built from, as two plain arrays: the line-of-sight tests
  /// scan every robot at once, and contiguous coordinates let that scan vectorise.
  std::vector<double> position_x, position_y;
  /// Robots the grid offered one robot, sorted before use (grid only): scratch for build and
  /// for the sensors' grid queries.
  std::vector<std::uint16_t> candidates;

  /// Sizes every buffer for `robots` robots, so that build never allocates.
  void resize(std::size_t robots);
  /// Chooses how pairs are found (SwarmState::resize picks the faster for the swarm's size);
  /// results do not depend on it. Forgets the last build.
  void use_neighbour_grid(bool on, std::size_t robots);
  /// Lists the pairs within `range` at least (and kProximityPairRange), their close pairs and
  /// the position arrays, for these positions.
  void build(std::span<const Vec2> position, double range = kProximityPairRange);
  /// True if the last build was from exactly these positions (nothing moved a robot since:
  /// an arrest rule may move robots between sensing and the next physics step), so that
  /// physics may take its contact candidates from the close pairs. A comparison, not a
  /// stamp, so a robot moved by anyone makes the pairs stale without anyone having to say so.
  bool built_from(std::span<const Vec2> position) const {
    bool same = position.size() == position_x.size();
    for (std::size_t i = 0; same && i < position.size(); ++i) same = position[i].x == position_x[i] && position[i].y == position_y[i];
    return same;
  }

 private:
  void list_near_pairs(std::span<const Vec2> position, double range);
};

}  // namespace sd
