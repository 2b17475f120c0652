#include "control/swarm_controller.hpp"

#include <utility>

#include "modules/catalogue.hpp"
#include "modules/conditions.hpp"

namespace sd {

SwarmController::SwarmController(const ControlSoftware& software, int robots, const arlequin::ModuleSet* arlequin)
    : software_(&software),
      arlequin_(arlequin),
      slots_(static_cast<int>(software.architecture == Architecture::Fsm             ? software.fsm.states.size()
                              : software.architecture == Architecture::BehaviourTree ? software.bt.nodes.size()
                                                                                     : 0)) {
  const auto n = static_cast<std::size_t>(robots);
  current_.resize(n);
  entering_.resize(n);
  running_.resize(n * static_cast<std::size_t>(slots_));
  memory_.resize(n * static_cast<std::size_t>(slots_));
  all_inputs_ = software.inputs();
  for (const FsmState& state : software.fsm.states) prepare_behaviour(state.behaviour);
  for (const BtNode& node : software.bt.nodes)
    if (node.type == BtNodeType::Action) prepare_behaviour(node.module);
  if (software.architecture == Architecture::Fsm) {
    for (const FsmState& state : software.fsm.states) {
      const ModuleSpec* behaviour = find_module(ModuleKind::Behaviour, state.behaviour.id);
      std::uint8_t bits = behaviour ? behaviour->inputs : all_inputs_;
      behaviour_inputs_.push_back(bits);
      for (const FsmTransition& t : state.transitions) {
        const ModuleSpec* condition = find_module(ModuleKind::Condition, t.condition.id);
        bits |= condition ? condition->inputs : all_inputs_;
      }
      state_inputs_.push_back(bits);
    }
  }
  tabulate_neighbours(robots - 1);
  reset();
}

void SwarmController::tabulate_neighbours(int max_neighbours) {
  table_start_.push_back(0);
  const auto add_slot = [&](const ModuleInstance* condition) {
    if (condition) {
      const std::vector<double> table = neighbours_table(*condition, max_neighbours);
      neighbours_tables_.insert(neighbours_tables_.end(), table.begin(), table.end());
    }
    table_start_.push_back(static_cast<std::uint32_t>(neighbours_tables_.size()));
  };
  if (software_->architecture == Architecture::Fsm) {
    for (const FsmState& state : software_->fsm.states)
      for (std::size_t t = 0; t < kMaxFsmTransitions; ++t)
        add_slot(t < state.transitions.size() ? &state.transitions[t].condition : nullptr);
  } else if (software_->architecture == Architecture::BehaviourTree) {
    for (const BtNode& node : software_->bt.nodes) add_slot(node.type == BtNodeType::Condition ? &node.module : nullptr);
  }
}

void SwarmController::reset() {
  const bool fsm = software_->architecture == Architecture::Fsm;
  std::fill(current_.begin(), current_.end(), static_cast<std::int16_t>(fsm ? 0 : -1));
  std::fill(entering_.begin(), entering_.end(), 1);
  std::fill(running_.begin(), running_.end(), 0);
  for (auto& m : memory_) reset_behaviour(m);
}

Actuation SwarmController::step(int robot, const ReferenceModel& rm, Rng& rng) {
  switch (software_->architecture) {
    case Architecture::Fsm: return step_fsm(robot, rm, rng);
    case Architecture::BehaviourTree: return step_tree(robot, rm, rng);
    case Architecture::NeuralNetwork: return arlequin::drive(software_->network.weights, rm);
  }
  return {0.0, 0.0};
}

// Inlined into step(): the control step of every robot at every tick goes through here.
inline Actuation SwarmController::step_fsm(int robot, const ReferenceModel& rm, Rng& rng) {
  const auto r = static_cast<std::size_t>(robot);
  const auto current = static_cast<std::size_t>(current_[r]);
  const FsmState& state = software_->fsm.states[current];
  BehaviourMemory& memory = memory_[r * static_cast<std::size_t>(slots_) + current];
  if (entering_[r] && resets_on_state_entry(state.behaviour.id)) reset_behaviour(memory);
  const Actuation actuation = run_module(state.behaviour, memory, rm, rng);
  if (entering_[r]) {
    entering_[r] = 0;
    return actuation;
  }
  const auto count = static_cast<std::uint32_t>(state.transitions.size());
  if (count == 0) return actuation;
  std::array<std::uint8_t, kMaxFsmTransitions> order{0, 1, 2, 3};
  for (std::uint32_t k = count - 1; k > 0; --k) std::swap(order[k], order[rng.below(k + 1)]);
  for (std::uint32_t k = 0; k < count; ++k) {
    const FsmTransition& t = state.transitions[order[k]];
    if (check_condition(t.condition, rm, rng, neighbours_table_of(transition_slot(current, order[k])))) {
      current_[r] = static_cast<std::int16_t>(t.target);
      entering_[r] = 1;
      break;
    }
  }
  return actuation;
}

Actuation SwarmController::step_tree(int robot, const ReferenceModel& rm, Rng& rng) {
  Actuation out{0.0, 0.0};
  current_[static_cast<std::size_t>(robot)] = -1;  // until an action runs at this step
  TreeTick t{static_cast<std::size_t>(robot), rm, rng, out};
  const Status status = tick(t, 0);
  if (status != Status::Running) return {0.0, 0.0, out.led};  // the tree ended: stop this step
  return out;
}

// Most nodes of a tree are leaves, and a leaf does less work than a call: a leaf is ticked
// where its parent asks for it, and only composites recurse.
inline SwarmController::Status SwarmController::tick(TreeTick& t, int node_index) {
  const BtNode& node = software_->bt.nodes[static_cast<std::size_t>(node_index)];
  if (node.type == BtNodeType::Condition)
    return check_condition(node.module, t.rm, t.rng, neighbours_table_of(static_cast<std::size_t>(node_index)))
               ? Status::Success
               : Status::Failure;
  if (node.type == BtNodeType::Action) return tick_action(t, node_index);
  return tick_composite(t, node_index);
}

inline SwarmController::Status SwarmController::tick_action(TreeTick& t, int node_index) {
  const BtNode& node = software_->bt.nodes[static_cast<std::size_t>(node_index)];
  // Actions are not reset when they become active again (their memory persists).
  if (node.success_probability > 0.0 && t.rng.bernoulli(node.success_probability)) return Status::Success;
  const std::size_t slot = t.robot * static_cast<std::size_t>(slots_) + static_cast<std::size_t>(node_index);
  t.out = run_module(node.module, memory_[slot], t.rm, t.rng);
  current_[t.robot] = static_cast<std::int16_t>(node_index);
  return Status::Running;
}

SwarmController::Status SwarmController::tick_composite(TreeTick& t, int node_index) {
  const BtNode& node = software_->bt.nodes[static_cast<std::size_t>(node_index)];
  const std::size_t slot = t.robot * static_cast<std::size_t>(slots_) + static_cast<std::size_t>(node_index);
  const auto children = static_cast<int>(node.children.size());
  switch (node.type) {
    case BtNodeType::Condition:
    case BtNodeType::Action:
      return tick(t, node_index);
    case BtNodeType::Negation: {
      const Status s = tick(t, node.children.front());
      return s == Status::Running ? s : (s == Status::Success ? Status::Failure : Status::Success);
    }
    case BtNodeType::Selector:
      for (const int child : node.children) {
        const Status s = tick(t, child);
        if (s != Status::Failure) return s;
      }
      return Status::Failure;
    case BtNodeType::Sequence:
      for (const int child : node.children) {
        const Status s = tick(t, child);
        if (s != Status::Success) return s;
      }
      return Status::Success;
    case BtNodeType::SelectorStar:
      for (int c = running_[slot]; c < children; ++c) {
        const Status s = tick(t, node.children[static_cast<std::size_t>(c)]);
        if (s == Status::Running) {
          running_[slot] = static_cast<std::uint8_t>(c);
          return s;
        }
        if (s == Status::Success) {
          running_[slot] = 0;
          return s;
        }
      }
      running_[slot] = 0;
      return Status::Success;  // ARGoS3-AutoMoDe's Selector* succeeds when all children fail
    case BtNodeType::SequenceStar:
      for (int c = running_[slot]; c < children; ++c) {
        const Status s = tick(t, node.children[static_cast<std::size_t>(c)]);
        if (s == Status::Running) {
          running_[slot] = static_cast<std::uint8_t>(c);
          return s;
        }
        if (s == Status::Failure) {
          running_[slot] = 0;
          return s;
        }
      }
      running_[slot] = 0;
      return Status::Success;
  }
  return Status::Failure;
}

}  // namespace sd
