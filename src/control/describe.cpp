#include "control/describe.hpp"

#include "control/config_string.hpp"

namespace sd {

std::uint8_t ControlSoftware::inputs() const {
  std::uint8_t bits = 0;
  if (architecture == Architecture::BehaviourTree) {
    for (const BtNode& node : bt.nodes) {
      if (node.type == BtNodeType::Action)
        if (const ModuleSpec* b = find_module(ModuleKind::Behaviour, node.module.id)) bits |= b->inputs;
      if (node.type == BtNodeType::Condition)
        if (const ModuleSpec* c = find_module(ModuleKind::Condition, node.module.id)) bits |= c->inputs;
    }
    return bits;
  }
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

namespace {

const char* node_name(BtNodeType t) {
  switch (t) {
    case BtNodeType::Selector: return "Selector";
    case BtNodeType::SelectorStar: return "Selector*";
    case BtNodeType::Sequence: return "Sequence";
    case BtNodeType::SequenceStar: return "Sequence*";
    case BtNodeType::Negation: return "Not";
    case BtNodeType::Action: return "Action";
    case BtNodeType::Condition: return "Condition";
  }
  return "?";
}

std::string node_label(const BtNode& node) {
  if (node.type == BtNodeType::Action) {
    std::string label = describe_module(node.module, ModuleKind::Behaviour);
    if (node.success_probability > 0.0) label += " [succeeds with p=" + format_number(node.success_probability) + "]";
    return label;
  }
  if (node.type == BtNodeType::Condition) return describe_module(node.module, ModuleKind::Condition) + "?";
  return node_name(node.type);
}

void describe_node(const BehaviourTree& tree, int index, int depth, std::string& out) {
  const BtNode& node = tree.nodes[static_cast<std::size_t>(index)];
  out += std::string(static_cast<std::size_t>(2 + 2 * depth), ' ') + node_label(node) + "\n";
  for (const int child : node.children) describe_node(tree, child, depth + 1, out);
}

}  // namespace

std::string describe(const ControlSoftware& software) {
  if (software.architecture == Architecture::BehaviourTree) {
    std::string out = "Behaviour tree, " + std::to_string(software.bt.nodes.size()) + " node(s)\n";
    describe_node(software.bt, 0, 0, out);
    return out;
  }
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
  if (software.architecture == Architecture::BehaviourTree) {
    std::string out = "digraph bt {\n  node [shape=box, style=rounded];\n";
    for (std::size_t i = 0; i < software.bt.nodes.size(); ++i) {
      const BtNode& node = software.bt.nodes[i];
      out += "  n" + std::to_string(i) + " [label=\"" + node_label(node) + "\"];\n";
      for (const int child : node.children) out += "  n" + std::to_string(i) + " -> n" + std::to_string(child) + ";\n";
    }
    return out + "}\n";
  }
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
