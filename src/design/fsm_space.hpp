#pragma once
// The probabilistic-FSM design space (structure of ARGoS3-AutoMoDe's irace grammar
// new_grammar.txt, names and two-digit module ids of the unified Demiurge grammar,
// ARGoS3-AutoMoDe master tokens: ξ in --p<i>x<j>, η in --w<i>x<j>).
//
// The module table is plain data so that the project's module catalogue can feed it; a module
// parameter shared by several modules (same name) becomes one irace parameter whose condition
// lists every module that has it, as the unified Demiurge grammar does.
#include <span>
#include <string>
#include <vector>

#include "design/parameter_space.hpp"
#include "modules/catalogue.hpp"

namespace sd::design {

struct ModuleParam {
  std::string name;   // irace parameter name stem, e.g. "RWM" -> RWM0, "P" -> P0x1
  std::string token;  // command-line token stem, e.g. "rwm" -> --rwm0, "p" -> --p0x1
  ParamType type = ParamType::Real;
  double lower = 0.0, upper = 1.0;  // integer / real
  std::vector<std::string> values;  // categorical / ordinal
  // Active only when the module's parameter `active_if` (irace name stem) takes one of
  // `active_values` (Coconut: RWM with EXP 1, MU and RHO with EXP 2).
  std::string active_if;
  std::vector<std::string> active_values;
};

struct Module {
  int id = 0;  // two-digit id: 10 * flavour + module digit
  std::vector<ModuleParam> params;
};

struct FsmModules {
  std::vector<Module> behaviours;
  std::vector<Module> conditions;
};

struct FsmSpaceOptions {
  int max_states = 4;       // NumStates in 1..max_states (>= 2)
  int max_transitions = 4;  // NumConnections<i> in 1..max_transitions
  int digits = 2;           // AutoMoDe scenarios use digits = 2
  /// Values of the architecture parameter ARCH "--" (first token of every string). With one
  /// value it is fixed; with several (later: "bt-config"), the FSM part is conditioned on
  /// ARCH == "fsm-config".
  std::vector<std::string> architectures = {"fsm-config"};
};

/// The modules of the given flavours, read from the project's module catalogue
/// (sd::modules), in id order. Empty lists for flavours that have no modules yet.
FsmModules catalogue_fsm_modules(std::span<const Flavour> flavours);
/// catalogue_fsm_modules({Chocolate}): behaviours 10-15, conditions 10-15.
FsmModules chocolate_fsm_modules();

/// Builds the finalized FSM parameter space. Throws std::invalid_argument on an inconsistent
/// table (same parameter name with different token/type/domain, no behaviours, ...).
ParameterSpace build_fsm_space(const FsmModules& modules, const FsmSpaceOptions& options = {});

/// Adds the FSM parameters to `space` (which already holds ARCH); shared with the combined
/// FSM + behaviour-tree space.
void add_fsm_parameters(ParameterSpace& space, const FsmModules& modules, const FsmSpaceOptions& options);

/// Adds the parameters of one module slot: for every parameter group, the irace parameter
/// `<NAME><suffix>` with switch `--<token><suffix> `, active when `selector` holds one of the
/// group's module ids (and its own activation clause holds).
void add_module_parameters(ParameterSpace& space, const std::vector<Module>& modules, const std::string& suffix,
                           const std::string& selector, const Condition& extra = {});

}  // namespace sd::design
