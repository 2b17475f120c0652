#pragma once
// Control laws of the behaviour modules (ARGoS3-AutoMoDe's and Demiurge's). A behaviour reads
// the reference model, may keep a little memory between steps, and sets the wheels (cm/s) and
// the RGB LEDs.
#include <cmath>
#include <cstdint>

#include "core/rng.hpp"
#include "modules/catalogue.hpp"
#include "robot/reference_model.hpp"

namespace sd {

/// What a behaviour remembers between control steps (Exploration's turn, for instance).
struct BehaviourMemory {
  bool turning = false;        // Exploration (Chocolate, TuttiFrutti, Maple)
  bool turn_left = false;
  std::int32_t turn_steps = 0;
  std::int32_t walk_steps = 0; // Coconut random turn / random walk
  double walk_angle = 0.0;
  std::int32_t steps_in_state = 0;  // Arlequin, Demiurge's machinery: steps since entry (capped)
};

/// A behaviour that does not touch the LEDs leaves them as they are (AutoMoDe keeps the
/// last colour a TuttiFrutti behaviour set).
inline constexpr std::uint32_t kLedUnchanged = 0xffffffffu;

struct Actuation {
  double left_cm = 0.0, right_cm = 0.0;  // wheel speeds, cm/s
  std::uint32_t led = kLedUnchanged;     // RGB of the RGB LEDs, 0 = off
};

/// Vectors shorter than 0.1 become "straight ahead" (AutoMoDe's small-vector fallback).
inline Vec2 with_fallback(Vec2 v) { return v.squared_length() < 0.01 ? Vec2{1.0, 0.0} : v; }

/// The direction laws of RM1.2's vector behaviours, with the small-vector fallback, shared by
/// every flavour that has them; each flavour turns the vector into wheel speeds its own way
/// (Chocolate and TuttiFrutti: wheels_towards; Maple: maple::bounded_wheels_towards).
inline Vec2 phototaxis_vector(const ReferenceModel& rm) { return with_fallback(rm.light - rm.proximity * 5.0); }
inline Vec2 anti_phototaxis_vector(const ReferenceModel& rm) { return with_fallback(-rm.light - rm.proximity * 5.0); }
/// att is stored as a UInt8 by AutoMoDe: its integer part counts.
inline Vec2 attraction_vector(const ReferenceModel& rm, double att) {
  return with_fallback(rm.attraction(std::trunc(att)) - rm.proximity * 6.0);
}
/// -A(rep) x strength - 5 P: master (Chocolate, TuttiFrutti) applies rep twice, inside A and
/// again as the strength (repulsion grows with rep^2); the BT branch (Maple) once, strength 1.
inline Vec2 repulsion_vector(const ReferenceModel& rm, double rep, bool rep_squared) {
  const double alpha = std::trunc(rep);
  return with_fallback(rm.attraction(alpha) * -(rep_squared ? alpha : 1.0) - rm.proximity * 5.0);
}

/// The colour vector of TuttiFrutti: sum over blobs of the colour at >= 6 cm of
/// 1 / (distance + 1) towards the blob.
Vec2 color_vector(const ReferenceModel& rm, std::uint32_t rgb);

/// W(v) of RM1.2: outer wheel at 12 cm/s, inner at 12 cos(angle of v). The zero vector
/// stops the robot (AutoMoDe would compute NaN speeds).
Actuation wheels_towards(Vec2 v);

/// Exploration's two-state law: straight on until an obstacle in front (a proximity vector
/// with x >= 0 and squared length >= obstacle_squared_reading), then a turn in place away
/// from it for U{0..rwm} steps. The step that sees the obstacle still drives forward.
Actuation exploration(double rwm, double obstacle_squared_reading, BehaviourMemory& memory, const ReferenceModel& rm, Rng& rng);
/// Master's threshold, a reading of 0.1 (written squared, as the law compares it).
inline constexpr double kChocolateObstacleSquaredReading = 0.01;

void reset_behaviour(BehaviourMemory& memory);
/// Whether entering a state resets its behaviour's memory. Demiurge's Coconut behaviours 32-35
/// keep their random-turn or random-walk counter and angle for the whole run (only
/// Exploration's Reset re-initialises them); every other behaviour starts afresh.
constexpr bool resets_on_state_entry(int behaviour_id) { return behaviour_id < 32 || behaviour_id > 35; }
/// Loads what a behaviour reads at every step (an Arlequin module's shipped network) before
/// the run, so that no step parses or allocates, and a missing network fails up front.
void prepare_behaviour(const ModuleInstance& behaviour);
Actuation run_behaviour(const ModuleInstance& behaviour, BehaviourMemory& memory, const ReferenceModel& rm, Rng& rng);

}  // namespace sd
