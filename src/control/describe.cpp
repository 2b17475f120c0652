#include "control/describe.hpp"

#include "control/config_string.hpp"

namespace sd {

std::uint8_t ControlSoftware::inputs() const {
  std::uint8_t bits = 0;
  for (const FsmState& state : fsm.states) {
    if (const ModuleSpec* b = find_module(ModuleKind::Behaviour, state.behaviour.id)) bits |= b->inputs;
    for (const FsmTransition& t : state.transitions)
      if (const ModuleSpec* c = find_module(ModuleKind::Condition, t.condition.id)) bits |= c->inputs;
  }
  return bits;
}

std::string describe_module(const ModuleInstance& module, ModuleKind kind) {
  const ModuleSpec* spec = find_module(kind, module.id);
  if (!spec) return "unknown(" + std::to_string(module.id) + ")";
  std::string text = spec->name + "[" + std::to_string(module.id) + "]";
  if (!spec->parameters.empty()) {
    text += "(";
    bool first = true;
    for (std::size_t p = 0; p < spec->parameters.size(); ++p) {
      if (!spec->parameter_active(p, module.parameters)) continue;
      text += (first ? "" : ", ") + spec->parameters[p].token + "=" + format_number(module.parameters[p]);
      first = false;
    }
    text += ")";
  }
  return text;
}

std::string describe(const ControlSoftware& software) {
  std::string out = "Finite-state machine, " + std::to_string(software.fsm.states.size()) + " state(s); state 0 is initial\n";
  for (std::size_t i = 0; i < software.fsm.states.size(); ++i) {
    const FsmState& s = software.fsm.states[i];
    out += "  state " + std::to_string(i) + ": " + describe_module(s.behaviour, ModuleKind::Behaviour) + "\n";
    for (const FsmTransition& t : s.transitions)
      out += "    -> state " + std::to_string(t.target) + " when " + describe_module(t.condition, ModuleKind::Condition) + "\n";
  }
  return out;
}

std::string to_dot(const ControlSoftware& software) {
  std::string out = "digraph fsm {\n  rankdir=LR;\n  node [shape=box, style=rounded];\n";
  for (std::size_t i = 0; i < software.fsm.states.size(); ++i) {
    const FsmState& s = software.fsm.states[i];
    out += "  s" + std::to_string(i) + " [label=\"" + std::to_string(i) + ": " +
           describe_module(s.behaviour, ModuleKind::Behaviour) + "\"" + (i == 0 ? ", peripheries=2" : "") + "];\n";
  }
  for (std::size_t i = 0; i < software.fsm.states.size(); ++i)
    for (const FsmTransition& t : software.fsm.states[i].transitions)
      out += "  s" + std::to_string(i) + " -> s" + std::to_string(t.target) + " [label=\"" +
             describe_module(t.condition, ModuleKind::Condition) + "\"];\n";
  return out + "}\n";
}

}  // namespace sd
