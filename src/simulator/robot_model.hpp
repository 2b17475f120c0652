#pragma once
// The parts of the robot model a mission may override (ARGoS3 as actually run by AutoMoDe).
// Defaults are the AutoMoDe experiment files' values: the *design model*. A pseudo-reality
// (reality/, Ligot & Birattari 2020) is another RobotModel sampled around it.
#include <array>
#include <string_view>

namespace sd {

struct RobotModel {
  // m; argos3-epuck's RAB actuator reads the experiment file's `range` attribute, 0.8 when
  // unset. The catalogue's missions set what their scenario files say (0.7, TuttiFrutti 0.5).
  double rab_range = 0.8;
  double rab_loss = 0.85;          // probability a packet is dropped
  /// m; argos3-epuck's RAB sensor `noise_std_dev`: each received packet's sender position is
  /// offset by a vector of length N(0, s) in a random direction (inclination and azimuth
  /// uniform). IRIDIA's files spell it `noise_std_deviation`, which the plugin ignores: 0.
  double rab_noise = 0.0;
  double wheel_noise = 0.05;       // std-dev of the multiplicative N(0, s) wheel noise
  double proximity_noise = 0.05;   // half-width of the additive uniform noise
  double light_noise = 0.05;
  double ground_noise = 0.05;
  double camera_range = 0.335;     // m, 0.122 * tan(70 deg)
  /// m; the omnidirectional camera's `noise_std_dev`: each blob's position is offset by a
  /// vector of length N(0, s) in a uniformly random direction.
  double camera_noise = 0.0;

  // Per-robot deviations (real e-pucks differ from one another; simulated ones do not): each
  // robot draws, once per run, a gain uniform in [1 - d, 1 + d] for each of these, from a
  // stream of its own so that the run's noise draws are those of the design model.
  double wheel_deviation = 0.0;      // each wheel's speed (left and right drawn apart)
  double proximity_deviation = 0.0;  // the proximity readings, before noise
  double light_deviation = 0.0;      // the light readings, before noise
  double rab_range_deviation = 0.0;  // the robot's range-and-bearing emission range

  bool has_deviations() const {
    return wheel_deviation > 0.0 || proximity_deviation > 0.0 || light_deviation > 0.0 || rab_range_deviation > 0.0;
  }
  /// The farthest any robot's packets reach.
  double max_rab_range() const { return rab_range * (1.0 + rab_range_deviation); }
};


/// What values a knob of the robot model takes.
enum class KnobDomain { Positive, NonNegative, Probability, Deviation /* [0, 1) */ };

/// Where argos3-epuck reads a knob: which of the controller's blocks, and whether the file
/// leaves the attribute out at zero (a noise the plugin adds only when asked for).
enum class ArgosBlock { None, Actuators, Sensors, SensorsIfNonZero };

/// Whether argos3-epuck creates a random generator for the knob's sensor or actuator only when
/// its value is above 0 (CRandom::CreateRNG in its Init). ARGoS seeds generators in the order they
/// are created, so one more or one fewer shifts every later one, the loop functions' placements
/// included: two files that differ in this are not paired seed by seed.
enum class ArgosGenerator { Always, IfNonZero };

/// One knob of the robot model: its name in mission and pseudo-reality files, and where
/// ARGoS reads it (the block and element of the e-puck's controller, and its attribute). The
/// ARGoS exporter (export/argos_experiment.cpp) writes every knob from this table.
struct RobotKnob {
  std::string_view name;
  double RobotModel::*member;
  KnobDomain domain;
  ArgosBlock argos_block;            // None: ARGoS has no such knob (camera geometry, per-robot deviations)
  std::string_view argos_element;
  std::string_view argos_attribute;
  ArgosGenerator argos_generator = ArgosGenerator::Always;  // (None: no generator of its own)
};

inline constexpr std::array<RobotKnob, 13> kRobotKnobs{{
    {"rab_range", &RobotModel::rab_range, KnobDomain::Positive, ArgosBlock::Actuators, "epuck_range_and_bearing", "range"},
    {"rab_loss", &RobotModel::rab_loss, KnobDomain::Probability, ArgosBlock::Sensors, "epuck_range_and_bearing", "loss_probability"},
    {"rab_noise", &RobotModel::rab_noise, KnobDomain::NonNegative, ArgosBlock::SensorsIfNonZero, "epuck_range_and_bearing", "noise_std_dev"},
    {"wheel_noise", &RobotModel::wheel_noise, KnobDomain::NonNegative, ArgosBlock::Actuators, "epuck_wheels", "noise_std_dev",
     ArgosGenerator::IfNonZero},
    {"proximity_noise", &RobotModel::proximity_noise, KnobDomain::NonNegative, ArgosBlock::Sensors, "epuck_proximity", "noise_level",
     ArgosGenerator::IfNonZero},
    {"light_noise", &RobotModel::light_noise, KnobDomain::NonNegative, ArgosBlock::Sensors, "epuck_light", "noise_level",
     ArgosGenerator::IfNonZero},
    {"ground_noise", &RobotModel::ground_noise, KnobDomain::NonNegative, ArgosBlock::Sensors, "epuck_ground", "noise_level",
     ArgosGenerator::IfNonZero},
    {"camera_range", &RobotModel::camera_range, KnobDomain::Positive, ArgosBlock::None, "", ""},
    {"camera_noise", &RobotModel::camera_noise, KnobDomain::NonNegative, ArgosBlock::SensorsIfNonZero, "epuck_omnidirectional_camera", "noise_std_dev",
     ArgosGenerator::IfNonZero},
    {"wheel_deviation", &RobotModel::wheel_deviation, KnobDomain::Deviation, ArgosBlock::None, "", ""},
    {"proximity_deviation", &RobotModel::proximity_deviation, KnobDomain::Deviation, ArgosBlock::None, "", ""},
    {"light_deviation", &RobotModel::light_deviation, KnobDomain::Deviation, ArgosBlock::None, "", ""},
    {"rab_range_deviation", &RobotModel::rab_range_deviation, KnobDomain::Deviation, ArgosBlock::None, "", ""},
}};

}  // namespace sd

namespace sd {

/// "must be in [0, 1)" and the like: why `value` is outside the knob's domain, or empty.
inline std::string_view knob_domain_error(KnobDomain domain, double value) {
  switch (domain) {
    case KnobDomain::Positive: return value > 0.0 ? "" : "must be positive";
    case KnobDomain::NonNegative: return value >= 0.0 ? "" : "must not be negative";
    case KnobDomain::Probability: return value >= 0.0 && value <= 1.0 ? "" : "must be in [0, 1]";
    case KnobDomain::Deviation: return value >= 0.0 && value < 1.0 ? "" : "must be in [0, 1)";
  }
  return "";
}

}  // namespace sd
