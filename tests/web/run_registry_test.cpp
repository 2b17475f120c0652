// The Exec runs a server keeps: numbered per user, and forgotten so that one user's many runs
// never push out another user's (the per-user limit first, then whoever keeps the most).
#include <gtest/gtest.h>

#include <chrono>
#include <thread>

#include "app/errors.hpp"
#include "control/config_string.hpp"
#include "missions/catalogue.hpp"
#include "web/run_registry.hpp"

namespace sd::web {
namespace {

constexpr const char* kFsm = "--fsm-config --nstates 1 --s0 0 --rwm0 50";

/// AAC cut to `ticks` ticks: 20 × ticks robot-ticks kept.
Mission short_aac(int ticks) {
  Mission mission = load_mission("aac");
  mission.ticks = ticks;
  return mission;
}

/// Starts a run and waits for it to finish (only finished runs are ever forgotten).
std::int64_t run_to_end(RunRegistry& runs, std::int64_t owner, int ticks = 50) {
  const std::int64_t id = runs.start(owner, short_aac(ticks), parse_control_software(kFsm), kFsm, 1);
  const auto run = runs.get(owner, id);
  while (!run->finished()) std::this_thread::sleep_for(std::chrono::milliseconds(2));
  return id;
}

bool kept(const RunRegistry& runs, std::int64_t owner, std::int64_t id) {
  try {
    runs.get(owner, id);
    return true;
  } catch (const app::NotFound&) {
    return false;
  }
}

TEST(RunRegistry, EachUserNumbersTheirOwnRunsAndSeesNoOneElses) {
  RunRegistry runs;
  EXPECT_EQ(run_to_end(runs, 1), 1);
  EXPECT_EQ(run_to_end(runs, 1), 2);
  EXPECT_EQ(run_to_end(runs, 2), 1) << "another user's ids tell nothing of user 1's work";
  EXPECT_NE(runs.get(1, 1), runs.get(2, 1));
  EXPECT_THROW(runs.get(2, 2), app::NotFound);
  EXPECT_THROW(runs.get(3, 1), app::NotFound);
}

TEST(RunRegistry, AUsersManyRunsForgetOnlyTheirOwnOldest) {
  // About 1000 robot-ticks a run: 3 kept per user by count, 5 500 robot-ticks for the server.
  RunRegistry runs(RunRegistry::KeptLimits{3, 100'000, 5'500});
  const std::int64_t light = run_to_end(runs, 2);
  for (int i = 0; i < 10; ++i) run_to_end(runs, 1);
  EXPECT_TRUE(kept(runs, 2, light)) << "user 1's runs pushed out user 2's";
  EXPECT_FALSE(kept(runs, 1, 7));
  for (std::int64_t id = 8; id <= 10; ++id) EXPECT_TRUE(kept(runs, 1, id)) << id;

  // The server full (3 + 1 + 1 runs, a sixth does not fit): a new run of user 3 forgets from user 1, who
  // keeps the most, not from user 2.
  run_to_end(runs, 3);
  run_to_end(runs, 3);
  EXPECT_TRUE(kept(runs, 2, light));
  EXPECT_FALSE(kept(runs, 1, 8));
  EXPECT_TRUE(kept(runs, 1, 9));
  EXPECT_TRUE(kept(runs, 3, 1));
  EXPECT_TRUE(kept(runs, 3, 2));
}

}  // namespace
}  // namespace sd::web
