#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include <cmath>

#include "design/checkpoint_store.hpp"
#include "design/iterated_race.hpp"
#include "design/state.hpp"

using namespace sd::design;

namespace {

ParameterSpace small_space() {
  ParameterSpace s(2);
  s.add({"C", "--c ", ParamType::Categorical, {"a", "b", "c"}, {}, {}, false, {}});
  s.add({"R", "--r ", ParamType::Real, {}, Bound::fixed(0), Bound::fixed(10), false, {}});
  s.finalize();
  return s;
}

double noisy_cost(const Experiment& e) {
  const auto& v = e.configuration->values;
  sd::Rng noise(e.seed);
  return (v[0] == 1 ? 0.0 : 1.0) + std::pow((v[1] - 3) / 10, 2) + 0.05 * noise.normal();
}

IraceOptions options() {
  IraceOptions o;
  o.max_experiments = 600;
  o.seed = 4;
  return o;
}

/// Runs a race that saves every checkpoint into `store`, for at most `steps` steps.
void run_saving(const ParameterSpace& space, CheckpointStore& store, std::optional<int> steps) {
  ThreadedRunner runner(noisy_cost, 1);
  IteratedRace race(space, options(), runner);
  if (auto state = store.load()) race.restore(std::move(*state));
  EliminationTracker eliminations;
  eliminations.reset(race.state());
  race.on_progress([&](const Progress&) { eliminations.observe(race.state()); });
  race.on_checkpoint([&](const Checkpoint& c) { store.save(c, eliminations.take()); });
  for (int step = 0; race.advance();)
    if (steps && ++step == *steps) return;
}

}  // namespace

TEST(design_CheckpointStore, AnEmptyStoreHasNoStateAndNoStep) {
  MemoryCheckpointStore store;
  EXPECT_FALSE(store.load().has_value());
  EXPECT_EQ(store.step(), 0);
}

TEST(design_CheckpointStore, ADesignStoppedAnywhereResumesFromItsStoreToTheUninterruptedResult) {
  const ParameterSpace space = small_space();
  MemoryCheckpointStore uninterrupted;
  run_saving(space, uninterrupted, std::nullopt);
  const std::string expected = state_to_json(*uninterrupted.load()).dump();
  ASSERT_GT(uninterrupted.step(), 10);
  for (const int stop_after : {1, 5, 17}) {
    MemoryCheckpointStore store;
    run_saving(space, store, stop_after);
    EXPECT_LT(store.step(), uninterrupted.step()) << stop_after;
    run_saving(space, store, std::nullopt);  // a new process: everything from the store
    EXPECT_EQ(state_to_json(*store.load()).dump(), expected) << "stopped after " << stop_after;
    // The race log is whole as well: every elimination once, in the same order.
    ASSERT_EQ(store.eliminations().size(), uninterrupted.eliminations().size()) << stop_after;
    for (std::size_t i = 0; i < store.eliminations().size(); ++i)
      EXPECT_EQ(store.eliminations()[i].configuration_id, uninterrupted.eliminations()[i].configuration_id);
  }
}
