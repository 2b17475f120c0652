#pragma once
// Reference model RM1.2 (demiurge-epuck-dao's ReferenceModel1Dot2): how an AutoMoDe controller sees
// its raw sensors. Per robot it keeps the 5- and 10-step ground histories and the 11-step
// range-and-bearing message buffer, and it exposes the processed quantities the modules use.
// Vectors are kept as vectors (never as angle + length) so the control step needs no trig.
//
// The memory (ground history, message buffer) is updated at every step. The processed
// quantities cost only the robots that read them: the proximity and light vectors are
// computed when the robot was sensed for them this step (SwarmState::demand), and the
// buffer sums are added up when a module asks for them.
#include <array>
#include <cstdint>
#include <span>

#include "core/geometry.hpp"
#include "simulator/swarm.hpp"

namespace sd {

struct ReferenceModel {
  /// What the raw views show before the first update: every sensor reads 0.
  static constexpr std::array<double, 8> kNoReadings8{};
  static constexpr std::array<double, 3> kNoReadings3{};

  // --- processed inputs of the current control step ---
  // Majority-filtered floor: 0 black, 0.5 gray, 1 white. TuttiFrutti's RM3.0 (demiurge-epuck-dao
  // branch tuttifrutti 0d55891) filters alike: 5 steps, < 0.03 and > 0.85. A noisy black floor
  // (0 + U(-0.05, 0.05)) passes 80 % of samples, so a robot on black reads gray at about one
  // step in six; ARGoS' set-4 traces show it.
  double ground = 0.5;
  // Demiurge's RM3.0 (the Coconut and Arlequin code base, AmmarHsn/demiurge-epuck-dao): the
  // last 10 steps (30 readings); black if more than 8 are below 0.02, else white if more than
  // 8 are above 0.97, else gray. The Coconut and Arlequin floor conditions read it.
  double ground_demiurge = 0.5;
  // Demiurge's RM3.0 GetGroundInput, what Demiurge's Arlequin modules read as ground inputs:
  // the same 10 steps, black if more than 10 of the 30 readings are below 0.03, else white if
  // more than 10 are above 0.85, else gray.
  double ground_input_demiurge = 0.5;
  // The two vectors keep their last value at a step that does not read them.
  Vec2 proximity;               // sum of proximity vectors, length clipped to 1 (RM1.2 Pv)
  Vec2 light;                   // unit vector to the light if any sensor reads > 0.2, else 0
  int neighbours = 0;           // senders heard this step
  std::span<const RabPacket> packets;    // this step's packets
  std::span<const CameraBlob> blobs;     // this step's camera blobs (RM3.0)
  // Raw readings of this step (Arlequin inputs): views into the swarm state, not copies.
  std::span<const double, 8> raw_proximity{kNoReadings8};
  std::span<const double, 8> raw_light{kNoReadings8};
  std::span<const double, 3> raw_ground{kNoReadings3};

  double proximity_value() const { return proximity.length(); }
  double proximity_angle() const { return proximity.angle(); }
  double light_value() const { return light.squared_length() > 0.0 ? 1.0 : 0.0; }
  /// Sum over the buffer of (1 / (1 + range_cm)) at the bearing.
  Vec2 attraction_sum() const { return buffer_sum(rab_steps); }
  /// A(alpha) of RM1.2: alpha / (1 + r) summed over every buffered message.
  Vec2 attraction(double alpha) const { return attraction_sum() * alpha; }
  /// RM1.1 GetNeighborsCenterOfMass (Arlequin inputs 20-23): sum over the same buffer of
  /// range_cm at the bearing, and how many messages the buffer holds.
  Vec2 neighbour_position_sum() const { return buffer_sum(rab_position_steps); }
  int buffered_messages() const;
  /// Demiurge's RM3.0 buffer emptied `steps` steps ago (Arlequin modules with Demiurge's
  /// machinery): the sum of range_cm at the bearing over the messages of the last
  /// min(steps, 11) steps, this one included, and in `messages` how many there are.
  Vec2 recent_neighbour_position_sum(int steps, int& messages) const;

  // --- memory ---
  static constexpr int kGroundHistory = 5;
  static constexpr int kRabBufferSteps = 11;  // messages of this step and of the 10 before
  std::array<std::uint8_t, kGroundHistory> ground_black{}, ground_white{};  // per step
  int window_black = 0, window_white = 0;                                   // over the window
  int ground_slot = 0;                        // the slot the next step overwrites
  static constexpr int kDemiurgeGroundHistory = 10;
  std::array<std::uint8_t, kDemiurgeGroundHistory> ground_black_demiurge{}, ground_white_demiurge{};
  int window_black_demiurge = 0, window_white_demiurge = 0;
  std::array<std::uint8_t, kDemiurgeGroundHistory> ground_black_input_demiurge{}, ground_white_input_demiurge{};
  int window_black_input_demiurge = 0, window_white_input_demiurge = 0;
  int ground_slot_demiurge = 0;
  // Per step of the buffer: the sums over that step's messages, so that a buffer sum adds
  // 11 terms, not every message.
  std::array<Vec2, kRabBufferSteps> rab_steps{};
  std::array<Vec2, kRabBufferSteps> rab_position_steps{};
  std::array<int, kRabBufferSteps> rab_message_steps{};
  int rab_slot = 0;                           // the slot the next step overwrites

  void reset();
  /// Reads this tick's raw sensors of robot `robot` (one control step of the DAO update).
  void update(const SwarmState& swarm, int robot);

 private:
  /// Sum of the buffer's steps, in slot order (the order fixes the rounding).
  static Vec2 buffer_sum(const std::array<Vec2, kRabBufferSteps>& steps) {
    Vec2 sum;
    for (const Vec2& step : steps) sum += step;
    return sum;
  }
  void update_ground();
  void update_proximity();
  void update_light();
  void update_range_and_bearing();
};

/// Unit vectors of the 8 reported sensor angles (17, 50, 90, 150, 210, 270, 310, 343 deg).
const std::array<Vec2, 8>& sensor_directions();

}  // namespace sd
