// What the TuttiFrutti scenario files add to the loop functions' arenas
// (experiments-loop-functions-ros scenarios/tuttifrutti/*.argos): the RAB range the actuator
// is given, and the foraging arena's divider box between the two sources.
#include <gtest/gtest.h>

#include <cmath>

#include "missions/catalogue.hpp"
#include "simulator/sensors.hpp"

namespace sd {
namespace {

TEST(TuttiScenario, RabRangeIsTheActuatorsHalfMetre) {
  for (const char* name : {"tutti-aggregation", "tutti-stop", "tutti-foraging"})
    EXPECT_EQ(load_mission(name).robot.rab_range, 0.5) << name;
}

TEST(TuttiScenario, ForagingDividerSplitsTheSourcesAndHidesWhatIsBehindIt) {
  const Mission m = load_mission("tutti-foraging");
  // 24 LED blocks plus the box "sep" 0.15 x 0.012 x 0.15 at (0.675, 0).
  ASSERT_EQ(m.arena.walls.size(), 25u);
  const Wall& sep = m.arena.walls.back();
  EXPECT_NEAR(sep.center.x, 0.675, 1e-12);
  EXPECT_NEAR(sep.center.y, 0.0, 1e-12);
  EXPECT_NEAR(sep.height, 0.15, 1e-12);
  EXPECT_LT(sep.distance({0.605, 0.0}, nullptr), 0.0);             // it reaches x = 0.6 ...
  EXPECT_NEAR(sep.distance({0.59, 0.0}, nullptr), 0.01, 1e-9);      // ... and no further
  EXPECT_NEAR(sep.distance({0.675, 0.05}, nullptr), 0.044, 1e-9);  // 6 mm either side of y = 0

  // Two robots face to face across it, in the two sources: taller than the camera, it hides
  // each one's LED from the other; 10 cm further out (x < 0.6) they see each other.
  for (const auto& [x, hidden] : {std::pair{0.68, true}, std::pair{0.5, false}}) {
    SwarmState s;
    s.resize(2, static_cast<int>(m.arena.leds.size()));
    s.position = {{x, -0.12}, {x, 0.12}};
    s.yaw = {kPi / 2, -kPi / 2};
    for (std::size_t i = 0; i < 2; ++i) s.heading[i] = Vec2::polar(1.0, s.yaw[i]);
    s.led = {0x00ffff, 0x00ffff};
    s.demand = {SwarmState::kDemandCamera, SwarmState::kDemandCamera};
    s.broad_phase.build(s.position);
    sense_camera(m.arena, m.robot, s);
    EXPECT_EQ(s.blob_count[0], hidden ? 0 : 1) << x;
    EXPECT_EQ(s.blob_count[1], hidden ? 0 : 1) << x;
  }
}

}  // namespace
}  // namespace sd
