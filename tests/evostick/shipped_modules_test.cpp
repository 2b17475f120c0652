// The shipped Arlequin modules do what they are named for: each one, alone on a swarm in
// its training arena, on seeds evolution never saw, beats the modules that should not do
// well on its measure.
#include <gtest/gtest.h>

#include "control/config_string.hpp"
#include "evostick/module_training.hpp"

namespace sd {
namespace {

using evostick::Measure;

/// Mean measure of module `id` run by every robot, in `arena_of`'s training arena, over
/// ten fresh seeds.
double score(int id, Measure measure, const char* arena_of) {
  const Mission m = evostick::training_mission(*evostick::find_module_training(arena_of));
  const ControlSoftware software = parse_control_software("--fsm-config --nstates 1 --s0 " + std::to_string(id));
  std::vector<EvaluationTask> tasks;
  for (std::uint64_t seed = 1001; seed <= 1010; ++seed) tasks.push_back({&software, seed});
  std::vector<double> scores(tasks.size());
  evostick::MeasureEvaluator(measure, 2).evaluate(m, tasks, scores);
  double mean = 0.0;
  for (const double s : scores) mean += s / static_cast<double>(scores.size());
  return mean;
}

constexpr int kExploration = 50, kStop = 51, kPhototaxis = 52, kAntiphototaxis = 53, kAttraction = 54, kRepulsion = 55;

TEST(ShippedModules, StopMovesLessThanAnyOtherModule) {
  const double stop = score(kStop, Measure::Stillness, "stop");
  EXPECT_GT(stop, -1.0) << "less than 1 m in 40 s (full speed covers 4.8 m)";
  for (const int other : {kExploration, kPhototaxis, kAntiphototaxis, kAttraction, kRepulsion})
    EXPECT_GT(stop, score(other, Measure::Stillness, "stop")) << other;
}

TEST(ShippedModules, ExplorationCoversMoreFloorThanStopAndAttraction) {
  const double exploration = score(kExploration, Measure::Coverage, "exploration");
  EXPECT_GT(exploration, 20.0);
  EXPECT_GT(exploration, score(kStop, Measure::Coverage, "exploration"));
  EXPECT_GT(exploration, score(kAttraction, Measure::Coverage, "exploration"));
}

TEST(ShippedModules, PhototaxisGoesToTheLightAndAntiphototaxisAway) {
  const double photo = score(kPhototaxis, Measure::LightApproach, "phototaxis");
  for (const int other : {kExploration, kStop, kAntiphototaxis})
    EXPECT_GT(photo, score(other, Measure::LightApproach, "phototaxis")) << other;
  const double anti = score(kAntiphototaxis, Measure::LightAvoidance, "antiphototaxis");
  for (const int other : {kExploration, kStop, kPhototaxis})
    EXPECT_GT(anti, score(other, Measure::LightAvoidance, "antiphototaxis")) << other;
}

TEST(ShippedModules, AttractionGathersTheSwarmAndRepulsionSpreadsIt) {
  const double attraction = score(kAttraction, Measure::Cohesion, "attraction");
  for (const int other : {kExploration, kStop, kRepulsion})
    EXPECT_GT(attraction, score(other, Measure::Cohesion, "attraction")) << other;
  const double repulsion = score(kRepulsion, Measure::Dispersion, "repulsion");
  for (const int other : {kStop, kAttraction})
    EXPECT_GT(repulsion, score(other, Measure::Dispersion, "repulsion")) << other;
}

}  // namespace
}  // namespace sd
