#pragma once
// Scoring control software on a list of seeds and printing it the way `evaluate` does
// (`Score <value>` per seed, the line AutoMoDe's irace runners grep; mean and median for
// several seeds), shared by `evaluate` and `test-design`.
#include <cstdint>
#include <vector>

#include "control/control_software.hpp"
#include "missions/mission.hpp"

namespace sd::cli {

/// Scores per seed, on `threads` threads (0: all cores); a progress line on a terminal.
std::vector<double> score_seeds(const Mission& mission, const ControlSoftware& software,
                                const std::vector<std::uint64_t>& seeds, int threads, bool progress);

void print_scores(const Mission& mission, const ControlSoftware& software, const std::vector<std::uint64_t>& seeds,
                  const std::vector<double>& scores, bool json);

}  // namespace sd::cli
