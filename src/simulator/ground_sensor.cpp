#include "simulator/epuck.hpp"
#include "simulator/sensor_noise.hpp"
#include "simulator/sensors.hpp"

namespace sd {

void sense_ground(const ArenaModel& arena, const RobotModel& model, SwarmState& swarm, Rng& rng) {
  for (int i = 0; i < swarm.size; ++i) {
    const double uniform = arena.uniform_floor_gray(swarm.position[i]);
    const double c = swarm.heading[i].x, s = swarm.heading[i].y;
    for (int k = 0; k < 3; ++k) {
      double gray = uniform;
      if (gray < 0.0) {  // near a patch edge: each sensor's own point
        const Vec2 o = epuck::kGroundSensorOffsets[k];
        gray = arena.floor_gray(swarm.position[i] + Vec2{c * o.x - s * o.y, s * o.x + c * o.y});
      }
      swarm.ground[i][k] = gray;
    }
    add_uniform_noise(swarm.ground[i], model.ground_noise, rng);
  }
}

}  // namespace sd
