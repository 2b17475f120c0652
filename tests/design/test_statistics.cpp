// Expected values computed with R 4.2.2 (irace 3.5 installed); each literal names its R call.
#include <gtest/gtest.h>

#include "design/statistics.hpp"

using namespace sd::design;

namespace {

CostMatrix matrix(std::size_t rows, std::size_t cols, std::vector<double> data) {
  CostMatrix m(rows, cols);
  m.data = std::move(data);
  return m;
}

// R: y <- matrix(c(...), ncol=4, byrow=TRUE)
CostMatrix y1() {
  return matrix(6, 4, {3.1, 2.0, 4.5, 3.3, 2.9, 2.2, 4.1, 3.0, 3.5, 1.9, 4.8, 3.9,
                       3.0, 2.5, 4.0, 3.1, 3.3, 2.4, 4.4, 3.2, 2.8, 2.1, 3.9, 3.4});
}
// R: y2 <- matrix(c(...), ncol=5, byrow=TRUE), with ties and one fully tied row
CostMatrix y2() {
  return matrix(5, 5, {1, 1, 2, 3, 3, 2, 1, 1, 3, 4, 1, 2, 2, 2, 5, 1, 1, 1, 1, 1, 2, 3, 1, 4, 4});
}
// R: set.seed(3); y3 <- matrix(round(rnorm(40, mean=rep(c(0,0.2,1,2,3), each=8)),3), ncol=5)
CostMatrix y3() {
  const double cols[5][8] = {{-0.962, -0.293, 0.259, -1.152, 0.196, 0.030, 0.085, 1.117},
                             {-1.019, 1.467, -0.545, -0.931, -0.516, 0.453, 0.352, -0.108},
                             {0.047, 0.352, 2.224, 1.200, 0.422, 0.058, 0.796, -0.666},
                             {1.516, 1.259, 3.161, 3.012, 1.928, 0.863, 2.901, 2.852},
                             {3.728, 3.737, 2.648, 3.706, 4.300, 3.038, 2.021, 3.794}};
  CostMatrix m(8, 5);
  for (std::size_t c = 0; c < 5; ++c)
    for (std::size_t r = 0; r < 8; ++r) m.at(r, c) = cols[c][r];
  return m;
}

}  // namespace

TEST(design_Statistics, AverageRanksMatchR) {
  // R: rank(c(3,1,4,1,5,9,2,6,5,3,5))
  const std::vector<double> x{3, 1, 4, 1, 5, 9, 2, 6, 5, 3, 5};
  const std::vector<double> expected{4.5, 1.5, 6, 1.5, 8, 11, 3, 10, 8, 4.5, 8};
  EXPECT_EQ(average_ranks(x), expected);
}

TEST(design_Statistics, FriedmanWithoutTies) {
  // R: friedman.test(y) -> 17, 0.00070674239233702875; colSums(t(apply(y,1,rank))) -> 13 6 24 17
  const FriedmanTest f = friedman_test(y1());
  EXPECT_NEAR(f.statistic, 17.0, 1e-12);
  EXPECT_NEAR(f.p_value, 0.00070674239233702875, 1e-15);
  EXPECT_EQ(f.rank_sums, (std::vector<double>{13, 6, 24, 17}));
}

TEST(design_Statistics, FriedmanWithTies) {
  // R: friedman.test(y2) -> 11.833333333333334, 0.018634646635166056; rank sums 10.5 12 11.5 19 22
  const FriedmanTest f = friedman_test(y2());
  EXPECT_NEAR(f.statistic, 11.833333333333334, 1e-12);
  EXPECT_NEAR(f.p_value, 0.018634646635166056, 1e-14);
  EXPECT_EQ(f.rank_sums, (std::vector<double>{10.5, 12, 11.5, 19, 22}));
}

TEST(design_Statistics, ConoverPostHocMatchesIrace) {
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

TEST(design_Statistics, FriedmanAtHighConfidenceKeepsEveryone) {
  // p = 0.0186 for y2: not significant at confidence 0.99
  const RaceTestOutcome t = friedman_conover(y2(), 0.99);
  EXPECT_FALSE(t.dropped_any);
  EXPECT_EQ(t.keep, (std::vector<bool>(5, true)));
}

TEST(design_Statistics, AllTiedRowsGiveNoTest) {
  const RaceTestOutcome t = friedman_conover(matrix(3, 3, std::vector<double>(9, 1.0)), 0.95);
  EXPECT_FALSE(t.dropped_any);
  EXPECT_EQ(t.keep, (std::vector<bool>(3, true)));
}

TEST(design_Statistics, SignedRankDistribution) {
  // R: psignrank(10, 9); psignrank(3, 5); psignrank(40, 12)
  EXPECT_NEAR(psignrank(10, 9), 0.08203125, 1e-15);
  EXPECT_NEAR(psignrank(3, 5), 0.15625, 1e-15);
  EXPECT_NEAR(psignrank(40, 12), 0.54516601562499989, 1e-14);
}

TEST(design_Statistics, WilcoxonExact) {
  // R: wilcox.test(x, y, paired=TRUE, conf.int=TRUE) -> V 40, p 0.0390625, estimate 0.46000000000000008
  const std::vector<double> x{1.83, 0.50, 1.62, 2.48, 1.68, 1.88, 1.55, 3.06, 1.30};
  const std::vector<double> y{0.878, 0.647, 0.598, 2.05, 1.06, 1.29, 1.06, 3.14, 1.29};
  const WilcoxonTest w = wilcoxon_signed_rank(x, y);
  EXPECT_TRUE(w.exact);
  EXPECT_EQ(w.statistic, 40);
  EXPECT_NEAR(w.p_value, 0.0390625, 1e-15);
  EXPECT_NEAR(w.estimate, 0.46000000000000008, 1e-12);
}

TEST(design_Statistics, WilcoxonNormalApproximationWithTies) {
  // R: wilcox.test(x2, y2w, paired=TRUE, conf.int=TRUE) -> V 30, p 0.49459932738312368, estimate -0.49995 (uniroot)
  const std::vector<double> x{1, 2, 3, 4, 5, 6, 7, 8, 9, 10, 11, 12};
  const std::vector<double> y{2, 1, 3.5, 3, 7, 5, 9, 8.5, 8, 12, 10, 13};
  const WilcoxonTest w = wilcoxon_signed_rank(x, y);
  EXPECT_FALSE(w.exact);
  EXPECT_EQ(w.statistic, 30);
  EXPECT_NEAR(w.p_value, 0.49459932738312368, 1e-14);
  EXPECT_NEAR(w.estimate, -0.5, 1e-3);

  // R: x3 vs y3w (differences with ties) -> V 77, p 0.0031808856350796738, estimate 0.39996 (uniroot)
  const std::vector<double> x3{5.1, 4.9, 6.2, 5.8, 6.0, 5.5, 5.3, 6.1, 5.9, 5.7, 6.3, 5.2};
  const std::vector<double> d{0.5, 0.3, 0.4, -0.1, 0.6, 0.5, 0.2, 0.7, 0.4, 0.5, 0.3, 0.2};
  std::vector<double> y3(12);
  for (std::size_t i = 0; i < 12; ++i) y3[i] = x3[i] - d[i];
  const WilcoxonTest w3 = wilcoxon_signed_rank(x3, y3);
  EXPECT_EQ(w3.statistic, 77);
  EXPECT_NEAR(w3.p_value, 0.0031808856350796738, 1e-14);
  EXPECT_NEAR(w3.estimate, 0.4, 1e-3);
}

TEST(design_Statistics, TwoSurvivorsFollowIrace) {
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
