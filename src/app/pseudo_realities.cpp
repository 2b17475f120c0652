#include "app/pseudo_realities.hpp"

#include <nlohmann/json.hpp>

#include "app/documents/reality.hpp"
#include "app/errors.hpp"
#include "app/inputs.hpp"

namespace sd::app {

NamedPseudoReality pseudo_reality_from_document(const std::string& reference, const std::string& document) {
  try {
    return {reference, parse_pseudo_reality(document, "pseudo-reality " + reference), document};
  } catch (const PseudoRealityError& e) {
    throw InvalidRequest(e.what());
  }
}

NamedPseudoReality load_requested_pseudo_reality(const std::string& name_or_path, const FileScope& scope) {
  if (name_or_path.empty()) throw InvalidRequest("pseudo-reality: empty name");
  for (const BuiltinPseudoReality& b : builtin_pseudo_realities())
    if (b.name == name_or_path) return pseudo_reality_from_document(name_or_path, std::string(b.json));
  const bool looks_like_file = name_or_path.find('/') != std::string::npos || name_or_path.ends_with(".json");
  if (!looks_like_file) {
    std::string names;
    for (const BuiltinPseudoReality& b : builtin_pseudo_realities()) names += (names.empty() ? "" : ", ") + std::string(b.name);
    throw InvalidRequest("unknown pseudo-reality '" + name_or_path + "' (shipped: " + names + "; or a .json file)");
  }
  return pseudo_reality_from_document(name_or_path, scope.read(name_or_path, "pseudo-reality file"));
}

std::vector<std::uint64_t> parse_sample_range(const std::string& text) {
  std::vector<std::uint64_t> samples;
  try {
    samples = parse_seed_range(text);
  } catch (const InvalidRequest&) {
    throw InvalidRequest("samples '" + text + "': expected K or A-B with positive integers");
  }
  if (samples.front() == 0) throw InvalidRequest("samples '" + text + "': samples are numbered from 1");
  if (samples.size() > 10'000) throw InvalidRequest("samples '" + text + "': at most 10,000 samples");
  return samples;
}

Mission in_pseudo_reality(const Mission& mission, const PseudoRealitySpec& spec, std::uint64_t sample) {
  Mission m = mission;
  m.robot = spec.sample(mission.robot, sample);
  return m;
}

Mission in_requested_sample(Mission mission, const std::string& pseudo_reality, const std::string& sample,
                            const FileScope& scope) {
  if (pseudo_reality.empty() != sample.empty())
    throw InvalidRequest("--pseudo-reality and --sample go together: the specification and which of its samples");
  if (pseudo_reality.empty()) return mission;
  const std::vector<std::uint64_t> k = parse_sample_range(sample);
  if (k.size() != 1) throw InvalidRequest("--sample: one sample number, not a range");
  return in_pseudo_reality(mission, load_requested_pseudo_reality(pseudo_reality, scope).spec, k.front());
}

nlohmann::json pseudo_realities_document() {
  nlohmann::json list = nlohmann::json::array();
  for (const BuiltinPseudoReality& b : builtin_pseudo_realities()) {
    const NamedPseudoReality named = load_requested_pseudo_reality(std::string(b.name));
    list.push_back({{"name", named.reference},
                    {"description", named.spec.description},
                    {"source", named.spec.source},
                    {"digest", named.spec.digest},
                    {"varies", named.spec.varies()}});
  }
  return list;
}

nlohmann::json pseudo_reality_samples_document(const std::string& name_or_path, const std::string& mission_name,
                                               const std::string& samples, const FileScope& scope) {
  const Mission mission = load_requested_mission(mission_name, scope);
  const NamedPseudoReality named = load_requested_pseudo_reality(name_or_path, scope);
  nlohmann::json rows = nlohmann::json::array();
  for (const std::uint64_t k : parse_sample_range(samples))
    rows.push_back({{"sample", k}, {"robot", robot_model_document(named.spec.sample(mission.robot, k))}});
  return {{"name", named.reference},
          {"digest", named.spec.digest},
          {"design_model", robot_model_document(mission.robot)},
          {"samples", rows}};
}

}  // namespace sd::app
