#pragma once
// Runs one piece of control software on every robot of a swarm. Each robot has its own
// execution state (current FSM state, behaviour memories); the software itself is shared.
#include <array>
#include <cstdint>
#include <vector>

#include "control/control_software.hpp"
#include "core/rng.hpp"
#include "modules/behaviours.hpp"
#include "robot/reference_model.hpp"

namespace sd {

class SwarmController {
 public:
  /// Keeps a reference to `software`, which must outlive the controller.
  SwarmController(const ControlSoftware& software, int robots);
  SwarmController(ControlSoftware&&, int) = delete;

  /// Start of a run: every robot in state 0, about to enter it.
  void reset();
  /// One control step of robot `robot` (modules-and-grammar.md §6.2): on the step a state
  /// is entered its behaviour is reset and no condition is checked; otherwise outgoing
  /// transitions are tried in a random order and the first that fires is taken. The
  /// behaviour that ran this step keeps its command either way.
  Actuation step(int robot, const ReferenceModel& rm, Rng& rng);

  int current_state(int robot) const { return robots_[static_cast<std::size_t>(robot)].current; }

 private:
  struct RobotExecution {
    std::uint8_t current = 0;
    bool entering = true;
  };
  const ControlSoftware* software_;
  int states_;
  std::vector<RobotExecution> robots_;
  std::vector<BehaviourMemory> memory_;  // robots x states
};

}  // namespace sd
