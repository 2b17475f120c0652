// Calibration against ARGoS3-AutoMoDe (tests/data/argos-reference.csv, copied from the
// project's calibration set): five Chocolate FSMs on AAC and on foraging, seeds 1-20. Seeds differ between
// the simulators, so we compare distributions: every mean lands within one standard
// deviation of ARGoS's, and the controllers rank the same.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <fstream>
#include <map>
#include <numeric>
#include <sstream>

#include "control/config_string.hpp"
#include "evaluation/evaluator.hpp"
#include "missions/catalogue.hpp"

namespace sd {
namespace {

struct Reference {
  std::string config;
  std::vector<double> scores;
};

std::map<std::string, Reference> read_reference(const std::string& mission) {
  std::ifstream in(std::string(SWARMDESIGN_SOURCE_DIR) + "/tests/data/argos-reference.csv");
  std::map<std::string, Reference> refs;
  std::string line;
  std::getline(in, line);  // header
  while (std::getline(in, line)) {
    std::vector<std::string> cells;
    std::stringstream row(line);
    for (std::string cell; std::getline(row, cell, ',');) cells.push_back(cell);
    if (cells.size() != 5 || cells[0] != mission) continue;
    refs[cells[1]].config = cells[2];
    refs[cells[1]].scores.push_back(std::stod(cells[4]));
  }
  return refs;
}

double mean(const std::vector<double>& v) { return std::accumulate(v.begin(), v.end(), 0.0) / static_cast<double>(v.size()); }
double stdev(const std::vector<double>& v) {
  const double m = mean(v);
  double s = 0;
  for (double x : v) s += (x - m) * (x - m);
  return std::sqrt(s / static_cast<double>(v.size() - 1));
}

class Calibration : public ::testing::TestWithParam<const char*> {};

TEST_P(Calibration, ControllersLandWithinArgosSpreadAndRankAlike) {
  const auto refs = read_reference(GetParam());
  ASSERT_EQ(refs.size(), 5u);
  const Mission mission = load_mission(GetParam());
  ThreadedEvaluator evaluator(0);
  std::vector<std::pair<double, std::string>> ours, theirs;
  for (const auto& [name, ref] : refs) {
    const ControlSoftware software = parse_control_software(ref.config);
    std::vector<EvaluationTask> tasks;
    for (std::uint64_t seed = 1; seed <= 20; ++seed) tasks.push_back({&software, seed});
    std::vector<double> scores(tasks.size());
    evaluator.evaluate(mission, tasks, scores);
    const double m = mean(scores), reference_mean = mean(ref.scores), reference_sd = stdev(ref.scores);
    EXPECT_NEAR(m, reference_mean, reference_sd) << name << ": ours " << m << ", ARGoS " << reference_mean << " +- " << reference_sd;
    ours.emplace_back(m, name);
    theirs.emplace_back(reference_mean, name);
  }
  std::sort(ours.begin(), ours.end());
  std::sort(theirs.begin(), theirs.end());
  for (std::size_t i = 0; i < ours.size(); ++i) EXPECT_EQ(ours[i].second, theirs[i].second) << "rank " << i;
}

INSTANTIATE_TEST_SUITE_P(ArgosReference, Calibration, ::testing::Values("aac", "foraging"));

}  // namespace
}  // namespace sd
