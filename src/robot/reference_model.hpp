#pragma once
// Reference model RM1.2 (modules-and-grammar.md §2.2-2.3): how an AutoMoDe controller sees
// its raw sensors. Per robot it keeps the 5-step ground history and the 11-step
// range-and-bearing message buffer, and it exposes the processed quantities the modules use.
// Vectors are kept as vectors (never as angle + length) so the control step needs no trig.
#include <array>
#include <cstdint>
#include <span>

#include "core/geometry.hpp"
#include "simulator/swarm.hpp"

namespace sd {

struct ReferenceModel {
  // --- processed inputs of the current control step ---
  double ground = 0.5;          // majority-filtered floor: 0 black, 0.5 gray, 1 white
  Vec2 proximity;               // sum of proximity vectors, length clipped to 1 (RM1.2 Pv)
  Vec2 light;                   // unit vector to the light if any sensor reads > 0.2, else 0
  int neighbours = 0;           // senders heard this step
  Vec2 attraction_sum;          // sum over the buffer of (1 / (1 + range_cm)) at the bearing
  // RM1.1 GetNeighborsCenterOfMass (Arlequin inputs 20-23): sum over the same buffer of
  // range_cm at the bearing, and how many messages the buffer holds.
  Vec2 neighbour_position_sum;
  int buffered_messages = 0;
  std::span<const RabPacket> packets;    // this step's packets
  std::span<const CameraBlob> blobs;     // this step's camera blobs (RM3.0)
  std::array<double, 8> raw_proximity{}; // raw readings (Arlequin inputs)
  std::array<double, 8> raw_light{};
  std::array<double, 3> raw_ground{};

  double proximity_value() const { return proximity.length(); }
  double proximity_angle() const { return proximity.angle(); }
  double light_value() const { return light.squared_length() > 0.0 ? 1.0 : 0.0; }
  /// A(alpha) of RM1.2: alpha / (1 + r) summed over every buffered message.
  Vec2 attraction(double alpha) const { return attraction_sum * alpha; }

  // --- memory ---
  static constexpr int kGroundHistory = 5;
  static constexpr int kRabBufferSteps = 11;  // messages of this step and of the 10 before
  std::array<std::uint8_t, kGroundHistory> ground_black{}, ground_white{};  // per step
  int window_black = 0, window_white = 0;                                   // over the window
  int ground_samples = 0;
  std::array<Vec2, kRabBufferSteps> rab_steps{};
  std::array<Vec2, kRabBufferSteps> rab_position_steps{};
  std::array<int, kRabBufferSteps> rab_message_steps{};
  int rab_step = 0;

  void reset();
  /// Reads this tick's raw sensors of robot `robot` (one control step of the DAO update).
  void update(const SwarmState& swarm, int robot);
};

/// Unit vectors of the 8 reported sensor angles (17, 50, 90, 150, 210, 270, 310, 343 deg).
const std::array<Vec2, 8>& sensor_directions();

}  // namespace sd
