#pragma once
// Cost matrices whose Friedman and Conover results were computed with R 4.2.2 (irace 3.5
// installed): shared by the statistics' tests and the race test's.
#include <cstddef>
#include <utility>
#include <vector>

#include "statistics/friedman.hpp"

namespace sd::statistics::testing {

inline CostMatrix matrix(std::size_t rows, std::size_t cols, std::vector<double> data) {
  CostMatrix m(rows, cols);
  m.data = std::move(data);
  return m;
}

// R: y <- matrix(c(...), ncol=4, byrow=TRUE)
inline CostMatrix y1() {
  return matrix(6, 4, {3.1, 2.0, 4.5, 3.3, 2.9, 2.2, 4.1, 3.0, 3.5, 1.9, 4.8, 3.9,
                       3.0, 2.5, 4.0, 3.1, 3.3, 2.4, 4.4, 3.2, 2.8, 2.1, 3.9, 3.4});
}
// R: y2 <- matrix(c(...), ncol=5, byrow=TRUE), with ties and one fully tied row
inline CostMatrix y2() {
  return matrix(5, 5, {1, 1, 2, 3, 3, 2, 1, 1, 3, 4, 1, 2, 2, 2, 5, 1, 1, 1, 1, 1, 2, 3, 1, 4, 4});
}
// R: set.seed(3); y3 <- matrix(round(rnorm(40, mean=rep(c(0,0.2,1,2,3), each=8)),3), ncol=5)
inline CostMatrix y3() {
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

}  // namespace sd::statistics::testing
