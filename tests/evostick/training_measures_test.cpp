// The training measures of the six Arlequin modules, checked on hand-made swarms (values
// worked out by hand) and on Chocolate modules whose behaviour is known.
#include <gtest/gtest.h>

#include "control/config_string.hpp"
#include "evostick/module_training.hpp"
#include "evostick/training_measures.hpp"

namespace sd {
namespace {

using evostick::Measure;

double measure(Measure m, const Mission& mission, const std::string& config, std::uint64_t seed) {
  const ControlSoftware software = parse_control_software(config);
  Simulation simulation(mission, software);
  evostick::MeasureObserver observer(m, mission);
  simulation.run(seed, &observer);
  return observer.value();
}

double mean_measure(Measure m, const Mission& mission, const std::string& config) {
  double sum = 0.0;
  for (std::uint64_t seed = 1; seed <= 5; ++seed) sum += measure(m, mission, config, seed);
  return sum / 5.0;
}

Mission cues() { return evostick::training_mission(*evostick::find_module_training("stop")); }
Mission symmetric() { return evostick::training_mission(*evostick::find_module_training("attraction")); }

const std::string kStop = "--fsm-config --nstates 1 --s0 11";
const std::string kExplore = "--fsm-config --nstates 1 --s0 10 --rwm0 20";
const std::string kPhoto = "--fsm-config --nstates 1 --s0 12";
const std::string kAntiPhoto = "--fsm-config --nstates 1 --s0 13";
const std::string kAttract = "--fsm-config --nstates 1 --s0 14 --att0 5";
const std::string kRepel = "--fsm-config --nstates 1 --s0 15 --rep0 5";

TEST(TrainingMeasures, AStoppedSwarmScoresExactlyAsWorkedOutByHand) {
  // Robots that never move: no distance travelled, one cell each, and the light, centroid
  // and nearest-neighbour distances of the placement, averaged by hand here.
  const Mission m = cues();
  const ControlSoftware stop = parse_control_software(kStop);
  Simulation simulation(m, stop);
  simulation.reset(4);
  const SwarmState& s = simulation.swarm();
  const Vec2 light = m.arena.lights[0].position.xy();
  double to_light = 0.0, to_centroid = 0.0, nearest = 0.0;
  Vec2 centroid;
  for (int i = 0; i < s.size; ++i) centroid += s.position[static_cast<std::size_t>(i)] * (1.0 / s.size);
  for (int i = 0; i < s.size; ++i) {
    const Vec2 p = s.position[static_cast<std::size_t>(i)];
    to_light += (p - light).length() / s.size;
    to_centroid += (p - centroid).length() / s.size;
    double best = 1e9;
    for (int j = 0; j < s.size; ++j)
      if (j != i) best = std::min(best, (s.position[static_cast<std::size_t>(j)] - p).length());
    nearest += best / s.size;
  }
  EXPECT_EQ(measure(Measure::Stillness, m, kStop, 4), 0.0);
  EXPECT_EQ(measure(Measure::Coverage, m, kStop, 4), 1.0);
  EXPECT_NEAR(measure(Measure::LightApproach, m, kStop, 4), -to_light, 1e-9);
  EXPECT_NEAR(measure(Measure::LightAvoidance, m, kStop, 4), to_light, 1e-9);
  EXPECT_NEAR(measure(Measure::Cohesion, m, kStop, 4), -to_centroid, 1e-9);
  EXPECT_NEAR(measure(Measure::Dispersion, m, kStop, 4), nearest, 1e-9);
}

TEST(TrainingMeasures, ExplorationCoversMoreThanStoppingAndPhototaxis) {
  const Mission m = cues();
  const double explore = mean_measure(Measure::Coverage, m, kExplore);
  EXPECT_GT(explore, 30.0);  // a robot crosses 4.8 m in 40 s: tens of 10-cm cells
  EXPECT_GT(explore, mean_measure(Measure::Coverage, m, kPhoto));
  EXPECT_LT(mean_measure(Measure::Stillness, m, kExplore), -2.0);
}

TEST(TrainingMeasures, PhototaxisApproachesTheLightAndAntiPhototaxisAvoidsIt) {
  const Mission m = cues();
  EXPECT_GT(mean_measure(Measure::LightApproach, m, kPhoto), mean_measure(Measure::LightApproach, m, kAntiPhoto) + 0.5);
  EXPECT_GT(mean_measure(Measure::LightAvoidance, m, kAntiPhoto), mean_measure(Measure::LightAvoidance, m, kStop));
}

TEST(TrainingMeasures, AttractionGathersAndRepulsionSpreads) {
  const Mission m = symmetric();
  EXPECT_GT(mean_measure(Measure::Cohesion, m, kAttract), mean_measure(Measure::Cohesion, m, kRepel));
  EXPECT_GT(mean_measure(Measure::Cohesion, m, kAttract), mean_measure(Measure::Cohesion, m, kStop));
  EXPECT_GT(mean_measure(Measure::Dispersion, m, kRepel), mean_measure(Measure::Dispersion, m, kAttract));
}

TEST(TrainingMeasures, TheSymmetricArenaPunishesGatheringByTheLight) {
  // Phototaxis gathers the swarm in the AAC arena but splits it in the symmetric one, where
  // only the neighbours can gather it (data/arlequin/training/symmetric-cues.json).
  EXPECT_GT(mean_measure(Measure::Cohesion, cues(), kPhoto), mean_measure(Measure::Cohesion, symmetric(), kPhoto));
  EXPECT_GT(mean_measure(Measure::Cohesion, symmetric(), kAttract), mean_measure(Measure::Cohesion, symmetric(), kPhoto));
}

TEST(TrainingMeasures, LightMeasuresNeedALight) {
  Mission m = cues();
  m.arena.lights.clear();
  EXPECT_THROW(evostick::MeasureObserver(Measure::LightApproach, m), std::invalid_argument);
  EXPECT_NO_THROW(evostick::MeasureObserver(Measure::Cohesion, m));
}

}  // namespace
}  // namespace sd
