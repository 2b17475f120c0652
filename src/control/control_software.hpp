#pragma once
// Control software as data: a probabilistic finite-state machine (and, with the Maple
// flavour, a behaviour tree) whose nodes are module instances from the catalogue.
#include <cstdint>
#include <string>
#include <vector>

#include "modules/arlequin.hpp"
#include "modules/catalogue.hpp"

namespace sd {

inline constexpr int kMaxFsmStates = 4;
inline constexpr int kMaxFsmTransitions = 4;

struct FsmTransition {
  int target = 0;               // absolute index of the destination state
  ModuleInstance condition;
  bool operator==(const FsmTransition&) const = default;
};

struct FsmState {
  ModuleInstance behaviour;
  std::vector<FsmTransition> transitions;  // outgoing, in definition order
  bool operator==(const FsmState&) const = default;
};

struct Fsm {
  std::vector<FsmState> states;  // state 0 is the initial state
  bool operator==(const Fsm&) const = default;
};

/// Behaviour-tree nodes as in ARGoS3-AutoMoDe's BehaviorTree branch.
enum class BtNodeType : std::uint8_t {
  Selector = 0,
  SelectorStar = 1,   // selector with memory
  Sequence = 2,
  SequenceStar = 3,   // sequence with memory (Maple's root)
  Negation = 4,
  Action = 5,
  Condition = 6,
};

inline constexpr int kMaxBtChildren = 9;  // one digit per level of node ids
inline constexpr int kMaxBtDepth = 5;     // node ids have at most 5 digits

struct BtNode {
  BtNodeType type = BtNodeType::Selector;
  std::vector<int> children;          // indices into BehaviourTree::nodes
  ModuleInstance module;              // Action: behaviour; Condition: condition
  double success_probability = 0.0;   // Action: chance per tick to succeed instead of running
  bool operator==(const BtNode&) const = default;
};

struct BehaviourTree {
  std::vector<BtNode> nodes;  // nodes[0] is the root; children come after their parent
  bool operator==(const BehaviourTree&) const = default;
};

/// EvoStick's control software: one Arlequin perceptron drives every robot (arlequin.hpp).
struct NeuralNetwork {
  arlequin::Weights weights{};
  bool operator==(const NeuralNetwork&) const = default;
};

enum class Architecture { Fsm, BehaviourTree, NeuralNetwork };

struct ControlSoftware {
  Architecture architecture = Architecture::Fsm;
  Fsm fsm;
  BehaviourTree bt;
  NeuralNetwork network;
  bool operator==(const ControlSoftware&) const = default;

  /// Union of the Input bits of every module it uses.
  std::uint8_t inputs() const;
};

}  // namespace sd
