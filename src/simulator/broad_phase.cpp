#include "simulator/broad_phase.hpp"

#include <algorithm>
#include <limits>

namespace sd {

namespace {

constexpr double kCloseSq = kProximityPairRange * kProximityPairRange;

}  // namespace

void BroadPhase::resize(std::size_t n) {
  const std::size_t slots = pair_count(n) + 1;  // one spare slot for the branch-free appends
  grid.reserve(n);
  candidates.assign(n, 0);
  close_pairs.assign(slots, 0);
  close_pair_count = 0;
  position_x.assign(n, 0.0);
  position_y.assign(n, 0.0);
  pairs.reserve(pair_count(n));
}

void BroadPhase::use_neighbour_grid(bool on, std::size_t n) {
  use_grid = on;
  pair_range = 0.0;
  close_pair_count = 0;
  // The close pairs no longer describe any positions (see built_from).
  std::fill(position_x.begin(), position_x.end(), std::numeric_limits<double>::quiet_NaN());
  pairs.clear();
  if (on) return;  // listed by build
  for (std::size_t a = 0; a < n; ++a)
    for (std::size_t b = a + 1; b < n; ++b)
      pairs.push_back({static_cast<std::uint16_t>(a), static_cast<std::uint16_t>(b), {}, 0.0});
}

/// The pairs within `range` of a large swarm, from the neighbour grid, in the order of the
/// full table (a, then b, ascending) so that everything downstream runs as in a small swarm.
void BroadPhase::list_near_pairs(std::span<const Vec2> position, double range) {
  const int size = static_cast<int>(position.size());
  pair_range = range;
  grid.build(position_x.data(), position_y.data(), size, range);
  const double range_sq = range * range;
  pairs.clear();  // capacity for every pair is reserved: no allocation
  int close = 0;
  for (int a = 0; a < size; ++a) {
    const double x = position_x[a], y = position_y[a];
    std::size_t count = 0;
    grid.for_each_run_near({x, y}, {x, y}, range, [&](int begin, int end) {
      // Whether a robot of the box is a later one within range is a coin toss for the branch
      // predictor: each is written, and the count advances only for those kept (a is never
      // kept, so at most size - 1 are and the write stays within the buffer).
      for (int k = begin; k < end; ++k) {
        const double dx = grid.x()[k] - x, dy = grid.y()[k] - y;
        const std::uint16_t b = grid.robot()[k];
        candidates[count] = b;
        count += ((b > a) & (dx * dx + dy * dy < range_sq)) ? 1 : 0;
      }
    });
    std::sort(candidates.begin(), candidates.begin() + static_cast<std::ptrdiff_t>(count));
    for (std::size_t k = 0; k < count; ++k) {
      const std::uint16_t b = candidates[k];
      const Vec2 delta = position[b] - position[a];
      const double distance_sq = delta.squared_length();
      close_pairs[static_cast<std::size_t>(close)] = static_cast<std::uint32_t>(pairs.size());
      close += distance_sq < kCloseSq ? 1 : 0;
      pairs.push_back({static_cast<std::uint16_t>(a), b, delta, distance_sq});
    }
  }
  close_pair_count = close;
}

void BroadPhase::build(std::span<const Vec2> position, double range) {
  for (std::size_t i = 0; i < position.size(); ++i) {
    position_x[i] = position[i].x;
    position_y[i] = position[i].y;
  }
  if (use_grid) {
    list_near_pairs(position, std::max(range, kProximityPairRange));
    return;
  }
  // Whether a pair is close is a coin toss for the branch predictor inside a cluster, so
  // every index is written and the count advances only for close pairs.
  int close = 0;
  for (std::size_t k = 0; k < pairs.size(); ++k) {
    RobotPair& pair = pairs[k];
    pair.delta = position[pair.b] - position[pair.a];
    pair.distance_sq = pair.delta.squared_length();
    close_pairs[static_cast<std::size_t>(close)] = static_cast<std::uint32_t>(k);
    close += pair.distance_sq < kCloseSq ? 1 : 0;
  }
  close_pair_count = close;
}

}  // namespace sd
