#include "modules/arlequin_module_set.hpp"

#include <nlohmann/json.hpp>

#include <bit>
#include <filesystem>
#include <stdexcept>

#include "core/bounded_file.hpp"
#include "core/fnv.hpp"
#include "core/json_syntax.hpp"
#include "modules/arlequin_builtin_weights.hpp"
#include "modules/arlequin_demiurge.hpp"

namespace sd::arlequin {

namespace {

constexpr std::string_view kProfileFile = "module-set";  // module-set.json: {"machinery": ...}

void set_digest(ModuleSet& set) {
  Fnv1a f;
  f.add(machinery_name(set.machinery));
  for (const Weights& w : set.weights)
    for (const double v : w) f.add_u64(std::bit_cast<std::uint64_t>(v));
  set.digest = f.hex();
}

Machinery machinery_from_profile(std::string_view json_text, const std::string& where) {
  nlohmann::json doc;
  try {
    doc = nlohmann::json::parse(json_text, nullptr, true, true);
  } catch (const nlohmann::json::parse_error& e) {
    throw std::runtime_error(where + ": not JSON (" + e.what() + ")");
  } catch (const nlohmann::json::out_of_range& e) {
    throw std::runtime_error(where + ": not JSON (" + json_number_error(e) + ")");
  }
  const auto* m = doc.is_object() && doc.contains("machinery") ? &doc["machinery"] : nullptr;
  if (m && m->is_string() && *m == "demiurge") return Machinery::Demiurge;
  if (m && m->is_string() && *m == "swarmdesign") return Machinery::SwarmDesign;
  throw std::runtime_error(where + ": \"machinery\" must be \"swarmdesign\" or \"demiurge\"");
}

ModuleSet demiurge_builtin() {
  ModuleSet set{"demiurge", Machinery::Demiurge, {}, {}};
  for (std::size_t d = 0; d < kModuleNames.size(); ++d) {
    bool found = false;
    for (const BuiltinWeightFile& file : demiurge_weight_files())
      if (file.name == kModuleNames[d]) {
        set.weights[d] = weights_from_json(file.json, "data/arlequin-demiurge/" + std::string(file.name) + ".json");
        found = true;
      }
    if (!found) throw std::runtime_error("the build carries no data/arlequin-demiurge/" + std::string(kModuleNames[d]) + ".json");
  }
  set_digest(set);
  return set;
}

ModuleSet swarmdesign_builtin() {
  ModuleSet set{"swarmdesign", Machinery::SwarmDesign, {}, {}};
  for (std::size_t d = 0; d < kModuleNames.size(); ++d) set.weights[d] = shipped_weights(kFirstModuleId + static_cast<int>(d));
  set_digest(set);
  return set;
}

// `allowed` (a shared server's scope) is asked about every file's real path; a file it refuses
// and a missing one get the same words, so a set names no file it may not read.
std::string read_set_file(const std::filesystem::path& file, const std::string& what, const PathRule& allowed) {
  try {
    return read_bounded_file(file, what, kMaxInputFileBytes, allowed).text;
  } catch (const FileReadError& e) {
    if (allowed && (e.problem == FileProblem::Missing || e.problem == FileProblem::Outside))
      throw std::runtime_error(what + " " + file.string() + " is not a file of your projects");
    throw;
  }
}

ModuleSet folder_set(const std::string& folder, const PathRule& allowed) {
  const std::filesystem::path dir(folder);
  ModuleSet set{folder, Machinery::SwarmDesign, {}, {}};
  for (std::size_t d = 0; d < kModuleNames.size(); ++d) {
    const std::filesystem::path file = dir / (std::string(kModuleNames[d]) + ".json");
    set.weights[d] = weights_from_json(read_set_file(file, "weight document", allowed), file.string());
  }
  const std::filesystem::path profile = dir / (std::string(kProfileFile) + ".json");
  std::error_code ec;
  if (std::filesystem::exists(profile, ec))
    set.machinery = machinery_from_profile(read_set_file(profile, "module-set file", allowed), profile.string());
  set_digest(set);
  return set;
}

}  // namespace

std::string_view machinery_name(Machinery m) { return m == Machinery::Demiurge ? "demiurge" : "swarmdesign"; }

Actuation ModuleSet::drive(int id, BehaviourMemory& memory, const ReferenceModel& rm, Rng& rng) const {
  const Weights& w = of(id);
  if (machinery == Machinery::SwarmDesign) return arlequin::drive(w, rm);
  const int since_entry = memory.steps_in_state;
  if (memory.steps_in_state < ReferenceModel::kRabBufferSteps) ++memory.steps_in_state;
  return wheels_from_outputs(forward(w, demiurge::encode_inputs(rm, since_entry, rng)));
}

const ModuleSet* builtin_module_set(std::string_view name) {
  // Built on first use, when a mission names the set (never inside a tick); the grey tables
  // are parsed with Demiurge's set so that a run never parses them.
  if (name == "swarmdesign") {
    static const ModuleSet set = swarmdesign_builtin();
    return &set;
  }
  if (name == "demiurge") {
    static const ModuleSet set = [] {
      demiurge::grey_samples();
      return demiurge_builtin();
    }();
    return &set;
  }
  return nullptr;
}

std::shared_ptr<const ModuleSet> load_module_set(const std::string& name_or_folder, const PathRule& allowed) {
  if (const ModuleSet* builtin = builtin_module_set(name_or_folder))
    return std::shared_ptr<const ModuleSet>(builtin, [](const ModuleSet*) {});
  std::error_code ec;
  // A folder outside `allowed` is answered as a missing one, before anything in it is touched.
  const auto real = std::filesystem::canonical(name_or_folder, ec);
  if (ec || (allowed && !allowed(real)) || !std::filesystem::is_directory(real, ec))
    throw std::runtime_error("Arlequin module set '" + name_or_folder +
                             "' is neither swarmdesign, demiurge nor a folder of the six weight documents");
  ModuleSet set;
  try {
    set = folder_set(name_or_folder, allowed);
  } catch (const std::exception& e) {
    throw std::runtime_error("Arlequin module set " + name_or_folder + ": " + e.what());
  }
  if (set.machinery == Machinery::Demiurge) demiurge::grey_samples();
  return std::make_shared<const ModuleSet>(std::move(set));
}

}  // namespace sd::arlequin
