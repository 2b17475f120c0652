// The omnidirectional camera and LEDs (as argos3-epuck simulates them).
#include <gtest/gtest.h>

#include <cmath>

#include "simulator/epuck.hpp"
#include "simulator/sensors.hpp"
#include "swarm_builder.hpp"

namespace sd {
namespace {

using test::robots;

TEST(Camera, SeesTheLitRearLedOfAnotherRobot) {
  ArenaModel arena;
  arena.compile();
  // Robot 1 at (0.2, 0) faces +x: its rear LED is at (0.164, 0). Robot 0 faces +y.
  SwarmState s = robots({{{0, 0}, kPi / 2}, {{0.2, 0.0}, 0.0}});
  s.led[1] = 0x00ffff;
  sense_camera(arena, RobotModel{}, s);
  ASSERT_EQ(s.blob_count[0], 1);
  const CameraBlob& b = s.blobs[0];
  EXPECT_EQ(b.rgb, 0x00ffffu);
  EXPECT_NEAR(b.distance_cm, 16.4, 1e-9);
  EXPECT_NEAR(b.angle(), -kPi / 2, 1e-12);  // to the right of a robot facing north
  EXPECT_EQ(s.blob_count[1], 0);            // robot 0's LEDs are off
}

TEST(Camera, RangeIsASquareOfHalfSideTheGroundHalfRange) {
  // argos3-epuck keeps an LED when |dx| and |dy| (world axes, camera to LED) are both below
  // 0.122 tan 70 deg = 0.335 m; the height difference is not counted.
  ArenaModel arena;
  arena.compile();
  struct Case {
    Vec2 led;
    bool seen;
  };
  const Case cases[] = {
      {{0.3349, 0.0}, true},  {{0.3351, 0.0}, false},  // along an axis: 0.335 in the plane
      {{0.33, 0.33}, true},                           // a corner of the square, 0.467 m away
      {{0.0, -0.3349}, true}, {{-0.3351, 0.1}, false},
  };
  for (const Case& c : cases) {
    // Robot 1 faces +x, so its lit rear LED is 0.036 m behind its centre.
    SwarmState s = robots({{{0, 0}, 0.0}, {{c.led.x + 0.036, c.led.y}, 0.0}});
    s.led[1] = 0xff0000;
    sense_camera(arena, RobotModel{}, s);
    EXPECT_EQ(s.blob_count[0] == 1, c.seen) << c.led.x << ", " << c.led.y;
    if (s.blob_count[0] == 1) {
      EXPECT_NEAR(s.blobs[0].distance_cm, c.led.length() * 100.0, 1e-9);
    }
  }
  // The square is fixed to the world, not to the robot: turning does not change what is seen.
  SwarmState t = robots({{{0, 0}, 0.7}, {{0.33 + 0.036, 0.33}, 0.0}});
  t.led[1] = 0xff0000;
  sense_camera(arena, RobotModel{}, t);
  EXPECT_EQ(t.blob_count[0], 1);
}

TEST(Camera, RobotsNeverOccludeButWallsCanNearTheLed) {
  // A robot between the camera and the LED does not hide it.
  ArenaModel open;
  open.compile();
  SwarmState s = robots({{{0, 0}, 0.0}, {{0.25, 0.0}, 0.0}, {{0.12, 0.0}, 0.0}});
  s.led[1] = 0x00ff00;  // robot 1 faces east: its rear LED is at (0.214, 0)
  sense_camera(open, RobotModel{}, s);
  EXPECT_EQ(s.blob_count[0], 1);

  // An 8 cm wall right in front of the LED blocks it (the ray leaves it at 7.8 cm); the same
  // wall near the camera does not (the ray is still about 11 cm high there).
  for (const auto& [x, blocked] : {std::pair{0.20, true}, std::pair{0.05, false}}) {
    ArenaModel arena;
    Wall w;
    w.center = {x, 0.0};
    w.axis = {0.0, 1.0};
    w.half_length = 0.05;
    w.half_thickness = 0.005;
    w.height = 0.08;
    arena.walls.push_back(w);
    arena.compile();
    SwarmState t = robots({{{0, 0}, 0.0}, {{0.25, 0.0}, 0.0}});
    t.led[1] = 0x00ff00;
    sense_camera(arena, RobotModel{}, t);
    EXPECT_EQ(t.blob_count[0] == 0, blocked) << "wall at " << x;
  }
}

TEST(Camera, SeesLitArenaLedsWithTheirCurrentColour) {
  ArenaModel arena;
  arena.leds.push_back({{0.2, 0.1, 0.067}, 0, 0x0000ff});
  arena.leds.push_back({{-0.2, 0.0, 0.067}, 0, 0});
  arena.compile();
  SwarmState s = robots({{{0, 0}, 0.0}}, 2);
  s.arena_led_color = {0x0000ff, 0};
  sense_camera(arena, RobotModel{}, s);
  ASSERT_EQ(s.blob_count[0], 1);
  EXPECT_EQ(s.blobs[0].rgb, 0x0000ffu);
  EXPECT_NEAR(s.blobs[0].distance_cm, std::sqrt(0.05) * 100.0, 1e-9);
  s.arena_led_color[1] = 0xff0000;  // a mission event lights the second one
  sense_camera(arena, RobotModel{}, s);
  EXPECT_EQ(s.blob_count[0], 2);
}

}  // namespace
}  // namespace sd
