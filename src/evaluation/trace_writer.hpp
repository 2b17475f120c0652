#pragma once
// --trace FILE: every tick of a run as CSV with the columns and tick semantics of the ARGoS
// set-4 traces (../shared/calibration/traces/set4/README.md), plus the running objective:
//   tick,robot,x,y,yaw,v_left,v_right,state,behaviour,ground,led,objective
// Row k holds the pose after the physics of tick k, the wheel speeds applied during it and the
// LED colour shown during it (both commanded at tick k-1), and what the control step of tick k
// did: FSM state after its transition check, or the behaviour tree's action counted
// depth-first (-1: none ran); the number the module has in its flavour's controller string
// (id % 10); the filtered floor its floor conditions read. Tick 0 is the placement.
#include <cstdint>
#include <ostream>
#include <vector>

#include "evaluation/simulation.hpp"

namespace sd {

class TraceWriter : public TickObserver {
 public:
  explicit TraceWriter(std::ostream& out);
  void on_tick(const Simulation& simulation) override;

 private:
  void start(const Simulation& simulation);
  /// State column and module of the behaviour that ran at this tick, for one robot.
  std::pair<int, int> what_ran(const Simulation& simulation, int robot) const;

  std::ostream& out_;
  std::vector<int> leaf_number_;                   // tree node -> depth-first action index
  std::vector<int> previous_state_;                // FSM state after the last tick
  std::vector<double> previous_left_, previous_right_;  // commanded at the last tick
  std::vector<std::uint32_t> previous_led_;
  bool demiurge_floor_ = false;                    // Coconut/Arlequin read Demiurge's filter
};

}  // namespace sd
