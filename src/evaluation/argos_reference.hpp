#pragma once
// The scores ARGoS3-AutoMoDe gave the project's calibration set (tests/data/argos-reference*.csv,
// seeds 1-20 per controller), read the same way by the calibration test, which gates on them,
// and by bench/calibration_wide, which compares them with many more of our seeds.
#include <string>
#include <vector>

#include "missions/mission.hpp"
#include "modules/catalogue.hpp"

namespace sd {

/// One calibration group: the rows of `file` whose mission column is `reference_mission` and
/// whose architecture column is `architecture` ("" for the first file, which has none).
struct ArgosReferenceGroup {
  const char* name;
  const char* file;
  const char* reference_mission;
  const char* architecture;
  const char* catalogue_mission;
  double duration_s;    // 0: the catalogue mission's; else ARGoS ran it this long
  bool exact_ranking;   // the group's controllers must rank exactly as in ARGoS
  const char* arlequin_modules = "";  // the module set ARGoS' 50-55 were ("": the mission's)
  /// ARGoS' tick-0 poses of seed N, "{seed}" standing for N, in the data folder ("": none known);
  /// a seed without its file is not known.
  const char* argos_starts = "";
};

/// Every group of the calibration set, in the order the README's tables list them.
const std::vector<ArgosReferenceGroup>& argos_reference_groups();

struct ArgosReferenceController {
  std::string name;
  std::string config;  // as ARGoS ran it
  Flavour legacy_flavour = Flavour::Chocolate;
  std::vector<double> scores;  // ARGoS' scores, seeds 1, 2, ... in order
};

/// The group's controllers, by name, from `folder`/group.file, each configuration string once.
/// Throws std::runtime_error naming the file and line when the file is missing or malformed,
/// or seeds are out of order.
std::vector<ArgosReferenceController> read_argos_reference(const std::string& folder, const ArgosReferenceGroup& group);

/// A group's means, ours and ARGoS', controller by controller, and how many of ours lie above
/// and below ARGoS'. Means of the same scores summed in another order may differ in the last
/// bit, so means that close count as a tie, neither above nor below.
struct ArgosAgreement {
  std::vector<double> ours, argos;
  std::vector<double> ratios;  // ours / ARGoS', where ARGoS' mean is not 0
  int above = 0, below = 0;
  void add(double our_mean, double argos_mean);
};

/// The catalogue mission of the group, run for as long as ARGoS ran it.
Mission argos_reference_mission(const ArgosReferenceGroup& group);

/// One of ARGoS' seeds whose start placement is known, and the group's mission started from it
/// (a run's seed then draws only noise).
struct ArgosStart {
  int seed;
  Mission mission;
};

/// The known starts of ARGoS' seeds 1..`seeds`, in seed order; empty when the group has none.
/// Throws MissionError naming the file when one is malformed.
std::vector<ArgosStart> argos_starts(const std::string& folder, const ArgosReferenceGroup& group, int seeds);

}  // namespace sd
