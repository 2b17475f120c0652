#include "export/legacy_string.hpp"

#include <regex>
#include <set>
#include <stdexcept>

#include "control/config_string.hpp"
#include "control/config_tokens.hpp"

namespace sd::argos {

namespace {

/// One module of the control software, where it sits and the index its tokens carry.
struct UsedModule {
  std::string where;   // "state 1", "transition 0 of state 1", "condition node 00"
  ModuleKind kind;
  const ModuleInstance* module;
  std::string suffix;  // "1", "1x0", "00"
  int n_token = -1;    // FSM transitions: the value of --n<suffix> in the string (the destination)
};

void tree_modules(const BehaviourTree& tree, int index, const std::string& id, std::vector<UsedModule>& out) {
  const BtNode& node = tree.nodes[static_cast<std::size_t>(index)];
  if (node.type == BtNodeType::Action) {
    out.push_back({"action node " + id, ModuleKind::Behaviour, &node.module, id, -1});
  } else if (node.type == BtNodeType::Condition) {
    out.push_back({"condition node " + id, ModuleKind::Condition, &node.module, id, -1});
  } else {
    for (std::size_t c = 0; c < node.children.size(); ++c)
      tree_modules(tree, node.children[c], id + std::to_string(c), out);
  }
}

std::vector<UsedModule> used_modules(const ControlSoftware& software) {
  std::vector<UsedModule> out;
  if (software.architecture == Architecture::Fsm) {
    for (std::size_t i = 0; i < software.fsm.states.size(); ++i) {
      const FsmState& state = software.fsm.states[i];
      const std::string si = std::to_string(i);
      out.push_back({"state " + si, ModuleKind::Behaviour, &state.behaviour, si, -1});
      for (std::size_t j = 0; j < state.transitions.size(); ++j) {
        const FsmTransition& t = state.transitions[j];
        const int k = t.target < static_cast<int>(i) ? t.target : t.target - 1;
        out.push_back({"transition " + std::to_string(j) + " of state " + si, ModuleKind::Condition, &t.condition,
                       si + "x" + std::to_string(j), k});
      }
    }
  } else if (software.architecture == Architecture::BehaviourTree) {
    const BtNode& root = software.bt.nodes.front();
    for (std::size_t c = 0; c < root.children.size(); ++c)
      tree_modules(software.bt, root.children[c], std::to_string(c), out);
  }
  return out;
}

std::string module_text(const UsedModule& m) {
  const ModuleSpec* spec = find_module(m.kind, m.module->id);
  std::string text = m.where;
  text += ": ";
  text += std::to_string(m.module->id);
  if (spec) {
    text += " ";
    text += spec->name;
    text += " (";
    text += flavour_name(spec->flavour());
    text += ")";
  }
  return text;
}

Flavour module_flavour(const UsedModule& m) { return static_cast<Flavour>(m.module->id / 10); }

std::string joined(const std::vector<std::string>& items) {
  std::string text;
  for (const std::string& item : items) {
    if (!text.empty()) text += "; ";
    text += item;
  }
  return text;
}

Flavour resolve_flavour(const std::vector<UsedModule>& modules, const ExportOptions& options) {
  if (options.flavour) {
    std::vector<std::string> foreign;
    for (const UsedModule& m : modules)
      if (module_flavour(m) != *options.flavour) foreign.push_back(module_text(m));
    if (!foreign.empty())
      throw ExportRefused("the " + std::string(flavour_name(*options.flavour)) +
                          " code base reads only its own flavour's modules, and these are not: " + joined(foreign));
    return *options.flavour;
  }
  std::set<Flavour> flavours;
  for (const UsedModule& m : modules) flavours.insert(module_flavour(m));
  if (flavours.size() == 1) return *flavours.begin();
  std::vector<std::string> all;
  all.reserve(all.size() + modules.size());
  for (const UsedModule& m : modules) all.push_back(module_text(m));
  throw ExportRefused("the control software mixes flavours, and every ARGoS3-AutoMoDe code base reads one flavour's "
                      "modules only: " + joined(all));
}

/// Demiurge's neighbour-count conditions read xi from the parameter "n", not "p": in an FSM
/// that is --n<i>x<j>, the transition's destination token; a tree's condition is handed only
/// the tokens from --c<id> on, so it finds no "n" and throws "Missing Parameter".
void check_demiurge_neighbour_counts(const std::vector<UsedModule>& modules, Flavour flavour) {
  std::vector<std::string> refused;
  for (const UsedModule& m : modules) {
    if (m.kind != ModuleKind::Condition || (m.module->id % 10 != 3 && m.module->id % 10 != 4)) continue;
    const ModuleSpec* spec = find_module(m.kind, m.module->id);
    const int p = spec ? spec->parameter_index("p") : -1;
    if (p < 0) continue;
    const double xi = m.module->parameters[static_cast<std::size_t>(p)];
    if (m.n_token >= 0 && xi == m.n_token) continue;
    std::string why = module_text(m);
    if (m.n_token < 0) {
      why += ": Demiurge's tree builder gives a condition no xi (Missing Parameter)";
    } else {
      why += " has xi = ";
      why += format_number(xi);
      why += " but Demiurge would read xi = ";
      why += std::to_string(m.n_token);
      why += " from --n";
      why += m.suffix;
    }
    refused.push_back(why);
  }
  if (!refused.empty())
    throw ExportRefused(std::string(flavour_name(flavour)) +
                        " exists only in the Demiurge code base, whose neighbour-count conditions read their "
                        "threshold xi from --n<i>x<j>, the token that names an FSM transition's destination: " +
                        joined(refused));
}

/// The canonical string with every module id made one-digit (the tokens the legacy reader
/// offsets: --s<i>, --c<i>x<j> of FSMs, --a<id>, --c<id> of trees).
std::string one_digit(const ControlSoftware& software, int offset) {
  static const std::regex fsm_ids("--(s[0-9]+|c[0-9]+x[0-9]+)");
  static const std::regex tree_ids("--(a[0-9]+|c[0-9]+(x[0-9]+)?)");
  const std::regex& ids = software.architecture == Architecture::Fsm ? fsm_ids : tree_ids;
  const std::vector<std::string> tokens = split_tokens(to_config_string(software));
  std::string out = tokens.front();
  for (std::size_t i = 1; i + 1 < tokens.size(); i += 2) {
    out += " ";
    out += tokens[i];
    out += " ";
    out += std::regex_match(tokens[i], ids) ? std::to_string(std::stoi(tokens[i + 1]) - offset) : tokens[i + 1];
  }
  return out;
}

/// Whether the tree has Maple's shape, which its --rootnode form can say.
bool maple_shape(const BehaviourTree& tree) {
  const BtNode& root = tree.nodes.front();
  if (root.type != BtNodeType::SequenceStar || root.children.empty() ||
      root.children.size() > static_cast<std::size_t>(kMaxBtChildren))
    return false;
  for (const int s : root.children) {
    const BtNode& selector = tree.nodes[static_cast<std::size_t>(s)];
    if (selector.type != BtNodeType::Selector || selector.children.size() < 2) return false;
    for (std::size_t c = 0; c < selector.children.size(); ++c) {
      const BtNode& leaf = tree.nodes[static_cast<std::size_t>(selector.children[c])];
      const bool last = c + 1 == selector.children.size();
      if (last && (leaf.type != BtNodeType::Action || leaf.success_probability != 0.0)) return false;
      if (!last && leaf.type != BtNodeType::Condition) return false;
    }
  }
  return true;
}

/// Maple's --rootnode form, one-digit ids.
std::string rootnode_form(const BehaviourTree& tree, int offset) {
  const BtNode& root = tree.nodes.front();
  std::string out = "--bt-config --rootnode 0 --nchildsroot ";
  out += std::to_string(root.children.size());
  for (std::size_t i = 0; i < root.children.size(); ++i) {
    const BtNode& selector = tree.nodes[static_cast<std::size_t>(root.children[i])];
    const std::string si = std::to_string(i);
    const std::size_t conditions = selector.children.size() - 1;
    out += " --n" + si + " 0 --nc" + si + " " + std::to_string(conditions);
    for (std::size_t j = 0; j < conditions; ++j) {
      const ModuleInstance& c = tree.nodes[static_cast<std::size_t>(selector.children[j])].module;
      const std::string ij = si + "x" + std::to_string(j);
      out += " --c" + ij + " " + std::to_string(c.id - offset);
      config::append_parameters(out, c, ModuleKind::Condition, ij);
    }
    const ModuleInstance& a = tree.nodes[static_cast<std::size_t>(selector.children.back())].module;
    out += " --a" + si + " " + std::to_string(a.id - offset);
    config::append_parameters(out, a, ModuleKind::Behaviour, si);
  }
  return out;
}

constexpr const char* kMaster = "ARGoS3-AutoMoDe master, automode_main";
constexpr const char* kBehaviorTreeBranch = "ARGoS3-AutoMoDe branch BehaviorTree, automode_main_bt";
constexpr const char* kBehaviorTreeBranchFsm = "ARGoS3-AutoMoDe branch BehaviorTree, automode_main";
constexpr const char* kTutti = "ARGoS3-AutoMoDe branch tuttifrutti, automode_main";
constexpr const char* kMaple = "ARGoS3-AutoMoDe's Maple code base (commit 835a721, BehaviorTree history), automode_main_bt";
constexpr const char* kDemiurge = "Demiurge (AmmarHsn/Demiurge), automode_main";
// Demiurge's modules 50-55 load its own NEAT genomes (gen/*), evolved for its simulator:
// SwarmDesign's networks (data/arlequin/) do not travel with the string.
constexpr const char* kDemiurgeArlequin =
    "Demiurge (AmmarHsn/Demiurge), automode_main, whose modules 50-55 run its own NEAT genomes, not SwarmDesign's "
    "networks";

LegacyString export_string(const ControlSoftware& software, Flavour flavour, const std::vector<UsedModule>& modules,
                           TreeForm form) {
  const bool tree = software.architecture == Architecture::BehaviourTree;
  const int offset = 10 * static_cast<int>(flavour);
  if (form != TreeForm::Automatic && !tree) throw ExportRefused("--tree-form applies to behaviour trees only");
  switch (flavour) {
    case Flavour::Chocolate:
      if (form == TreeForm::RootNode) throw ExportRefused("the --rootnode form is Maple's; Chocolate trees use --nroot");
      return {one_digit(software, offset), flavour, tree ? kBehaviorTreeBranch : kMaster};
    case Flavour::TuttiFrutti:
      if (tree)
        throw ExportRefused("ARGoS3-AutoMoDe's tuttifrutti code base runs finite-state machines only; this is a "
                            "behaviour tree (only Demiurge reads TuttiFrutti trees: in SwarmDesign's own two-digit string)");
      return {one_digit(software, offset), flavour, kTutti};
    case Flavour::Maple:
      if (!tree) return {one_digit(software, offset), flavour, kBehaviorTreeBranchFsm};
      if (form != TreeForm::NRoot && maple_shape(software.bt)) return {rootnode_form(software.bt, offset), flavour, kMaple};
      if (form == TreeForm::RootNode)
        throw ExportRefused("the tree does not have Maple's shape (a Sequence* root over Selectors of conditions and "
                            "one action that never succeeds), which the --rootnode form needs");
      return {one_digit(software, offset), flavour, kBehaviorTreeBranch};
    case Flavour::Coconut:
    case Flavour::Arlequin:
      if (form == TreeForm::RootNode) throw ExportRefused("the --rootnode form is Maple's; Demiurge reads --nroot trees");
      check_demiurge_neighbour_counts(modules, flavour);
      return {to_config_string(software), flavour, flavour == Flavour::Arlequin ? kDemiurgeArlequin : kDemiurge};
  }
  throw ExportRefused("unknown flavour");
}

}  // namespace

Flavour export_flavour(const std::string& name) {
  const auto flavour = flavour_from_name(name);
  if (!flavour)
    throw ExportRefused("unknown flavour '" + name + "' (chocolate, tuttifrutti, maple, coconut or arlequin)");
  return *flavour;
}

LegacyString to_legacy_string(const ControlSoftware& software, const ExportOptions& options) {
  if (software.architecture == Architecture::NeuralNetwork)
    throw ExportRefused("an EvoStick network (--nn-config) is not modular control software: no ARGoS3-AutoMoDe "
                        "flavour reads it");
  const std::vector<UsedModule> modules = used_modules(software);
  const Flavour flavour = resolve_flavour(modules, options);
  LegacyString result = export_string(software, flavour, modules, options.tree_form);
  // The contract: the legacy reader gives back exactly this control software.
  ParseOptions parse;
  parse.legacy_flavour = flavour;
  if (parse_control_software(result.text, parse) != software)
    throw std::logic_error("the exported string does not read back as the same control software: " + result.text);
  return result;
}

}  // namespace sd::argos
