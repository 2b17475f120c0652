#include "evaluation/simulation.hpp"

#include "simulator/placement.hpp"
#include "simulator/sensors.hpp"

namespace sd {

Simulation::Simulation(const Mission& mission, const ControlSoftware& software)
    : mission_(&mission),
      robot_(mission.robot),
      software_(software),
      controller_(software_, mission.robots, mission.arlequin_modules.get()),
      objective_(mission) {
  swarm_.resize(mission.robots, static_cast<int>(mission.arena.leds.size()));
  physics_.reset(mission.robots);
  reference_.resize(static_cast<std::size_t>(mission.robots));
  const std::uint8_t inputs = software_.inputs();
  sensors_.proximity = inputs & kProximityInput;
  sensors_.light = inputs & kLightInput;
  sensors_.ground = inputs & kGroundInput;
  sensors_.range_and_bearing = inputs & kRangeAndBearingInput;
  sensors_.camera = inputs & kCameraInput;
}

void Simulation::reset(std::uint64_t seed, const RobotModel* robot) {
  robot_ = robot != nullptr ? *robot : mission_->robot;
  rng_.reseed(seed);
  swarm_.deviations.draw(robot_, swarm_.size, seed);
  tick_ = 0;
  place_robots(mission_->arena, [this](Rng& rng) { return mission_->draw_start(rng); }, swarm_, rng_);
  const std::vector<StartPose>& given = mission_->start_poses;
  for (std::size_t r = 0; r < given.size() && r < swarm_.position.size(); ++r) {
    swarm_.position[r] = given[r].position;
    swarm_.yaw[r] = wrap_signed(given[r].yaw);
    swarm_.heading[r] = Vec2::polar(1.0, swarm_.yaw[r]);
  }
  for (std::size_t k = 0; k < mission_->arena.leds.size(); ++k) swarm_.arena_led_color[k] = mission_->arena.leds[k].initial_color;
  physics_.reset(mission_->robots);
  for (auto& rm : reference_) rm.reset();
  controller_.reset();
  objective_.reset();
}

void Simulation::step() {
  ++tick_;
  const Mission& m = *mission_;
  physics_.step(m.arena, swarm_);
  for (int i = 0; i < swarm_.size; ++i) {
    const std::uint8_t in = controller_.inputs_of_next_step(i);
    swarm_.demand[static_cast<std::size_t>(i)] = static_cast<std::uint8_t>(
        ((in & kProximityInput) ? SwarmState::kDemandProximity : 0) | ((in & kLightInput) ? SwarmState::kDemandLight : 0) |
        ((in & kCameraInput) ? SwarmState::kDemandCamera : 0));
  }
  sense(m.arena, robot_, swarm_, rng_, sensors_);
  const double wheel_noise = robot_.wheel_noise;
  const RobotDeviations& deviations = swarm_.deviations;
  for (int i = 0; i < swarm_.size; ++i) {
    const auto r = static_cast<std::size_t>(i);
    reference_[r].update(swarm_, i);
    const Actuation a = controller_.step(i, reference_[r], rng_);
    // The wheel actuator takes cm/s; its noise multiplies each speed by 1 + N(0, s), drawn
    // at every control step (a stopped wheel stays stopped, so no draw is needed).
    double left = a.left_cm * 0.01, right = a.right_cm * 0.01;
    if (deviations.active) {  // this robot's own wheels (a pseudo-reality)
      left *= deviations.wheel_left[r];
      right *= deviations.wheel_right[r];
    }
    if (wheel_noise > 0.0) {
      if (left != 0.0) left *= 1.0 + wheel_noise * rng_.normal();
      if (right != 0.0) right *= 1.0 + wheel_noise * rng_.normal();
    }
    swarm_.wheel_left[r] = left;
    swarm_.wheel_right[r] = right;
    if (a.led != kLedUnchanged) swarm_.led[r] = a.led;
  }
  objective_.post_step(swarm_, tick_, rng_);
}

double Simulation::run(std::uint64_t seed, TickObserver* observer, const RobotModel* robot) {
  reset(seed, robot);
  if (observer) observer->on_tick(*this);
  while (!finished()) {
    step();
    if (observer) observer->on_tick(*this);
  }
  return score();
}

double evaluate(const Mission& mission, const ControlSoftware& software, std::uint64_t seed) {
  Simulation simulation(mission, software);
  return simulation.run(seed);
}

}  // namespace sd
