#include <algorithm>
#include <cmath>

#include "core/vector_clones.hpp"
#include "simulator/epuck.hpp"
#include "simulator/neighbour_grid.hpp"
#include "simulator/sensors.hpp"

namespace sd {

namespace {

constexpr double kRadius = epuck::kBodyRadius;

}  // namespace

namespace {

/// 1 if one of the centres (x[k], y[k]), k in [begin, end), lies within r of the line
/// through a along ab and projects strictly inside the segment, else 0. One branch-free
/// pass, which vectorises: a hit selects 1 instead of adding it, so no lane waits for the
/// sum of another.
SD_VECTOR_CLONES double body_on_segment(const double* x, const double* y, int begin, int end, double ax, double ay,
                                        double abx, double aby, double len2) {
  const double line_limit = kRadius * kRadius * len2;
  double hit = 0.0;
  for (int k = begin; k < end; ++k) {
    const double cx = x[k] - ax, cy = y[k] - ay;
    const double along = cx * abx + cy * aby;
    const double cross = cx * aby - cy * abx;
    hit = ((along > 0.0) & (along < len2) & (cross * cross < line_limit)) ? 1.0 : hit;
  }
  return hit;
}

/// True if no other robot's body touches the segment between the two robots of `pair`. The
/// RAB ray runs at 5.2 cm, below every body's top, so any body on it blocks the packet.
bool no_robot_between(const SwarmState& swarm, const RobotPair& pair) {
  // A body touches the segment a-b when its centre projects strictly inside the segment and
  // lies within r of the line. (Its distance to an end would also do, but no body comes
  // within r of another's centre, and the two ends themselves project onto the segment's
  // ends, so they are not counted.)
  const BroadPhase& ws = swarm.broad_phase;
  const double ax = ws.position_x[pair.a], ay = ws.position_y[pair.a];
  const double abx = pair.delta.x, aby = pair.delta.y, len2 = pair.distance_sq;
  if (!ws.use_grid) return body_on_segment(ws.position_x.data(), ws.position_y.data(), 0, swarm.size, ax, ay, abx, aby, len2) == 0.0;
  // Only centres within r of the segment can touch it.
  double hit = 0.0;
  ws.grid.for_each_run_near({ax, ay}, {ws.position_x[pair.b], ws.position_y[pair.b]}, kRadius, [&](int begin, int end) {
    if (hit == 0.0) hit = body_on_segment(ws.grid.x(), ws.grid.y(), begin, end, ax, ay, abx, aby, len2);
  });
  return hit == 0.0;
}

/// The packet a receiver gets from a sender `offset` (sender minus receiver, world frame, m)
/// away, seen with heading h, with argos3-epuck's position noise: a vector of length N(0, s)
/// whose inclination and azimuth are uniform (as its sensor draws them) is added to the
/// offset in 3D, and the range is that vector's length.
RabPacket noisy_packet(Vec2 offset, Vec2 h, double noise, std::uint16_t sender, Rng& rng) {
  const double length = noise * rng.normal();
  const math::SinCos inclination = math::sincos(rng.uniform(0.0, kPi));
  const math::SinCos azimuth = math::sincos(rng.uniform(0.0, 2.0 * kPi));
  const Vec2 v{offset.x + length * inclination.sin * azimuth.cos, offset.y + length * inclination.sin * azimuth.sin};
  const double z = length * inclination.cos;
  const double horizontal = v.length();
  const Vec2 u = horizontal > 0.0 ? v * (1.0 / horizontal) : Vec2{1.0, 0.0};
  const double range_cm = std::sqrt(horizontal * horizontal + z * z) * 100.0 - epuck::kRabRangeOffsetCm;
  return {range_cm, {h.x * u.x + h.y * u.y, h.x * u.y - h.y * u.x}, sender};
}

}  // namespace

void sense_range_and_bearing(const ArenaModel& arena, const RobotModel& model, SwarmState& swarm, Rng& rng) {
  std::fill(swarm.rab_count.begin(), swarm.rab_count.end(), 0);
  const double max_range = model.max_rab_range();
  if (swarm.broad_phase.use_grid && swarm.broad_phase.pair_range < max_range) swarm.broad_phase.build(swarm.position, max_range);
  const std::size_t stride = swarm.rab_stride();
  const double range_sq = max_range * max_range;
  const auto loss_threshold = static_cast<std::uint64_t>(model.rab_loss * 4294967296.0);
  // Whether a pair is in range, and whether a packet survives loss, are coin tosses for the
  // branch predictor; the pairs are therefore filtered in two branch-free passes (every
  // index written, the count advanced only for the kept ones), in pair order as before.
  std::uint32_t* kept = swarm.sensing.rab_pairs.data();
  int in_range = 0;
  for (std::size_t k = 0; k < swarm.broad_phase.pairs.size(); ++k) {
    kept[in_range] = static_cast<std::uint32_t>(k);
    in_range += swarm.broad_phase.pairs[k].distance_sq < range_sq ? 1 : 0;
  }
  // Loss is drawn first: line of sight is only worth computing for the 28 % of pairs where a
  // packet survives, and the outcome is the same in distribution. One 64-bit draw gives both
  // directions' 32-bit Bernoulli draws (ARGoS' resolution).
  std::uint64_t* received = swarm.sensing.rab_receivers.data();
  int surviving = 0;
  for (int n = 0; n < in_range; ++n) {
    const std::uint64_t bits = rng.next();
    std::uint64_t to_a = (bits >> 32) >= loss_threshold ? 1 : 0;
    std::uint64_t to_b = (bits & 0xffffffffu) >= loss_threshold ? 2 : 0;
    if (swarm.deviations.active) {  // a packet reaches as far as its sender's own range
      const RobotPair& pair = swarm.broad_phase.pairs[kept[n]];
      const double from_a = swarm.deviations.rab_range[pair.a], from_b = swarm.deviations.rab_range[pair.b];
      to_a = pair.distance_sq < from_b * from_b ? to_a : 0;
      to_b = pair.distance_sq < from_a * from_a ? to_b : 0;
    }
    kept[surviving] = kept[n];
    received[surviving] = to_a | to_b;
    surviving += (to_a | to_b) != 0 ? 1 : 0;
  }
  // Whether a packet arrives is a coin toss too, so each is written to its receiver's next
  // slot and counted only if it arrived. A receiver meets each other robot once, so at most
  // size - 2 packets precede a write: the slot is always within its stride.
  const double noise = model.rab_noise;
  for (int n = 0; n < surviving; ++n) {
    const RobotPair& pair = swarm.broad_phase.pairs[kept[n]];
    const bool visible = arena.line_of_sight_walls(swarm.position[pair.a], swarm.position[pair.b]) &&
                         no_robot_between(swarm, pair);
    const std::uint64_t arrived = visible ? received[n] : 0;
    const Vec2 ha = swarm.heading[pair.a], hb = swarm.heading[pair.b];
    RabPacket& at_a = swarm.rab[pair.a * stride + swarm.rab_count[pair.a]];
    RabPacket& at_b = swarm.rab[pair.b * stride + swarm.rab_count[pair.b]];
    if (noise > 0.0) {  // a pseudo-reality's: one draw per packet that arrives
      if (arrived & 1) at_a = noisy_packet(pair.delta, ha, noise, pair.b, rng);
      if (arrived & 2) at_b = noisy_packet(-pair.delta, hb, noise, pair.a, rng);
    } else {
      const double distance = std::sqrt(pair.distance_sq);
      const double range_cm = distance * 100.0 - epuck::kRabRangeOffsetCm;
      const Vec2 u = pair.delta * (1.0 / distance);  // from a towards b, world frame
      at_a = {range_cm, {ha.x * u.x + ha.y * u.y, ha.x * u.y - ha.y * u.x}, pair.b};
      at_b = {range_cm, {-(hb.x * u.x + hb.y * u.y), -(hb.x * u.y - hb.y * u.x)}, pair.a};
    }
    swarm.rab_count[pair.a] = static_cast<std::uint16_t>(swarm.rab_count[pair.a] + (arrived & 1));
    swarm.rab_count[pair.b] = static_cast<std::uint16_t>(swarm.rab_count[pair.b] + (arrived >> 1));
  }
}

}  // namespace sd
