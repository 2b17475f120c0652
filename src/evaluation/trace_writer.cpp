#include "evaluation/trace_writer.hpp"

#include <cstdio>

namespace sd {

TraceWriter::TraceWriter(std::ostream& out) : out_(out) {
  out_ << "tick,robot,x,y,yaw,v_left,v_right,state,led,objective\n";
}

void TraceWriter::on_tick(const Simulation& sim) {
  const SwarmState& s = sim.swarm();
  char line[256];
  for (int i = 0; i < s.size; ++i) {
    const auto r = static_cast<std::size_t>(i);
    std::snprintf(line, sizeof line, "%d,%d,%.9g,%.9g,%.9g,%.9g,%.9g,%d,#%06x,%.17g\n", sim.tick(), i, s.position[r].x,
                  s.position[r].y, s.yaw[r], s.wheel_left[r], s.wheel_right[r], sim.fsm_state(i), s.led[r], sim.score());
    out_ << line;
  }
}

}  // namespace sd
