// The design methods beyond Iterated F-Race (design/method_options.hpp): local search's moves
// (design/neighbourhood.hpp) and random and local search raced like irace, deterministic per
// seed, independent of the thread count and resumable from any checkpoint.
#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include <algorithm>
#include <cmath>
#include <set>
#include <string>
#include <vector>

#include "core/rng.hpp"
#include "design/design_space.hpp"
#include "design/fsm_space.hpp"
#include "design/iterated_race.hpp"
#include "design/method_options.hpp"
#include "design/neighbourhood.hpp"
#include "design/sampling.hpp"
#include "synthetic_objective.hpp"

using namespace sd::design;
using sd::design::fixtures::synthetic_cost;
using sd::design::fixtures::synthetic_space;

namespace {

/// Parameters whose value differs between two configurations (NA against a value counts).
std::vector<std::size_t> changed(const Configuration& a, const Configuration& b) {
  std::vector<std::size_t> out;
  for (std::size_t i = 0; i < a.values.size(); ++i) {
    const bool na_a = is_na(a.values[i]), na_b = is_na(b.values[i]);
    if (na_a != na_b || (!na_a && a.values[i] != b.values[i])) out.push_back(i);
  }
  return out;
}

/// What many one-move neighbours of uniform configurations reach: every valid, none equal to
/// its parent, and which parameters and categorical values they change to.
struct Reach {
  std::set<std::size_t> parameters_changed;
  std::set<std::pair<std::size_t, int>> values_reached;  // (categorical parameter, value index) a move set
  std::size_t invalid = 0, unchanged = 0;
};

Reach one_move_reach(const ParameterSpace& space, int parents, int children, std::uint64_t seed) {
  sd::Rng rng(seed);
  Reach reach;
  for (int p = 0; p < parents; ++p) {
    const Configuration parent = sample_uniform(space, rng);
    for (int k = 0; k < children; ++k) {
      const Configuration child = neighbour(space, parent, rng, 1);
      if (!space.validate(child).empty()) ++reach.invalid;
      const std::vector<std::size_t> diff = changed(parent, child);
      if (diff.empty()) ++reach.unchanged;
      for (std::size_t i : diff) {
        if (is_na(child.values[i])) continue;
        reach.parameters_changed.insert(i);
        if (!space[i].is_numeric()) reach.values_reached.insert({i, static_cast<int>(child.values[i])});
      }
    }
  }
  return reach;
}

void expect_reaches_everything(const ParameterSpace& space, const Reach& reach) {
  EXPECT_EQ(reach.invalid, 0u);
  EXPECT_EQ(reach.unchanged, 0u);
  for (std::size_t i = 0; i < space.size(); ++i) {
    if (space[i].is_fixed()) continue;
    EXPECT_TRUE(reach.parameters_changed.count(i)) << space[i].name << " is never changed by a move";
    if (space[i].is_numeric()) continue;
    for (std::size_t v = 0; v < space[i].values.size(); ++v)
      EXPECT_TRUE(reach.values_reached.count({i, static_cast<int>(v)}))
          << space[i].name << " = " << space[i].values[v] << " is never reached by a move";
  }
}


const MethodInfo* const kSearches[] = {&kRandomSearch, &kLocalSearch};

}  // namespace

TEST(design_Neighbourhood, OneMoveReachesEveryModuleAndParameterOfTheChocolateFsmSpace) {
  const ParameterSpace space = build_fsm_space(chocolate_fsm_modules());
  expect_reaches_everything(space, one_move_reach(space, 400, 10, 1));
}

TEST(design_Neighbourhood, AMoveOfEachParameterReachesEachOfItsValuesInTheCombinedSpace) {
  // Both architectures and all five flavours: behaviour trees' branches and Arlequin's networks
  // too. Deep branches are active in few configurations, so each parameter is moved on purpose,
  // from a configuration where it is active.
  const ParameterSpace space = build_design_space(resolve_design_space({}));
  sd::Rng rng(2);
  std::vector<Configuration> parents;
  for (int k = 0; k < 3000; ++k) parents.push_back(sample_uniform(space, rng));
  for (std::size_t i = 0; i < space.size(); ++i) {
    if (space[i].is_fixed()) continue;
    const auto parent = std::find_if(parents.begin(), parents.end(), [&](const Configuration& c) {
      const auto movable = movable_parameters(space, c);
      return std::find(movable.begin(), movable.end(), i) != movable.end();
    });
    ASSERT_NE(parent, parents.end()) << space[i].name << " is movable in none of 3000 configurations";
    std::set<double> values;
    for (int k = 0; k < 40 * static_cast<int>(std::max<std::size_t>(space[i].values.size(), 2)); ++k) {
      const Configuration child = moved(space, *parent, i, rng);
      ASSERT_EQ(space.validate(child), "") << space.render(child);
      ASSERT_NE(child.values[i], parent->values[i]) << space[i].name;
      values.insert(child.values[i]);
    }
    if (space[i].is_numeric()) {
      const auto [lb, ub] = *space.domain(*parent, i);
      const bool two_values = space[i].type == ParamType::Integer && ub - lb == 1;
      EXPECT_EQ(values.size() > 1, !two_values) << space[i].name << " over [" << lb << ", " << ub << "]";
    } else {
      EXPECT_EQ(values.size() + 1, space[i].values.size()) << space[i].name << ": every other value is reached";
    }
  }
}

TEST(design_Neighbourhood, AMoveChangesOneParameterAndOnlyWhatItSwitchesOnOrOff) {
  const ParameterSpace space = build_fsm_space(chocolate_fsm_modules());
  const std::size_t states = *space.index_of("NumStates");
  sd::Rng rng(3);
  int structural = 0;
  for (int k = 0; k < 2000; ++k) {
    const Configuration parent = sample_uniform(space, rng);
    const Configuration child = neighbour(space, parent, rng, 1);
    const std::vector<std::size_t> diff = changed(parent, child);
    ASSERT_FALSE(diff.empty());
    // Parameters both active in parent and child that changed: the one moved, plus those whose
    // dependent domain the move shrank (a transition's target after a state was removed).
    std::size_t kept_and_changed = 0;
    for (std::size_t i : diff) kept_and_changed += !is_na(parent.values[i]) && !is_na(child.values[i]);
    if (parent.values[states] != child.values[states]) {
      ++structural;  // a state added or removed: adds or clears its parameters
    } else {
      EXPECT_LE(kept_and_changed, 1u) << space.render(parent) << "\n -> " << space.render(child);
    }
  }
  EXPECT_GT(structural, 0);  // states are added and removed
}

TEST(design_Neighbourhood, MoreMovesGoFurther) {
  const ParameterSpace space = build_fsm_space(chocolate_fsm_modules());
  sd::Rng rng(4);
  std::size_t one = 0, three = 0;
  for (int k = 0; k < 500; ++k) {
    const Configuration parent = sample_uniform(space, rng);
    one += changed(parent, neighbour(space, parent, rng, 1)).size();
    three += changed(parent, neighbour(space, parent, rng, 3)).size();
  }
  EXPECT_GT(three, one * 2);
}

TEST(design_SearchMethods, OptionsDifferFromIraceOnlyInHowCandidatesAreDrawn) {
  const ParameterSpace space = build_fsm_space(chocolate_fsm_modules());
  const IraceOptions irace = method_options(kAutoMoDe, 20000, 5, 1, space);
  EXPECT_EQ(irace.sampler, Sampler::Model);
  EXPECT_EQ(fingerprint(space, irace), fingerprint(space, [] {
              IraceOptions o;  // AutoMoDe's designs keep the fingerprint they were made with
              o.max_experiments = 20000;
              o.seed = 5;
              return o;
            }()));
  const IraceOptions random = method_options(kRandomSearch, 20000, 5, 1, space);
  EXPECT_EQ(random.sampler, Sampler::Uniform);
  EXPECT_EQ(random.nb_iterations, irace.nb_iterations);
  EXPECT_NE(fingerprint(space, random), fingerprint(space, irace));
  const IraceOptions local = method_options(kLocalSearch, 20000, 5, 1, space);
  EXPECT_EQ(local.sampler, Sampler::Neighbourhood);
  EXPECT_EQ(local.nb_iterations, 0);  // as many small races as the budget pays for
  EXPECT_NE(fingerprint(space, local), fingerprint(space, random));
  EXPECT_THROW(method_options(kEvoStick, 20000, 5, 1, space), std::invalid_argument);
  EXPECT_GE(method_minimum_budget(kLocalSearch, space), 2 * local.nb_experiments_per_iteration);
}

TEST(design_SearchMethods, EachFindsTheOptimumOfASyntheticObjectiveWithinTheBudget) {
  const ParameterSpace s = synthetic_space();
  for (const MethodInfo* method : kSearches) {
    SCOPED_TRACE(std::string(method->name));
    ThreadedRunner runner(synthetic_cost, 2);
    IteratedRace design(s, method_options(*method, 4000, 1, 1, s), runner);
    const DesignResult r = design.run();
    ASSERT_FALSE(r.elites.empty());
    EXPECT_LE(r.experiments_used, 4000);
    EXPECT_GT(r.experiments_used, 3000);
    const auto& best = r.elites.front().configuration.values;
    EXPECT_EQ(best[0], 2) << s.render(r.elites.front().configuration);
    EXPECT_LT(r.elites.front().mean_cost, 0.25);
    // How each draws its candidates after the first race: random search from nobody, local
    // search from an elite; so local search races more, smaller races.
    int with_parent = 0;
    for (const ConfigRecord& c : design.state().configurations.all()) with_parent += c.parent != 0;
    if (method == &kRandomSearch) {
      EXPECT_EQ(with_parent, 0);
    } else {
      EXPECT_GT(with_parent, 0);
      EXPECT_GT(r.iterations, default_nb_iterations(s.nb_variable()));
    }
  }
}

TEST(design_SearchMethods, ResultsDoNotDependOnTheThreadCount) {
  const ParameterSpace space = build_fsm_space(chocolate_fsm_modules());
  auto cost = [&](const Experiment& e) {
    const auto& v = e.configuration->values;
    double c = std::fabs(v[*space.index_of("NumStates")] - 3);
    c += space.value_text(*e.configuration, *space.index_of("S0")) == "14" ? 0 : 1;
    sd::Rng noise(e.seed + static_cast<std::uint64_t>(e.configuration_id));
    return c + 0.3 * noise.normal();
  };
  for (const MethodInfo* method : kSearches) {
    SCOPED_TRACE(std::string(method->name));
    const IraceOptions o = method_options(*method, method_minimum_budget(*method, space) + 500, 42, 1, space);
    auto run_with = [&](unsigned threads) {
      ThreadedRunner runner(cost, threads);
      IteratedRace design(space, o, runner);
      design.run();
      return state_to_json(design.state()).dump();
    };
    EXPECT_EQ(run_with(1), run_with(2));
  }
}

TEST(design_SearchMethods, ResumingFromACheckpointGivesTheSameResult) {
  const ParameterSpace s = synthetic_space();
  for (const MethodInfo* method : kSearches) {
    SCOPED_TRACE(std::string(method->name));
    const IraceOptions o = method_options(*method, 2500, 9, 1, s);
    std::vector<nlohmann::json> checkpoints;
    ThreadedRunner full_runner(synthetic_cost, 1);
    IteratedRace full(s, o, full_runner);
    full.on_checkpoint([&](const Checkpoint& c) { checkpoints.push_back(state_to_json(c.state)); });
    full.run();
    const std::string expected = state_to_json(full.state()).dump();
    ASSERT_GT(checkpoints.size(), 10u);
    for (std::size_t k : {std::size_t{1}, checkpoints.size() / 2, checkpoints.size() - 2}) {
      ThreadedRunner runner(synthetic_cost, 2);
      IteratedRace resumed(s, o, runner);
      resumed.restore(state_from_json(nlohmann::json::parse(checkpoints[k].dump())));
      resumed.run();
      EXPECT_EQ(state_to_json(resumed.state()).dump(), expected) << "checkpoint " << k;
    }
  }
}
