// Behaviour-tree configuration strings: format B, the generic one of ARGoS3-AutoMoDe's
// BehaviorTree branch and of Demiurge (AmmarHsn/Demiurge), read and printed; format A, Maple's
// original, read. Nodes are stored depth-first, so print -> parse gives the same tree.
#include <regex>

#include "control/config_string.hpp"
#include "control/config_tokens.hpp"

namespace sd {

namespace {

using config::Entry;
using config::TokenReader;

bool composite(BtNodeType t) { return t != BtNodeType::Action && t != BtNodeType::Condition; }

class FormatB {
 public:
  FormatB(TokenReader& reader, int id_offset) : reader_(reader), id_offset_(id_offset) {}

  BehaviourTree read() {
    const Entry& root_type = reader_.require("--nroot", "type of the root node");
    const auto type = static_cast<BtNodeType>(config::integer_value(root_type, 0, 4, "the root's node type (0-4)"));
    tree_.nodes.push_back({type, {}, {}, 0.0});
    const Entry& k = reader_.require("--nchildroot", "number of children of the root");
    read_children(0, "", k, type);
    return std::move(tree_);
  }

 private:
  void read_children(int parent, const std::string& id, const Entry& count_entry, BtNodeType type) {
    const int count = type == BtNodeType::Negation
                          ? config::integer_value(count_entry, 1, 1, "a negation's number of children")
                          : config::integer_value(count_entry, 1, kMaxBtChildren, "the number of children");
    for (int c = 0; c < count; ++c) {
      const std::string child = id + std::to_string(c);
      const int index = read_node(child);
      tree_.nodes[static_cast<std::size_t>(parent)].children.push_back(index);
    }
  }

  int read_node(const std::string& id) {
    if (id.size() > static_cast<std::size_t>(kMaxBtDepth))
      throw ConfigError("node '" + id + "' is deeper than " + std::to_string(kMaxBtDepth) + " levels");
    const Entry& t = reader_.require("--n" + id, "type of node " + id);
    const auto type = static_cast<BtNodeType>(config::integer_value(t, 0, 6, "a node type (0-6)"));
    const int index = static_cast<int>(tree_.nodes.size());
    tree_.nodes.push_back({type, {}, {}, 0.0});
    if (composite(type)) {
      read_children(index, id, reader_.require("--nchild" + id, "number of children of node " + id), type);
    } else if (type == BtNodeType::Action) {
      const Entry& a = reader_.require("--a" + id, "behaviour of action " + id);
      const int bid = config::integer_value(a, 0, 99, "a behaviour id") + id_offset_;
      tree_.nodes[static_cast<std::size_t>(index)].module = config::read_module(reader_, ModuleKind::Behaviour, a, bid, id);
      if (const Entry* p = reader_.find("--p" + id)) {
        if (p->value < 0.0 || p->value > 1.0) throw ConfigError("'" + p->text + "': a success probability must be in [0, 1]");
        tree_.nodes[static_cast<std::size_t>(index)].success_probability = p->value;
      }
    } else {
      const Entry& c = reader_.require("--c" + id, "condition of node " + id);
      const int cid = config::integer_value(c, 0, 99, "a condition id") + id_offset_;
      tree_.nodes[static_cast<std::size_t>(index)].module = config::read_module(reader_, ModuleKind::Condition, c, cid, id);
    }
    return index;
  }

  TokenReader& reader_;
  int id_offset_;
  BehaviourTree tree_;
};

/// Maple's format A: a Sequence* root over Selectors of condition leaves and one action.
BehaviourTree read_format_a(TokenReader& reader, int id_offset) {
  const Entry& root = reader.require("--rootnode", "root node type");
  config::integer_value(root, 0, 0, "Maple's root node type (0 = Sequence*)");
  const int count = config::integer_value(reader.require("--nchildsroot", "number of children of the root"), 1,
                                          kMaxBtChildren, "the number of children");
  BehaviourTree tree;
  tree.nodes.push_back({BtNodeType::SequenceStar, {}, {}, 0.0});
  for (int i = 0; i < count; ++i) {
    const std::string si = std::to_string(i);
    config::integer_value(reader.require("--n" + si, "type of node " + si), 0, 0, "a Maple branch type (0 = Selector)");
    const int selector = static_cast<int>(tree.nodes.size());
    tree.nodes[0].children.push_back(selector);
    tree.nodes.push_back({BtNodeType::Selector, {}, {}, 0.0});
    const int conditions = config::integer_value(reader.require("--nc" + si, "number of conditions of branch " + si), 1,
                                                 kMaxBtChildren - 1, "the number of conditions");
    for (int j = 0; j < conditions; ++j) {
      const std::string ij = si + "x" + std::to_string(j);
      const Entry& c = reader.require("--c" + ij, "condition " + std::to_string(j) + " of branch " + si);
      const int cid = config::integer_value(c, 0, 99, "a condition id") + id_offset;
      tree.nodes[static_cast<std::size_t>(selector)].children.push_back(static_cast<int>(tree.nodes.size()));
      tree.nodes.push_back({BtNodeType::Condition, {}, config::read_module(reader, ModuleKind::Condition, c, cid, ij), 0.0});
    }
    const Entry& a = reader.require("--a" + si, "action of branch " + si);
    const int bid = config::integer_value(a, 0, 99, "a behaviour id") + id_offset;
    tree.nodes[static_cast<std::size_t>(selector)].children.push_back(static_cast<int>(tree.nodes.size()));
    tree.nodes.push_back({BtNodeType::Action, {}, config::read_module(reader, ModuleKind::Behaviour, a, bid, si), 0.0});
  }
  return tree;
}

bool bt_name(const std::string& token) {
  static const std::regex pattern("--(nroot|nchildroot|rootnode|nchildsroot|[a-z]+[0-9]{1,5}(x[0-9]{1,2})?)");
  return std::regex_match(token, pattern);
}

void append_node(std::string& out, const BehaviourTree& tree, int index, const std::string& id) {
  const BtNode& node = tree.nodes[static_cast<std::size_t>(index)];
  out += " --n" + id + " " + std::to_string(static_cast<int>(node.type));
  if (composite(node.type)) {
    out += " --nchild" + id + " " + std::to_string(node.children.size());
    for (std::size_t c = 0; c < node.children.size(); ++c) append_node(out, tree, node.children[c], id + std::to_string(c));
  } else if (node.type == BtNodeType::Action) {
    out += " --a" + id + " " + std::to_string(node.module.id);
    config::append_parameters(out, node.module, ModuleKind::Behaviour, id);
    out += " --p" + id + " " + format_number(node.success_probability);
  } else {
    out += " --c" + id + " " + std::to_string(node.module.id);
    config::append_parameters(out, node.module, ModuleKind::Condition, id);
  }
}

}  // namespace

ControlSoftware parse_behaviour_tree(std::span<const std::string> tokens, ParseOptions options) {
  TokenReader reader(tokens, "--bt-config", bt_name);
  static const std::regex module_id("--(a[0-9]+|c[0-9]+(x[0-9]+)?)");
  const int id_offset = config::legacy_offset(
      reader.values_where([](const std::string& n) { return std::regex_match(n, module_id); }), options.legacy_flavour);
  ControlSoftware software;
  software.architecture = Architecture::BehaviourTree;
  const bool format_a = reader.find("--rootnode") != nullptr;
  software.bt = format_a ? read_format_a(reader, id_offset) : FormatB(reader, id_offset).read();
  reader.reject_unused([](const std::string& name) {
    std::string stem, index;
    config::split_name(name, stem, index);
    return index.empty() ? "not part of the --bt-config grammar" : "nothing in the tree reads it for node " + index;
  });
  return software;
}

std::string behaviour_tree_to_string(const BehaviourTree& tree) {
  const BtNode& root = tree.nodes.front();
  std::string out = "--bt-config --nroot " + std::to_string(static_cast<int>(root.type)) + " --nchildroot " +
                    std::to_string(root.children.size());
  for (std::size_t c = 0; c < root.children.size(); ++c) append_node(out, tree, root.children[c], std::to_string(c));
  return out;
}

}  // namespace sd
