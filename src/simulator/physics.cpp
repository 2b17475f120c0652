#include "simulator/physics.hpp"

#include <algorithm>
#include <cmath>

#include "simulator/epuck.hpp"

namespace sd {

namespace {
constexpr double kRadius = epuck::kBodyRadius;
constexpr double kDt = epuck::kSubstepSeconds;
constexpr double kMaxDeltaV = epuck::kMaxDriveForce / epuck::kMass * kDt;  // per sub-step
constexpr double kRobotFriction = 0.7 * 0.7;
constexpr double kWallFriction = 0.7 * 0.1;
constexpr int kSolverSweeps = 6;
}  // namespace

void Physics::reset(int robots) {
  const auto n = static_cast<std::size_t>(robots);
  target_velocity_.assign(n, {});
  target_angular_.assign(n, 0.0);
  island_.assign(n, 0);
  moving_.assign(n, 0);
  in_contact_.assign(n, 0);
  contact_robots_.clear();
  contact_robots_.reserve(n);
  for (auto* v : {&pair_candidates_, &wall_candidates_}) {
    v->clear();
    v->reserve(n * (n - 1) / 2 + 8 * n);
  }
  for (auto* v : {&pair_contacts_, &wall_contacts_}) {
    v->clear();
    v->reserve(n * (n - 1) / 2 + 8 * n);
  }
}

void Physics::step(const ArenaModel& arena, SwarmState& swarm) {
  const int n = swarm.size;

  // Drive targets, fixed for the whole tick (dynamics2d updates them once per tick).
  double max_speed = 0.0;
  for (int i = 0; i < n; ++i) {
    const double left = swarm.wheel_left[i], right = swarm.wheel_right[i];
    const double v = 0.5 * (left + right);
    target_velocity_[i] = swarm.heading[i] * v;
    target_angular_[i] = (right - left) / epuck::kInterwheelDistance;
    max_speed = std::max({max_speed, std::abs(v), swarm.velocity[i].length()});
  }

  // Contact candidates: everything that could touch within this tick.
  const double reach = max_speed * epuck::kTickSeconds + 1e-3;
  pair_candidates_.clear();
  const double pair_limit = 2.0 * kRadius + 2.0 * reach;
  for (const RobotPair& pair : swarm.pairs) {
    const Vec2 d = swarm.position[pair.b] - swarm.position[pair.a];
    if (d.squared_length() < pair_limit * pair_limit) pair_candidates_.push_back({pair.a, pair.b});
  }
  wall_candidates_.clear();
  for (int i = 0; i < n; ++i)
    for (const std::uint16_t w : arena.walls_near(swarm.position[i]))
      if (arena.walls[w].distance(swarm.position[i], nullptr) < kRadius + reach)
        wall_candidates_.push_back({static_cast<std::uint16_t>(i), w});

  // Islands of robots linked by candidate contacts. An island whose robots are all at rest
  // (no velocity, no command) cannot move during this tick, and a robot with no candidate
  // moves freely: only robots of moving islands need the sub-stepped contact solver.
  for (int i = 0; i < n; ++i) {
    island_[i] = static_cast<std::uint16_t>(i);
    moving_[i] = 0;
    in_contact_[i] = 0;
  }
  for (const Candidate& c : pair_candidates_) {
    const std::uint16_t ra = find_island(c.a), rb = find_island(c.b);
    if (ra != rb) island_[ra] = rb;
    in_contact_[c.a] = in_contact_[c.b] = 1;
  }
  for (const Candidate& c : wall_candidates_) in_contact_[c.a] = 1;
  for (int i = 0; i < n; ++i) {
    const bool at_rest = swarm.velocity[i].x == 0.0 && swarm.velocity[i].y == 0.0 && target_velocity_[i].x == 0.0 &&
                         target_velocity_[i].y == 0.0;
    if (!at_rest) moving_[find_island(static_cast<std::uint16_t>(i))] = 1;
  }
  contact_robots_.clear();
  for (int i = 0; i < n; ++i) {
    if (in_contact_[i] && moving_[find_island(static_cast<std::uint16_t>(i))])
      contact_robots_.push_back(static_cast<std::uint16_t>(i));
    else
      move_freely(swarm, i);
  }
  std::erase_if(pair_candidates_, [&](const Candidate& c) { return !moving_[find_island(c.a)]; });
  std::erase_if(wall_candidates_, [&](const Candidate& c) { return !moving_[find_island(c.a)]; });

  if (!contact_robots_.empty()) {
    for (int sub = 0; sub < epuck::kPhysicsSubsteps; ++sub) {
      for (const std::uint16_t i : contact_robots_) accelerate(swarm.velocity[i], target_velocity_[i]);
      solve_contacts(arena, swarm, max_speed);
      for (const std::uint16_t i : contact_robots_) swarm.position[i] += swarm.velocity[i] * kDt;
      separate_overlaps(arena, swarm);
    }
  }
  for (int i = 0; i < n; ++i) {
    swarm.yaw[i] = wrap_signed(swarm.yaw[i] + target_angular_[i] * epuck::kTickSeconds);
    swarm.heading[i] = {std::cos(swarm.yaw[i]), std::sin(swarm.yaw[i])};
  }
}

std::uint16_t Physics::find_island(std::uint16_t i) {
  while (island_[i] != i) {
    island_[i] = island_[island_[i]];  // path halving
    i = island_[i];
  }
  return i;
}

void Physics::accelerate(Vec2& velocity, Vec2 target) {
  // The drive joint pulls the body's velocity towards the target with at most 1.5 N.
  Vec2 dv = target - velocity;
  const double len2 = dv.squared_length();
  if (len2 > kMaxDeltaV * kMaxDeltaV) dv = dv * (kMaxDeltaV / std::sqrt(len2));
  velocity += dv;
}

void Physics::move_freely(SwarmState& swarm, int i) {
  Vec2& v = swarm.velocity[i];
  Vec2& p = swarm.position[i];
  const Vec2 target = target_velocity_[i];
  for (int sub = 0; sub < epuck::kPhysicsSubsteps; ++sub) {
    if (v == target) {  // converged: the rest of the tick is a straight line
      p += v * (kDt * (epuck::kPhysicsSubsteps - sub));
      return;
    }
    accelerate(v, target);
    p += v * kDt;
  }
}

void Physics::solve_contacts(const ArenaModel& arena, SwarmState& swarm, double max_speed) {
  // Speculative constraints: the approach speed along the normal may close the current gap
  // within this sub-step but never more; an existing overlap may only shrink. Contacts too
  // far apart to close within the sub-step are left out.
  const double closing = 2.0 * (max_speed + 2.0 * kMaxDeltaV) * kDt + 1e-9;
  pair_contacts_.clear();
  for (const Candidate& c : pair_candidates_) {
    const Vec2 d = swarm.position[c.b] - swarm.position[c.a];
    const double limit = 2.0 * kRadius + closing;
    const double dist2 = d.squared_length();
    if (dist2 >= limit * limit || dist2 <= 0.0) continue;
    const double dist = std::sqrt(dist2);
    const double gap = dist - 2.0 * kRadius;
    pair_contacts_.push_back({c.a, c.b, d * (1.0 / dist), gap > 0.0 ? -gap / kDt : 0.0, 0.0, 0.0});
  }
  wall_contacts_.clear();
  for (const Candidate& c : wall_candidates_) {
    Vec2 normal;
    const double gap = arena.walls[c.b].distance(swarm.position[c.a], &normal) - kRadius;
    if (gap >= closing) continue;
    wall_contacts_.push_back({c.a, c.b, normal, gap > 0.0 ? -gap / kDt : 0.0, 0.0, 0.0});
  }
  if (pair_contacts_.empty() && wall_contacts_.empty()) return;

  auto still = [&](std::uint16_t i) { return swarm.velocity[i].x == 0.0 && swarm.velocity[i].y == 0.0; };
  for (int sweep = 0; sweep < kSolverSweeps; ++sweep) {
    double largest = 0.0;
    for (Contact& c : pair_contacts_) {
      // Two motionless bodies with no impulse yet: nothing to correct (allowed <= 0).
      if (c.normal_impulse == 0.0 && still(c.a) && still(c.b)) continue;
      Vec2& va = swarm.velocity[c.a];
      Vec2& vb = swarm.velocity[c.b];
      const double vn = dot(vb - va, c.normal);
      // Equal masses: each body takes half of the relative correction.
      const double accumulated = std::max(c.normal_impulse + 0.5 * (c.allowed - vn), 0.0);
      const double jn = accumulated - c.normal_impulse;
      c.normal_impulse = accumulated;
      va -= c.normal * jn;
      vb += c.normal * jn;
      largest = std::max(largest, std::abs(jn));
      if (c.normal_impulse <= 0.0) continue;
      const Vec2 tangent{-c.normal.y, c.normal.x};
      const double vt = dot(vb - va, tangent);
      const double limit = kRobotFriction * c.normal_impulse;
      const double accumulated_t = std::clamp(c.tangent_impulse - 0.5 * vt, -limit, limit);
      const double jt = accumulated_t - c.tangent_impulse;
      c.tangent_impulse = accumulated_t;
      va -= tangent * jt;
      vb += tangent * jt;
    }
    for (Contact& c : wall_contacts_) {
      Vec2& v = swarm.velocity[c.a];
      const double vn = dot(v, c.normal);
      const double accumulated = std::max(c.normal_impulse + (c.allowed - vn), 0.0);
      const double jn = accumulated - c.normal_impulse;
      c.normal_impulse = accumulated;
      v += c.normal * jn;
      largest = std::max(largest, std::abs(jn));
      if (c.normal_impulse <= 0.0) continue;
      const Vec2 tangent{-c.normal.y, c.normal.x};
      const double vt = dot(v, tangent);
      const double limit = kWallFriction * c.normal_impulse;
      const double accumulated_t = std::clamp(c.tangent_impulse - vt, -limit, limit);
      v += tangent * (accumulated_t - c.tangent_impulse);
      c.tangent_impulse = accumulated_t;
    }
    if (largest < 1e-6) break;  // converged to a micrometre per second
  }
}

void Physics::separate_overlaps(const ArenaModel& arena, SwarmState& swarm) {
  // In a dense crowd a few solver sweeps may leave a residual approach speed; remove the
  // resulting overlap at once so that it can never accumulate. A push can create an
  // overlap further along a chain or against a wall, hence a few passes; walls come last in
  // each pass, so no robot ever ends inside a wall.
  for (int pass = 0; pass < 4; ++pass) {
    bool moved = false;
    for (const Candidate& c : pair_candidates_) {
      const Vec2 d = swarm.position[c.b] - swarm.position[c.a];
      const double dist2 = d.squared_length();
      if (dist2 >= 4.0 * kRadius * kRadius || dist2 <= 0.0) continue;
      const double dist = std::sqrt(dist2);
      const Vec2 push = d * (0.5 * (2.0 * kRadius - dist) / dist);
      swarm.position[c.a] -= push;
      swarm.position[c.b] += push;
      moved = true;
    }
    for (const Candidate& c : wall_candidates_) {
      Vec2 normal;
      const double gap = arena.walls[c.b].distance(swarm.position[c.a], &normal) - kRadius;
      if (gap < 0.0) swarm.position[c.a] -= normal * gap;
    }
    if (!moved) break;
  }
}

}  // namespace sd
