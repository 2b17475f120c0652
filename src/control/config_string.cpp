#include "control/config_string.hpp"

#include <algorithm>
#include <charconv>
#include <cmath>
#include <cstdlib>
#include <map>
#include <optional>
#include <sstream>

namespace sd {

namespace {

/// A token `--<stem><i>[x<j>]` with its value, as read from the command line.
struct Entry {
  std::string text;   // "--att0 3.5", for messages
  double value = 0.0;
  bool used = false;
};

struct Key {
  std::string stem;
  int state = -1;       // -1: no index (nstates)
  int transition = -1;  // -1: not a transition token
  auto operator<=>(const Key&) const = default;
};

std::optional<Key> parse_key(const std::string& token) {
  if (token.size() < 3 || token[0] != '-' || token[1] != '-') return std::nullopt;
  Key key;
  std::size_t pos = 2;
  while (pos < token.size() && std::isalpha(static_cast<unsigned char>(token[pos]))) key.stem += token[pos++];
  if (key.stem.empty()) return std::nullopt;
  auto read_index = [&](int& out) {
    const std::size_t start = pos;
    while (pos < token.size() && std::isdigit(static_cast<unsigned char>(token[pos]))) ++pos;
    if (pos == start || pos - start > 3) return false;
    out = std::stoi(token.substr(start, pos - start));
    return true;
  };
  if (pos == token.size()) return key;  // --nstates
  if (!read_index(key.state)) return std::nullopt;
  if (pos < token.size()) {
    if (token[pos] != 'x') return std::nullopt;
    ++pos;
    if (!read_index(key.transition) || pos != token.size()) return std::nullopt;
  }
  // "--n0x1": the stem swallowed the 'x'? No: stems are letters only and indices digits, so
  // "n0x1" reads as stem "n", state 0, transition 1.
  return key;
}

std::optional<double> parse_number(const std::string& text) {
  if (text.empty()) return std::nullopt;
  char* end = nullptr;
  const double v = std::strtod(text.c_str(), &end);
  if (end != text.c_str() + text.size() || !std::isfinite(v)) return std::nullopt;
  return v;
}

class Reader {
 public:
  Reader(std::span<const std::string> tokens, std::string grammar) : grammar_(std::move(grammar)) {
    for (std::size_t i = 0; i < tokens.size(); ++i) {
      const std::string& token = tokens[i];
      const auto key = parse_key(token);
      if (!key) throw ConfigError("unexpected token '" + token + "' in " + grammar_);
      if (i + 1 >= tokens.size()) throw ConfigError("missing value after '" + token + "'");
      const std::string& value_text = tokens[++i];
      const auto value = parse_number(value_text);
      if (!value && parse_key(value_text)) throw ConfigError("missing value after '" + token + "'");
      if (!value) throw ConfigError("'" + token + " " + value_text + "': the value is not a number");
      const auto [it, inserted] = entries_.emplace(*key, Entry{token + " " + value_text, *value, false});
      if (!inserted) throw ConfigError("duplicate token '" + token + "'");
    }
  }

  Entry* find(const Key& key) {
    const auto it = entries_.find(key);
    if (it == entries_.end()) return nullptr;
    it->second.used = true;
    return &it->second;
  }

  Entry& require(const Key& key, const std::string& why) {
    Entry* e = find(key);
    if (!e) throw ConfigError("missing " + token_name(key) + " (" + why + ")");
    return *e;
  }

  void reject_unused() const {
    for (const auto& [key, entry] : entries_)
      if (!entry.used) throw ConfigError("unexpected token '" + entry.text + "' (" + why_unused(key) + ")");
  }

  std::vector<double> module_ids() const {
    std::vector<double> ids;
    for (const auto& [key, entry] : entries_)
      if ((key.stem == "s" && key.transition < 0) || (key.stem == "c" && key.transition >= 0)) ids.push_back(entry.value);
    return ids;
  }

  static std::string token_name(const Key& key) {
    std::string t = "--" + key.stem;
    if (key.state >= 0) t += std::to_string(key.state);
    if (key.transition >= 0) t += "x" + std::to_string(key.transition);
    return t;
  }

 private:
  std::string why_unused(const Key& key) const {
    if (key.state >= 0 && key.transition < 0) return "no parameter of that name for state " + std::to_string(key.state);
    if (key.transition >= 0)
      return "no parameter of that name for transition " + std::to_string(key.transition) + " of state " +
             std::to_string(key.state);
    return "not part of the " + grammar_ + " grammar";
  }

  std::string grammar_;
  std::map<Key, Entry> entries_;
};

int integer_value(const Entry& e, int lo, int hi, const std::string& what) {
  if (e.value != std::floor(e.value) || e.value < lo || e.value > hi)
    throw ConfigError("'" + e.text + "': " + what + " must be an integer in [" + std::to_string(lo) + ", " +
                      std::to_string(hi) + "]");
  return static_cast<int>(e.value);
}

ModuleInstance read_module(Reader& reader, ModuleKind kind, const Entry& id_entry, int id, int state, int transition) {
  const ModuleSpec* spec = find_module(kind, id);
  const char* kind_name = kind == ModuleKind::Behaviour ? "behaviour" : "condition";
  if (!spec) throw ConfigError("'" + id_entry.text + "': unknown " + std::string(kind_name) + " id " + std::to_string(id));
  ModuleInstance instance;
  instance.id = id;
  for (std::size_t p = 0; p < spec->parameters.size(); ++p) {
    const ParameterSpec& param = spec->parameters[p];
    if (!spec->parameter_active(p, instance.parameters)) continue;  // e.g. rwm without exp 1
    const Entry& e = reader.require({param.token, state, transition}, spec->name + " needs it");
    if (!param.accepts(e.value))
      throw ConfigError("'" + e.text + "': " + param.token + " of " + spec->name + " must be " + param.domain_text());
    instance.parameters[p] = e.value;
  }
  return instance;
}

ControlSoftware parse_fsm(std::span<const std::string> tokens, ParseOptions options) {
  Reader reader(tokens, "--fsm-config");
  // Legacy single-flavour strings: every module id has one digit.
  const auto ids = reader.module_ids();
  const bool legacy = !ids.empty() && std::all_of(ids.begin(), ids.end(), [](double v) { return v >= 0 && v < 10; });
  const int id_offset = legacy ? 10 * static_cast<int>(options.legacy_flavour) : 0;

  const Entry& nstates_entry = reader.require({"nstates", -1, -1}, "number of states");
  const int nstates = integer_value(nstates_entry, 1, kMaxFsmStates, "the number of states");

  ControlSoftware software;
  software.architecture = Architecture::Fsm;
  software.fsm.states.resize(static_cast<std::size_t>(nstates));
  for (int i = 0; i < nstates; ++i) {
    FsmState& state = software.fsm.states[static_cast<std::size_t>(i)];
    const Entry& s = reader.require({"s", i, -1}, "behaviour of state " + std::to_string(i));
    const int id = integer_value(s, 0, 99, "a behaviour id") + id_offset;
    state.behaviour = read_module(reader, ModuleKind::Behaviour, s, id, i, -1);

    const Entry* n = reader.find({"n", i, -1});
    const int transitions = n ? integer_value(*n, 0, kMaxFsmTransitions, "the number of transitions") : 0;
    if (transitions > 0 && nstates == 1)
      throw ConfigError("'" + n->text + "': a single-state FSM has no other state to go to");
    for (int j = 0; j < transitions; ++j) {
      FsmTransition t;
      const Entry& target = reader.require({"n", i, j}, "destination of transition " + std::to_string(j));
      // The destination indexes the OTHER states: k < i means state k, else state k + 1.
      const int k = integer_value(target, 0, nstates - 2, "a destination (index among the other states)");
      t.target = k < i ? k : k + 1;
      const Entry& c = reader.require({"c", i, j}, "condition of transition " + std::to_string(j));
      const int cid = integer_value(c, 0, 99, "a condition id") + id_offset;
      t.condition = read_module(reader, ModuleKind::Condition, c, cid, i, j);
      state.transitions.push_back(t);
    }
  }
  reader.reject_unused();
  return software;
}

}  // namespace

std::vector<std::string> split_tokens(const std::string& text) {
  std::istringstream in(text);
  std::vector<std::string> tokens;
  for (std::string t; in >> t;) tokens.push_back(t);
  return tokens;
}

ControlSoftware parse_control_software(std::span<const std::string> tokens, ParseOptions options) {
  if (tokens.empty()) throw ConfigError("empty control software: expected --fsm-config ...");
  if (tokens.front() == "--fsm-config") return parse_fsm(tokens.subspan(1), options);
  if (tokens.front() == "--bt-config")
    throw ConfigError("'--bt-config': behaviour trees are not available yet in this build (FSM only)");
  if (tokens.front() == "--nstates") return parse_fsm(tokens, options);
  throw ConfigError("unexpected token '" + tokens.front() + "': control software starts with --fsm-config");
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
  std::string out = "--fsm-config --nstates " + std::to_string(software.fsm.states.size());
  auto emit_parameters = [&](const ModuleInstance& m, ModuleKind kind, const std::string& suffix) {
    const ModuleSpec* spec = find_module(kind, m.id);
    if (!spec) return;
    for (std::size_t p = 0; p < spec->parameters.size(); ++p)
      if (spec->parameter_active(p, m.parameters))
        out += " --" + spec->parameters[p].token + suffix + " " + format_number(m.parameters[p]);
  };
  for (std::size_t i = 0; i < software.fsm.states.size(); ++i) {
    const FsmState& state = software.fsm.states[i];
    const std::string si = std::to_string(i);
    out += " --s" + si + " " + std::to_string(state.behaviour.id);
    emit_parameters(state.behaviour, ModuleKind::Behaviour, si);
    if (state.transitions.empty()) continue;
    out += " --n" + si + " " + std::to_string(state.transitions.size());
    for (std::size_t j = 0; j < state.transitions.size(); ++j) {
      const FsmTransition& t = state.transitions[j];
      const std::string ij = si + "x" + std::to_string(j);
      const int k = t.target < static_cast<int>(i) ? t.target : t.target - 1;
      out += " --n" + ij + " " + std::to_string(k);
      out += " --c" + ij + " " + std::to_string(t.condition.id);
      emit_parameters(t.condition, ModuleKind::Condition, ij);
    }
  }
  return out;
}

}  // namespace sd
