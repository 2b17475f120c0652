#include "evaluation/argos_reference.hpp"

#include <algorithm>
#include <cmath>
#include <fstream>
#include <map>
#include <set>
#include <sstream>
#include <stdexcept>

#include "missions/catalogue.hpp"
#include "simulator/epuck.hpp"

namespace sd {

const std::vector<ArgosReferenceGroup>& argos_reference_groups() {
  static const std::vector<ArgosReferenceGroup> groups{
      {"aac", "argos-reference.csv", "aac", "", "aac", 0, true},
      {"foraging", "argos-reference.csv", "foraging", "", "foraging", 0, true},
      {"sca", "argos-reference-2.csv", "sca", "fsm", "sca", 0, false},
      {"lcn", "argos-reference-2.csv", "lcn", "fsm", "lcn", 0, false},
      // ARGoS ran the two-spot aggregation for 180 s; the catalogue's lasts 250 s.
      {"aggregation180", "argos-reference-2.csv", "aggregation180", "fsm", "aggregation", 180, false},
      {"aac_bt", "argos-reference-2.csv", "aac", "bt", "aac", 0, false},
      {"foraging_bt", "argos-reference-2.csv", "foraging", "bt", "foraging", 0, false},
      {"tutti_aggregation", "argos-reference-3.csv", "tutti-aggregation", "fsm", "tutti-aggregation", 0, false},
      {"tutti_stop", "argos-reference-3.csv", "tutti-stop", "fsm", "tutti-stop", 0, false},
      {"tutti_foraging", "argos-reference-3.csv", "tutti-foraging", "fsm", "tutti-foraging", 0, false},
      {"grid_exploration", "argos-reference-5.csv", "grid-exploration", "fsm", "grid-exploration", 0, false},
      {"coconut_aggregation", "argos-reference-5.csv", "coconut-aggregation", "fsm", "coconut-aggregation", 0, false},
      {"coconut_foraging", "argos-reference-5.csv", "coconut-foraging", "fsm", "coconut-foraging", 0, false},
      // Demiurge's Arlequin: its own six networks and machinery, not SwarmDesign's shipped set.
      {"arlequin_aac", "argos-reference-6.csv", "aac", "fsm", "aac", 0, false, "demiurge"},
      {"aggregation_xor", "argos-reference-6.csv", "aggregation-xor", "fsm", "aggregation-xor", 0, false, "demiurge"},
  };
  return groups;
}

namespace {

std::vector<std::string> split_csv(std::string line) {
  if (!line.empty() && line.back() == '\r') line.pop_back();  // the first file has CRLF line ends
  std::vector<std::string> cells;
  std::stringstream row(line);
  for (std::string cell; std::getline(row, cell, ',');) cells.push_back(cell);
  return cells;
}

}  // namespace

std::vector<ArgosReferenceController> read_argos_reference(const std::string& folder, const ArgosReferenceGroup& group) {
  const std::string path = folder + "/" + group.file;
  std::ifstream in(path);
  if (!in) throw std::runtime_error("cannot read " + path);
  std::string line;
  std::getline(in, line);
  const std::vector<std::string> header = split_csv(line);
  const auto column = [&](const std::string& name) {
    const auto it = std::find(header.begin(), header.end(), name);
    return it == header.end() ? -1 : static_cast<int>(it - header.begin());
  };
  const int mission = column("mission"), controller = column("controller"), config = column("config"),
            seed = column("seed"), score = column("argos_score"), architecture = column("architecture"),
            flavour = column("legacy_flavour");
  if (mission < 0 || controller < 0 || config < 0 || seed < 0 || score < 0)
    throw std::runtime_error(path + ": the header lacks mission, controller, config, seed or argos_score");
  std::map<std::string, ArgosReferenceController> found;
  for (int number = 2; std::getline(in, line); ++number) {
    const std::vector<std::string> cells = split_csv(line);
    const auto cell = [&](int k) { return cells[static_cast<std::size_t>(k)]; };
    if (cells.size() != header.size() || cell(mission) != group.reference_mission) continue;
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

}  // namespace sd
