#include "simulator/physics.hpp"

#include <algorithm>
#include <cmath>

#include "simulator/epuck.hpp"
#include "simulator/broad_phase.hpp"

namespace sd {

namespace {
constexpr double kRadius = epuck::kBodyRadius;
constexpr double kDt = epuck::kSubstepSeconds;
constexpr double kMaxDeltaV = epuck::kMaxDriveForce / epuck::kMass * kDt;  // per sub-step
constexpr double kRobotFriction = 0.7 * 0.7;
constexpr double kWallFriction = 0.7 * 0.1;
constexpr int kProjectionPasses = 4;
constexpr double kKeptOverlap = 1e-6;  // m: deeper overlaps at a sub-step's start are kept
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
    v->reserve(pair_count(n) + 8 * n);
  }
  close_pairs_.assign(pair_count(n) + 1, {});  // one spare slot for the branch-free append
  wall_kept_.clear();
  wall_kept_.reserve(pair_count(n) + 8 * n);  // as many as wall candidates can be
  start_.assign(n, {});
}

void Physics::step(const ArenaModel& arena, SwarmState& swarm) {
  const int n = swarm.size;

  // Drive targets, fixed for the whole tick (dynamics2d updates them once per tick).
  double max_speed = 0.0;
  for (int i = 0; i < n; ++i) {
    const double left = swarm.wheel_left[i], right = swarm.wheel_right[i];
    const double v = 0.5 * (left + right);
    target_velocity_[i] = swarm.heading[i] * v;
    target_angular_[i] = (right - left) / epuck::kInterwheelDistance;  // both 0: the drive stops
    max_speed = std::max({max_speed, std::abs(v), swarm.velocity[i].length()});
  }

  // Contact candidates: everything that could touch within this tick.
  const double reach = max_speed * epuck::kTickSeconds + 1e-3;
  pair_candidates_.clear();
  const double pair_limit = 2.0 * kRadius + 2.0 * reach;
  const double pair_limit_sq = pair_limit * pair_limit;
  const BroadPhase& broad = swarm.broad_phase;
  if (pair_limit_sq <= kProximityPairRange * kProximityPairRange && broad.built_from(swarm.position)) {
    // The broad phase's close pairs of the last tick, still exact, hold every candidate, in
    // pair order, with the same squared distances: a few pairs to test instead of all of them.
    for (int k = 0; k < broad.close_pair_count; ++k) {
      const RobotPair& pair = broad.pairs[broad.close_pairs[static_cast<std::size_t>(k)]];
      if (pair.distance_sq < pair_limit_sq) pair_candidates_.push_back({pair.a, pair.b});
    }
  } else {  // every pair, in the order of the pair table (the first tick of a run)
    for (int a = 0; a < n; ++a)
      for (int b = a + 1; b < n; ++b) {
        const Vec2 d = swarm.position[b] - swarm.position[a];
        if (d.squared_length() < pair_limit_sq) pair_candidates_.push_back({static_cast<std::uint16_t>(a), static_cast<std::uint16_t>(b)});
      }
  }
  wall_candidates_.clear();
  const double wall_limit = kRadius + reach;
  for (int i = 0; i < n; ++i) {
    const Vec2 p = swarm.position[i];
    for (const std::uint16_t w : arena.walls_near(p)) {
      // The bound rules out most near walls before the exact distance and its square root.
      const Wall& wall = arena.walls[w];
      if (!wall.surely_beyond(p, wall_limit) && wall.distance(p, nullptr) < wall_limit)
        wall_candidates_.push_back({static_cast<std::uint16_t>(i), w});
    }
  }

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

  // Chipmunk's order within a sub-step: move with the velocity of the previous sub-step,
  // then let the drive and the contacts set the next one. So the first sub-step of a tick
  // still moves with the last tick's velocity (a turn starting from straight motion covers
  // 9/10 of omega dt, as in the ARGoS traces). Contacts are projected right after each
  // move, and the velocity of the next sub-step is the displacement they allowed.
  if (!contact_robots_.empty()) {
    for (int sub = 0; sub < epuck::kPhysicsSubsteps; ++sub) {
      for (const std::uint16_t i : contact_robots_) {
        start_[i] = swarm.position[i];
        swarm.position[i] += swarm.velocity[i] * kDt;
      }
      project_contacts(arena, swarm);
      for (const std::uint16_t i : contact_robots_) {
        swarm.velocity[i] = (swarm.position[i] - start_[i]) * (1.0 / kDt);
        accelerate(swarm.velocity[i], target_velocity_[i]);
      }
    }
  }
  for (int i = 0; i < n; ++i) {
    const double turn = (swarm.angular_velocity[i] + target_angular_[i] * (epuck::kPhysicsSubsteps - 1)) * kDt;
    swarm.angular_velocity[i] = target_angular_[i];  // the angular joint is stiff: one sub-step
    if (turn == 0.0) continue;  // heading unchanged: no trigonometry
    swarm.yaw[i] = wrap_signed(swarm.yaw[i] + turn);
    swarm.heading[i] = Vec2::polar(1.0, swarm.yaw[i]);
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
    p += v * kDt;
    accelerate(v, target);
  }
}

void Physics::project_contacts(const ArenaModel& arena, SwarmState& swarm) {
  // Bodies are moved first, then pushed out of each other: each of two robots takes half of
  // their overlap along the normal, and up to friction x overlap of their relative sliding
  // in this sub-step is cancelled (Coulomb's law, with overlap standing for the normal
  // impulse). A push can create an overlap further along a chain or against a wall, hence
  // a few passes; later passes only revisit pairs that were close in the first, since a
  // push moves a body by well under a millimetre. Walls come last in each pass, so no robot
  // ever ends inside a wall.
  constexpr double kTouchSq = 4.0 * kRadius * kRadius;
  constexpr double kCloseSq = (2.0 * kRadius + 1e-3) * (2.0 * kRadius + 1e-3);
  constexpr double kNegligible = 1e-12;  // metres of overlap not worth another pass
  std::span<const Candidate> pairs = pair_candidates_;
  std::size_t close = 0;
  // dynamics2d's contacts only stop the approach, nothing pushes bodies apart (in the trace,
  // epuck4's depth in the wall stays constant to 1e-10 m for 18 ticks; Chipmunk's default
  // collision slop, 0.1, exceeds any overlap in metres): a robot that starts a sub-step
  // overlapping a wall -- placed into one that the loop function added after placement --
  // keeps that overlap, and leaves only by driving out (ARGoS SCA seed 2: epuck4 slides
  // inside the back wall for 128 ticks). Only such walls keep overlaps: our projection ends
  // every other contact touching, and the residue it may leave where two walls meet is solver
  // error, not an overlap ARGoS would have. The overlap kept is the sub-step's start's, the
  // same for every pass.
  wall_kept_.resize(wall_candidates_.size());
  for (std::size_t k = 0; k < wall_candidates_.size(); ++k) {
    const Candidate& c = wall_candidates_[k];
    const Wall& wall = arena.walls[c.b];
    double kept = 0.0;
    if (wall.placed_after_robots) {
      const double start_gap = wall.distance(start_[c.a], nullptr) - kRadius;
      kept = start_gap < -kKeptOverlap ? start_gap : 0.0;
    }
    wall_kept_[k] = kept;
  }
  for (int pass = 0; pass < kProjectionPasses; ++pass) {
    bool pushed = false;
    for (const Candidate& c : pairs) {
      Vec2& pa = swarm.position[c.a];
      Vec2& pb = swarm.position[c.b];
      const Vec2 d = pb - pa;
      const double dist2 = d.squared_length();
      if (pass == 0) {  // branch-free append: whether a pair is close is a coin toss
        close_pairs_[close] = c;
        close += dist2 < kCloseSq ? 1 : 0;
      }
      if (dist2 >= kTouchSq || dist2 <= 0.0) continue;
      const double dist = std::sqrt(dist2);
      const double depth = 2.0 * kRadius - dist;
      if (depth < kNegligible) continue;
      const Vec2 normal = d * (1.0 / dist);
      const Vec2 tangent{-normal.y, normal.x};
      const double slide = dot((pb - start_[c.b]) - (pa - start_[c.a]), tangent);
      const double grip = kRobotFriction * depth;
      const double stick = std::clamp(slide, -grip, grip);
      const Vec2 push = normal * (0.5 * depth) - tangent * (0.5 * stick);
      pa -= push;
      pb += push;
      pushed = true;
    }
    for (std::size_t k = 0; k < wall_candidates_.size(); ++k) {
      const Candidate& c = wall_candidates_[k];
      Vec2 normal;
      Vec2& p = swarm.position[c.a];
      const Wall& wall = arena.walls[c.b];
      const double gap = wall.distance(p, &normal) - kRadius;
      const double kept = wall_kept_[k];
      if (gap >= kept) continue;
      p -= normal * (gap - kept);
      const Vec2 tangent{-normal.y, normal.x};
      const double grip = kWallFriction * (kept - gap);
      p -= tangent * std::clamp(dot(p - start_[c.a], tangent), -grip, grip);
    }
    if (!pushed) break;
    pairs = std::span<const Candidate>(close_pairs_.data(), close);
  }
}

}  // namespace sd
