// Expected values computed with R 4.2.2 (irace 3.5 installed); each literal names its R call.
#include <gtest/gtest.h>

#include "design/race_test.hpp"
#include "statistics/r_matrices.hpp"

using namespace sd::design;
using namespace sd::statistics::testing;

TEST(design_RaceTest, ConoverPostHocMatchesIrace) {
  // R: qt(0.975,(n-1)*(k-1)) * sqrt(2*(n*A - sum(R^2))/((n-1)*(k-1))) -> 2.461185937786083;
  //    irace:::aux2.friedman(y, 1:4, rep(TRUE,4), 0.95)$alive -> FALSE TRUE FALSE FALSE
  const RaceTestOutcome t1 = friedman_conover(y1(), 0.95);
  EXPECT_NEAR(t1.critical_difference, 2.461185937786083, 1e-12);
  EXPECT_EQ(t1.keep, (std::vector<bool>{false, true, false, false}));
  EXPECT_EQ(t1.best, 1u);
  EXPECT_TRUE(t1.dropped_any);

  // R: irace:::aux2.friedman(y2, 1:5, rep(TRUE,5), 0.95)$alive -> TRUE TRUE TRUE FALSE FALSE, best 1
  const RaceTestOutcome t2 = friedman_conover(y2(), 0.95);
  EXPECT_EQ(t2.keep, (std::vector<bool>{true, true, true, false, false}));
  EXPECT_EQ(t2.best, 0u);

  // R: CD for y3 -> 6.9680261327127928; aux2.friedman alive -> TRUE TRUE FALSE FALSE FALSE
  const RaceTestOutcome t3 = friedman_conover(y3(), 0.95);
  EXPECT_NEAR(t3.critical_difference, 6.9680261327127928, 1e-12);
  EXPECT_NEAR(t3.p_value, 8.3647065498803505e-05, 1e-17);
  EXPECT_EQ(t3.keep, (std::vector<bool>{true, true, false, false, false}));
}

TEST(design_RaceTest, FriedmanAtHighConfidenceKeepsEveryone) {
  // p = 0.0186 for y2: not significant at confidence 0.99
  const RaceTestOutcome t = friedman_conover(y2(), 0.99);
  EXPECT_FALSE(t.dropped_any);
  EXPECT_EQ(t.keep, (std::vector<bool>(5, true)));
}

TEST(design_RaceTest, AllTiedRowsGiveNoTest) {
  const RaceTestOutcome t = friedman_conover(matrix(3, 3, std::vector<double>(9, 1.0)), 0.95);
  EXPECT_FALSE(t.dropped_any);
  EXPECT_EQ(t.keep, (std::vector<bool>(3, true)));
}

TEST(design_RaceTest, TwoSurvivorsFollowIrace) {
  // R: irace:::aux_friedman(cbind(x, yy), c(TRUE,TRUE), 1:2, 0.95) -> alive FALSE TRUE, best 2, p 0.0390625
  CostMatrix m(9, 2);
  const std::vector<double> x{1.83, 0.50, 1.62, 2.48, 1.68, 1.88, 1.55, 3.06, 1.30};
  const std::vector<double> y{0.878, 0.647, 0.598, 2.05, 1.06, 1.29, 1.06, 3.14, 1.29};
  for (std::size_t i = 0; i < 9; ++i) {
    m.at(i, 0) = x[i];
    m.at(i, 1) = y[i];
  }
  const RaceTestOutcome t = race_test(m, 0.95);
  EXPECT_EQ(t.keep, (std::vector<bool>{false, true}));
  EXPECT_EQ(t.best, 1u);
  EXPECT_NEAR(t.p_value, 0.0390625, 1e-15);

  // Not significant: both stay, best by the pseudo-median's sign.
  const RaceTestOutcome loose = race_test(m, 0.99);
  EXPECT_EQ(loose.keep, (std::vector<bool>{true, true}));
  EXPECT_EQ(loose.best, 1u);

  // Dominance: a column <= the other everywhere drops the other without a test.
  CostMatrix d = matrix(5, 2, {1, 1, 2, 2.5, 3, 3, 1, 1.1, 0, 0.2});
  const RaceTestOutcome dom = race_test(d, 0.95);
  EXPECT_EQ(dom.keep, (std::vector<bool>{true, false}));
  EXPECT_TRUE(dom.dropped_any);
}
