#pragma once
// A mission run from given start poses: the robots' poses at tick 0 of a trace, ARGoS' set-4
// traces or SwarmDesign's own `evaluate --trace` files (both have the columns tick, robot, x,
// y, yaw, robots named epuck0 ... epuckN-1). Comparing with ARGoS seed by seed from its own
// start placements takes the start sample out of the comparison (README, "Fidelity to ARGoS";
// the calibration set keeps ARGoS' placements in tests/data/argos-starts/).
#include <filesystem>
#include <string_view>
#include <vector>

#include "missions/mission.hpp"

namespace sd {

/// The tick-0 poses of a trace's text, robot i at index i. Lines after tick 0 are not read.
/// MissionError in one line naming the line and what is wrong (a missing column, a bad number,
/// a robot missing or twice, a robot count other than `robots`).
std::vector<StartPose> start_poses_from_trace(std::string_view text, int robots);

/// `mission` with the start poses of the trace file at `path` (read within a bound: a
/// 20-robot, 1200-tick trace is about 2 MB, the bound 64 MiB). MissionError naming the file
/// when it cannot be read or is malformed.
Mission started_from_trace(const Mission& mission, const std::filesystem::path& path);

}  // namespace sd
