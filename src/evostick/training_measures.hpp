#pragma once
// How EvoStick scores a network while it trains one Arlequin module: a measure of what the
// swarm did, read from the robots' positions after every tick. Every measure is maximised
// and is a mean over the robots, so it does not grow with the swarm size.
#include <string_view>
#include <vector>

#include "evaluation/simulation.hpp"

namespace sd::evostick {

enum class Measure {
  Coverage,        // exploration: floor cells of 10 x 10 cm a robot has visited
  Stillness,       // stop: minus the distance a robot's wheels have rolled (m)
  LightApproach,   // phototaxis: minus the mean distance to the light (m)
  LightAvoidance,  // antiphototaxis: the mean distance to the light (m)
  Cohesion,        // attraction: minus the mean distance to the swarm's centroid (m)
  Dispersion,      // repulsion: the mean distance to the nearest other robot (m)
};

std::string_view measure_name(Measure measure);
/// One sentence for --help, the weight files and the README.
std::string_view measure_description(Measure measure);

/// Accumulates a measure over one run; light measures use the mission's first light.
class MeasureObserver : public TickObserver {
 public:
  MeasureObserver(Measure measure, const Mission& mission);
  void on_tick(const Simulation& simulation) override;
  /// The measure of the run so far (0 before the first tick).
  double value() const;

 private:
  void start(const SwarmState& swarm);

  Measure measure_;
  Vec2 light_;
  double sum_ = 0.0;      // of the per-tick means over the robots
  int ticks_ = 0;
  std::vector<unsigned char> visited_;   // Coverage: robots x cells
  int visited_count_ = 0;
  int robots_ = 0;
};

}  // namespace sd::evostick
