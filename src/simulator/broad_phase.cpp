#include "simulator/sensors.hpp"

#include <algorithm>

#include "simulator/neighbour_grid.hpp"

namespace sd {

namespace {

constexpr double kCloseSq = kProximityPairRange * kProximityPairRange;

/// The pairs within `range` of a large swarm, from the neighbour grid, in the order of the
/// full table (a, then b, ascending) so that everything downstream runs as in a small swarm.
void list_near_pairs(SwarmState& swarm, double range) {
  SensorWorkspace& ws = swarm.sensing;
  ws.pair_range = range;
  ws.grid.build(ws.position_x.data(), ws.position_y.data(), swarm.size, range);
  const NeighbourGrid& grid = ws.grid;
  const double range_sq = range * range;
  swarm.pairs.clear();  // capacity for every pair is reserved: no allocation
  int close = 0;
  for (int a = 0; a < swarm.size; ++a) {
    const double x = ws.position_x[a], y = ws.position_y[a];
    std::size_t count = 0;
    grid.for_each_run_near({x, y}, {x, y}, range, [&](int begin, int end) {
      // Whether a robot of the box is a later one within range is a coin toss for the branch
      // predictor: each is written, and the count advances only for those kept (a is never
      // kept, so at most size - 1 are and the write stays within the buffer).
      for (int k = begin; k < end; ++k) {
        const double dx = grid.x()[k] - x, dy = grid.y()[k] - y;
        const std::uint16_t b = grid.robot()[k];
        ws.candidates[count] = b;
        count += (b > a) & (dx * dx + dy * dy < range_sq) ? 1 : 0;
      }
    });
    std::sort(ws.candidates.begin(), ws.candidates.begin() + static_cast<std::ptrdiff_t>(count));
    for (std::size_t k = 0; k < count; ++k) {
      const std::uint16_t b = ws.candidates[k];
      const Vec2 delta = swarm.position[b] - swarm.position[a];
      const double distance_sq = delta.squared_length();
      ws.close_pairs[static_cast<std::size_t>(close)] = static_cast<std::uint32_t>(swarm.pairs.size());
      close += distance_sq < kCloseSq ? 1 : 0;
      swarm.pairs.push_back({static_cast<std::uint16_t>(a), b, delta, distance_sq});
    }
  }
  ws.close_pair_count = close;
}

}  // namespace

void update_pairs(SwarmState& swarm, double range) {
  for (int i = 0; i < swarm.size; ++i) {
    swarm.sensing.position_x[i] = swarm.position[i].x;
    swarm.sensing.position_y[i] = swarm.position[i].y;
  }
  if (swarm.sensing.use_grid) {
    list_near_pairs(swarm, std::max(range, kProximityPairRange));
    return;
  }
  // Whether a pair is close is a coin toss for the branch predictor inside a cluster, so
  // every index is written and the count advances only for close pairs.
  int close = 0;
  for (std::size_t k = 0; k < swarm.pairs.size(); ++k) {
    RobotPair& pair = swarm.pairs[k];
    pair.delta = swarm.position[pair.b] - swarm.position[pair.a];
    pair.distance_sq = pair.delta.squared_length();
    swarm.sensing.close_pairs[static_cast<std::size_t>(close)] = static_cast<std::uint32_t>(k);
    close += pair.distance_sq < kCloseSq ? 1 : 0;
  }
  swarm.sensing.close_pair_count = close;
}

}  // namespace sd
