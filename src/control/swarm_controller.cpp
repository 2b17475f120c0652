#include "control/swarm_controller.hpp"

#include <utility>

#include "modules/conditions.hpp"

namespace sd {

SwarmController::SwarmController(const ControlSoftware& software, int robots)
    : software_(&software), states_(static_cast<int>(software.fsm.states.size())) {
  robots_.resize(static_cast<std::size_t>(robots));
  memory_.resize(static_cast<std::size_t>(robots) * static_cast<std::size_t>(states_));
  reset();
}

void SwarmController::reset() {
  for (auto& r : robots_) r = RobotExecution{};
  for (auto& m : memory_) reset_behaviour(m);
}

Actuation SwarmController::step(int robot, const ReferenceModel& rm, Rng& rng) {
  RobotExecution& exec = robots_[static_cast<std::size_t>(robot)];
  const FsmState& state = software_->fsm.states[exec.current];
  BehaviourMemory& memory = memory_[static_cast<std::size_t>(robot * states_ + exec.current)];
  if (exec.entering) reset_behaviour(memory);
  const Actuation actuation = run_behaviour(state.behaviour, memory, rm, rng);
  if (exec.entering) {
    exec.entering = false;
    return actuation;
  }
  const auto count = static_cast<std::uint32_t>(state.transitions.size());
  if (count == 0) return actuation;
  std::array<std::uint8_t, kMaxFsmTransitions> order{0, 1, 2, 3};
  for (std::uint32_t k = count - 1; k > 0; --k) std::swap(order[k], order[rng.below(k + 1)]);
  for (std::uint32_t k = 0; k < count; ++k) {
    const FsmTransition& t = state.transitions[order[k]];
    if (check_condition(t.condition, rm, rng)) {
      exec.current = static_cast<std::uint8_t>(t.target);
      exec.entering = true;
      break;
    }
  }
  return actuation;
}

}  // namespace sd
