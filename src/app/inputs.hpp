#pragma once
// The one reading of each value a user types, whichever front end took it: budgets, seeds,
// seed ranges, missions. Each throws InvalidRequest with the same words everywhere.
#include <cstdint>
#include <string>
#include <vector>

#include "missions/mission.hpp"

namespace sd::app {

/// A design or evolution budget: a positive integer number of simulation runs.
long long parse_budget(const std::string& text);
/// A seed: a non-negative integer below 2^64.
std::uint64_t parse_seed(const std::string& text);
/// "S" or "A-B" (at most 1,000,000 seeds): the seeds to evaluate on.
std::vector<std::uint64_t> parse_seed_range(const std::string& text);
/// A mission the user named (catalogue name or file): the mission file's own error (the path of
/// the bad field) or the catalogue's, as an InvalidRequest.
Mission load_requested_mission(const std::string& name_or_path);
/// A fresh seed in 1..2^31-1 (irace's range), for a design the user gave none.
std::uint64_t random_seed();

}  // namespace sd::app
