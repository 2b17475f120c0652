#include "control/config_string.hpp"

#include <charconv>
#include <regex>
#include <sstream>

#include "control/config_tokens.hpp"

namespace sd {

namespace {

using config::Entry;
using config::TokenReader;

std::string state_token(const char* stem, int i) { return std::string("--") + stem + std::to_string(i); }
std::string transition_token(const char* stem, int i, int j) {
  return std::string("--") + stem + std::to_string(i) + "x" + std::to_string(j);
}

/// FSM token names: --nstates, --<stem><i>, --<stem><i>x<j>.
bool fsm_name(const std::string& token) {
  static const std::regex pattern("--(nstates|[a-z]+[0-9]{1,3}(x[0-9]{1,3})?)");
  return std::regex_match(token, pattern);
}

std::string why_unused(const std::string& name) {
  std::string stem, index;
  config::split_name(name, stem, index);
  const auto x = index.find('x');
  if (index.empty()) return "not part of the --fsm-config grammar";
  if (x == std::string::npos) return "no parameter of that name for state " + index;
  return "no parameter of that name for transition " + index.substr(x + 1) + " of state " + index.substr(0, x);
}

ControlSoftware parse_fsm(std::span<const std::string> tokens, ParseOptions options) {
  TokenReader reader(tokens, "--fsm-config", fsm_name);
  // Legacy single-flavour strings: every module id has one digit.
  static const std::regex module_id("--(s[0-9]+|c[0-9]+x[0-9]+)");
  const int id_offset = config::legacy_offset(
      reader.values_where([](const std::string& n) { return std::regex_match(n, module_id); }), options.legacy_flavour);

  const Entry& nstates_entry = reader.require("--nstates", "number of states");
  const int nstates = config::integer_value(nstates_entry, 1, kMaxFsmStates, "the number of states");

  ControlSoftware software;
  software.architecture = Architecture::Fsm;
  software.fsm.states.resize(static_cast<std::size_t>(nstates));
  for (int i = 0; i < nstates; ++i) {
    FsmState& state = software.fsm.states[static_cast<std::size_t>(i)];
    const Entry& s = reader.require(state_token("s", i), "behaviour of state " + std::to_string(i));
    const int id = config::integer_value(s, 0, 99, "a behaviour id") + id_offset;
    state.behaviour = config::read_module(reader, ModuleKind::Behaviour, s, id, std::to_string(i));

    const Entry* n = reader.find(state_token("n", i));
    const int transitions = n ? config::integer_value(*n, 0, kMaxFsmTransitions, "the number of transitions") : 0;
    if (transitions > 0 && nstates == 1)
      throw ConfigError("'" + n->text + "': a single-state FSM has no other state to go to");
    for (int j = 0; j < transitions; ++j) {
      FsmTransition t;
      const Entry& target = reader.require(transition_token("n", i, j), "destination of transition " + std::to_string(j));
      // The destination indexes the OTHER states: k < i means state k, else state k + 1.
      const int k = config::integer_value(target, 0, nstates - 2, "a destination (index among the other states)");
      t.target = k < i ? k : k + 1;
      const Entry& c = reader.require(transition_token("c", i, j), "condition of transition " + std::to_string(j));
      const int cid = config::integer_value(c, 0, 99, "a condition id") + id_offset;
      t.condition = config::read_module(reader, ModuleKind::Condition, c, cid, std::to_string(i) + "x" + std::to_string(j));
      state.transitions.push_back(t);
    }
  }
  reader.reject_unused(why_unused);
  return software;
}

std::string fsm_to_string(const Fsm& fsm) {
  std::string out = "--fsm-config --nstates " + std::to_string(fsm.states.size());
  for (std::size_t i = 0; i < fsm.states.size(); ++i) {
    const FsmState& state = fsm.states[i];
    const std::string si = std::to_string(i);
    out += " --s" + si + " " + std::to_string(state.behaviour.id);
    config::append_parameters(out, state.behaviour, ModuleKind::Behaviour, si);
    if (state.transitions.empty()) continue;
    out += " --n" + si + " " + std::to_string(state.transitions.size());
    for (std::size_t j = 0; j < state.transitions.size(); ++j) {
      const FsmTransition& t = state.transitions[j];
      const std::string ij = si + "x" + std::to_string(j);
      const int k = t.target < static_cast<int>(i) ? t.target : t.target - 1;
      out += " --n" + ij + " " + std::to_string(k);
      out += " --c" + ij + " " + std::to_string(t.condition.id);
      config::append_parameters(out, t.condition, ModuleKind::Condition, ij);
    }
  }
  return out;
}

}  // namespace

std::vector<std::string> split_tokens(const std::string& text) {
  std::istringstream in(text);
  std::vector<std::string> tokens;
  for (std::string t; in >> t;) tokens.push_back(t);
  return tokens;
}

ControlSoftware parse_control_software(std::span<const std::string> tokens, ParseOptions options) {
  if (tokens.empty()) throw ConfigError("empty control software: expected --fsm-config ... or --bt-config ...");
  const std::string& first = tokens.front();
  if (first == "--fsm-config") return parse_fsm(tokens.subspan(1), options);
  if (first == "--bt-config") return parse_behaviour_tree(tokens.subspan(1), options);
  if (first == "--nstates") return parse_fsm(tokens, options);
  if (first == "--nroot" || first == "--rootnode") return parse_behaviour_tree(tokens, options);
  throw ConfigError("unexpected token '" + first + "': control software starts with --fsm-config or --bt-config");
}

ControlSoftware parse_control_software(const std::string& text, ParseOptions options) {
  const auto tokens = split_tokens(text);
  return parse_control_software(std::span<const std::string>(tokens), options);
}

std::string format_number(double value) {
  char buffer[32];
  const auto result = std::to_chars(buffer, buffer + sizeof buffer, value);
  return std::string(buffer, result.ptr);
}

std::string to_config_string(const ControlSoftware& software) {
  return software.architecture == Architecture::Fsm ? fsm_to_string(software.fsm) : behaviour_tree_to_string(software.bt);
}

}  // namespace sd
