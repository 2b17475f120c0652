#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include <atomic>
#include <cmath>
#include <set>
#include <string>

#include "design/fsm_space.hpp"
#include "design/iterated_race.hpp"
#include "refusal.hpp"
#include "synthetic_objective.hpp"

using namespace sd::design;
using sd::design::fixtures::synthetic_cost;
using sd::design::fixtures::synthetic_space;

namespace {


IraceOptions options(long long budget, std::uint64_t seed) {
  IraceOptions o;
  o.max_experiments = budget;
  o.seed = seed;
  return o;
}

// Counts evaluations, to check that a resumed design never re-evaluates.
struct CountingRunner final : ExperimentRunner {
  std::size_t evaluated = 0;
  ThreadedRunner inner{synthetic_cost, 1};
  void run(std::span<const Experiment> ex, std::span<double> costs) override {
    evaluated += ex.size();
    inner.run(ex, costs);
  }
};

}  // namespace

TEST(design_IteratedRace, BudgetFormulasMatchIrace) {
  EXPECT_EQ(default_nb_iterations(1), 2);
  EXPECT_EQ(default_nb_iterations(11), 5);
  EXPECT_EQ(default_nb_iterations(101), 8);
  EXPECT_EQ(default_nb_iterations(133), 9);
  // irace 3.5's ACOTSP example output (vignettes/irace-acotsp-stdout.txt, budget 1000):
  // N_1 = floor(200 / 6) = 33;
  // N_2 = floor((208 + 4 elites x 5 old instances) / max(5 + 2, 5 + 1)) = 32.
  EXPECT_EQ(nb_configurations_for(200, 1, 5, 1, 0, 0, 0), 33);
  EXPECT_EQ(nb_configurations_for(208, 2, 5, 1, 4, 5, 1), 32);
  // The 1024 cap (B_1 = 22222 for an AutoMoDe-sized space: budget 200 000, 9 iterations).
  EXPECT_EQ(nb_configurations_for(22222, 1, 5, 1, 0, 0, 0), 1024);
  // Elitist saving when old instances dominate: n_j = round_to_multiple(n_old + T_new).
  EXPECT_EQ(nb_configurations_for(100, 2, 5, 1, 3, 20, 1), (100 + 60) / 21);
  IraceOptions o;
  EXPECT_EQ(minimum_budget(o, 9, 9), 1350);  // irace's computeMinimumBudget: (9 + 1) x 9 x 15
  o.elitist = false;
  EXPECT_EQ(minimum_budget(o, 5, 5), 6 * 5 * 10);
}

TEST(design_IteratedRace, FirstIterationScheduleMatchesIrace) {
  // irace 3.5 on the same 5-parameter space with maxExperiments = 3000 printed:
  // nbIterations 4, minNbSurvival 4, "Iteration 1 of 4", currentBudget 750, nbConfigurations 125.
  const ParameterSpace s = synthetic_space();
  ThreadedRunner runner(synthetic_cost, 1);
  IteratedRace design(s, options(3000, 1), runner);
  design.advance();
  const DesignState& st = design.state();
  EXPECT_EQ(st.nb_iterations, 4);
  EXPECT_EQ(st.min_survival, 4);
  EXPECT_EQ(st.current_budget, 750);
  EXPECT_EQ(st.nb_configurations, 125);
  ASSERT_TRUE(st.race);
  EXPECT_EQ(st.race->config_ids.size(), 125u);
  EXPECT_EQ(st.instances.size(), 750u);  // ceil(3000 / minSurvival) positions
}

TEST(design_IteratedRace, TheFingerprintWithoutAnEngineIsTheEnginesOwn) {
  // Design folders store the engine-free fingerprint and checkpoints the engine's: both must be
  // taken of the options as the engine runs them (mu raised to firstTest, the soft-restart
  // threshold filled in), or a design would refuse to resume.
  const ParameterSpace s = synthetic_space();
  ThreadedRunner runner(synthetic_cost, 1);
  IraceOptions o = options(3000, 1);
  o.mu = 2;  // below firstTest: raised by the engine
  EXPECT_EQ(fingerprint(s, o), IteratedRace(s, o, runner).fingerprint());
  IraceOptions other = o;
  other.seed = 2;
  EXPECT_NE(fingerprint(s, other), fingerprint(s, o));
}

TEST(design_IteratedRace, RejectsAnInsufficientBudget) {
  const ParameterSpace s = synthetic_space();
  ThreadedRunner runner(synthetic_cost, 1);
  IteratedRace design(s, options(100, 1), runner);  // N_iter 4, minSurv 4 -> needs 180
  EXPECT_THROW(design.run(), std::invalid_argument);
}

TEST(design_IteratedRace, FindsTheOptimumOfASyntheticObjective) {
  const ParameterSpace s = synthetic_space();
  ThreadedRunner runner(synthetic_cost, 2);
  IteratedRace design(s, options(3000, 1), runner);
  int last_iteration = 0;
  long long last_used = 0;
  design.on_progress([&](const Progress& p) {
    EXPECT_GE(p.iteration, last_iteration);
    EXPECT_GE(p.experiments_used, last_used);
    EXPECT_LE(p.experiments_used, p.budget);
    EXPECT_GE(p.alive, 1u);
    last_iteration = p.iteration;
    last_used = p.experiments_used;
  });
  const DesignResult r = design.run();
  ASSERT_FALSE(r.elites.empty());
  EXPECT_LE(r.experiments_used, 3000);
  EXPECT_GT(r.experiments_used, 2500);  // the budget is (nearly) spent
  EXPECT_GE(r.iterations, 4);
  const auto& best = r.elites.front().configuration.values;
  EXPECT_EQ(best[0], 2) << s.render(r.elites.front().configuration);
  EXPECT_NEAR(best[1], 42, 10);
  EXPECT_NEAR(best[2], 7.5, 1.2);
  EXPECT_NEAR(best[3], 3, 1);
  EXPECT_NEAR(best[4], 0.3, 0.2);
  EXPECT_LT(r.elites.front().mean_cost, 0.1);
  // Elites are distinct configurations, best first.
  for (std::size_t a = 0; a < r.elites.size(); ++a)
    for (std::size_t b = a + 1; b < r.elites.size(); ++b) EXPECT_FALSE(r.elites[a].configuration == r.elites[b].configuration);
}

TEST(design_IteratedRace, ResultDoesNotDependOnTheThreadCount) {
  const ParameterSpace space = build_fsm_space(chocolate_fsm_modules());
  // A cheap stand-in for a mission: prefer 3 states, attraction in state 0, and p close to 0.7.
  auto cost = [&](const Experiment& e) {
    const auto& v = e.configuration->values;
    double c = std::fabs(v[*space.index_of("NumStates")] - 3);
    c += space.value_text(*e.configuration, *space.index_of("S0")) == "14" ? 0 : 1;
    const double p = v[*space.index_of("P0x0")];
    c += std::isnan(p) ? 0.5 : std::fabs(p - 0.7);
    sd::Rng noise(e.seed + static_cast<std::uint64_t>(e.configuration_id));
    return c + 0.3 * noise.normal();
  };
  auto run_with = [&](unsigned threads) {
    ThreadedRunner runner(cost, threads);
    IteratedRace design(space, options(1500, 42), runner);
    design.run();
    return design.state();
  };
  const DesignState one = run_with(1);
  const DesignState two = run_with(2);
  ASSERT_EQ(one.experiments.size(), two.experiments.size());
  for (std::size_t i = 0; i < one.experiments.size(); ++i) {
    ASSERT_EQ(one.experiments[i].configuration_id, two.experiments[i].configuration_id);
    ASSERT_EQ(one.experiments[i].position, two.experiments[i].position);
    ASSERT_EQ(one.experiments[i].cost, two.experiments[i].cost);
  }
  ASSERT_EQ(one.elites.size(), two.elites.size());
  for (std::size_t i = 0; i < one.elites.size(); ++i) {
    EXPECT_EQ(one.elites[i].id, two.elites[i].id);
    EXPECT_EQ(space.render(one.configurations[one.elites[i].id].config),
              space.render(two.configurations[two.elites[i].id].config));
  }
  EXPECT_EQ(state_to_json(one).dump(), state_to_json(two).dump());
}

TEST(design_IteratedRace, ResumingFromAnyCheckpointGivesTheSameResult) {
  const ParameterSpace s = synthetic_space();
  std::vector<nlohmann::json> checkpoints;
  std::vector<std::size_t> evaluated_at, ahead_at;
  CountingRunner full_runner;
  IteratedRace full(s, options(1200, 9), full_runner);
  std::size_t configurations_seen = 0, experiments_seen = 0;
  full.on_checkpoint([&](const Checkpoint& c) {
    // The new-record indices tile the history without gaps or overlaps.
    EXPECT_EQ(c.first_new_configuration, configurations_seen);
    EXPECT_EQ(c.first_new_experiment, experiments_seen);
    configurations_seen = c.state.configurations.size();
    experiments_seen = c.state.experiments.size();
    checkpoints.push_back(state_to_json(c.state, checkpoints.size() % 2 == 0));
    evaluated_at.push_back(full_runner.evaluated);
    ahead_at.push_back(c.state.race ? c.state.race->ahead.size() : 0);
  });
  const DesignResult expected = full.run();
  const std::string expected_state = state_to_json(full.state()).dump();
  ASSERT_GT(checkpoints.size(), 20u);
  const std::size_t n = checkpoints.size();
  for (std::size_t k : {std::size_t{0}, std::size_t{1}, std::size_t{2}, std::size_t{7}, n / 3, n / 2 + 1, n - 2}) {
    // Odd checkpoints were written without history: hand it over separately, as a database
    // that stores the new records of every checkpoint would.
    std::optional<History> history;
    if (k % 2 == 1) {
      history.emplace();
      const auto& all = full.state().configurations.all();
      const auto& log = full.state().experiments;
      history->configurations.assign(all.begin(), all.begin() + checkpoints[k]["configuration_count"].get<std::ptrdiff_t>());
      history->experiments.assign(log.begin(), log.begin() + checkpoints[k]["experiment_count"].get<std::ptrdiff_t>());
    }
    DesignState restored = state_from_json(nlohmann::json::parse(checkpoints[k].dump()), history);
    CountingRunner runner;
    IteratedRace resumed(s, options(1200, 9), runner);
    resumed.restore(std::move(restored));
    const DesignResult r = resumed.run();
    // Only the runs made ahead of their step (before a race's first test) are made again.
    EXPECT_EQ(runner.evaluated + evaluated_at[k], full_runner.evaluated + ahead_at[k]) << "checkpoint " << k;
    ASSERT_EQ(r.elites.size(), expected.elites.size()) << "checkpoint " << k;
    for (std::size_t i = 0; i < r.elites.size(); ++i) EXPECT_EQ(r.elites[i].id, expected.elites[i].id);
    EXPECT_EQ(state_to_json(resumed.state()).dump(), expected_state) << "checkpoint " << k;
  }
}

TEST(design_IteratedRace, RunsUpToTheFirstTestGoOutAsOneBatchWithTheSameResult) {
  // A runner that records the size of every batch it is given.
  struct BatchSizes final : ExperimentRunner {
    std::vector<std::size_t> sizes;
    void run(std::span<const Experiment> experiments, std::span<double> costs) override {
      sizes.push_back(experiments.size());
      for (std::size_t i = 0; i < experiments.size(); ++i) costs[i] = synthetic_cost(experiments[i]);
    }
  };
  const ParameterSpace s = synthetic_space();
  BatchSizes runner;
  IteratedRace race(s, options(1200, 9), runner);
  std::size_t first_race_width = 0;
  race.on_progress([&](const Progress& p) {
    if (first_race_width == 0) first_race_width = static_cast<std::size_t>(p.race_configurations);
  });
  const DesignResult r = race.run();
  ASSERT_FALSE(runner.sizes.empty());
  // The first race's first batch holds every configuration on each instance up to the first
  // test (irace's firstTest, 5 here); its next four steps need no run of their own.
  EXPECT_EQ(runner.sizes.front(), first_race_width * 5);
  ThreadedRunner plain(synthetic_cost, 1);
  IteratedRace same(s, options(1200, 9), plain);
  const DesignResult expected = same.run();
  ASSERT_EQ(r.elites.size(), expected.elites.size());
  for (std::size_t i = 0; i < r.elites.size(); ++i) EXPECT_EQ(r.elites[i].id, expected.elites[i].id);
  EXPECT_EQ(state_to_json(race.state()).dump(), state_to_json(same.state()).dump());
}

TEST(design_IteratedRace, WorkersThatANarrowStepWouldLeaveIdleTakeTheNextInstancesWithTheSameResult) {
  // A runner with many workers: narrow steps after the first test are filled with the same
  // configurations' runs on the next instances.
  struct Wide final : ExperimentRunner {
    std::size_t workers = 1, runs = 0;
    std::vector<std::size_t> sizes;
    void run(std::span<const Experiment> experiments, std::span<double> costs) override {
      sizes.push_back(experiments.size());
      runs += experiments.size();
      for (std::size_t i = 0; i < experiments.size(); ++i) costs[i] = synthetic_cost(experiments[i]);
    }
    std::size_t parallelism() const override { return workers; }
  };
  const ParameterSpace s = synthetic_space();
  Wide one, many;
  many.workers = 64;
  IteratedRace narrow(s, options(1200, 9), one);
  IteratedRace wide(s, options(1200, 9), many);
  narrow.run();
  wide.run();
  EXPECT_EQ(state_to_json(wide.state()).dump(), state_to_json(narrow.state()).dump());
  // Fewer, wider batches; some runs made ahead were never asked for (their configuration was
  // eliminated first), which costs idle workers only.
  EXPECT_LT(many.sizes.size(), one.sizes.size());
  EXPECT_GE(many.runs, one.runs);
}

TEST(design_IteratedRace, RefusesAForeignCheckpoint) {
  const ParameterSpace s = synthetic_space();
  ThreadedRunner runner(synthetic_cost, 1);
  IteratedRace a(s, options(600, 1), runner);
  a.advance();
  IteratedRace b(s, options(600, 2), runner);  // other seed
  EXPECT_THROW(b.restore(a.state()), std::runtime_error);
  nlohmann::json broken = state_to_json(a.state());
  broken.erase("model");
  EXPECT_THROW(state_from_json(broken), std::runtime_error);
  EXPECT_THROW(state_from_json(nlohmann::json{{"hello", 1}}), std::runtime_error);
  // A history that does not match the state is refused.
  EXPECT_THROW(state_from_json(state_to_json(a.state(), false), History{}), std::runtime_error);
}

// A damaged state is refused in one line naming the field; nlohmann's own conversion of 1e300
// or 2^40 to int would be undefined behaviour or wrap to another number.
TEST(design_IteratedRace, RefusesIntegersOutOfRangeInACheckpoint) {
  const ParameterSpace s = synthetic_space();
  ThreadedRunner runner(synthetic_cost, 1);
  IteratedRace a(s, options(600, 1), runner);
  a.advance();
  const nlohmann::json good = state_to_json(a.state());
  ASSERT_NO_THROW(state_from_json(good));
  const auto refusal = [](const nlohmann::json& state) {
    return sd::test::refusal_of<std::runtime_error>([&] { return state_from_json(state); });
  };
  nlohmann::json huge = good;
  huge["iteration"] = 1e300;
  EXPECT_EQ(refusal(huge), "design state: iteration is not an integer in range");
  nlohmann::json wraps = good;
  wraps["nb_iterations"] = std::int64_t{1} << 40;
  EXPECT_EQ(refusal(wraps), "design state: nb_iterations is not an integer in range");
  nlohmann::json negative_list = good;
  negative_list["all_elites"] = nlohmann::json::array({nlohmann::json::array({-1e200})});
  EXPECT_EQ(refusal(negative_list), "design state: all_elites[][] is not an integer in range");
  nlohmann::json seed = good;
  seed["rng"]["s"][2] = -5;
  EXPECT_EQ(refusal(seed), "design state: rng.s is not an integer in range");
}

TEST(design_IteratedRace, InitialConfigurationsAreRacedFirst) {
  const ParameterSpace s = synthetic_space();
  ThreadedRunner runner(synthetic_cost, 1);
  IraceOptions o = options(600, 3);
  o.initial_configurations = {s.parse("--c c --i 42 --r 7.5 --o o4 --q 0.3")};
  IteratedRace design(s, o, runner);
  const DesignResult r = design.run();
  EXPECT_EQ(design.state().configurations[1].config, o.initial_configurations[0]);
  EXPECT_EQ(design.state().all_elites.front().front(), 1);  // the optimum wins the first race
  EXPECT_EQ(r.elites.front().configuration.values[0], 2);
}

TEST(design_IteratedRace, TwinsTriggerTheSoftRestartButAreNotRaced) {
  // 4 x 10 = 40 distinct configurations: sampling a few dozen from a peaked model gives twins
  // (irace's similarConfigurations then triggers a soft restart), yet there are enough distinct
  // configurations for the redraw of twins (unique_new_configurations) to avoid all of them.
  // The soft restart must still happen, as in irace; the race of iteration 2 must still hold no
  // twin (later, with a peaked model, the redraw may give up after 50 tries and keep one).
  ParameterSpace s(2);
  s.add({"C", "--c ", ParamType::Categorical, {"a", "b", "c", "d"}, {}, {}, false, {}});
  s.add({"I", "--i ", ParamType::Integer, {}, Bound::fixed(1), Bound::fixed(10), false, {}});
  s.finalize();
  const auto cost = [](const Experiment& e) {
    const auto& v = e.configuration->values;
    sd::Rng noise(e.seed);
    return (v[0] == 1 ? 0.0 : 1.0) + std::pow((v[1] - 7) / 9, 2) + 0.05 * noise.normal();
  };
  ThreadedRunner runner(cost, 1);
  IteratedRace design(s, options(400, 4), runner);
  int last_checked = 0;
  while (design.advance()) {
    const DesignState& st = design.state();
    if (!st.race || st.iteration == last_checked || st.iteration != 2) continue;
    last_checked = st.iteration;
    std::set<std::string> keys;
    for (int id : st.race->config_ids) EXPECT_TRUE(keys.insert(st.configurations[id].config.key()).second) << id;
  }
  const DesignState& st = design.state();
  ASSERT_GE(st.soft_restarts.size(), 2u);
  EXPECT_EQ(st.soft_restarts[1], 1);  // iteration 2
}
