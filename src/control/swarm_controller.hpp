#pragma once
// Runs one piece of control software on every robot of a swarm. Each robot has its own
// execution state (current FSM state or behaviour-tree memories, behaviour memories); the
// software itself is shared.
#include <array>
#include <cstdint>
#include <span>
#include <vector>

#include "control/control_software.hpp"
#include "core/rng.hpp"
#include "modules/arlequin_module_set.hpp"
#include "modules/behaviours.hpp"
#include "robot/reference_model.hpp"

namespace sd {

class SwarmController {
 public:
  /// Keeps a reference to `software`, which must outlive the controller, and to `arlequin`,
  /// the module set that runs modules 50-55 (nullptr: the shipped networks, SwarmDesign's
  /// machinery), which must too.
  SwarmController(const ControlSoftware& software, int robots, const arlequin::ModuleSet* arlequin = nullptr);
  SwarmController(ControlSoftware&&, int, const arlequin::ModuleSet* = nullptr) = delete;

  /// Start of a run: every robot in state 0 / at the tree's first child, memories cleared.
  void reset();
  /// One control step of robot `robot`.
  Actuation step(int robot, const ReferenceModel& rm, Rng& rng);

  /// The inputs (Input bits) the robot reads at its next control step. FSM: its state's
  /// behaviour, plus the conditions of its outgoing transitions unless it has just entered
  /// the state (no condition is checked then). Trees and networks: all their inputs.
  std::uint8_t inputs_of_next_step(int robot) const {
    if (software_->architecture != Architecture::Fsm) return all_inputs_;
    const auto r = static_cast<std::size_t>(robot);
    const auto state = static_cast<std::size_t>(current_[r]);
    return entering_[r] ? behaviour_inputs_[state] : state_inputs_[state];
  }
  /// FSM: the robot's current state; behaviour tree: the action that ran at the last step
  /// (-1: none, the tree ended and the robot stood still).
  int current_state(int robot) const { return current_[static_cast<std::size_t>(robot)]; }

 private:
  enum class Status : std::uint8_t { Success, Failure, Running };

  /// run_behaviour, except that a module set given to the constructor runs modules 50-55.
  Actuation run_module(const ModuleInstance& behaviour, BehaviourMemory& memory, const ReferenceModel& rm, Rng& rng) const {
    if (arlequin_ && arlequin::is_module(behaviour.id)) return arlequin_->drive(behaviour.id, memory, rm, rng);
    return run_behaviour(behaviour, memory, rm, rng);
  }

  /// FSM step (as ARGoS3-AutoMoDe's AutoMoDeFiniteStateMachine::ControlStep): on the step a
  /// state is entered its behaviour is reset and no condition is checked; otherwise outgoing
  /// transitions are tried in a random order and the first that fires is taken. The behaviour
  /// that ran this step keeps its command either way.
  Actuation step_fsm(int robot, const ReferenceModel& rm, Rng& rng);
  /// Behaviour-tree step (as ARGoS3-AutoMoDe's BehaviorTree branch): tick the root once; a
  /// tree that returns success or failure stops the robot for this step.
  Actuation step_tree(int robot, const ReferenceModel& rm, Rng& rng);
  /// What every node of one robot's tree tick reads or writes.
  struct TreeTick {
    std::size_t robot;
    const ReferenceModel& rm;
    Rng& rng;
    Actuation& out;  // the command of the action that ran
  };
  /// Ticks any node: leaves in place, composites through tick_composite.
  Status tick(TreeTick& t, int node);
  Status tick_action(TreeTick& t, int node);
  Status tick_composite(TreeTick& t, int node);
  /// Fills neighbours_tables_ and table_start_: FSM, kMaxFsmTransitions slots per state in
  /// transition_slot order; tree, one slot per node.
  void tabulate_neighbours(int max_neighbours);
  /// The condition slot of an FSM state's transition.
  static std::size_t transition_slot(std::size_t state, std::size_t transition) {
    return state * static_cast<std::size_t>(kMaxFsmTransitions) + transition;
  }
  /// The neighbours_table of the condition in `slot` (FSM: transition_slot; tree: the node),
  /// empty for other conditions.
  std::span<const double> neighbours_table_of(std::size_t slot) const {
    return std::span(neighbours_tables_).subspan(table_start_[slot], table_start_[slot + 1] - table_start_[slot]);
  }

  const ControlSoftware* software_;
  const arlequin::ModuleSet* arlequin_;
  int slots_;                             // states (FSM) or nodes (tree) per robot
  std::vector<std::int16_t> current_;     // FSM state or last action, per robot
  std::vector<std::uint8_t> entering_;    // FSM: entering the current state
  std::vector<std::uint8_t> running_;     // tree: remembered child of * nodes, robots x nodes
  std::vector<BehaviourMemory> memory_;   // robots x slots
  std::uint8_t all_inputs_;
  std::vector<std::uint8_t> behaviour_inputs_, state_inputs_;  // FSM, per state
  // The (Inverted)NeighborsCount conditions' probabilities for 0 .. robots - 1 neighbours,
  // tabulated once so that no step calls exp: slot s's table is
  // neighbours_tables_[table_start_[s] .. table_start_[s + 1]).
  std::vector<double> neighbours_tables_;
  std::vector<std::uint32_t> table_start_;
};

}  // namespace sd
