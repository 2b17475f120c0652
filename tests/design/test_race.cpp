#include <gtest/gtest.h>

#include <cmath>
#include <map>
#include <set>

#include "design/race.hpp"

using namespace sd::design;

namespace {

ParameterSpace one_real() {
  ParameterSpace s(2);
  s.add({"X", "--x ", ParamType::Real, {}, Bound::fixed(0), Bound::fixed(100), false, {}});
  s.finalize();
  return s;
}

// Cost = mean of the configuration (its X value) + unit noise that depends on the seed only
// (common random numbers) and on the configuration.
double noisy_cost(const Experiment& e) {
  sd::Rng rng(e.seed * 7919 + static_cast<std::uint64_t>(e.configuration_id));
  return e.configuration->values[0] + rng.normal();
}

}  // namespace

TEST(design_Race, KeepsTheBestOfConfigurationsWithKnownMeans) {
  const ParameterSpace s = one_real();
  ConfigurationStore store;
  std::vector<int> ids;
  for (int i = 0; i < 10; ++i) ids.push_back(store.add(s.parse("--x " + std::to_string(0.8 * i)), 0));
  InstanceList instances(1, 99, true);
  instances.append(200);
  ThreadedRunner runner(noisy_cost, 1);
  RaceSettings settings;
  settings.min_survival = 2;
  settings.max_experiments = 300;
  sd::Rng rng(1);
  RaceState state = start_race(settings, ids, 0, 0, 0, instances.size(), true, {}, rng);
  std::set<std::size_t> positions;
  RaceEnvironment env{store, instances, runner, [&](std::size_t p, int, double) { positions.insert(p); }};
  std::size_t steps = 0;
  while (!state.finished) {
    race_step(state, settings, env);
    ++steps;
    if (state.next_task - 1 < 5) {
      EXPECT_EQ(state.nb_alive(), 10u) << "no test before firstTest instances";
    }
  }
  const RaceResult r = finish_race(state);
  EXPECT_LE(r.experiments_used, 300);
  EXPECT_EQ(r.ids.front(), ids.front()) << state.stop_reason;
  EXPECT_TRUE(r.alive.front());
  EXPECT_LT(r.nb_alive, 10u);
  // The worst configuration is eliminated, and eliminated ones rank after the survivors.
  const auto worst = std::find(r.ids.begin(), r.ids.end(), ids.back()) - r.ids.begin();
  EXPECT_FALSE(r.alive[static_cast<std::size_t>(worst)]);
  EXPECT_TRUE(std::isinf(r.ranks.back()));
  // The first race walks through the instance list in order.
  EXPECT_EQ(*positions.rbegin(), positions.size());
}

TEST(design_Race, EliteIsProtectedUntilItHasSeenItsOldInstances) {
  const ParameterSpace s = one_real();
  ConfigurationStore store;
  std::vector<int> ids;
  ids.push_back(store.add(s.parse("--x 10"), 0));  // the elite: clearly worst
  for (int i = 0; i < 7; ++i) ids.push_back(store.add(s.parse("--x " + std::to_string(0.1 * i)), 0));
  InstanceList instances(1, 5, true);
  instances.append(100);
  // The elite's results on the 6 old positions.
  std::map<std::size_t, double> elite_old;
  for (std::size_t p = 1; p <= 6; ++p) elite_old[p] = 10.0 + 0.01 * static_cast<double>(p);
  const ResultLookup lookup = [&](std::size_t p, int id) {
    return id == ids[0] && elite_old.count(p) ? elite_old[p] : std::nan("");
  };
  std::vector<std::pair<std::size_t, int>> runs;
  ThreadedRunner runner(noisy_cost, 2);
  RaceSettings settings;
  settings.min_survival = 2;
  settings.max_experiments = 400;
  sd::Rng rng(3);
  RaceState state = start_race(settings, ids, 1, 6, 1, instances.size(), true, lookup, rng);
  EXPECT_EQ(state.position_of(1), 7u);  // the new instance first
  std::set<std::size_t> old_order;
  for (std::size_t t = 2; t <= 7; ++t) old_order.insert(state.position_of(t));
  EXPECT_EQ(old_order, (std::set<std::size_t>{1, 2, 3, 4, 5, 6}));
  EXPECT_EQ(state.is_elite[0], 6);
  RaceEnvironment env{store, instances, runner, [&](std::size_t p, int id, double) { runs.push_back({p, id}); }};
  bool dropped = false;
  while (!state.finished) {
    race_step(state, settings, env);
    if (state.is_elite[0] > 0) {
      EXPECT_TRUE(state.alive[0]) << "elite dropped while protected";
    }
    if (!state.alive[0]) dropped = true;
  }
  EXPECT_TRUE(dropped);
  for (const auto& [p, id] : runs)
    if (id == ids[0]) {
      EXPECT_GT(p, 6u) << "elite re-run on an old instance";
    }
}

TEST(design_Race, ImmediateRejectionOnInfiniteCost) {
  const ParameterSpace s = one_real();
  ConfigurationStore store;
  std::vector<int> ids;
  for (int i = 0; i < 6; ++i) ids.push_back(store.add(s.parse("--x " + std::to_string(i)), 0));
  InstanceList instances(1, 1, true);
  instances.append(50);
  ThreadedRunner runner([&](const Experiment& e) { return e.configuration_id == ids[2] ? INFINITY : noisy_cost(e); }, 1);
  RaceSettings settings;
  settings.min_survival = 2;
  settings.max_experiments = 200;
  sd::Rng rng(1);
  RaceState state = start_race(settings, ids, 0, 0, 0, instances.size(), true, {}, rng);
  RaceEnvironment env{store, instances, runner, {}};
  race_step(state, settings, env);
  EXPECT_FALSE(state.alive[2]);
  while (!state.finished) race_step(state, settings, env);
  EXPECT_EQ(finish_race(state).rejected_ids, (std::vector<int>{ids[2]}));
}

TEST(design_Race, OverallRanksPreferMoreInstances) {
  const double na = std::nan("");
  // Column 2 has the lowest costs but only 3 results: it ranks after columns 0 and 1.
  const std::vector<std::vector<double>> results{{5, 4, 0}, {5, 4, 0}, {3, 4, 0}, {5, 4, na}, {5, 4, na}};
  const auto r = overall_ranks(results, {0, 1, 2});
  EXPECT_EQ(r, (std::vector<double>{9, 6, 10}));  // rank sums 9 and 6, then 6 + 1 + ... = max + 1
}

TEST(design_Race, ExtractElitesDropsDuplicatesAndWeightsByRank) {
  const ParameterSpace s = one_real();
  ConfigurationStore store;
  store.add(s.parse("--x 1"), 0);
  store.add(s.parse("--x 2"), 0);
  store.add(s.parse("--x 1"), 0);  // twin of 1
  store.add(s.parse("--x 3"), 0);
  RaceResult rr;
  rr.ids = {3, 2, 1, 4};
  rr.ranks = {5, 6, 7, INFINITY};
  rr.alive = {1, 1, 1, 0};
  rr.nb_alive = 3;
  const auto elites = extract_elites(rr, store, 5);
  ASSERT_EQ(elites.size(), 2u);
  EXPECT_EQ(elites[0].id, 2);  // 3 is a duplicate of 1 (lower id kept), so 2 ranks first
  EXPECT_EQ(elites[1].id, 1);
  EXPECT_DOUBLE_EQ(elites[0].weight, 2.0 / 3.0);
  EXPECT_DOUBLE_EQ(elites[1].weight, 1.0 / 3.0);
}
