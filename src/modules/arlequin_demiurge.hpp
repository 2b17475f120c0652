#pragma once
// Demiurge's machinery for Arlequin's modules 50-55: the 25 inputs as AmmarHsn/Demiurge
// 0179ecf8's AutoMoDeBehaviourGenomeHarlequin computes them on demiurge-epuck-dao's
// ReferenceModel3Dot0 (bad4dba). Demiurge's own networks (data/arlequin-demiurge/) were
// evolved with it, so a module set that holds them runs them this way.
#include <array>

#include "core/rng.hpp"
#include "modules/arlequin.hpp"
#include "robot/reference_model.hpp"

namespace sd::arlequin::demiurge {

/// m_GraySamples{Left,Center,Right}: a real e-puck's ground readings on the grey floor,
/// 4205 each, float32 as Demiurge declares them (data/arlequin-demiurge/grey-samples.csv).
inline constexpr int kGreySamples = 4205;
struct GreySamples {
  std::array<float, kGreySamples> left{}, centre{}, right{};
};
/// Parsed once from the table compiled into the binary; throws std::runtime_error if the
/// build carries a broken one.
const GreySamples& grey_samples();

/// The 25 inputs, `steps_since_entry` steps after the running state was entered:
///   0-7 raw proximity, 8-15 raw light (as the sensors give them),
///   16-18 ground: RM3.0 GetGroundInput (ReferenceModel::ground_input_demiurge) mapped to 0
///         (black) or 1 (white); on grey, one real-robot sample per sensor, left, centre,
///         right, each at index Uniform(0, 4204) drawn from the robot's generator,
///   19    1 - 2 / (1 + e^n), n = senders heard this step,
///   20-23 max(0, c . u_k), c the mean position of the messages RM3.0's buffer holds: the
///         Harlequin module's Reset empties it on the state's entry step after this step's
///         messages were stored, so only messages of the min(steps_since_entry, 11) last steps
///         count (none at the entry step),
///   24    bias, 1.
Inputs encode_inputs(const ReferenceModel& rm, int steps_since_entry, Rng& rng);

}  // namespace sd::arlequin::demiurge
