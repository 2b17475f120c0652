#include "design/fsm_space.hpp"

#include <algorithm>
#include <cctype>
#include <charconv>
#include <stdexcept>

namespace sd::design {

namespace {

std::string number_text(double v) {
  char buffer[32];
  const auto result = std::to_chars(buffer, buffer + sizeof buffer, v);
  return std::string(buffer, result.ptr);
}

// irace parameter names follow the AutoMoDe grammars: the upper-cased token, except where one
// token carries two meanings. Chocolate's neighbour-count conditions send their integer
// threshold ξ in --p<i>x<j>, which the probability of the floor conditions also uses; the
// grammars call ξ "B".
std::string upper(std::string text) {
  for (char& ch : text) ch = static_cast<char>(std::toupper(static_cast<unsigned char>(ch)));
  return text;
}

// A parameter that exists only for some values of another (Coconut's RWM with EXP 1) gets its
// own irace name, e.g. RWMEXP1: the same switch as Chocolate's RWM but another condition,
// as the AutoMoDe grammars do for B and P.
std::string irace_name(const ParameterSpec& spec) {
  if (spec.token == "p" && spec.type == ParameterType::Integer) return "B";
  std::string name = upper(spec.token);
  if (!spec.active_if.empty()) {
    name += upper(spec.active_if);
    for (double v : spec.active_values) name += number_text(v);
  }
  return name;
}

ModuleParam from_catalogue(const ParameterSpec& spec) {
  ModuleParam mp;
  mp.name = irace_name(spec);
  if (!spec.active_if.empty()) {
    mp.active_if = upper(spec.active_if);
    for (double v : spec.active_values) mp.active_values.push_back(number_text(v));
  }
  mp.token = spec.token;
  mp.lower = spec.min;
  mp.upper = spec.max;
  switch (spec.type) {
    case ParameterType::Integer: mp.type = ParamType::Integer; break;
    case ParameterType::Real: mp.type = ParamType::Real; break;
    case ParameterType::Categorical:
      mp.type = ParamType::Categorical;
      for (double v : spec.values) mp.values.push_back(number_text(v));
      break;
  }
  return mp;
}

std::vector<Module> catalogue_modules(ModuleKind kind, std::span<const Flavour> flavours) {
  std::vector<Module> out;
  for (const ModuleSpec& spec : modules(kind)) {
    if (std::find(flavours.begin(), flavours.end(), spec.flavour()) == flavours.end()) continue;
    Module m{spec.id, {}};
    for (const ParameterSpec& p : spec.parameters) m.params.push_back(from_catalogue(p));
    out.push_back(std::move(m));
  }
  return out;
}

// A module parameter shared by several modules, in order of first appearance.
struct ParamGroup {
  ModuleParam param;
  std::vector<std::string> module_ids;
};

bool same_definition(const ModuleParam& a, const ModuleParam& b) {
  return a.token == b.token && a.type == b.type && a.lower == b.lower && a.upper == b.upper && a.values == b.values &&
         a.active_if == b.active_if && a.active_values == b.active_values;
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
                            const std::vector<std::string>& ids, const Condition& extra) {
  Parameter p;
  p.name = mp.name + suffix;
  p.switch_ = "--" + mp.token + suffix + " ";
  p.type = mp.type;
  p.values = mp.values;
  p.lower = Bound::fixed(mp.lower);
  p.upper = Bound::fixed(mp.upper);
  p.condition = extra;
  p.condition.push_back(Clause{selector, Clause::Op::In, ids, 0.0});
  if (!mp.active_if.empty()) p.condition.push_back(Clause{mp.active_if + suffix, Clause::Op::In, mp.active_values, 0.0});
  return p;
}

Clause greater(const std::string& param, double v) { return Clause{param, Clause::Op::Gt, {}, v}; }

}  // namespace

void add_module_parameters(ParameterSpace& space, const std::vector<Module>& modules, const std::string& suffix,
                           const std::string& selector, const Condition& extra) {
  for (const auto& g : group_params(modules)) space.add(from_module_param(g.param, suffix, selector, g.module_ids, extra));
}

FsmModules catalogue_fsm_modules(std::span<const Flavour> flavours) {
  return {catalogue_modules(ModuleKind::Behaviour, flavours), catalogue_modules(ModuleKind::Condition, flavours)};
}

FsmModules chocolate_fsm_modules() {
  const Flavour chocolate[] = {Flavour::Chocolate};
  return catalogue_fsm_modules(chocolate);
}

ParameterSpace build_fsm_space(const FsmModules& modules, const FsmSpaceOptions& o) {
  if (o.architectures.empty()) throw std::invalid_argument("no architecture value given");
  ParameterSpace space(o.digits);
  // ARCH "--" c ("fsm-config", ...): first token of the string, as in the
  // unified Demiurge grammar (Demiurge_grammar.txt).
  space.add(Parameter{"ARCH", "--", ParamType::Categorical, o.architectures, {}, {}, false, {}});
  add_fsm_parameters(space, modules, o);
  space.finalize();
  return space;
}

void add_fsm_parameters(ParameterSpace& space, const FsmModules& modules, const FsmSpaceOptions& o) {
  if (modules.behaviours.empty() || modules.conditions.empty())
    throw std::invalid_argument("an FSM space needs at least one behaviour and one condition");
  if (o.max_states < 2 || o.max_transitions < 1)
    throw std::invalid_argument("an FSM space needs max_states >= 2 and max_transitions >= 1");

  const auto behaviour_ids = ids_of(modules.behaviours);
  const auto condition_ids = ids_of(modules.conditions);

  Parameter nstates{"NumStates", "--nstates ", ParamType::Integer, {}, Bound::fixed(1),
                    Bound::fixed(o.max_states), false, {}};
  if (o.architectures.size() > 1) nstates.condition = {Clause{"ARCH", Clause::Op::In, {"fsm-config"}, 0.0}};
  space.add(nstates);

  for (int i = 0; i < o.max_states; ++i) {
    const std::string si = std::to_string(i);
    const std::string state = "S" + si;
    space.add(Parameter{state, "--s" + si + " ", ParamType::Categorical, behaviour_ids, {}, {}, false,
                        {greater("NumStates", i)}});
    add_module_parameters(space, modules.behaviours, si, state);

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
      add_module_parameters(space, modules.conditions, ij, cond);
    }
  }
}

}  // namespace sd::design
