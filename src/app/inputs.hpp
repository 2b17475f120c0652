#pragma once
// The one reading of each value a user types, whichever front end took it: budgets, seeds,
// seed ranges. Each throws InvalidRequest with the same words everywhere. Missions and the
// other files a user names are read by app/user_files.hpp's one rule.
#include <cstdint>
#include <string>
#include <vector>


namespace sd::app {

/// A design or evolution budget: a positive integer number of simulation runs.
long long parse_budget(const std::string& text);
/// A seed: a non-negative integer below 2^64.
std::uint64_t parse_seed(const std::string& text);
/// "S" or "A-B" (at most 1,000,000 seeds): the seeds to evaluate on.
std::vector<std::uint64_t> parse_seed_range(const std::string& text);
/// A fresh seed in 1..2^31-1 (irace's range), for a design the user gave none.
std::uint64_t random_seed();

}  // namespace sd::app
