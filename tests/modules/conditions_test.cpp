// Condition modules (ARGoS3-AutoMoDe's AutoMoDeCondition*): floor conditions on the filtered ground
// value, the logistic neighbour conditions, FixedProbability; the Bernoulli draw happens only
// when the precondition holds.
#include <gtest/gtest.h>

#include <bit>
#include <cmath>
#include <cstdint>
#include <span>
#include <vector>

#include "module_test_helpers.hpp"
#include "modules/conditions.hpp"

namespace sd {
namespace {

using test::expect_binomial;
using test::module;

ReferenceModel on_ground(double g) {
  ReferenceModel rm;
  rm.ground = g;
  return rm;
}

ReferenceModel with_neighbours(int n) {
  ReferenceModel rm;
  rm.neighbours = n;
  return rm;
}

int fire_count(const ModuleInstance& condition, const ReferenceModel& rm, int trials, Rng& rng,
               std::span<const double> table = {}) {
  int fired = 0;
  for (int t = 0; t < trials; ++t) fired += check_condition(condition, rm, rng, table);
  return fired;
}

double logistic(double xi, double eta, int n) { return 1.0 / (1.0 + std::exp(eta * (xi - n))); }

TEST(ModulesFloorConditions, FireOnlyOnTheirOwnColour) {
  Rng rng(1);
  const double grounds[] = {0.0, 0.5, 1.0};
  for (int c = 0; c < 3; ++c) {      // 10 Black, 11 Gray, 12 White
    for (int g = 0; g < 3; ++g) {
      const int fired = fire_count(module(10 + c, {1.0}), on_ground(grounds[g]), 100, rng);
      EXPECT_EQ(fired, c == g ? 100 : 0) << "condition " << 10 + c << " on ground " << grounds[g];
    }
  }
}

TEST(ModulesFloorConditions, FireWithTheirProbabilityOnTheirColour) {
  Rng rng(2);
  const int trials = 20000;
  expect_binomial(fire_count(module(10, {0.3}), on_ground(0.0), trials, rng), trials, 0.3);
  expect_binomial(fire_count(module(11, {0.6}), on_ground(0.5), trials, rng), trials, 0.6);
  expect_binomial(fire_count(module(12, {0.05}), on_ground(1.0), trials, rng), trials, 0.05);
  EXPECT_EQ(fire_count(module(10, {0.0}), on_ground(0.0), 1000, rng), 0);
}

TEST(ModulesFloorConditions, FailedPreconditionDrawsNoRandomNumber) {
  Rng rng(3);
  const Rng before = rng;
  EXPECT_FALSE(check_condition(module(10, {1.0}), on_ground(0.5), rng));
  EXPECT_FALSE(check_condition(module(10, {1.0}), on_ground(1.0), rng));
  EXPECT_FALSE(check_condition(module(11, {1.0}), on_ground(0.0), rng));
  EXPECT_FALSE(check_condition(module(11, {1.0}), on_ground(1.0), rng));
  EXPECT_FALSE(check_condition(module(12, {1.0}), on_ground(0.0), rng));
  EXPECT_FALSE(check_condition(module(12, {1.0}), on_ground(0.5), rng));
  EXPECT_TRUE(test::same_rng_state(rng, before));
}

TEST(ModulesFloorConditions, HeldPreconditionDrawsExactlyOneUniform) {
  for (const int id : {10, 11, 12}) {
    const double g = (id - 10) * 0.5;
    Rng rng(4), expected(4);
    const bool fired = check_condition(module(id, {0.5}), on_ground(g), rng);
    EXPECT_EQ(fired, expected.uniform() < 0.5);
    EXPECT_TRUE(test::same_rng_state(rng, expected)) << "condition " << id;
  }
}

TEST(ModulesFloorConditions, ThresholdsOnTheGroundValue) {
  // black g <= 0.1, gray 0.1 < g < 0.95, white g >= 0.95.
  Rng rng(5);
  EXPECT_TRUE(check_condition(module(10, {1.0}), on_ground(0.1), rng));
  EXPECT_FALSE(check_condition(module(11, {1.0}), on_ground(0.1), rng));
  EXPECT_TRUE(check_condition(module(11, {1.0}), on_ground(0.94), rng));
  EXPECT_TRUE(check_condition(module(12, {1.0}), on_ground(0.95), rng));
  EXPECT_FALSE(check_condition(module(11, {1.0}), on_ground(0.95), rng));
}

TEST(ModulesNeighboursProbability, IsOneHalfAtTheThreshold) {
  for (int xi = 1; xi <= 10; ++xi)
    for (const double eta : {0.0, 0.5, 3.0, 20.0}) EXPECT_DOUBLE_EQ(neighbours_probability(xi, eta, xi), 0.5);
}

TEST(ModulesNeighboursProbability, MatchesTheLogisticAndIncreasesWithNeighbours) {
  for (const double eta : {0.1, 1.0, 5.07}) {
    double previous = 0.0;
    for (int n = 0; n <= 20; ++n) {
      const double p = neighbours_probability(5, eta, n);
      EXPECT_NEAR(p, logistic(5, eta, n), 1e-15);
      // Strictly increasing until it rounds to 1 in double precision.
      if (previous < 1.0) EXPECT_GT(p, previous) << "eta " << eta << " n " << n;
      else EXPECT_EQ(p, 1.0);
      previous = p;
    }
  }
  EXPECT_NEAR(neighbours_probability(3, 1.0, 5), 1.0 / (1.0 + std::exp(-2.0)), 1e-15);
  // More neighbours than xi with a large eta: almost certain; fewer: almost never. (No
  // unsigned wrap-around for n > xi.)
  EXPECT_GT(neighbours_probability(2, 20.0, 9), 0.999999);
  EXPECT_LT(neighbours_probability(9, 20.0, 2), 1e-6);
}

TEST(ModulesNeighboursProbability, EtaZeroIsAFairCoin) {
  for (int n = 0; n < 12; ++n) EXPECT_EQ(neighbours_probability(4, 0.0, n), 0.5);
}

TEST(ModulesNeighboursProbability, XiIsTruncatedToAnInteger) {
  for (int n = 0; n < 10; ++n) {
    EXPECT_EQ(neighbours_probability(5.9, 2.0, n), neighbours_probability(5, 2.0, n));
    EXPECT_EQ(neighbours_probability(1.5, 2.0, n), neighbours_probability(1, 2.0, n));
  }
  EXPECT_EQ(neighbours_probability(5.9, 2.0, 5), 0.5);
}

TEST(ModulesNeighbourConditions, FireWithTheLogisticProbability) {
  Rng rng(6);
  const int trials = 20000;
  for (const int n : {1, 3, 4, 6}) {
    const double p = logistic(4, 0.8, n);
    expect_binomial(fire_count(module(13, {4, 0.8}), with_neighbours(n), trials, rng), trials, p);
    expect_binomial(fire_count(module(14, {4, 0.8}), with_neighbours(n), trials, rng), trials, 1.0 - p);
  }
}

TEST(ModulesNeighbourConditions, InvertedIsTheComplementDrawForDraw) {
  // With the same generator state, Inverted fires exactly when NeighborsCount would fire with
  // probability 1 - p: u < 1 - p.
  for (int seed = 0; seed < 200; ++seed) {
    Rng a(static_cast<std::uint64_t>(seed)), b(static_cast<std::uint64_t>(seed));
    const bool inverted = check_condition(module(14, {3, 1.5}), with_neighbours(2), a);
    EXPECT_EQ(inverted, b.uniform() < 1.0 - logistic(3, 1.5, 2));
  }
}

TEST(ModulesNeighboursTable, HoldsTheFunctionsValuesBitForBit) {
  for (const int id : {13, 23, 33, 43, 53, 14, 24, 34, 44, 54}) {
    for (const double xi : {0.0, 3.0, 5.9, 10.0}) {
      for (const double eta : {0.0, 0.7, 5.07, 20.0}) {
        const std::vector<double> table = neighbours_table(module(id, {xi, eta}), 19);
        ASSERT_EQ(table.size(), 20u);
        for (int n = 0; n < 20; ++n)
          EXPECT_EQ(std::bit_cast<std::uint64_t>(table[static_cast<std::size_t>(n)]),
                    std::bit_cast<std::uint64_t>(neighbours_probability(xi, eta, n)))
              << "condition " << id << " xi " << xi << " eta " << eta << " n " << n;
      }
    }
  }
}

TEST(ModulesNeighboursTable, IsEmptyForOtherConditionsAndForNoRobot) {
  for (const int id : {10, 11, 12, 15, 25, 27, 55}) EXPECT_TRUE(neighbours_table(module(id, {0.5, 2}), 19).empty()) << id;
  EXPECT_TRUE(neighbours_table(module(13, {3, 1}), -1).empty());
}

TEST(ModulesNeighbourConditions, LookUpTheTableOnlyForTheCountsItCovers) {
  // A doctored table says "certain" for 0 .. 2 neighbours where the logistic (xi 9, eta 20)
  // says "almost never": the draws show which one the condition read.
  const ModuleInstance count = module(13, {9, 20}), inverted = module(14, {9, 20});
  const std::vector<double> certain(3, 1.0);
  Rng rng(9);
  for (int n = 0; n < 3; ++n) {
    EXPECT_EQ(fire_count(count, with_neighbours(n), 100, rng, certain), 100) << n;
    EXPECT_EQ(fire_count(inverted, with_neighbours(n), 100, rng, certain), 0) << n;
  }
  for (const int n : {-1, 3, 5}) {
    EXPECT_EQ(fire_count(count, with_neighbours(n), 100, rng, certain), 0) << n;
    EXPECT_EQ(fire_count(inverted, with_neighbours(n), 100, rng, certain), 100) << n;
  }
}

TEST(ModulesNeighbourConditions, DrawTheSameWithTheirTableAsWithout) {
  for (const ModuleInstance& c : {module(13, {4, 0.8}), module(44, {2, 3.5})}) {
    const std::vector<double> table = neighbours_table(c, 5);
    for (int n = 0; n <= 8; ++n) {
      Rng with(static_cast<std::uint64_t>(n)), without(static_cast<std::uint64_t>(n));
      for (int k = 0; k < 200; ++k)
        ASSERT_EQ(check_condition(c, with_neighbours(n), with, table), check_condition(c, with_neighbours(n), without))
            << "condition " << c.id << " n " << n << " draw " << k;
      EXPECT_TRUE(test::same_rng_state(with, without));
    }
  }
}

TEST(ModulesFixedProbability, FiresWithItsProbability) {
  Rng rng(7);
  const int trials = 20000;
  expect_binomial(fire_count(module(15, {0.25}), ReferenceModel{}, trials, rng), trials, 0.25);
  expect_binomial(fire_count(module(15, {0.9}), ReferenceModel{}, trials, rng), trials, 0.9);
  EXPECT_EQ(fire_count(module(15, {0.0}), ReferenceModel{}, 1000, rng), 0);
  EXPECT_EQ(fire_count(module(15, {1.0}), ReferenceModel{}, 1000, rng), 1000);
}

TEST(ModulesFixedProbability, IgnoresTheFloor) {
  Rng rng(8);
  for (const double g : {0.0, 0.5, 1.0}) EXPECT_TRUE(check_condition(module(15, {1.0}), on_ground(g), rng));
}

}  // namespace
}  // namespace sd
