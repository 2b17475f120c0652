#include "evaluation/argos_reference.hpp"

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <map>
#include <set>
#include <stdexcept>

#include "core/csv_fields.hpp"
#include "missions/catalogue.hpp"
#include "missions/start_trace.hpp"
#include "simulator/epuck.hpp"

namespace sd {

namespace {

// ARGoS' own tick-0 poses, seeds 1-20 (set 7; tests/data/argos-starts/README.md), one folder per
// ARGoS mission file. The behaviour-tree missions have none of their own: ARGoS places their
// robots exactly as in the FSM missions of the same name.
constexpr const char* kAacStarts = "argos-starts/aac_120s/seed{seed}.csv";
constexpr const char* kForagingStarts = "argos-starts/foraging_120s/seed{seed}.csv";

}  // namespace

const std::vector<ArgosReferenceGroup>& argos_reference_groups() {
  static const std::vector<ArgosReferenceGroup> groups{
      {"aac", "argos-reference.csv", "aac", "", "aac", 0, true, "", kAacStarts},
      {"foraging", "argos-reference.csv", "foraging", "", "foraging", 0, true, "", kForagingStarts},
      {"sca", "argos-reference-2.csv", "sca", "fsm", "sca", 0, false, "", "argos-starts/sca_120s/seed{seed}.csv"},
      {"lcn", "argos-reference-2.csv", "lcn", "fsm", "lcn", 0, false, "", "argos-starts/lcn_120s/seed{seed}.csv"},
      // ARGoS ran the two-spot aggregation for 180 s; the catalogue's lasts 250 s.
      {"aggregation180", "argos-reference-2.csv", "aggregation180", "fsm", "aggregation", 180, false, "",
       "argos-starts/aggregation_180s/seed{seed}.csv"},
      {"aac_bt", "argos-reference-2.csv", "aac", "bt", "aac", 0, false, "", kAacStarts},
      {"foraging_bt", "argos-reference-2.csv", "foraging", "bt", "foraging", 0, false, "", kForagingStarts},
      {"tutti_aggregation", "argos-reference-3.csv", "tutti-aggregation", "fsm", "tutti-aggregation", 0, false, "",
       "argos-starts/tutti_aggregation_120s/seed{seed}.csv"},
      {"tutti_stop", "argos-reference-3.csv", "tutti-stop", "fsm", "tutti-stop", 0, false},
      {"tutti_foraging", "argos-reference-3.csv", "tutti-foraging", "fsm", "tutti-foraging", 0, false},
      {"grid_exploration", "argos-reference-5.csv", "grid-exploration", "fsm", "grid-exploration", 0, false, "",
       "argos-starts/grid_exploration_120s/seed{seed}.csv"},
      {"coconut_aggregation", "argos-reference-5.csv", "coconut-aggregation", "fsm", "coconut-aggregation", 0, false, "",
       "argos-starts/coconut_aggregation_120s/seed{seed}.csv"},
      {"coconut_foraging", "argos-reference-5.csv", "coconut-foraging", "fsm", "coconut-foraging", 0, false, "",
       "argos-starts/coconut_foraging_120s/seed{seed}.csv"},
      // Demiurge's Arlequin: its own six networks and machinery, not SwarmDesign's shipped set.
      {"arlequin_aac", "argos-reference-6.csv", "aac", "fsm", "aac", 0, false, "demiurge",
       "argos-starts/demiurge_aac_120s/seed{seed}.csv"},
      {"aggregation_xor", "argos-reference-6.csv", "aggregation-xor", "fsm", "aggregation-xor", 0, false, "demiurge",
       "argos-starts/aggregation_xor_180s/seed{seed}.csv"},
  };
  return groups;
}

std::vector<ArgosReferenceController> read_argos_reference(const std::string& folder, const ArgosReferenceGroup& group) {
  const std::string path = folder + "/" + group.file;
  std::ifstream in(path);
  if (!in) throw std::runtime_error("cannot read " + path);
  std::string line;
  std::getline(in, line);
  const std::vector<std::string_view> header = csv_fields(line);
  const auto column = [&](const std::string& name) {
    const auto it = std::find(header.begin(), header.end(), name);
    return it == header.end() ? -1 : static_cast<int>(it - header.begin());
  };
  const int mission = column("mission"), controller = column("controller"), config = column("config"),
            seed = column("seed"), score = column("argos_score"), architecture = column("architecture"),
            flavour = column("legacy_flavour");
  if (mission < 0 || controller < 0 || config < 0 || seed < 0 || score < 0)
    throw std::runtime_error(path + ": the header lacks mission, controller, config, seed or argos_score");
  const std::size_t columns = header.size();  // `header` views `line`, which the loop reuses
  std::map<std::string, ArgosReferenceController> found;
  for (int number = 2; std::getline(in, line); ++number) {
    const std::vector<std::string_view> cells = csv_fields(line);
    const auto cell = [&](int k) { return std::string(cells[static_cast<std::size_t>(k)]); };
    if (cells.size() != columns || cell(mission) != group.reference_mission) continue;
    if (architecture >= 0 && cell(architecture) != group.architecture) continue;
    ArgosReferenceController& ref = found[cell(controller)];
    ref.name = cell(controller);
    ref.config = cell(config);
    if (flavour >= 0 && !cell(flavour).empty()) {
      const auto f = flavour_from_name(cell(flavour));
      if (!f) throw std::runtime_error(path + ":" + std::to_string(number) + ": unknown legacy_flavour '" + cell(flavour) + "'");
      ref.legacy_flavour = *f;
    }
    if (std::stoi(cell(seed)) != static_cast<int>(ref.scores.size()) + 1)
      throw std::runtime_error(path + ":" + std::to_string(number) + ": seeds of " + ref.name + " are not 1, 2, ... in order");
    ref.scores.push_back(std::stod(cell(score)));
  }
  // A string measured twice under two names (set 6's A01 = S52, A02 = S51, A06 = S54, identical
  // seed by seed) is one controller: read once, under the name that sorts last, so that the
  // per-mission tests do not count it twice.
  std::vector<ArgosReferenceController> refs;
  std::set<std::string> configs;
  for (auto it = found.rbegin(); it != found.rend(); ++it)
    if (configs.insert(it->second.config).second) refs.push_back(std::move(it->second));
  std::reverse(refs.begin(), refs.end());
  return refs;
}

void ArgosAgreement::add(double our_mean, double argos_mean) {
  const bool tie = std::abs(our_mean - argos_mean) <= 1e-9 * std::max(1.0, std::abs(argos_mean));
  above += !tie && our_mean > argos_mean;
  below += !tie && our_mean < argos_mean;
  if (argos_mean != 0) ratios.push_back(our_mean / argos_mean);
  ours.push_back(our_mean);
  argos.push_back(argos_mean);
}

Mission argos_reference_mission(const ArgosReferenceGroup& group) {
  Mission mission = load_mission(group.catalogue_mission);
  if (*group.arlequin_modules) mission = with_arlequin_modules(mission, group.arlequin_modules);
  if (group.duration_s > 0) {
    mission.duration_s = group.duration_s;
    mission.ticks = static_cast<int>(std::lround(group.duration_s / epuck::kTickSeconds));  // as a mission file's
  }
  return mission;
}

std::vector<ArgosStart> argos_starts(const std::string& folder, const ArgosReferenceGroup& group, int seeds) {
  std::vector<ArgosStart> out;
  const std::string pattern = group.argos_starts;
  const std::size_t at = pattern.find("{seed}");
  if (at == std::string::npos) return out;
  const Mission mission = argos_reference_mission(group);
  for (int seed = 1; seed <= seeds; ++seed) {
    const std::filesystem::path path = folder + "/" + std::string(pattern).replace(at, 6, std::to_string(seed));
    if (std::filesystem::exists(path)) out.push_back({seed, started_from_trace(mission, path)});
  }
  return out;
}

}  // namespace sd
