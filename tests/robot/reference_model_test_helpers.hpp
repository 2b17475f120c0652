#pragma once
// Hand-built SwarmStates for reference-model tests.
#include <gtest/gtest.h>

#include <array>
#include <cmath>
#include <vector>

#include "robot/reference_model.hpp"
#include "simulator/swarm.hpp"

namespace sd::test {

/// The sensor angles argos3-epuck's control interface reports (17, 50, 90, 150, 210, 270, 310
/// and 343 degrees), in radians.
inline constexpr std::array<double, 8> kReportedAngles = {0.2967, 0.8727, 1.5708, 2.6180,
                                                          3.6654, 4.7122, 5.4109, 5.9874};
inline constexpr double kAngleTolerance = 2e-4;

inline Vec2 unit_at(double angle) { return {std::cos(angle), std::sin(angle)}; }

/// A swarm of `robots` with every sensor silent.
inline SwarmState silent_swarm(int robots = 2) {
  SwarmState s;
  s.resize(robots);
  return s;
}

struct Packet {
  double range_cm;
  double bearing;
  std::uint16_t sender;
};

/// Replaces robot `robot`'s packets of this tick.
inline void set_packets(SwarmState& s, int robot, const std::vector<Packet>& packets) {
  const std::size_t base = static_cast<std::size_t>(robot) * s.rab_stride();
  for (std::size_t k = 0; k < packets.size(); ++k)
    s.rab[base + k] = RabPacket{packets[k].range_cm, unit_at(packets[k].bearing), packets[k].sender};
  s.rab_count[static_cast<std::size_t>(robot)] = static_cast<std::uint16_t>(packets.size());
}

/// One robot's ground sensors fed tick by tick into a reference model, for the floor filters.
class GroundFilterTest : public testing::Test {
 protected:
  using Floor = std::array<double, 3>;
  void step(const Floor& floor) {
    swarm.ground[0] = floor;
    rm.update(swarm, 0);
  }
  SwarmState swarm = silent_swarm();
  ReferenceModel rm;
};

}  // namespace sd::test
