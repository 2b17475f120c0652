// Memoryless sensors (proximity, light, camera) are simulated only for the robots whose
// current FSM state reads them at the coming step.
#include <gtest/gtest.h>

#include <algorithm>

#include "control/config_string.hpp"
#include "control/swarm_controller.hpp"
#include "evaluation/simulation.hpp"
#include "missions/catalogue.hpp"

namespace sd {
namespace {

// State 0 explores (proximity) and leaves on a black floor (ground); state 1 is phototaxis
// (light and proximity) and never leaves.
const char* kExploreThenPhototaxis =
    "--fsm-config --nstates 2 --s0 10 --rwm0 50 --n0 1 --n0x0 0 --c0x0 10 --p0x0 1 --s1 12 --n1 0";

TEST(SensingDemand, AnFsmStateAsksForItsBehaviourAndOnceEnteredForItsConditions) {
  const ControlSoftware sw = parse_control_software(std::string(kExploreThenPhototaxis));
  SwarmController controller(sw, 1);
  // Entering state 0: no condition is checked, so only Exploration's proximity.
  EXPECT_EQ(controller.inputs_of_next_step(0), kProximityInput);
  ReferenceModel rm;  // grey floor: BlackFloor does not fire
  Rng rng(1);
  controller.step(0, rm, rng);
  EXPECT_EQ(controller.inputs_of_next_step(0), kProximityInput | kGroundInput);
}

TEST(SensingDemand, TreesAskForEverythingTheyRead) {
  const ControlSoftware sw = parse_control_software(std::string(
      "--bt-config --nroot 3 --nchildroot 2 --n0 0 --nchild0 2 --n00 6 --c00 40 --p00 1 --n01 5 --a01 44 --att01 5 "
      "--p01 0 --n1 0 --nchild1 2 --n10 6 --c10 41 --p10 0.1 --n11 5 --a11 41 --p11 0"));
  SwarmController controller(sw, 1);
  EXPECT_EQ(controller.inputs_of_next_step(0), sw.inputs());
}

bool all_zero(const std::array<double, 8>& reading) {
  return std::all_of(reading.begin(), reading.end(), [](double v) { return v == 0.0; });
}

TEST(SensingDemand, OnlyRobotsThatReadASensorAreSensedForIt) {
  const Mission m = load_mission("aac");
  const ControlSoftware sw = parse_control_software(std::string(kExploreThenPhototaxis));
  Simulation sim(m, sw);
  sim.reset(3);
  int phototaxis_seen = 0, exploring_seen = 0;
  for (int t = 0; t < 1200; ++t) {
    sim.step();
    const SwarmState& s = sim.swarm();
    for (int i = 0; i < s.size; ++i) {
      const auto r = static_cast<std::size_t>(i);
      // The demand was set before this tick's sensing, from the state the robot was in.
      const bool proximity = s.demand[r] & SwarmState::kDemandProximity;
      const bool light = s.demand[r] & SwarmState::kDemandLight;
      EXPECT_TRUE(proximity) << "both states read proximity";
      if (light) {
        ++phototaxis_seen;
      } else {
        ++exploring_seen;
        EXPECT_TRUE(all_zero(s.light[r])) << "robot " << i << " tick " << t << " was sensed for light";
      }
    }
  }
  // The light is on: robots in phototaxis read it, and the run had robots in both states.
  EXPECT_GT(phototaxis_seen, 0);
  EXPECT_GT(exploring_seen, 0);
}

TEST(SensingDemand, PhototaxisRobotsStillSeeTheLight) {
  const Mission m = load_mission("aac");
  const ControlSoftware sw = parse_control_software(std::string("--fsm-config --nstates 1 --s0 12 --n0 0"));
  Simulation sim(m, sw);
  sim.reset(4);
  sim.step();
  sim.step();
  int lit = 0;
  for (int i = 0; i < sim.swarm().size; ++i) lit += all_zero(sim.swarm().light[static_cast<std::size_t>(i)]) ? 0 : 1;
  EXPECT_GT(lit, sim.swarm().size / 2);
}

}  // namespace
}  // namespace sd
