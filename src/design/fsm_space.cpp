#include "design/fsm_space.hpp"

#include <algorithm>
#include <stdexcept>

namespace sd::design {

namespace {

ModuleParam real(std::string name, std::string token, double lo, double hi) {
  return {std::move(name), std::move(token), ParamType::Real, lo, hi, {}};
}
ModuleParam integer(std::string name, std::string token, double lo, double hi) {
  return {std::move(name), std::move(token), ParamType::Integer, lo, hi, {}};
}

// A module parameter shared by several modules, in order of first appearance.
struct ParamGroup {
  ModuleParam param;
  std::vector<std::string> module_ids;
};

bool same_definition(const ModuleParam& a, const ModuleParam& b) {
  return a.token == b.token && a.type == b.type && a.lower == b.lower && a.upper == b.upper && a.values == b.values;
}

std::vector<ParamGroup> group_params(const std::vector<Module>& modules) {
  std::vector<ParamGroup> groups;
  for (const Module& m : modules) {
    for (const ModuleParam& mp : m.params) {
      ParamGroup* g = nullptr;
      for (auto& existing : groups)
        if (existing.param.name == mp.name) g = &existing;
      if (!g) {
        groups.push_back({mp, {}});
        g = &groups.back();
      } else if (!same_definition(g->param, mp)) {
        throw std::invalid_argument("module parameter '" + mp.name + "' is defined differently by module " +
                                    std::to_string(m.id));
      }
      g->module_ids.push_back(std::to_string(m.id));
    }
  }
  return groups;
}

std::vector<std::string> ids_of(const std::vector<Module>& modules) {
  std::vector<std::string> ids;
  for (const Module& m : modules) {
    if (m.id < 10 || m.id > 99) throw std::invalid_argument("module ids must have two digits: " + std::to_string(m.id));
    ids.push_back(std::to_string(m.id));
  }
  return ids;
}

Parameter from_module_param(const ModuleParam& mp, const std::string& suffix, const std::string& selector,
                            const std::vector<std::string>& ids) {
  Parameter p;
  p.name = mp.name + suffix;
  p.switch_ = "--" + mp.token + suffix + " ";
  p.type = mp.type;
  p.values = mp.values;
  p.lower = Bound::fixed(mp.lower);
  p.upper = Bound::fixed(mp.upper);
  p.condition = {Clause{selector, Clause::Op::In, ids, 0.0}};
  return p;
}

Clause greater(const std::string& param, double v) { return Clause{param, Clause::Op::Gt, {}, v}; }

}  // namespace

FsmModules chocolate_fsm_modules() {
  FsmModules m;
  m.behaviours = {
      {10, {integer("RWM", "rwm", 1, 100)}},  // exploration: random-walk steps
      {11, {}},                               // stop
      {12, {}},                               // phototaxis
      {13, {}},                               // anti-phototaxis
      {14, {real("ATT", "att", 1, 5)}},       // attraction
      {15, {real("REP", "rep", 1, 5)}},       // repulsion
  };
  const ModuleParam p = real("P", "p", 0, 1);
  // Neighbour-count conditions: ξ travels in --p<i>x<j>, η in --w<i>x<j> (AM master encoding).
  const std::vector<ModuleParam> neighbours = {integer("B", "p", 1, 10), real("W", "w", 0, 20)};
  m.conditions = {
      {10, {p}}, {11, {p}}, {12, {p}}, {13, neighbours}, {14, neighbours}, {15, {p}},
  };
  return m;
}

ParameterSpace build_fsm_space(const FsmModules& modules, const FsmSpaceOptions& o) {
  if (modules.behaviours.empty() || modules.conditions.empty())
    throw std::invalid_argument("an FSM space needs at least one behaviour and one condition");
  if (o.max_states < 2 || o.max_transitions < 1)
    throw std::invalid_argument("an FSM space needs max_states >= 2 and max_transitions >= 1");
  if (o.architectures.empty()) throw std::invalid_argument("no architecture value given");

  const auto behaviour_ids = ids_of(modules.behaviours);
  const auto condition_ids = ids_of(modules.conditions);
  const auto behaviour_params = group_params(modules.behaviours);
  const auto condition_params = group_params(modules.conditions);

  ParameterSpace space(o.digits);
  // ARCH "--" c ("fsm-config", ...): first token of the string (§8.5).
  space.add(Parameter{"ARCH", "--", ParamType::Categorical, o.architectures, {}, {}, false, {}});

  Parameter nstates{"NumStates", "--nstates ", ParamType::Integer, {}, Bound::fixed(1),
                    Bound::fixed(o.max_states), false, {}};
  if (o.architectures.size() > 1) nstates.condition = {Clause{"ARCH", Clause::Op::In, {"fsm-config"}, 0.0}};
  space.add(nstates);

  for (int i = 0; i < o.max_states; ++i) {
    const std::string si = std::to_string(i);
    const std::string state = "S" + si;
    space.add(Parameter{state, "--s" + si + " ", ParamType::Categorical, behaviour_ids, {}, {}, false,
                        {greater("NumStates", i)}});
    for (const auto& g : behaviour_params) space.add(from_module_param(g.param, si, state, g.module_ids));

    const std::string nconn = "NumConnections" + si;
    space.add(Parameter{nconn, "--n" + si + " ", ParamType::Integer, {}, Bound::fixed(1),
                        Bound::fixed(o.max_transitions), false, {greater("NumStates", std::max(1, i))}});
    for (int j = 0; j < o.max_transitions; ++j) {
      const std::string ij = si + "x" + std::to_string(j);
      // Target as an index into the other states: 0..NumStates-2 (dependent domain).
      space.add(Parameter{"N" + ij, "--n" + ij + " ", ParamType::Integer, {}, Bound::fixed(0),
                          Bound::of("NumStates", -2), false, {greater(nconn, j)}});
      const std::string cond = "C" + ij;
      space.add(Parameter{cond, "--c" + ij + " ", ParamType::Categorical, condition_ids, {}, {}, false,
                          {greater(nconn, j)}});
      for (const auto& g : condition_params) space.add(from_module_param(g.param, ij, cond, g.module_ids));
    }
  }
  space.finalize();
  return space;
}

}  // namespace sd::design
