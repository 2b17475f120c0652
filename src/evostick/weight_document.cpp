#include "evostick/weight_document.hpp"

#include <cstdio>
#include <limits>
#include <stdexcept>

#include "control/config_string.hpp"
#include "core/json_integer.hpp"

namespace sd::evostick {

std::string module_command(const ModuleTraining& module, const Settings& s) {
  const Settings defaults;
  std::string command = "swarmdesign evostick --module " + std::string(module.name) + " --seed " + std::to_string(s.seed) +
                        " --generations " + std::to_string(s.generations);
  if (s.population != defaults.population) command += " --population " + std::to_string(s.population);
  if (s.evaluations != defaults.evaluations) command += " --evaluations " + std::to_string(s.evaluations);
  if (s.elites != defaults.elites) command += " --elites " + std::to_string(s.elites);
  if (s.mutation_sigma != defaults.mutation_sigma) command += " --mutation-sigma " + format_number(s.mutation_sigma);
  if (s.mutation_probability != defaults.mutation_probability)
    command += " --mutation-probability " + format_number(s.mutation_probability);
  return command;
}

// The settings' fields by their own names, both ways.
nlohmann::json settings_json(const Settings& s) {
  return {{"seed", s.seed},
          {"population", s.population},
          {"evaluations", s.evaluations},
          {"elites", s.elites},
          {"mutation_sigma", s.mutation_sigma},
          {"mutation_probability", s.mutation_probability},
          {"weight_bound", s.weight_bound},
          {"generations", s.generations}};
}

namespace {

const nlohmann::json& settings_field(const nlohmann::json& j, const char* key) {
  if (!j.is_object() || !j.contains(key)) throw std::invalid_argument(std::string("settings.") + key + " is missing");
  return j.at(key);
}

template <class Int>
Int integer_setting(const nlohmann::json& j, const char* key) {
  const auto value = json_integer<Int>(settings_field(j, key));
  if (!value) throw std::invalid_argument(std::string("settings.") + key + " must be an integer of at most " +
                                          std::to_string(std::numeric_limits<Int>::max()));
  return *value;
}

double number_setting(const nlohmann::json& j, const char* key) {
  const nlohmann::json& v = settings_field(j, key);
  if (!v.is_number()) throw std::invalid_argument(std::string("settings.") + key + " must be a number");
  return v.get<double>();
}

}  // namespace

Settings settings_from_json(const nlohmann::json& j) {
  Settings s;
  s.seed = integer_setting<std::uint64_t>(j, "seed");
  s.population = integer_setting<int>(j, "population");
  s.evaluations = integer_setting<int>(j, "evaluations");
  s.elites = integer_setting<int>(j, "elites");
  s.mutation_sigma = number_setting(j, "mutation_sigma");
  s.mutation_probability = number_setting(j, "mutation_probability");
  s.weight_bound = number_setting(j, "weight_bound");
  s.generations = integer_setting<int>(j, "generations");
  return s;
}

std::string digest_text(std::uint64_t digest) {
  char text[19];
  std::snprintf(text, sizeof text, "0x%016llx", static_cast<unsigned long long>(digest));
  return text;
}

nlohmann::json history_json(const std::vector<GenerationRecord>& history) {
  nlohmann::json out = nlohmann::json::array();
  for (const GenerationRecord& r : history)
    out.push_back({{"generation", r.generation},
                   {"best_mean", r.best_mean},
                   {"population_mean", r.population_mean},
                   {"best_digest", digest_text(r.best_digest)}});
  return out;
}

nlohmann::json weights_json(const arlequin::Weights& weights) {
  nlohmann::json left = nlohmann::json::array(), right = nlohmann::json::array();
  const auto inputs = static_cast<std::size_t>(arlequin::kInputs);
  for (std::size_t i = 0; i < inputs; ++i) {
    left.push_back(weights[i]);
    right.push_back(weights[inputs + i]);
  }
  return {{"left", left}, {"right", right}};
}

nlohmann::json module_document(const ModuleTraining& module, const Settings& settings, const Result& result) {
  const Mission mission = training_mission(module);
  nlohmann::json doc;
  doc["module"] = module.id;
  doc["name"] = module.name;
  doc["produced_by"] = module_command(module, settings);
  doc["training"] = {{"arena", "data/arlequin/training/" + std::string(module.arena) + ".json"},
                     {"mission", mission.name},
                     {"measure", measure_name(module.measure)},
                     {"measure_description", measure_description(module.measure)},
                     {"direction", "maximize"}};
  doc["settings"] = settings_json(settings);
  doc["runs"] = result.runs;
  doc["best_mean"] = result.best_mean;
  doc["weights_digest"] = digest_text(weight_digest(result.best));
  doc["history"] = history_json(result.history);
  doc["weights"] = weights_json(result.best);
  return doc;
}

std::string document_text(const nlohmann::json& document) { return document.dump(2) + "\n"; }

}  // namespace sd::evostick
