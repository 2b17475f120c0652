#pragma once
// The behaviour-tree design space: Maple's topology in format B (as the Demiurge grammar
// generator's generate_grammar_bt writes it) — a Sequence* root over 1..4 Selectors, each a
// condition leaf then an action leaf.
#include "design/fsm_space.hpp"
#include "design/parameter_space.hpp"

namespace sd::design {

struct BtSpaceOptions {
  int max_branches = 4;  // NumChildsRoot in 1..max_branches
};

/// Adds the tree's parameters to `space` (which already holds ARCH). When ARCH has other
/// values, every tree parameter is conditioned on ARCH == "bt-config".
void add_bt_parameters(ParameterSpace& space, const FsmModules& modules, const BtSpaceOptions& options,
                       bool conditioned_on_arch);

}  // namespace sd::design
