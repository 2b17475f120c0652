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
std::string irace_name(const ParameterSpec& spec) {
  if (spec.token == "p" && spec.type == ParameterType::Integer) return "B";
  std::string name = spec.token;
  for (char& ch : name) ch = static_cast<char>(std::toupper(static_cast<unsigned char>(ch)));
  return name;
}

ModuleParam from_catalogue(const ParameterSpec& spec) {
  ModuleParam mp;
  mp.name = irace_name(spec);
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

FsmModules catalogue_fsm_modules(std::span<const Flavour> flavours) {
  return {catalogue_modules(ModuleKind::Behaviour, flavours), catalogue_modules(ModuleKind::Condition, flavours)};
}

FsmModules chocolate_fsm_modules() {
  const Flavour chocolate[] = {Flavour::Chocolate};
  return catalogue_fsm_modules(chocolate);
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
