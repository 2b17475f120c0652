#pragma once
// --trace FILE: every tick's robot poses, FSM states, LED colours and the running objective,
// as CSV in the layout of the ARGoS calibration traces (tick 0 = placement).
#include <ostream>

#include "evaluation/simulation.hpp"

namespace sd {

class TraceWriter : public TickObserver {
 public:
  explicit TraceWriter(std::ostream& out);
  void on_tick(const Simulation& simulation) override;

 private:
  std::ostream& out_;
};

}  // namespace sd
