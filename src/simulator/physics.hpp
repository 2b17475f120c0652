#pragma once
// One tick of rigid-body motion (as ARGoS3's dynamics2d engine moves e-pucks), written for a
// swarm of identical discs among static box walls.
//
// What we keep from ARGoS/dynamics2d: the drive sets, once per tick, a target velocity along
// the heading at the START of the tick (so motion within a tick is a chord, not an arc) and
// a target angular velocity; 10 sub-steps of 0.01 s in Chipmunk's order (move with the
// previous sub-step's velocity, then update it); the drive joint's 1.5 N force limit on a
// 0.4 kg body (so a robot needs ~3 sub-steps to reach 12 cm/s and slides a little when it
// turns); inelastic contacts with Coulomb friction 0.49 robot-robot and 0.07 robot-wall.
//
// What we simplify, and why: contacts are resolved on positions (position-based dynamics)
// instead of Chipmunk's velocity arbiters. In each sub-step the robots in contact move, are
// pushed out of each other (half each, equal masses) with Coulomb friction bounding the
// cancelled sliding, and their velocity becomes the displacement over the sub-step, so a
// robot pushing another moves at half speed just as the impulse solution makes it. Robots
// thus touch at 2r where dynamics2d lets them sink a few tenths of a millimetre, overlap
// never grows, and one pass over the contacts costs a fraction of an iterative impulse
// solver. The drive's angular joint is treated as infinitely stiff (its limit, 1530
// rad/s^2, is reached within one sub-step at e-puck speeds) and friction torque is
// ignored, which only matters for a robot spinning while it touches another. A robot placed
// into a wall added after placement (placed_after_robots) keeps its overlap, as in ARGoS,
// where contacts only stop the approach: see project_contacts.
#include <span>
#include <vector>

#include "simulator/arena.hpp"
#include "simulator/swarm.hpp"

namespace sd {

class Physics {
 public:
  void reset(int robots);
  /// Moves the swarm by one tick with the wheel speeds stored in `swarm`.
  void step(const ArenaModel& arena, SwarmState& swarm);

 private:
  struct Candidate {
    std::uint16_t a, b;  // robots, or robot and wall
  };
  void project_contacts(const ArenaModel& arena, SwarmState& swarm);
  std::uint16_t find_island(std::uint16_t robot);
  static void accelerate(Vec2& velocity, Vec2 target);
  void move_freely(SwarmState& swarm, int robot);

  std::vector<Vec2> target_velocity_;
  std::vector<double> target_angular_;
  std::vector<std::uint16_t> island_;        // union-find parent
  std::vector<std::uint8_t> moving_, in_contact_;
  std::vector<std::uint16_t> contact_robots_;
  std::vector<Candidate> pair_candidates_, wall_candidates_;
  std::vector<Candidate> close_pairs_;        // pairs within a millimetre of touching
  std::vector<Vec2> start_;                   // positions at the start of the sub-step
  std::vector<double> wall_kept_;             // per wall candidate: the overlap it keeps this sub-step
};

}  // namespace sd
