// RM1.2 range and bearing (demiurge-epuck-dao's ReferenceModel1Dot2, RabMessageBuffer): the
// neighbour count is this step's senders; the attraction vector sums 1 / (1 + range_cm) at the
// bearing over every message of the current and the previous 10 steps.
#include <gtest/gtest.h>

#include <cmath>

#include "reference_model_test_helpers.hpp"

namespace sd {
namespace {

using test::set_packets;
using test::unit_at;

class RobotRangeAndBearing : public testing::Test {
 protected:
  void step(const std::vector<test::Packet>& packets, int robot = 0) {
    set_packets(swarm, robot, packets);
    rm.update(swarm, robot);
  }
  void expect_sum(Vec2 expected, const char* where) {
    EXPECT_NEAR(rm.attraction_sum().x, expected.x, 1e-12) << where;
    EXPECT_NEAR(rm.attraction_sum().y, expected.y, 1e-12) << where;
  }
  SwarmState swarm = test::silent_swarm(4);
  ReferenceModel rm;
};

TEST_F(RobotRangeAndBearing, NeighbourCountIsThisStepsPackets) {
  step({{10.0, 0.5, 1}, {20.0, -1.0, 2}, {5.0, 3.0, 3}});
  EXPECT_EQ(rm.neighbours, 3);
  EXPECT_EQ(rm.packets.size(), 3u);
  step({{10.0, 0.5, 1}});
  EXPECT_EQ(rm.neighbours, 1);
  step({});
  EXPECT_EQ(rm.neighbours, 0);
  EXPECT_NE(rm.attraction_sum(), (Vec2{0.0, 0.0}));  // the buffer still remembers them
}

TEST_F(RobotRangeAndBearing, EachMessageWeighsOneOverOnePlusRange) {
  step({{9.0, kPi / 2.0, 1}});
  expect_sum(Vec2{0.0, 0.1}, "range 9 cm at 90 deg");
  rm.reset();
  step({{0.0, 0.0, 1}, {3.0, kPi, 2}});
  expect_sum(Vec2{1.0 - 0.25, 0.0}, "range 0 ahead and 3 behind");
}

TEST_F(RobotRangeAndBearing, AttractionScalesTheSumByAlpha) {
  const double bearing = degrees_to_radians(-40);
  step({{4.0, bearing, 1}});
  const Vec2 a = rm.attraction(3.0);
  EXPECT_NEAR(a.x, 3.0 / 5.0 * std::cos(bearing), 1e-12);
  EXPECT_NEAR(a.y, 3.0 / 5.0 * std::sin(bearing), 1e-12);
}

TEST_F(RobotRangeAndBearing, MessageCountsForElevenStepsThenExpires) {
  const Vec2 message = unit_at(1.0) * (1.0 / 13.0);
  step({{12.0, 1.0, 1}});  // heard at step t
  expect_sum(message, "step t");
  for (int k = 1; k <= 10; ++k) {
    step({});
    expect_sum(message, ("step t+" + std::to_string(k)).c_str());
  }
  step({});  // t + 11
  expect_sum({}, "step t+11");
}

TEST_F(RobotRangeAndBearing, RepeatedMessagesOfOneNeighbourAllCount) {
  // The same sender heard on three consecutive steps contributes three times.
  for (int k = 0; k < 3; ++k) step({{1.0, 0.0, 7}});
  expect_sum({1.5, 0.0}, "three steps");
  // Twelve steps in a row: only the last eleven are summed.
  rm.reset();
  for (int k = 0; k < 12; ++k) step({{1.0, 0.0, 7}});
  expect_sum({11 * 0.5, 0.0}, "twelve steps");
}

TEST_F(RobotRangeAndBearing, SlidingWindowDropsTheOldestStepFirst) {
  // Step 0: a message ahead; steps 1..10: one on the left each; step 11: the ahead one expires.
  step({{0.0, 0.0, 1}});
  for (int k = 1; k <= 10; ++k) step({{1.0, kPi / 2.0, 2}});
  expect_sum({1.0, 5.0}, "steps 0-10");
  step({{1.0, kPi / 2.0, 2}});
  expect_sum({0.0, 5.5}, "steps 1-11");
}

TEST_F(RobotRangeAndBearing, EachRobotReadsItsOwnPackets) {
  set_packets(swarm, 0, {{1.0, 0.0, 2}});
  set_packets(swarm, 1, {{3.0, kPi / 2.0, 0}, {0.0, kPi, 2}, {1.0, -kPi / 2.0, 3}});
  set_packets(swarm, 2, {});
  ReferenceModel robot1;
  robot1.update(swarm, 1);
  EXPECT_EQ(robot1.neighbours, 3);
  EXPECT_NEAR(robot1.attraction_sum().x, -1.0, 1e-12);
  EXPECT_NEAR(robot1.attraction_sum().y, 0.25 - 0.5, 1e-12);
  ReferenceModel robot2;
  robot2.update(swarm, 2);
  EXPECT_EQ(robot2.neighbours, 0);
  EXPECT_EQ(robot2.attraction_sum(), (Vec2{0.0, 0.0}));
}

TEST_F(RobotRangeAndBearing, ResetEmptiesTheBuffer) {
  step({{1.0, 0.0, 1}});
  rm.reset();
  EXPECT_EQ(rm.neighbours, 0);
  EXPECT_EQ(rm.attraction_sum(), (Vec2{0.0, 0.0}));
  step({});
  EXPECT_EQ(rm.attraction_sum(), (Vec2{0.0, 0.0}));
}

}  // namespace
}  // namespace sd
