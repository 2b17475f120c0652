// A run from given tick-0 poses (evaluate --start-from, the calibration's ARGoS starts). Read from a trace, the poses land on
// the right robots; a run from its own start is the run itself, bit for bit; and every
// malformed trace is one line naming what is wrong (the bad-input catalogue has the CLI's).
#include "missions/start_trace.hpp"

#include <gtest/gtest.h>

#include <string>
#include <vector>

#include "control/config_string.hpp"
#include "evaluation/simulation.hpp"
#include "missions/catalogue.hpp"
#include "refusal.hpp"

namespace sd {
namespace {

/// Captures the poses after placement.
class StartRecorder : public TickObserver {
 public:
  void on_tick(const Simulation& simulation) override {
    if (simulation.tick() != 0) return;
    const SwarmState& s = simulation.swarm();
    poses.clear();
    for (int r = 0; r < s.size; ++r)
      poses.push_back({s.position[static_cast<std::size_t>(r)], s.yaw[static_cast<std::size_t>(r)]});
  }
  std::vector<StartPose> poses;
};

std::string refusal(const std::string& text, int robots) {
  return test::refusal_of<MissionError>([&] { return start_poses_from_trace(text, robots); });
}

TEST(StartPoses, EachRobotGetsItsPoseWhateverTheRowOrderAndLaterTicksAreNotRead) {
  // ARGoS writes robots in lexicographic id order (epuck0, epuck1, epuck10, epuck2, ...); here
  // they come in reverse, and tick 1's row would move epuck0 if it were read.
  std::string text = "tick,robot,x,y,yaw,v_left,v_right,state,behaviour,ground,led\n";
  for (int r = 10; r >= 0; --r)
    text += "0,epuck" + std::to_string(r) + "," + std::to_string(r - 5) + ".5,-1," + std::to_string(r) + "e-1,0,0,,,,\n";
  text += "1,epuck0,9,9,9,0,0,0,4,0.5,\n";
  const std::vector<StartPose> poses = start_poses_from_trace(text, 11);
  ASSERT_EQ(poses.size(), 11U);
  for (int r = 0; r < 11; ++r) {
    EXPECT_EQ(poses[static_cast<std::size_t>(r)].position.x, r - 5 + (r < 5 ? -0.5 : 0.5));
    EXPECT_EQ(poses[static_cast<std::size_t>(r)].position.y, -1.0);
    EXPECT_DOUBLE_EQ(poses[static_cast<std::size_t>(r)].yaw, r * 1e-1);
  }
  EXPECT_EQ(refusal(text, 4), "the start trace's line 2: 'epuck10' is no robot of the mission's 4 (epuck0 to epuck3)");
}

TEST(StartPoses, WindowsLineEndsReadAsUnixOnes) {
  const std::vector<StartPose> poses = start_poses_from_trace("tick,robot,x,y,yaw\r\n0,epuck1,1,2,3\r\n0,epuck0,4,5,6\r\n", 2);
  ASSERT_EQ(poses.size(), 2U);
  EXPECT_EQ(poses[0].position.x, 4.0);
  EXPECT_EQ(poses[1].yaw, 3.0);
}

TEST(StartPoses, MalformedTracesAreOneLineNamingTheProblem) {
  EXPECT_EQ(refusal("", 2), "the start trace is empty");
  EXPECT_EQ(refusal("tick,robot,x,y\n", 2), "the start trace has no column 'yaw' (line 1)");
  EXPECT_EQ(refusal("tick,robot,x,y,yaw\n0,epuck0,0,0,0\n1,epuck0,0,0,0\n", 2),
            "the start trace has 1 robots at tick 0; the mission has 2");
  EXPECT_EQ(refusal("tick,robot,x,y,yaw\n0,epuck0,0,0,0\n0,epuck0,1,1,0\n", 2),
            "the start trace's line 3: robot epuck0 appears twice at tick 0");
  EXPECT_EQ(refusal("tick,robot,x,y,yaw\n0,epuck0,nan,0,0\n", 2), "the start trace's line 2: x, y and yaw must be finite numbers");
  EXPECT_EQ(refusal("tick,robot,x,y,yaw\n0,robot-a,0,0,0\n", 2),
            "the start trace's line 2: 'robot-a' is no robot of the mission's 2 (epuck0 to epuck1)");
  EXPECT_EQ(refusal("tick,robot,x,y,yaw\n0,epuck0,0,11,0\n", 2), "the start trace's line 2: the robot lies beyond 10 m from the origin");
  EXPECT_EQ(refusal("tick,robot,x,y,yaw\nzero,epuck0,0,0,0\n", 2), "the start trace's line 2: the tick 'zero' is no number");
}

TEST(StartPoses, ARunFromItsOwnStartIsTheRunItselfAndAnotherSeedKeepsTheGivenStart) {
  const Mission aac = load_mission("aac");
  const ControlSoftware software = parse_control_software("--fsm-config --nstates 1 --s0 4 --att0 3");
  Simulation plain(aac, software);
  StartRecorder seed3;
  const double score = plain.run(3, &seed3);

  Mission started = aac;
  started.start_poses = seed3.poses;
  Simulation from_start(started, software);
  StartRecorder again;
  EXPECT_EQ(from_start.run(3, &again), score) << "same start, same seed: the same run";

  StartRecorder seed4;
  (void)from_start.run(4, &seed4);
  ASSERT_EQ(seed4.poses.size(), seed3.poses.size());
  for (std::size_t r = 0; r < seed3.poses.size(); ++r) {
    EXPECT_EQ(seed4.poses[r].position.x, seed3.poses[r].position.x);
    EXPECT_EQ(seed4.poses[r].position.y, seed3.poses[r].position.y);
    EXPECT_EQ(seed4.poses[r].yaw, seed3.poses[r].yaw);
  }
  StartRecorder drawn4;
  (void)plain.run(4, &drawn4);
  EXPECT_NE(drawn4.poses[0].position.x, seed3.poses[0].position.x) << "without start poses seed 4 draws its own";
}

}  // namespace
}  // namespace sd
