#include "simulator/sensors.hpp"

#include <algorithm>
#include <cmath>
#include <span>

#include "core/branchless.hpp"
#include "core/math.hpp"
#include "core/vector_clones.hpp"
#include "simulator/epuck.hpp"
#include "simulator/neighbour_grid.hpp"

namespace sd {

namespace {

constexpr double kRadius = epuck::kBodyRadius;

/// Adds uniform noise in [-level, level) to each reading and clamps it to [0, 1] (the
/// e-puck's proximity, light and ground sensors), drawn as one batch.
template <std::size_t N>
void add_uniform_noise(std::array<double, N>& readings, double level, Rng& rng) {
  std::array<double, N> noise;
  rng.coarse_uniforms(-level, level, noise.data(), static_cast<int>(N));
  for (std::size_t k = 0; k < N; ++k) readings[k] = clamp01(readings[k] + noise[k]);
}

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

double ray_disc_entry(Vec2 origin, Vec2 direction, Vec2 center, double radius) {
  const Vec2 oc = origin - center;
  const double b = dot(oc, direction);
  const double c = oc.squared_length() - radius * radius;
  if (c <= 0.0) return 0.0;
  const double disc = b * b - c;
  if (disc < 0.0 || b > 0.0) return -1.0;
  return -b - std::sqrt(disc);
}

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
  for (int n = 0; n < swarm.sensing.close_pair_count; ++n) {
    const RobotPair& pair = swarm.pairs[swarm.sensing.close_pairs[static_cast<std::size_t>(n)]];
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
    add_uniform_noise(reading, model.proximity_noise, rng);
  }
}

void sense_light(const ArenaModel& arena, const RobotModel& model, SwarmState& swarm, Rng& rng) {
  const int n = swarm.size;
  for (int i = 0; i < n; ++i) {
    std::array<double, 8>& reading = swarm.light[i];
    reading.fill(0.0);
    if (!(swarm.demand[i] & SwarmState::kDemandLight)) continue;
    const Vec2 p = swarm.position[i];
    for (std::size_t l = 0; l < arena.lights.size(); ++l) {
      const Light& light = arena.lights[l];
      if (light.intensity <= 0.0) continue;
      const Vec2 to_light = light.position.xy() - p;
      // Occlusion: the ray rises from the robot's ground point to the light; a body of
      // height H blocks it only within the first H / z of the way.
      bool occluded = false;
      for (const std::uint16_t w : arena.walls_shading(l, p)) {
        const double t = arena.light_clearance_fraction(l, arena.walls[w].height);
        // A robot inside a wall added after placement is not shaded by it: Chipmunk's segment
        // query ignores a shape the ray starts in (the same rule as the proximity rays').
        const Wall& wall = arena.walls[w];
        const double entry = wall.segment_entry(p, p + to_light * t);
        if (entry <= 1.0 && !(entry == 0.0 && wall.placed_after_robots && wall.contains(p))) {
          occluded = true;
          break;
        }
      }
      if (!occluded) {
        const double reach = to_light.length() * arena.light_clearance_fraction(l, epuck::kBodyHeight);
        const double reach_sq = (reach + kRadius) * (reach + kRadius);
        const Vec2 dir = to_light * (1.0 / to_light.length());
        auto blocks = [&](Vec2 center) {
          const double t = ray_disc_entry(p, dir, center, kRadius);
          return t >= 0.0 && t <= reach;
        };
        auto blocks_from = [&](int j) {
          return j != i && (swarm.position[j] - p).squared_length() < reach_sq && blocks(swarm.position[j]);
        };
        if (!swarm.sensing.use_grid) {
          for (int j = 0; j < n && !occluded; ++j) occluded = blocks_from(j);
        } else {  // a blocking body's centre lies within r of the ray's first `reach`
          const NeighbourGrid& grid = swarm.sensing.grid;
          grid.for_each_run_near(p, p + dir * reach, kRadius, [&](int begin, int end) {
            for (int k = begin; k < end && !occluded; ++k) occluded = blocks_from(grid.robot()[k]);
          });
        }
      }
      if (occluded) continue;
      const double dz = light.position.z;
      const double distance = std::sqrt(to_light.squared_length() + dz * dz) / light.intensity;
      if (distance > 2.5) continue;
      const double base = math::exp(-2.0 * distance);
      const double bearing = to_light.angle() - swarm.yaw[i];
      for (int k = 0; k < 8; ++k) {
        const double delta = std::abs(wrap_signed(bearing - epuck::kSensorAngles[k]));
        if (delta < kPi / 2.0) reading[k] += base * (1.0 - 2.0 * delta / kPi);
      }
    }
    add_uniform_noise(reading, model.light_noise, rng);
  }
}

void sense_ground(const ArenaModel& arena, const RobotModel& model, SwarmState& swarm, Rng& rng) {
  for (int i = 0; i < swarm.size; ++i) {
    const double uniform = arena.uniform_floor_gray(swarm.position[i]);
    const double c = swarm.heading[i].x, s = swarm.heading[i].y;
    for (int k = 0; k < 3; ++k) {
      double gray = uniform;
      if (gray < 0.0) {  // near a patch edge: each sensor's own point
        const Vec2 o = epuck::kGroundSensorOffsets[k];
        gray = arena.floor_gray(swarm.position[i] + Vec2{c * o.x - s * o.y, s * o.x + c * o.y});
      }
      swarm.ground[i][k] = gray;
    }
    add_uniform_noise(swarm.ground[i], model.ground_noise, rng);
  }
}

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
    hit = (along > 0.0) & (along < len2) & (cross * cross < line_limit) ? 1.0 : hit;
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
  const SensorWorkspace& ws = swarm.sensing;
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

}  // namespace

void sense_range_and_bearing(const ArenaModel& arena, const RobotModel& model, SwarmState& swarm, Rng& rng) {
  std::fill(swarm.rab_count.begin(), swarm.rab_count.end(), 0);
  if (swarm.sensing.use_grid && swarm.sensing.pair_range < model.rab_range) update_pairs(swarm, model.rab_range);
  const std::size_t stride = swarm.rab_stride();
  const double range_sq = model.rab_range * model.rab_range;
  const auto loss_threshold = static_cast<std::uint64_t>(model.rab_loss * 4294967296.0);
  // Whether a pair is in range, and whether a packet survives loss, are coin tosses for the
  // branch predictor; the pairs are therefore filtered in two branch-free passes (every
  // index written, the count advanced only for the kept ones), in pair order as before.
  std::uint32_t* kept = swarm.sensing.rab_pairs.data();
  int in_range = 0;
  for (std::size_t k = 0; k < swarm.pairs.size(); ++k) {
    kept[in_range] = static_cast<std::uint32_t>(k);
    in_range += swarm.pairs[k].distance_sq < range_sq ? 1 : 0;
  }
  // Loss is drawn first: line of sight is only worth computing for the 28 % of pairs where a
  // packet survives, and the outcome is the same in distribution. One 64-bit draw gives both
  // directions' 32-bit Bernoulli draws (ARGoS' resolution).
  std::uint64_t* received = swarm.sensing.rab_receivers.data();
  int surviving = 0;
  for (int n = 0; n < in_range; ++n) {
    const std::uint64_t bits = rng.next();
    const std::uint64_t to_a = (bits >> 32) >= loss_threshold ? 1 : 0;
    const std::uint64_t to_b = (bits & 0xffffffffu) >= loss_threshold ? 2 : 0;
    kept[surviving] = kept[n];
    received[surviving] = to_a | to_b;
    surviving += (to_a | to_b) != 0 ? 1 : 0;
  }
  // Whether a packet arrives is a coin toss too, so each is written to its receiver's next
  // slot and counted only if it arrived. A receiver meets each other robot once, so at most
  // size - 2 packets precede a write: the slot is always within its stride.
  for (int n = 0; n < surviving; ++n) {
    const RobotPair& pair = swarm.pairs[kept[n]];
    const bool visible = arena.line_of_sight_walls(swarm.position[pair.a], swarm.position[pair.b]) &&
                         no_robot_between(swarm, pair);
    const std::uint64_t arrived = visible ? received[n] : 0;
    const double distance = std::sqrt(pair.distance_sq);
    const double range_cm = distance * 100.0 - epuck::kRabRangeOffsetCm;
    const Vec2 u = pair.delta * (1.0 / distance);  // from a towards b, world frame
    const Vec2 ha = swarm.heading[pair.a], hb = swarm.heading[pair.b];
    swarm.rab[pair.a * stride + swarm.rab_count[pair.a]] = {range_cm, {ha.x * u.x + ha.y * u.y, ha.x * u.y - ha.y * u.x}, pair.b};
    swarm.rab_count[pair.a] = static_cast<std::uint16_t>(swarm.rab_count[pair.a] + (arrived & 1));
    swarm.rab[pair.b * stride + swarm.rab_count[pair.b]] = {range_cm, {-(hb.x * u.x + hb.y * u.y), -(hb.x * u.y - hb.y * u.x)}, pair.a};
    swarm.rab_count[pair.b] = static_cast<std::uint16_t>(swarm.rab_count[pair.b] + (arrived >> 1));
  }
}

void sense_camera(const ArenaModel& arena, const RobotModel& model, SwarmState& swarm) {
  // argos3-epuck's rot_z_only camera (epuck_omnidirectional_camera_sensor.cpp) keeps an LED
  // when |dx| and |dy| of its offset from the camera are both below the ground half-range
  // 0.122 tan 70 deg: a square aligned with the world axes, not a disc, and the height
  // difference does not count.
  const double half_range = model.camera_range;
  auto in_view = [half_range](Vec2 offset) { return std::abs(offset.x) < half_range && std::abs(offset.y) < half_range; };
  for (int i = 0; i < swarm.size; ++i) {
    const auto r = static_cast<std::size_t>(i);
    CameraBlob* out = swarm.blobs.data() + r * static_cast<std::size_t>(swarm.blobs_per_robot);
    std::uint16_t count = 0;
    if (!(swarm.demand[r] & SwarmState::kDemandCamera)) {
      swarm.blob_count[r] = 0;
      continue;
    }
    const Vec2 p = swarm.position[r], h = swarm.heading[r];
    const Vec3 camera{p.x, p.y, epuck::kCameraElevation};
    auto add = [&](std::uint32_t rgb, Vec2 offset) {
      const double d = offset.length();
      const Vec2 local{h.x * offset.x + h.y * offset.y, h.x * offset.y - h.y * offset.x};
      out[count++] = {rgb, d > 0.0 ? local * (1.0 / d) : Vec2{1.0, 0.0}, d * 100.0};
    };
    // Robots never occlude LEDs: the ray stays above their 7.6 cm tops down to 7.65 cm.
    auto see_robot = [&](int j) {
      const std::uint32_t rgb = swarm.led[static_cast<std::size_t>(j)];
      if (rgb == 0 || j == i) return;
      const Vec2 led = swarm.position[j] + swarm.heading[j] * kRgbLedOffset;
      const Vec2 offset = led - p;
      if (!in_view(offset)) return;
      if (!arena.camera_line_of_sight(camera, {led.x, led.y, epuck::kRgbLedElevation})) return;
      add(rgb, offset);
    };
    if (!swarm.sensing.use_grid) {
      for (int j = 0; j < swarm.size; ++j) see_robot(j);
    } else {  // the robots whose LED can be in view, in index order as above
      const NeighbourGrid& grid = swarm.sensing.grid;
      std::uint16_t* candidate = swarm.sensing.candidates.data();
      std::size_t found = 0;
      grid.for_each_run_near(p, p, half_range - kRgbLedOffset, [&](int begin, int end) {
        for (int k = begin; k < end; ++k) candidate[found++] = grid.robot()[k];
      });
      std::sort(candidate, candidate + found);
      for (std::size_t k = 0; k < found; ++k) see_robot(candidate[k]);
    }
    for (std::size_t k = 0; k < arena.leds.size(); ++k) {
      const std::uint32_t rgb = swarm.arena_led_color[k];
      if (rgb == 0) continue;
      const ArenaLed& led = arena.leds[k];
      const Vec2 offset = led.position.xy() - p;
      if (!in_view(offset)) continue;
      if (!arena.camera_line_of_sight(camera, led.position, led.wall)) continue;
      add(rgb, offset);
    }
    swarm.blob_count[r] = count;
  }
}

void sense(const ArenaModel& arena, const RobotModel& model, SwarmState& swarm, Rng& rng, SensorSet sensors) {
  update_pairs(swarm, sensors.range_and_bearing ? model.rab_range : kProximityPairRange);
  if (sensors.range_and_bearing) sense_range_and_bearing(arena, model, swarm, rng);
  if (sensors.proximity) sense_proximity(arena, model, swarm, rng);
  if (sensors.light) sense_light(arena, model, swarm, rng);
  if (sensors.ground) sense_ground(arena, model, swarm, rng);
  if (sensors.camera) sense_camera(arena, model, swarm);
}

}  // namespace sd
