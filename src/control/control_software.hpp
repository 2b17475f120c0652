#pragma once
// Control software as data: a probabilistic finite-state machine (and, with the Maple
// flavour, a behaviour tree) whose nodes are module instances from the catalogue.
#include <cstdint>
#include <string>
#include <vector>

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

enum class Architecture { Fsm, BehaviourTree };

struct ControlSoftware {
  Architecture architecture = Architecture::Fsm;
  Fsm fsm;
  bool operator==(const ControlSoftware&) const = default;

  /// Union of the Input bits of every module it uses.
  std::uint8_t inputs() const;
};

}  // namespace sd
