#include "simulator/sensors.hpp"

namespace sd {

void sense(const ArenaModel& arena, const RobotModel& model, SwarmState& swarm, Rng& rng, SensorSet sensors) {
  swarm.broad_phase.build(swarm.position, sensors.range_and_bearing ? model.max_rab_range() : kProximityPairRange);
  if (sensors.range_and_bearing) sense_range_and_bearing(arena, model, swarm, rng);
  if (sensors.proximity) sense_proximity(arena, model, swarm, rng);
  if (sensors.light) sense_light(arena, model, swarm, rng);
  if (sensors.ground) sense_ground(arena, model, swarm, rng);
  if (sensors.camera) sense_camera(arena, model, swarm, &rng);
}

}  // namespace sd
