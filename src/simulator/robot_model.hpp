#pragma once
// The parts of the robot model a mission may override (ARGoS3 as actually run by AutoMoDe).
// Defaults are the AutoMoDe experiment files' values.
namespace sd {

struct RobotModel {
  // m; argos3-epuck's RAB actuator reads the experiment file's `range` attribute, 0.8 when
  // unset. The catalogue's missions set what their scenario files say (0.7, TuttiFrutti 0.5).
  double rab_range = 0.8;
  double rab_loss = 0.85;          // probability a packet is dropped
  double wheel_noise = 0.05;       // std-dev of the multiplicative N(0, s) wheel noise
  double proximity_noise = 0.05;   // half-width of the additive uniform noise
  double light_noise = 0.05;
  double ground_noise = 0.05;
  double camera_range = 0.335;     // m, 0.122 * tan(70 deg)
};

}  // namespace sd
