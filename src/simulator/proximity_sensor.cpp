#include <array>
#include <cmath>

#include "core/branchless.hpp"
#include "core/math.hpp"
#include "simulator/epuck.hpp"
#include "simulator/sensor_noise.hpp"
#include "simulator/sensors.hpp"

namespace sd {

namespace {

constexpr double kRadius = epuck::kBodyRadius;

struct RayDirections {
  std::array<double, 8> cos{}, sin{};
  RayDirections() {
    for (int k = 0; k < 8; ++k) {
      const double a = degrees_to_radians(epuck::kProximityFirstRayDegrees + 45.0 * k);
      const math::SinCos sc = math::sincos(a);
      cos[k] = sc.cos;
      sin[k] = sc.sin;
    }
  }
};
const RayDirections kRays;

/// The ray k (counter-clockwise) such that a direction `v` in the robot's frame lies between
/// rays k and k + 1 (mod 8), found without trigonometry and without branches (the bearing
/// of a neighbour is a coin toss for the predictor): rotate by the first ray's angle, then
/// the half plane, the quadrant within it and the octant within that are three comparisons.
int bracketing_ray(Vec2 v) {
  const double x = v.x * kRays.cos[0] + v.y * kRays.sin[0], y = v.y * kRays.cos[0] - v.x * kRays.sin[0];
  const int lower = y < 0.0 ? 1 : 0;
  const int left = (x < 0.0 ? 1 : 0) ^ lower;  // after the half turn that brings y up
  const int second = (std::abs(y) > std::abs(x) ? 1 : 0) ^ left;
  return 4 * lower + 2 * left + second;
}

}  // namespace

void sense_proximity(const ArenaModel& arena, const RobotModel& model, SwarmState& swarm, Rng& rng) {
  constexpr double kRing = epuck::kProximityRingRadius;
  constexpr double kNoHit = 2.0 * epuck::kProximityRange;  // reads 0
  // First the distance along each ray to the nearest body (kept in the reading array), then
  // the readings. Bodies come from the close pairs, both ways; the minimum does not depend
  // on the order in which they are met.
  for (int i = 0; i < swarm.size; ++i) swarm.proximity[i].fill(kNoHit);
  auto cast_towards = [&](int i, Vec2 delta, double distance_sq) {
    std::array<double, 8>& best = swarm.proximity[i];
    const Vec2 h = swarm.heading[i];
    // The other body, in the robot's frame: ray k starts at kRing u_k and runs along u_k.
    const Vec2 c{h.x * delta.x + h.y * delta.y, h.x * delta.y - h.y * delta.x};
    const double base = distance_sq - kRadius * kRadius + kRing * kRing;
    auto cast = [&](int k) {  // branch-free: whether a ray meets the body is a coin toss
      const double along = c.x * kRays.cos[k] + c.y * kRays.sin[k];
      const double b = kRing - along;               // (origin - centre) . u
      const double q = base - 2.0 * kRing * along;  // |origin - centre|^2 - r^2
      const double disc = b * b - q;
      const double entry = -b - std::sqrt(max0(disc));
      double t = select((disc >= 0.0) & (b <= 0.0), entry, kNoHit);
      t = select(q <= 0.0, 0.0, t);  // the sensor point is inside the other body
      best[k] = t < best[k] ? t : best[k];
    };
    // Rays are radial, so a body seen from the centre under a half-angle below 45 degrees
    // (any body further than r sqrt 2, i.e. every body that does not overlap) can only
    // meet the two rays that bracket its bearing; the others would find no root.
    if (distance_sq > 2.0 * kRadius * kRadius) {
      const int k = bracketing_ray(c);
      cast(k);
      cast((k + 1) & 7);
    } else {
      for (int k = 0; k < 8; ++k) cast(k);
    }
  };
  for (int n = 0; n < swarm.broad_phase.close_pair_count; ++n) {
    const RobotPair& pair = swarm.broad_phase.pairs[swarm.broad_phase.close_pairs[static_cast<std::size_t>(n)]];
    if (swarm.demand[pair.a] & SwarmState::kDemandProximity) cast_towards(pair.a, pair.delta, pair.distance_sq);
    if (swarm.demand[pair.b] & SwarmState::kDemandProximity) cast_towards(pair.b, -pair.delta, pair.distance_sq);
  }
  for (int i = 0; i < swarm.size; ++i) {
    std::array<double, 8>& reading = swarm.proximity[i];
    if (!(swarm.demand[i] & SwarmState::kDemandProximity)) {
      reading.fill(0.0);
      continue;
    }
    const Vec2 p = swarm.position[i], h = swarm.heading[i];
    SegmentBatch rays;
    bool rays_ready = false;
    for (const std::uint16_t w : arena.walls_near(p)) {
      const Wall& wall = arena.walls[w];
      constexpr double kReach = kRing + epuck::kProximityRange;
      if (wall.surely_beyond(p, kReach) || wall.distance(p, nullptr) > kReach) continue;
      if (!rays_ready) {  // the 8 rays as segments, once per robot near a wall
        for (std::size_t k = 0; k < 8; ++k) {
          const Vec2 dir{h.x * kRays.cos[k] - h.y * kRays.sin[k], h.y * kRays.cos[k] + h.x * kRays.sin[k]};
          const Vec2 origin = p + dir * kRing, end = origin + dir * epuck::kProximityRange;
          rays.ax[k] = origin.x;
          rays.ay[k] = origin.y;
          rays.bx[k] = end.x;
          rays.by[k] = end.y;
        }
        rays_ready = true;
      }
      std::array<double, 8> t;
      wall.segment_entries(rays, t);
      // A ray starting inside the wall does not see it (Chipmunk's segment query only tests
      // the sides its start lies in front of): a robot that starts inside a wall added after
      // placement senses only what lies beyond. Only for such walls: a robot touching any
      // wall has its nearest ring origin 1 mm inside it, and ARGoS would not see that wall
      // either, but the shipped calibration (AAC, foraging) stands on the reading it gives.
      if (wall.placed_after_robots && wall.distance(p, nullptr) < kRing)
        for (std::size_t k = 0; k < 8; ++k)
          if (t[k] == 0.0 && wall.contains({rays.ax[k], rays.ay[k]})) t[k] = 2.0;
      for (std::size_t k = 0; k < 8; ++k) {
        const double hit = t[k] * epuck::kProximityRange;
        reading[k] = t[k] <= 1.0 && hit < reading[k] ? hit : reading[k];
      }
    }
    for (double& v : reading) v = epuck::proximity_reading(v);
    if (swarm.deviations.active) scale_readings(reading, swarm.deviations.proximity[static_cast<std::size_t>(i)]);
    add_uniform_noise(reading, model.proximity_noise, rng);
  }
}

}  // namespace sd
