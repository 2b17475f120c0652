// EvoStick's generational algorithm (src/evostick/evolution.hpp). A scripted evaluator that
// scores a network by a function of its weights makes the algorithm's rules visible (shared
// seeds, elitism, bounds, budget); real simulations show it improves a cheap objective and
// that the thread count never changes a result.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <functional>
#include <map>
#include <set>

#include "evostick/evolution.hpp"
#include "evostick/module_training.hpp"
#include "missions/catalogue.hpp"

namespace sd {
namespace {

using evostick::Settings;

/// score = -sum (w - target)^2, plus `noise` times a value drawn from the task's seed; it
/// records every task it was given.
class ScriptedEvaluator : public Evaluator {
 public:
  explicit ScriptedEvaluator(double target, double noise = 0.0) : target_(target), noise_(noise) {}
  int workers() const override { return 1; }
  void evaluate(const Mission&, std::span<const EvaluationTask> tasks, std::span<double> scores) override {
    batches.emplace_back();
    for (std::size_t i = 0; i < tasks.size(); ++i) {
      const auto& w = tasks[i].software->network.weights;
      EXPECT_EQ(tasks[i].software->architecture, Architecture::NeuralNetwork);
      double s = 0.0;
      for (const double v : w) s -= (v - target_) * (v - target_);
      Rng rng(tasks[i].seed);
      scores[i] = s + noise_ * rng.uniform();
      batches.back().push_back({w, tasks[i].seed});
    }
  }
  struct Seen {
    arlequin::Weights weights;
    std::uint64_t seed;
  };
  std::vector<std::vector<Seen>> batches;  // one per generation

 private:
  double target_, noise_;
};

Settings small(int generations, std::uint64_t seed = 1) {
  Settings s;
  s.population = 12;
  s.evaluations = 3;
  s.elites = 3;
  s.mutation_sigma = 0.5;
  s.generations = generations;
  s.seed = seed;
  return s;
}

TEST(EvoStick, EveryNetworkOfAGenerationRunsOnTheSameFreshSeeds) {
  ScriptedEvaluator evaluator(0.0);
  const Settings s = small(4);
  const auto result = evostick::evolve(Mission{}, Direction::Maximize, evaluator, s);
  ASSERT_EQ(evaluator.batches.size(), 4u);
  EXPECT_EQ(result.runs, 4 * 12 * 3);
  EXPECT_EQ(result.runs, s.runs());
  std::set<std::uint64_t> all_seeds;
  for (const auto& batch : evaluator.batches) {
    ASSERT_EQ(batch.size(), 36u);
    for (std::size_t p = 0; p < 12; ++p)
      for (std::size_t e = 0; e < 3; ++e) {
        EXPECT_EQ(batch[p * 3 + e].seed, batch[e].seed) << "network " << p << " run " << e;
        EXPECT_EQ(batch[p * 3 + e].weights, batch[p * 3].weights) << "a network's runs are consecutive tasks";
      }
    for (std::size_t e = 0; e < 3; ++e) all_seeds.insert(batch[e].seed);
  }
  EXPECT_EQ(all_seeds.size(), 12u) << "every generation draws new seeds";
}

TEST(EvoStick, GenerationOneIsTheSilentNetworkAndMutantsOfIt) {
  ScriptedEvaluator evaluator(0.0);
  Settings s = small(1);
  s.population = 200;
  evostick::evolve(Mission{}, Direction::Maximize, evaluator, s);
  const auto& batch = evaluator.batches.front();
  EXPECT_EQ(batch.front().weights, arlequin::Weights{}) << "network 0 is the silent network";
  int mutated = 0, weights = 0;
  for (std::size_t p = 1; p < 200; ++p) {
    const auto& w = batch[p * 3].weights;
    EXPECT_NE(w, arlequin::Weights{}) << p;
    for (const double v : w) {
      mutated += v != 0.0;
      ++weights;
      EXPECT_LE(std::abs(v), 5.0);
    }
  }
  // Each weight gets noise with probability 0.3: 199 x 50 draws, 5 standard deviations.
  const double p = s.mutation_probability, n = weights;
  EXPECT_NEAR(mutated, n * p, 5.0 * std::sqrt(n * p * (1.0 - p)));
}

TEST(EvoStick, ElitesSurviveUnchangedAndChildrenAreMutatedElites) {
  ScriptedEvaluator evaluator(1.0);
  const Settings s = small(6);
  const auto result = evostick::evolve(Mission{}, Direction::Maximize, evaluator, s);
  for (std::size_t g = 0; g + 1 < evaluator.batches.size(); ++g) {
    // Rank generation g by its scores (deterministic here), as the algorithm must have.
    std::vector<std::pair<double, arlequin::Weights>> ranked;
    for (std::size_t p = 0; p < 12; ++p) {
      const auto& w = evaluator.batches[g][p * 3].weights;
      double score = 0.0;
      for (const double v : w) score -= (v - 1.0) * (v - 1.0);
      ranked.push_back({score, w});
    }
    std::stable_sort(ranked.begin(), ranked.end(), [](const auto& a, const auto& b) { return a.first > b.first; });
    const auto& next = evaluator.batches[g + 1];
    for (std::size_t k = 0; k < 3; ++k) EXPECT_EQ(next[k * 3].weights, ranked[k].second) << "elite " << k;
    for (std::size_t p = 3; p < 12; ++p) {
      // A child differs from every elite, but stays within a few sigma of one of them.
      double closest = 1e300;
      for (std::size_t k = 0; k < 3; ++k) {
        double d2 = 0.0;
        for (std::size_t i = 0; i < 50; ++i) d2 += std::pow(next[p * 3].weights[i] - ranked[k].second[i], 2);
        closest = std::min(closest, d2);
      }
      EXPECT_GT(closest, 0.0);
      EXPECT_LT(std::sqrt(closest / 50.0), 4.0 * s.mutation_sigma) << "generation " << g + 2 << " child " << p;
    }
  }
  // Without noise, keeping the elites means the best never gets worse.
  for (std::size_t g = 1; g < result.history.size(); ++g)
    EXPECT_GE(result.history[g].best_mean, result.history[g - 1].best_mean);
}

TEST(EvoStick, ImprovesAScriptedObjectiveAndKeepsWeightsInBounds) {
  ScriptedEvaluator evaluator(7.0);  // beyond the bound: the best a network can do is all 5
  const Settings s = small(300);
  const auto result = evostick::evolve(Mission{}, Direction::Maximize, evaluator, s);
  for (const auto& batch : evaluator.batches)
    for (const auto& seen : batch)
      for (const double w : seen.weights) {
        ASSERT_GE(w, -5.0);
        ASSERT_LE(w, 5.0);
      }
  EXPECT_GT(result.history.back().best_mean, result.history.front().best_mean + 1000.0);
  EXPECT_GT(result.history.back().population_mean, result.history.front().population_mean);
  int at_bound = 0;
  for (const double w : result.best) {
    EXPECT_GT(w, 3.0) << "every weight has moved most of the way from the silent start to the bound";
    at_bound += w == 5.0;
  }
  EXPECT_GT(at_bound, 0) << "noise that crosses the bound is clipped to it, exactly";
  EXPECT_EQ(result.best_mean, result.history.back().best_mean);
  EXPECT_EQ(evostick::weight_digest(result.best), result.history.back().best_digest);
}

TEST(EvoStick, MinimisingRanksTheOtherWay) {
  // Score -sum (w - 1)^2: maximising pulls the weights towards 1, minimising pushes them away.
  ScriptedEvaluator up(1.0), down(1.0);
  const auto max = evostick::evolve(Mission{}, Direction::Maximize, up, small(15));
  const auto min = evostick::evolve(Mission{}, Direction::Minimize, down, small(15));
  EXPECT_GT(max.best_mean, max.history.front().best_mean);
  EXPECT_LT(min.best_mean, min.history.front().best_mean);
  EXPECT_GT(max.best_mean, -50.0) << "better than the silent network";
  EXPECT_LT(min.best_mean, -50.0) << "worse than the silent network";
}

TEST(EvoStick, SameSeedSameNetworkOtherSeedOtherNetwork) {
  ScriptedEvaluator a(0.5, 3.0), b(0.5, 3.0), c(0.5, 3.0);
  const auto x = evostick::evolve(Mission{}, Direction::Maximize, a, small(5, 11));
  const auto y = evostick::evolve(Mission{}, Direction::Maximize, b, small(5, 11));
  const auto z = evostick::evolve(Mission{}, Direction::Maximize, c, small(5, 12));
  EXPECT_EQ(x.best, y.best);
  EXPECT_EQ(x.history, y.history);
  EXPECT_NE(x.best, z.best);
}

TEST(EvoStick, AnEvolutionResumedFromAnyGenerationEndsAsTheUninterruptedOne) {
  ScriptedEvaluator whole_evaluator(0.5, 3.0);
  std::vector<evostick::Checkpoint> saved;
  const auto whole = evostick::evolve(Mission{}, Direction::Maximize, whole_evaluator, small(6, 9), {}, nullptr,
                                      [&](const evostick::Checkpoint& c) { saved.push_back(c); });
  ASSERT_EQ(saved.size(), 6u) << "the start, then after generations 1 to 5";
  for (const evostick::Checkpoint& c : saved) {
    ScriptedEvaluator rest_evaluator(0.5, 3.0);
    const auto rest = evostick::evolve(Mission{}, Direction::Maximize, rest_evaluator, small(6, 9), {}, &c);
    EXPECT_EQ(rest.best, whole.best) << c.generation;
    EXPECT_EQ(rest.best_mean, whole.best_mean) << c.generation;
    EXPECT_EQ(rest.history, whole.history) << c.generation;
    EXPECT_EQ(rest.runs, whole.runs) << c.generation;
    EXPECT_EQ(rest_evaluator.batches.size(), static_cast<std::size_t>(6 - c.generation)) << "only what is left runs";
  }
  Settings other = small(6, 9);
  other.population = 10;
  EXPECT_THROW(evostick::evolve(Mission{}, Direction::Maximize, whole_evaluator, other, {}, &saved[2]),
               std::invalid_argument);
}

TEST(EvoStick, AStopRequestEndsAfterTheGenerationWhoseStateIsSavedAndTheRestResumesExactly) {
  ScriptedEvaluator whole_evaluator(0.5, 3.0);
  const auto whole = evostick::evolve(Mission{}, Direction::Maximize, whole_evaluator, small(6, 9));
  EXPECT_FALSE(whole.stopped);
  ScriptedEvaluator first_evaluator(0.5, 3.0);
  std::vector<evostick::Checkpoint> saved;
  int asked = 0;
  const auto stopped = evostick::evolve(
      Mission{}, Direction::Maximize, first_evaluator, small(6, 9), {}, nullptr,
      [&](const evostick::Checkpoint& c) { saved.push_back(c); }, [&] { return ++asked == 2; });
  EXPECT_TRUE(stopped.stopped);
  EXPECT_EQ(first_evaluator.batches.size(), 2u) << "two generations, then the stop";
  ASSERT_EQ(saved.back().generation, 2) << "the state after the last generation run is saved";
  ScriptedEvaluator rest_evaluator(0.5, 3.0);
  const auto rest = evostick::evolve(Mission{}, Direction::Maximize, rest_evaluator, small(6, 9), {}, &saved.back());
  EXPECT_EQ(rest.best, whole.best);
  EXPECT_EQ(rest.history, whole.history);
  EXPECT_EQ(rest_evaluator.batches.size(), 4u);
}

TEST(EvoStick, SettingsAndBudgetsAreChecked) {
  EXPECT_NO_THROW(Settings{}.validate());
  const std::pair<std::function<void(Settings&)>, std::string> cases[] = {
      {[](Settings& s) { s.elites = 100; }, "elites must be between 1 and population - 1 = 99"},
      {[](Settings& s) { s.elites = 0; }, "elites must be between"},
      {[](Settings& s) { s.population = 1; }, "population must be at least 2"},
      {[](Settings& s) { s.mutation_sigma = 0.0; }, "mutation sigma must be a positive number"},
      {[](Settings& s) { s.mutation_probability = 0.0; }, "mutation probability must be in (0, 1]"},
      {[](Settings& s) { s.mutation_probability = 1.5; }, "mutation probability must be in (0, 1]"},
      {[](Settings& s) { s.weight_bound = -1.0; }, "weight bound must be a positive number"},
      {[](Settings& s) { s.evaluations = 0; }, "evaluations must be at least 1"},
      {[](Settings& s) { s.generations = 0; }, "generations must be at least 1"},
  };
  for (const auto& [change, message] : cases) {
    Settings s;
    change(s);
    try {
      s.validate();
      ADD_FAILURE() << "accepted; expected: " << message;
    } catch (const std::invalid_argument& e) {
      EXPECT_NE(std::string(e.what()).find(message), std::string::npos) << e.what();
    }
  }

  const Settings d;
  EXPECT_EQ(evostick::generations_for_budget(1000, d), 1);
  EXPECT_EQ(evostick::generations_for_budget(20999, d), 20);
  EXPECT_EQ(evostick::generations_for_budget(200000, d), 200);
  EXPECT_THROW(evostick::generations_for_budget(999, d), std::invalid_argument);
}

// ---- with simulations -------------------------------------------------------------------

/// The phototaxis training arena, cut to 5 robots and 20 s so that an evolution takes a
/// second or two.
Mission cheap_phototaxis_arena() {
  Mission m = evostick::training_mission(*evostick::find_module_training("phototaxis"));
  m.robots = 5;
  m.ticks = 200;
  m.duration_s = 20.0;
  return m;
}

double mean_on_fresh_seeds(const Mission& m, Evaluator& evaluator, const arlequin::Weights& weights) {
  ControlSoftware network;
  network.architecture = Architecture::NeuralNetwork;
  network.network.weights = weights;
  std::vector<EvaluationTask> tasks;
  for (std::uint64_t seed = 5000; seed < 5020; ++seed) tasks.push_back({&network, seed});
  std::vector<double> scores(tasks.size());
  evaluator.evaluate(m, tasks, scores);
  double mean = 0.0;
  for (const double s : scores) mean += s / static_cast<double>(scores.size());
  return mean;
}

TEST(EvoStick, ImprovesTheLightApproachOfASmallSwarmOverGenerations) {
  // Each generation runs on new seeds, so the per-generation means are noisy; the claim is
  // checked on twenty seeds neither evolution saw: the network after ten generations beats
  // the best one of the first generation.
  const Mission m = cheap_phototaxis_arena();
  evostick::MeasureEvaluator evaluator(evostick::Measure::LightApproach, 2);
  Settings s;
  s.population = 30;
  s.evaluations = 4;
  s.elites = 6;
  s.generations = 10;
  const auto result = evostick::evolve(m, Direction::Maximize, evaluator, s);
  ASSERT_EQ(result.history.size(), 10u);
  Settings first = s;
  first.generations = 1;
  const auto first_best = evostick::evolve(m, Direction::Maximize, evaluator, first);
  EXPECT_EQ(first_best.history.front(), result.history.front()) << "the first generation does not depend on the last";
  EXPECT_GT(mean_on_fresh_seeds(m, evaluator, result.best), mean_on_fresh_seeds(m, evaluator, first_best.best));
}

TEST(EvoStick, OneAndTwoThreadsGiveTheSameEvolutionBitForBit) {
  Settings s;
  s.population = 10;
  s.evaluations = 3;
  s.elites = 2;
  s.generations = 3;
  s.seed = 99;
  {
    const Mission m = cheap_phototaxis_arena();
    evostick::MeasureEvaluator one(evostick::Measure::LightApproach, 1), two(evostick::Measure::LightApproach, 2);
    const auto x = evostick::evolve(m, Direction::Maximize, one, s);
    const auto y = evostick::evolve(m, Direction::Maximize, two, s);
    EXPECT_EQ(x.best, y.best);
    EXPECT_EQ(x.history, y.history);
  }
  {
    Mission aac = load_mission("aac");
    aac.ticks = 150;
    ThreadedEvaluator one(1), two(2);
    const auto x = evostick::evolve(aac, aac.objective.direction, one, s);
    const auto y = evostick::evolve(aac, aac.objective.direction, two, s);
    EXPECT_EQ(x.best, y.best);
    EXPECT_EQ(x.history, y.history);
  }
}

}  // namespace
}  // namespace sd
