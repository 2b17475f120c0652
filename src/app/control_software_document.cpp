#include "app/control_software_document.hpp"

#include <array>
#include <regex>
#include <string>
#include <type_traits>

#include "app/errors.hpp"
#include "control/config_string.hpp"
#include "core/json_integer.hpp"

namespace sd::app {

using nlohmann::json;

namespace {

constexpr std::array<const char*, 7> kNodeTypes = {"selector", "selector*", "sequence", "sequence*",
                                                   "negation", "action",    "condition"};

const char* type_name(ParameterType type) {
  switch (type) {
    case ParameterType::Integer: return "integer";
    case ParameterType::Real: return "real";
    case ParameterType::Categorical: return "categorical";
  }
  return "real";
}

json modules_document(ModuleKind kind) {
  json list = json::array();
  for (const ModuleSpec& m : modules(kind)) {
    json parameters = json::array();
    for (const ParameterSpec& p : m.parameters)
      parameters.push_back({{"token", p.token}, {"type", type_name(p.type)}, {"min", p.min}, {"max", p.max},
                            {"values", p.values}, {"meaning", p.meaning}, {"domain", p.domain_text()},
                            {"active_if", p.active_if}, {"active_values", p.active_values}});
    list.push_back({{"id", m.id}, {"name", m.name}, {"flavour", flavour_name(m.flavour())}, {"parameters", parameters}});
  }
  return list;
}

json module_document(const ModuleInstance& instance, ModuleKind kind) {
  json parameters = json::object();
  if (const ModuleSpec* spec = find_module(kind, instance.id))
    for (std::size_t p = 0; p < spec->parameters.size(); ++p)
      if (spec->parameter_active(p, instance.parameters)) parameters[spec->parameters[p].token] = instance.parameters[p];
  return {{"id", instance.id}, {"parameters", parameters}};
}

/// Reads one field, saying where it is when it is missing or of the wrong type.
/// An integer is range-checked before it is converted: get<int>() on 1e300 is undefined.
template <typename T>
T field(const json& object, const char* key, const std::string& where) {
  if (!object.is_object() || !object.contains(key)) throw InvalidRequest(where + "." + key + " is missing");
  if constexpr (std::is_integral_v<T>) {
    const auto value = json_integer<T>(object.at(key));
    if (!value) throw InvalidRequest(where + "." + key + " must be an integer");
    return *value;
  } else {
    try {
      return object.at(key).get<T>();
    } catch (const json::exception&) {
      throw InvalidRequest(where + "." + key + " has the wrong type");
    }
  }
}

/// A list field that may be left out (an empty list then).
json optional_list(const json& object, const char* key, const std::string& where) {
  if (!object.contains(key)) return json::array();
  const json& list = object.at(key);
  if (!list.is_array()) throw InvalidRequest(where + "." + key + " must be a list");
  return list;
}

ModuleInstance module_from(const json& doc, ModuleKind kind, const std::string& where) {
  ModuleInstance instance;
  instance.id = field<int>(doc, "id", where);
  const ModuleSpec* spec = find_module(kind, instance.id);
  if (!spec)
    throw InvalidRequest(where + ".id " + std::to_string(instance.id) + " is no " +
                         (kind == ModuleKind::Behaviour ? "behaviour" : "condition") + " of the catalogue");
  const json parameters = doc.contains("parameters") ? doc.at("parameters") : json::object();
  if (!parameters.is_object()) throw InvalidRequest(where + ".parameters must be an object");
  for (const auto& [token, value] : parameters.items()) {
    const int p = spec->parameter_index(token);
    if (p < 0) throw InvalidRequest(where + ": " + spec->name + " has no parameter '" + token + "'");
    if (!value.is_number()) throw InvalidRequest(where + ".parameters." + token + " must be a number");
    instance.parameters[static_cast<std::size_t>(p)] = value.get<double>();
  }
  return instance;
}

ControlSoftware fsm_from(const json& model) {
  const json states = field<json>(model, "states", "software");
  if (!states.is_array() || states.empty()) throw InvalidRequest("software.states must list at least one state");
  ControlSoftware software;
  software.architecture = Architecture::Fsm;
  for (std::size_t s = 0; s < states.size(); ++s) {
    const std::string where = "software.states[" + std::to_string(s) + "]";
    FsmState state;
    state.behaviour = module_from(field<json>(states[s], "behaviour", where), ModuleKind::Behaviour, where + ".behaviour");
    const json transitions = optional_list(states[s], "transitions", where);
    for (std::size_t t = 0; t < transitions.size(); ++t) {
      const std::string at = where + ".transitions[" + std::to_string(t) + "]";
      state.transitions.push_back({field<int>(transitions[t], "target", at),
                                   module_from(field<json>(transitions[t], "condition", at), ModuleKind::Condition,
                                               at + ".condition")});
    }
    software.fsm.states.push_back(std::move(state));
  }
  return software;
}

ControlSoftware bt_from(const json& model) {
  const json nodes = field<json>(model, "nodes", "software");
  if (!nodes.is_array() || nodes.empty()) throw InvalidRequest("software.nodes must list at least the root");
  ControlSoftware software;
  software.architecture = Architecture::BehaviourTree;
  for (std::size_t n = 0; n < nodes.size(); ++n) {
    const std::string where = "software.nodes[" + std::to_string(n) + "]";
    const std::string type = field<std::string>(nodes[n], "type", where);
    BtNode node;
    std::size_t t = 0;
    while (t < kNodeTypes.size() && type != kNodeTypes[t]) ++t;
    if (t == kNodeTypes.size()) throw InvalidRequest(where + ".type '" + type + "' is no behaviour-tree node type");
    node.type = static_cast<BtNodeType>(t);
    if (node.type == BtNodeType::Action || node.type == BtNodeType::Condition) {
      const ModuleKind kind = node.type == BtNodeType::Action ? ModuleKind::Behaviour : ModuleKind::Condition;
      node.module = module_from(field<json>(nodes[n], "module", where), kind, where + ".module");
      if (node.type == BtNodeType::Action && nodes[n].contains("success"))
        node.success_probability = field<double>(nodes[n], "success", where);
    } else {
      const json children = field<json>(nodes[n], "children", where);
      if (!children.is_array()) throw InvalidRequest(where + ".children must be a list");
      for (const json& c : children) {
        const auto child = json_integer<std::size_t>(c);
        if (!child || *child <= n || *child >= nodes.size())
          throw InvalidRequest(where + ".children must name later nodes of the list");
        node.children.push_back(static_cast<int>(*child));
      }
    }
    software.bt.nodes.push_back(std::move(node));
  }
  return software;
}

}  // namespace

json catalogue_document() {
  json flavours = json::array();
  for (int f = 1; f <= 5; ++f)
    flavours.push_back({{"id", f}, {"name", flavour_name(static_cast<Flavour>(f))}});
  return {{"flavours", flavours},
          {"behaviours", modules_document(ModuleKind::Behaviour)},
          {"conditions", modules_document(ModuleKind::Condition)},
          {"bt_node_types", kNodeTypes},
          {"limits",
           {{"fsm_states", kMaxFsmStates}, {"fsm_transitions", kMaxFsmTransitions}, {"bt_children", kMaxBtChildren},
            {"bt_depth", kMaxBtDepth}}}};
}

json software_document(const ControlSoftware& software) {
  switch (software.architecture) {
    case Architecture::Fsm: {
      json states = json::array();
      for (const FsmState& s : software.fsm.states) {
        json transitions = json::array();
        for (const FsmTransition& t : s.transitions)
          transitions.push_back({{"target", t.target}, {"condition", module_document(t.condition, ModuleKind::Condition)}});
        states.push_back({{"behaviour", module_document(s.behaviour, ModuleKind::Behaviour)}, {"transitions", transitions}});
      }
      return {{"architecture", "fsm"}, {"states", states}};
    }
    case Architecture::BehaviourTree: {
      json nodes = json::array();
      for (const BtNode& n : software.bt.nodes) {
        json node{{"type", kNodeTypes[static_cast<std::size_t>(n.type)]}};
        if (n.type == BtNodeType::Action) {
          node["module"] = module_document(n.module, ModuleKind::Behaviour);
          node["success"] = n.success_probability;
        } else if (n.type == BtNodeType::Condition) {
          node["module"] = module_document(n.module, ModuleKind::Condition);
        } else {
          node["children"] = n.children;
        }
        nodes.push_back(std::move(node));
      }
      return {{"architecture", "bt"}, {"nodes", nodes}};
    }
    case Architecture::NeuralNetwork: return {{"architecture", "nn"}};
  }
  return {};
}

ControlSoftware software_from_document(const json& model) {
  const std::string architecture = field<std::string>(model, "architecture", "software");
  ControlSoftware drawn;
  if (architecture == "fsm") drawn = fsm_from(model);
  else if (architecture == "bt") drawn = bt_from(model);
  else throw InvalidRequest("software.architecture must be fsm or bt (a network is edited as text)");
  // The one parser decides: a drawing is valid exactly when its string is.
  try {
    return parse_control_software(to_config_string(drawn));
  } catch (const ConfigError& e) {
    throw InvalidRequest(e.what());
  }
}

std::string token_named_in(const std::string& message) {
  static const std::regex quoted("'([^']+)'");
  std::smatch match;
  return std::regex_search(message, match, quoted) ? match[1].str() : std::string();
}

}  // namespace sd::app
