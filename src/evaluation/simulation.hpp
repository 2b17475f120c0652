#pragma once
// One run of a mission with one piece of control software: the whole data flow
//   mission + control software + seed -> placement -> ticks -> score
// Each tick: act (last command) -> physics -> sense -> reference model + control -> objective,
// the order of ARGoS. Everything is sized in the constructor; a tick never allocates, and
// one Simulation can run many seeds.
#include <cstdint>
#include <vector>

#include "control/control_software.hpp"
#include "control/swarm_controller.hpp"
#include "core/rng.hpp"
#include "missions/mission.hpp"
#include "missions/objective.hpp"
#include "robot/reference_model.hpp"
#include "simulator/physics.hpp"
#include "simulator/sensors.hpp"
#include "simulator/swarm.hpp"

namespace sd {

class Simulation;

/// Observes a run tick by tick (trace files, the live viewer).
class TickObserver {
 public:
  virtual ~TickObserver() = default;
  /// Called after placement (tick 0) and after every tick.
  virtual void on_tick(const Simulation& simulation) = 0;
};

class Simulation {
 public:
  Simulation(const Mission& mission, const ControlSoftware& software);
  // The controller points into software_: a copy or move would dangle.
  Simulation(const Simulation&) = delete;
  Simulation& operator=(const Simulation&) = delete;

  /// A whole evaluation: the mission's natural score for this seed. `robot`: the robot
  /// model of this run (a pseudo-reality); null: the mission's own (the design model).
  double run(std::uint64_t seed, TickObserver* observer = nullptr, const RobotModel* robot = nullptr);

  void reset(std::uint64_t seed, const RobotModel* robot = nullptr);
  void step();
  bool finished() const { return tick_ >= mission_->ticks; }

  int tick() const { return tick_; }
  double score() const { return objective_.value(); }
  const Mission& mission() const { return *mission_; }
  /// The robot model of the current run.
  const RobotModel& robot_model() const { return robot_; }
  const SwarmState& swarm() const { return swarm_; }
  int fsm_state(int robot) const { return controller_.current_state(robot); }
  const ControlSoftware& software() const { return software_; }
  /// What the robot's control step read at the last tick (traces).
  const ReferenceModel& reference_model(int robot) const { return reference_[static_cast<std::size_t>(robot)]; }
  /// Finds pairs with the neighbour grid or among all pairs; by default whichever is faster
  /// for the mission's swarm. Scores are the same either way (tests and benchmarks).
  void use_neighbour_grid(bool on) { swarm_.use_neighbour_grid(on); }

 private:
  const Mission* mission_;
  RobotModel robot_;
  ControlSoftware software_;
  SwarmState swarm_;
  Physics physics_;
  std::vector<ReferenceModel> reference_;
  SwarmController controller_;
  ObjectiveTracker objective_;
  Rng rng_;
  SensorSet sensors_;
  int tick_ = 0;
};

/// Convenience: one evaluation.
double evaluate(const Mission& mission, const ControlSoftware& software, std::uint64_t seed);

}  // namespace sd
