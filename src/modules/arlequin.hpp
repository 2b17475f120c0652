#pragma once
// Arlequin's neural-network behaviours (Demiurge's Harlequin modules), also the whole control
// software of EvoStick: a single-layer perceptron from 25 inputs (the last one a bias of 1)
// to 2 sigmoid outputs that drive the wheels.
//
// Weight layout: weights[o * kInputs + i] connects input i to output o; output 0 drives the
// left wheel, output 1 the right one.
#include <array>
#include <span>
#include <string_view>

#include "modules/behaviours.hpp"
#include "robot/reference_model.hpp"

namespace sd::arlequin {

inline constexpr int kInputs = 25;
inline constexpr int kOutputs = 2;
inline constexpr int kWeights = kInputs * kOutputs;
inline constexpr double kSigmoidSlope = 4.924273;  // NEAT's fsigmoid
inline constexpr double kWeightBound = 5.0;        // EvoStick keeps weights in [-5, 5]

using Inputs = std::array<double, kInputs>;
using Weights = std::array<double, kWeights>;

/// Inputs 20-23 from c, the mean position of the buffered messages: max(0, c . u_k), u_k the
/// unit vector at 45 + 90 k degrees.
void set_neighbour_direction_inputs(Vec2 centre, Inputs& x);

/// The 25 inputs with SwarmDesign's machinery (RM1.1 encoding of ARGoS3-NEAT's NeuralNetworkRM1Dot1, used by EvoStick):
///   0-7 raw proximity, 8-15 raw light,
///   16-18 ground left, centre, right: 0 on a black floor and 1 on a white one (5-step
///         majority); on grey, the sensor's own simulated raw reading. DEMI draws grey values
///         from tables of real-robot readings that we do not have; the raw reading is our
///         documented substitute (it carries the simulated sensor noise instead),
///   19    1 - 2 / (1 + e^n), n = neighbours heard this step,
///   20-23 max(0, c . u_k), u_k the unit vector at 45 + 90 k degrees and c the mean of
///         range_cm at the bearing over the messages of the RAB buffer (0 if it is empty),
///   24    bias, 1.
/// Reads only the reference model, which keeps the RAB buffer across state changes: the DEMI
/// quirk that clears it when an Arlequin state is entered is not reproduced.
Inputs encode_inputs(const ReferenceModel& rm);

/// o = 1 / (1 + exp(-4.924273 * sum_i w_i x_i)), summed in input order.
std::array<double, kOutputs> forward(const Weights& weights, const Inputs& inputs);

/// Wheels from the outputs: -12 + 24 o, in cm/s (o = 0.5 stops a wheel).
Actuation wheels_from_outputs(const std::array<double, kOutputs>& outputs);

/// One control step of a network: encode, forward, wheels. Never touches the LEDs.
Actuation drive(const Weights& weights, const ReferenceModel& rm);

/// The six modules, by digit: 0 exploration, 1 stop, 2 phototaxis, 3 antiphototaxis,
/// 4 attraction, 5 repulsion (the names of the shipped weight files and of `evostick --module`).
inline constexpr std::array<std::string_view, 6> kModuleNames = {"exploration",    "stop",       "phototaxis",
                                                                 "antiphototaxis", "attraction", "repulsion"};
inline constexpr int kFirstModuleId = 50;
/// True for the ids of the six Arlequin modules (50-55).
inline constexpr bool is_module(int id) {
  return id >= kFirstModuleId && id < kFirstModuleId + static_cast<int>(kModuleNames.size());
}

/// Weights shipped for module `id` (50-55), read once from the data/arlequin/<name>.json
/// files compiled into the binary. Throws std::out_of_range for another id, and
/// std::runtime_error if the build carries no valid file for it.
const Weights& shipped_weights(int id);

/// Reads the "weights" of a weight document ({"weights": {"left": [25], "right": [25]}});
/// throws std::runtime_error naming what is wrong.
Weights weights_from_json(std::string_view json_text, std::string_view source);

}  // namespace sd::arlequin
