#include "experiments/protocol.hpp"

#include <nlohmann/json.hpp>

#include <algorithm>
#include <cctype>
#include <cmath>
#include <fstream>
#include <set>

#include "core/bounded_file.hpp"
#include "core/json_syntax.hpp"

namespace sd::experiments {

namespace {

const std::vector<std::string> kAllFlavours = {"chocolate", "tuttifrutti", "coconut", "maple", "arlequin"};
const std::vector<std::string> kArchitectures = {"fsm", "bt"};

/// The thesis' missions with their budgets and the flavour that introduced each.
struct ThesisMission {
  const char* mission;
  long long budget;
  const char* flavour;
  const char* architecture;  // the flavour's own architecture: Maple's are behaviour trees
};
constexpr ThesisMission kThesisMissions[] = {
    {"aac", 200000, "chocolate", "fsm"},
    {"foraging", 50000, "maple", "bt"},
    {"tutti-aggregation", 100000, "tuttifrutti", "fsm"},
    {"grid-exploration", 100000, "coconut", "fsm"},
    {"aggregation-xor", 200000, "arlequin", "fsm"},
};

const std::string kAutoMoDe{design::kAutoMoDe.name};

Condition alone(const ThesisMission& m) { return {"alone", kAutoMoDe, {m.architecture}, {m.flavour}}; }
Condition combined() { return {"combined", kAutoMoDe, kArchitectures, kAllFlavours}; }
Condition evostick() { return {"evostick", std::string(design::kEvoStick.name), {}, {}}; }

[[noreturn]] void fail(const std::string& path, const std::string& what) {
  throw ProtocolError("protocol: " + path + ": " + what);
}

/// A condition's method; ProtocolError for a name design/methods.hpp does not have.
const design::MethodInfo& method_of(const Condition& condition, const std::string& path) {
  const design::MethodInfo* method = design::find_method(condition.method);
  if (!method) fail(path, "unknown '" + condition.method + "' (" + design::method_names_text() + ")");
  return *method;
}

void only_fields(const nlohmann::json& object, const std::string& path, std::initializer_list<std::string_view> allowed) {
  if (!object.is_object()) fail(path.empty() ? "(document)" : path, "must be an object");
  for (const auto& [key, value] : object.items())
    if (std::find(allowed.begin(), allowed.end(), key) == allowed.end())
      fail((path.empty() ? "" : path + ".") + key, "unknown field");
}

std::string join(const std::string& path, const std::string& key) { return path.empty() ? key : path + "." + key; }

std::string text_field(const nlohmann::json& object, const std::string& path, const std::string& key) {
  if (!object.contains(key)) fail(join(path, key), "is missing");
  const auto& v = object.at(key);
  if (!v.is_string() || v.get<std::string>().empty()) fail(join(path, key), "must be a non-empty string");
  return v.get<std::string>();
}

long long integer_field(const nlohmann::json& v, const std::string& path, long long min, long long max) {
  if (!v.is_number_integer() && !v.is_number_unsigned()) fail(path, "must be an integer");
  const long long value = v.get<long long>();
  if (value < min || value > max)
    fail(path, "must be between " + std::to_string(min) + " and " + std::to_string(max) + ", not " + std::to_string(value));
  return value;
}

/// A name safe in a file name, a URL and a table cell: a letter, then letters, digits, '-', '_', '.'.
void check_name(const std::string& name, const std::string& path) {
  if (name.size() > 64) fail(path, "is longer than 64 characters");
  if (name.empty() || !std::isalpha(static_cast<unsigned char>(name[0]))) fail(path, "'" + name + "' must start with a letter");
  for (const char c : name)
    if (!std::isalnum(static_cast<unsigned char>(c)) && c != '-' && c != '_' && c != '.')
      fail(path, "'" + name + "' may only hold letters, digits, '-', '_' and '.'");
}

std::vector<std::string> names_field(const nlohmann::json& object, const std::string& path, const std::string& key,
                                     const std::vector<std::string>& known) {
  if (!object.contains(key)) fail(join(path, key), "is missing");
  const auto& list = object.at(key);
  if (!list.is_array() || list.empty()) fail(join(path, key), "must be a non-empty list");
  std::vector<std::string> names;
  for (std::size_t i = 0; i < list.size(); ++i) {
    const std::string at = join(path, key) + "[" + std::to_string(i) + "]";
    if (!list[i].is_string()) fail(at, "must be a string");
    const auto name = list[i].get<std::string>();
    if (std::find(known.begin(), known.end(), name) == known.end()) {
      std::string options;
      for (const auto& k : known) options += (options.empty() ? "" : ", ") + k;
      fail(at, "unknown '" + name + "' (one of: " + options + ")");
    }
    if (std::find(names.begin(), names.end(), name) != names.end()) fail(at, "'" + name + "' is listed twice");
    names.push_back(name);
  }
  return names;
}

Condition condition_from_json(const nlohmann::json& c, const std::string& path) {
  only_fields(c, path, {"name", "method", "architectures", "flavours"});
  Condition condition;
  condition.name = text_field(c, path, "name");
  check_name(condition.name, join(path, "name"));
  if (c.contains("method")) condition.method = text_field(c, path, "method");
  if (!method_of(condition, join(path, "method")).has_design_space) {
    if (c.contains("architectures") || c.contains("flavours"))
      fail(path, "an " + condition.method + " condition has no architectures or flavours (it searches no design space)");
    return condition;
  }
  condition.architectures = names_field(c, path, "architectures", kArchitectures);
  condition.flavours = names_field(c, path, "flavours", kAllFlavours);
  return condition;
}

constexpr int kMaxSamples = 1000;

PseudoRealityPlan pseudo_reality_from_json(const nlohmann::json& r) {
  const std::string path = "pseudo_reality";
  only_fields(r, path, {"spec", "samples", "definition"});
  PseudoRealityPlan plan;
  plan.spec = text_field(r, path, "spec");
  if (r.contains("samples")) plan.samples = static_cast<int>(integer_field(r["samples"], join(path, "samples"), 1, kMaxSamples));
  if (r.contains("definition")) {
    if (!r["definition"].is_object()) fail(join(path, "definition"), "must be an object (a pseudo-reality specification)");
    plan.definition = r["definition"].dump();
  }
  return plan;
}

}  // namespace

std::vector<std::string> builtin_protocol_names() { return {"validation", "combination", "architecture", "methods"}; }

Protocol builtin_protocol(std::string_view name, bool with_evostick) {
  Protocol protocol;
  protocol.name = std::string(name);
  for (const ThesisMission& m : kThesisMissions) {
    MissionPlan plan{m.mission, m.budget, {}};
    if (name == "validation") {
      plan.conditions = {alone(m)};
    } else if (name == "combination") {
      plan.conditions = {alone(m), combined()};
    } else if (name == "architecture") {
      plan.budget = 200000;  // the thesis' architecture experiment: 200 000 on every mission
      plan.conditions = {{"fsm", kAutoMoDe, {"fsm"}, kAllFlavours}, {"bt", kAutoMoDe, {"bt"}, kAllFlavours}};
    } else if (name == "methods") {
      // Issue #57: every method that searches the modular space, on the mission's own flavour and
      // on the combined space, at 20 000 runs (--budget-scale 5 gives the 100 000 of the goal).
      plan.budget = 20000;
      plan.conditions.clear();
      for (const design::MethodInfo* method : design::kMethods) {
        if (!method->has_design_space) continue;
        const std::string n(method->name);
        plan.conditions.push_back({n, n, {m.architecture}, {m.flavour}});
      }
      for (const design::MethodInfo* method : design::kMethods)
        if (method->has_design_space)
          plan.conditions.push_back({std::string(method->name) + "-combined", std::string(method->name), kArchitectures, kAllFlavours});
    } else {
      throw ProtocolError("unknown experiment '" + std::string(name) +
                          "' (validation, combination, architecture, methods, or --file with your own protocol)");
    }
    if (with_evostick) plan.conditions.push_back(evostick());
    protocol.missions.push_back(std::move(plan));
  }
  return protocol;
}

Protocol protocol_from_json(const nlohmann::json& document) {
  only_fields(document, "", {"name", "designs", "assessment_seeds", "budget_scale", "seed", "missions", "pseudo_reality"});
  Protocol protocol;
  protocol.name = text_field(document, "", "name");
  check_name(protocol.name, "name");
  if (document.contains("designs")) protocol.designs = static_cast<int>(integer_field(document["designs"], "designs", 1, 1000));
  if (document.contains("assessment_seeds"))
    protocol.assessment_seeds = static_cast<int>(integer_field(document["assessment_seeds"], "assessment_seeds", 1, 100000));
  if (document.contains("budget_scale")) {
    const auto& s = document["budget_scale"];
    if (!s.is_number() || !(s.get<double>() > 0.0) || s.get<double>() > 1000.0)
      fail("budget_scale", "must be a number in (0, 1000]");
    protocol.budget_scale = s.get<double>();
  }
  if (document.contains("seed"))
    protocol.seed = static_cast<std::uint64_t>(integer_field(document["seed"], "seed", 0, (1LL << 62)));
  if (!document.contains("missions")) fail("missions", "is missing");
  const auto& missions = document["missions"];
  if (!missions.is_array() || missions.empty()) fail("missions", "must be a non-empty list");
  std::set<std::string> seen_missions;
  for (std::size_t i = 0; i < missions.size(); ++i) {
    const std::string path = "missions[" + std::to_string(i) + "]";
    const auto& m = missions[i];
    only_fields(m, path, {"mission", "budget", "conditions"});
    MissionPlan plan;
    plan.mission = text_field(m, path, "mission");
    if (!seen_missions.insert(plan.mission).second) fail(join(path, "mission"), "'" + plan.mission + "' is listed twice");
    if (!m.contains("budget")) fail(join(path, "budget"), "is missing");
    plan.budget = integer_field(m["budget"], join(path, "budget"), 1, 1'000'000'000);
    if (!m.contains("conditions") || !m["conditions"].is_array() || m["conditions"].empty())
      fail(join(path, "conditions"), "must be a non-empty list");
    std::set<std::string> seen_conditions;
    for (std::size_t j = 0; j < m["conditions"].size(); ++j) {
      const std::string at = join(path, "conditions") + "[" + std::to_string(j) + "]";
      Condition c = condition_from_json(m["conditions"][j], at);
      if (!seen_conditions.insert(c.name).second) fail(join(at, "name"), "'" + c.name + "' is listed twice");
      plan.conditions.push_back(std::move(c));
    }
    protocol.missions.push_back(std::move(plan));
  }
  if (document.contains("pseudo_reality")) protocol.pseudo_reality = pseudo_reality_from_json(document["pseudo_reality"]);
  return protocol;
}

nlohmann::json to_json(const Protocol& protocol) {
  nlohmann::json missions = nlohmann::json::array();
  for (const auto& m : protocol.missions) {
    nlohmann::json conditions = nlohmann::json::array();
    for (const auto& c : m.conditions) {
      nlohmann::json j{{"name", c.name}, {"method", c.method}};
      if (method_of(c, "conditions").has_design_space) {
        j["architectures"] = c.architectures;
        j["flavours"] = c.flavours;
      }
      conditions.push_back(std::move(j));
    }
    missions.push_back({{"mission", m.mission}, {"budget", m.budget}, {"conditions", std::move(conditions)}});
  }
  nlohmann::json document{{"name", protocol.name},
                           {"designs", protocol.designs},
                           {"assessment_seeds", protocol.assessment_seeds},
                           {"budget_scale", protocol.budget_scale},
                           {"seed", protocol.seed},
                           {"missions", std::move(missions)}};
  // Only when asked for: a protocol without it is stored as before (an interrupted experiment
  // of an older version resumes, its stored protocol being compared as text).
  if (const auto& r = protocol.pseudo_reality) {
    nlohmann::json reality{{"spec", r->spec}, {"samples", r->samples}};
    if (!r->definition.empty()) reality["definition"] = nlohmann::json::parse(r->definition);
    document["pseudo_reality"] = std::move(reality);
  }
  return document;
}

Protocol read_protocol_file(const std::string& path) {
  std::string text;
  try {
    text = read_bounded_file(path, "protocol file").text;
  } catch (const FileReadError& e) {
    throw ProtocolError(e.what());
  }
  return parse_protocol_text(text, path);
}

Protocol parse_protocol_text(const std::string& text, const std::string& path) {
  // A protocol's own errors already start "protocol: "; a text with no file says nothing more.
  const std::string where = path.empty() ? std::string() : path + ": ";
  nlohmann::json document;
  try {
    document = nlohmann::json::parse(text, nullptr, true, /*ignore_comments=*/true);
  } catch (const nlohmann::json::parse_error& e) {
    throw ProtocolError((path.empty() ? "protocol: " : where) + "not a JSON document: " + json_syntax_error(e, text));
  } catch (const nlohmann::json::out_of_range& e) {
    throw ProtocolError((path.empty() ? "protocol: " : where) + "not a JSON document: " + json_number_error(e));
  }
  try {
    return protocol_from_json(document);
  } catch (const ProtocolError& e) {
    throw ProtocolError(where + e.what());
  }
}

Protocol with_overrides(Protocol protocol, const ProtocolOverrides& o) {
  if (o.name) {
    check_name(*o.name, "--name");
    protocol.name = *o.name;
  }
  if (o.designs) {
    if (*o.designs < 1 || *o.designs > 1000) throw ProtocolError("--designs must be between 1 and 1000");
    protocol.designs = *o.designs;
  }
  if (o.assessment_seeds) {
    if (*o.assessment_seeds < 1 || *o.assessment_seeds > 100000)
      throw ProtocolError("assessment seeds (--assessment-seeds) must be between 1 and 100000");
    protocol.assessment_seeds = *o.assessment_seeds;
  }
  if (o.budget_scale) {
    if (!(*o.budget_scale > 0.0) || *o.budget_scale > 1000.0) throw ProtocolError("--budget-scale must be in (0, 1000]");
    protocol.budget_scale = *o.budget_scale;
  }
  if (o.seed) protocol.seed = *o.seed;
  if (o.pseudo_reality) {
    if (o.pseudo_reality->empty()) throw ProtocolError("--pseudo-reality: empty name");
    if (!protocol.pseudo_reality || protocol.pseudo_reality->spec != *o.pseudo_reality)
      protocol.pseudo_reality = PseudoRealityPlan{*o.pseudo_reality, protocol.pseudo_reality ? protocol.pseudo_reality->samples : 20, ""};
  }
  if (o.pseudo_reality_samples) {
    if (!protocol.pseudo_reality)
      throw ProtocolError("--pseudo-reality-samples: the protocol has no pseudo_reality; name one with --pseudo-reality");
    if (*o.pseudo_reality_samples < 1 || *o.pseudo_reality_samples > kMaxSamples)
      throw ProtocolError("--pseudo-reality-samples must be between 1 and " + std::to_string(kMaxSamples));
    protocol.pseudo_reality->samples = *o.pseudo_reality_samples;
  }
  if (o.missions) {
    std::vector<MissionPlan> kept;
    for (const auto& name : *o.missions) {
      const auto found = std::find_if(protocol.missions.begin(), protocol.missions.end(),
                                      [&](const MissionPlan& m) { return m.mission == name; });
      if (found == protocol.missions.end()) {
        std::string has;
        for (const auto& m : protocol.missions) has += (has.empty() ? "" : ", ") + m.mission;
        throw ProtocolError("--missions: experiment " + protocol.name + " has no mission '" + name + "' (it has " + has + ")");
      }
      if (std::any_of(kept.begin(), kept.end(), [&](const MissionPlan& m) { return m.mission == name; }))
        throw ProtocolError("--missions: '" + name + "' is listed twice");
      kept.push_back(*found);
    }
    protocol.missions = std::move(kept);
  }
  return protocol;
}

long long scaled_budget(const Protocol& protocol, const MissionPlan& mission) {
  return std::max(1LL, std::llround(static_cast<double>(mission.budget) * protocol.budget_scale));
}

std::vector<std::string> condition_names(const Protocol& protocol) {
  std::vector<std::string> names;
  for (const auto& m : protocol.missions)
    for (const auto& c : m.conditions)
      if (std::find(names.begin(), names.end(), c.name) == names.end()) names.push_back(c.name);
  return names;
}

}  // namespace sd::experiments
