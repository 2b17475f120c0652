#pragma once
// `evaluate` and `test-design` print scores alike: `Score <value>` per seed (the line
// AutoMoDe's irace runners grep), mean and median for several seeds; or the JSON document.
#include <cstdint>
#include <vector>

#include "control/control_software.hpp"
#include "missions/mission.hpp"

namespace sd::cli {

/// Scores on `threads` threads (0: all cores) with a progress line on a terminal, then prints.
void score_and_print(const Mission& mission, const ControlSoftware& software, const std::vector<std::uint64_t>& seeds,
                     int threads, bool json);
void print_scores(const Mission& mission, const ControlSoftware& software, const std::vector<std::uint64_t>& seeds,
                  const std::vector<double>& scores, bool json);

}  // namespace sd::cli
