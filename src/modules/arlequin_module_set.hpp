#pragma once
// An Arlequin module set: the six networks of modules 50-55 together with the machinery they
// were made for (how the 25 inputs are computed and what a state entry resets). Networks are
// evolved against one machinery, so a set always names its own.
//
// Two sets are built in:
//   "swarmdesign" (the default): data/arlequin/, SwarmDesign's EvoStick networks, with its
//                 machinery (arlequin::encode_inputs);
//   "demiurge":   data/arlequin-demiurge/, AmmarHsn/Demiurge's six NEAT genomes converted
//                 1:1, with Demiurge's machinery (arlequin_demiurge.hpp).
// A folder holding the six <module>.json weight documents is a set too; its optional
// module-set.json ({"machinery": "swarmdesign" | "demiurge"}) names the machinery.
#include <array>
#include <memory>
#include <string>
#include <string_view>

#include "core/bounded_file.hpp"
#include "modules/arlequin.hpp"
#include "modules/behaviours.hpp"

namespace sd::arlequin {

enum class Machinery {
  SwarmDesign,  // 5-step ground filter, raw reading on grey, RAB buffer kept across states
  Demiurge,     // RM3.0 GetGroundInput, real-robot grey samples, buffer emptied on entry
};
std::string_view machinery_name(Machinery m);

struct ModuleSet {
  std::string name;        // "swarmdesign", "demiurge", or the folder as given
  Machinery machinery = Machinery::SwarmDesign;
  std::array<Weights, 6> weights{};  // by module digit (kModuleNames order)
  std::string digest;      // FNV-1a of the machinery and the 300 weights: what runs depend on

  const Weights& of(int id) const { return weights[static_cast<std::size_t>(id - kFirstModuleId)]; }
  /// One control step of module `id` (50-55) with this set's network and machinery. Demiurge's
  /// machinery counts, in `memory`, the steps since the state was entered.
  Actuation drive(int id, BehaviourMemory& memory, const ReferenceModel& rm, Rng& rng) const;
};

inline constexpr std::string_view kDefaultModuleSet = "swarmdesign";

/// The built-in sets (parsed once, on first use); nullptr for another name.
const ModuleSet* builtin_module_set(std::string_view name);
/// "swarmdesign", "demiurge", or a folder of weight documents (read now). Throws
/// std::runtime_error with one line naming what is wrong.
std::shared_ptr<const ModuleSet> load_module_set(const std::string& name_or_folder, const PathRule& allowed = {});

}  // namespace sd::arlequin
