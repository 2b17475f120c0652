#pragma once
// evaluate --start-from: a run started from the robots' poses at tick 0 of a trace, ARGoS' set-4
// traces or SwarmDesign's own --trace files (both have the columns tick, robot, x, y, yaw, robots
// named epuck0 ... epuckN-1). Comparing with ARGoS seed by seed from its own start placements
// takes the start sample out of the comparison (README, "Fidelity to ARGoS").
#include <string>
#include <vector>

#include "missions/mission.hpp"

namespace sd::app {

/// The tick-0 poses of a trace's text, robot i at index i; InvalidRequest in one line naming
/// the line and what is wrong (a missing column, a bad number, a robot missing or twice, a
/// robot count other than `robots`).
std::vector<StartPose> start_poses_from_trace(const std::string& text, int robots);

/// `mission` with the start poses of the trace file at `path`; `mission` itself when `path` is
/// empty. The command line's only (a whole trace is larger than the web's 1 MiB inputs).
Mission with_start_from(const Mission& mission, const std::string& path);

}  // namespace sd::app
